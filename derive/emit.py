"""The emitter: each function spec becomes a CasADi Function (sympy -> SX, after CSE), written as
a serialized ``.casadi`` file and C source; the typed Python wrappers of them all (``api.py``,
:mod:`derive.wrappers`); ``manifest.json`` (each artifact's sha256, the derive sources hash, tool
versions, constants, variant names); and the folder comparison behind ``python -m derive --check``.

Deterministic: the same derive sources and tool versions give the same bytes (run under
PYTHONHASHSEED=0, which ``python -m derive`` arranges).
"""

from __future__ import annotations

import hashlib
import json
import os
import platform
import shutil
import tempfile
from pathlib import Path

import casadi as ca
import sympy as sp

from .spec import FunctionSpec
from .wrappers import API_NAME, api_text

DERIVE_DIR = Path(__file__).resolve().parent
REPO_DIR = DERIVE_DIR.parent
GENERATED_DIR = REPO_DIR / "generated"

HEADER_LINES = [
    "GENERATED FILE - DO NOT EDIT BY HAND.",
    "Produced by `python -m derive` from the sympy derivations in derive/.",
    "Edit derive/ and regenerate; `python -m derive --check` verifies freshness.",
]
MANIFEST_NAME = "manifest.json"


# --------------------------------------------------------------------------- sympy -> SX
_UNARY = {
    sp.sin: ca.sin,
    sp.cos: ca.cos,
    sp.tan: ca.tan,
    sp.asin: ca.asin,
    sp.acos: ca.acos,
    sp.atan: ca.atan,
    sp.exp: ca.exp,
    sp.log: ca.log,
    sp.Abs: ca.fabs,
    sp.sign: ca.sign,
}


class SympyToCasadi:
    """Convert sympy expressions to CasADi SX given a symbol map, memoising sub-trees."""

    def __init__(self, symbols: dict):
        self.env = dict(symbols)

    def __call__(self, expr):
        if expr in self.env:
            return self.env[expr]
        out = self._convert(expr)
        self.env[expr] = out
        return out

    def _convert(self, expr):
        if expr.is_Number or expr is sp.pi or expr.is_NumberSymbol:
            return ca.SX(float(expr))
        if isinstance(expr, sp.Symbol):
            raise KeyError(f"free symbol {expr} is not an input")
        if expr.is_Add:
            terms = [self(a) for a in expr.args]
            acc = terms[0]
            for t in terms[1:]:
                acc = acc + t
            return acc
        if expr.is_Mul:
            factors = [self(a) for a in expr.args]
            acc = factors[0]
            for f in factors[1:]:
                acc = acc * f
            return acc
        if expr.is_Pow:
            base, ex = expr.args
            b = self(base)
            if ex.is_Integer:
                n = int(ex)
                if n == 2:
                    return b * b
                if n == -1:
                    return 1 / b
                if n == -2:
                    return 1 / (b * b)
                return b**n if n > 0 else 1 / (b ** (-n))
            if ex == sp.Rational(1, 2):
                return ca.sqrt(b)
            if ex == sp.Rational(-1, 2):
                return 1 / ca.sqrt(b)
            if ex == sp.Rational(3, 2):
                return b * ca.sqrt(b)
            if ex == sp.Rational(-3, 2):
                return 1 / (b * ca.sqrt(b))
            return b ** self(ex)
        if isinstance(expr, sp.atan2):
            return ca.atan2(self(expr.args[0]), self(expr.args[1]))
        for sym_fn, ca_fn in _UNARY.items():
            if isinstance(expr, sym_fn):
                return ca_fn(self(expr.args[0]))
        raise NotImplementedError(f"no CasADi mapping for {type(expr).__name__}: {expr}")


def to_casadi_function(spec: FunctionSpec) -> ca.Function:
    """Build a CasADi Function (dense inputs and outputs) from a spec, after sympy CSE."""
    sx_inputs, symbols = [], {}
    for port in spec.inputs:
        rows, cols = port.shape
        sx = ca.SX.sym(port.name, rows, cols)
        for i in range(rows):
            for j in range(cols):
                s = port.matrix[i, j]
                if not isinstance(s, sp.Symbol):
                    raise TypeError(f"{spec.name}: input {port.name} must hold plain symbols")
                symbols[s] = sx[i, j]
        sx_inputs.append(sx)

    entries = [e for port in spec.outputs for e in port.matrix]  # row-major per port
    replacements, reduced = sp.cse(entries, symbols=sp.numbered_symbols("_cse"), order="none")
    conv = SympyToCasadi(symbols)
    for sym, sub in replacements:
        conv.env[sym] = conv(sub)
    reduced_sx = [conv(e) for e in reduced]

    sx_outputs, k = [], 0
    for port in spec.outputs:
        rows, cols = port.shape
        m = ca.SX.zeros(rows, cols)
        for i in range(rows):
            for j in range(cols):
                m[i, j] = reduced_sx[k]
                k += 1
        sx_outputs.append(ca.densify(m))
    return ca.Function(
        spec.name,
        sx_inputs,
        sx_outputs,
        [p.name for p in spec.inputs],
        [p.name for p in spec.outputs],
        {"cse": True},
    )


# --------------------------------------------------------------------------- files
def sha256_bytes(data: bytes) -> str:
    """Hex sha256 of ``data``."""
    return hashlib.sha256(data).hexdigest()


def derive_sources_sha256(derive_dir: Path = DERIVE_DIR) -> str:
    """sha256 over every derive/*.py (name and bytes, sorted): the freshness key."""
    h = hashlib.sha256()
    for path in sorted(derive_dir.glob("*.py")):
        h.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    return h.hexdigest()


def tool_versions() -> dict:
    """The versions of the tools whose output the artifacts depend on."""
    return {
        "casadi": ca.__version__,  # type: ignore[attr-defined]
        "sympy": sp.__version__,
        "python": ".".join(platform.python_version_tuple()[:2]),
    }


def _casadi_text(fn: ca.Function) -> bytes:
    head = "".join(f"# {line}\n" for line in HEADER_LINES)
    return (head + fn.serialize() + "\n").encode()


def _c_text(fn: ca.Function) -> bytes:
    cg = ca.CodeGenerator(f"{fn.name()}.c", {"with_header": False})
    cg.add(fn)
    head = "/*\n" + "".join(f" * {line}\n" for line in HEADER_LINES) + " */\n"
    return (head + cg.dump()).encode()


def _port_meta(port) -> dict:
    return {"name": port.name, "shape": list(port.shape), "unit": port.unit}


def emit_all(specs: list, out_dir: Path, constants: dict, variants: dict) -> dict:
    """Write every artifact and the manifest into ``out_dir``, replacing it as a whole.

    ``constants`` (name -> sympy number) and ``variants`` (kind -> variant names) are recorded in
    the manifest for the runtime.
    Everything is built in a sibling temporary folder first; ``out_dir`` is replaced only when
    every function was built, so a failing derivation leaves the previous artifacts intact.
    """
    out_dir = Path(out_dir)
    out_dir.parent.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=f".{out_dir.name}-", dir=out_dir.parent))
    staging.chmod(0o755)
    try:
        manifest = _emit_into(specs, staging, constants, variants)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise
    if out_dir.exists():
        old = out_dir.with_name(f".{out_dir.name}-old-{os.getpid()}")
        out_dir.rename(old)
        staging.rename(out_dir)
        shutil.rmtree(old)
    else:
        staging.rename(out_dir)
    return manifest


def _emit_into(specs: list, out_dir: Path, constants: dict, variants: dict) -> dict:
    functions = {}
    for spec in sorted(specs, key=lambda s: s.name):
        fn = spec.build() if hasattr(spec, "build") else to_casadi_function(spec)
        artifacts = {}
        for kind, data in (("casadi", _casadi_text(fn)), ("c", _c_text(fn))):
            fname = f"{spec.name}.{kind}"
            (out_dir / fname).write_bytes(data)
            artifacts[kind] = {"file": fname, "sha256": sha256_bytes(data)}
        functions[spec.name] = {
            "doc": spec.doc,
            "inputs": [_port_meta(p) for p in spec.inputs],
            "outputs": [_port_meta(p) for p in spec.outputs],
            "jacobians": [
                {"output": j.output, "of": j.of, "wrt": list(j.wrt)} for j in getattr(spec, "jacobians", ())
            ],
            "work": {"sz_arg": fn.sz_arg(), "sz_res": fn.sz_res(), "sz_iw": fn.sz_iw(), "sz_w": fn.sz_w()},
            "artifacts": artifacts,
        }
    init = '"""' + " ".join(HEADER_LINES) + '\n\nData package holding the generated CasADi artifacts."""\n'
    (out_dir / "__init__.py").write_text(init)
    api = api_text(functions, variants, HEADER_LINES)
    (out_dir / API_NAME).write_bytes(api)
    manifest = {
        "header": " ".join(HEADER_LINES),
        "regenerate_command": "python -m derive",
        "derive_sources_sha256": derive_sources_sha256(),
        "tool_versions": tool_versions(),
        "constants": {k: float(v) for k, v in constants.items()},
        "functions": functions,
        "modules": {"api": {"file": API_NAME, "sha256": sha256_bytes(api)}},
        "variants": {kind: list(names) for kind, names in variants.items()},
    }
    (out_dir / MANIFEST_NAME).write_text(json.dumps(manifest, indent=2, sort_keys=True) + "\n")
    return manifest


def compare_dirs(expected: Path, actual: Path) -> list[str]:
    """Human-readable differences between a fresh generation and the committed folder."""
    problems = []
    exp = {p.name for p in expected.iterdir() if p.is_file()}
    act = {p.name for p in actual.iterdir() if p.is_file()} if actual.exists() else set()
    for name in sorted(exp - act):
        problems.append(f"missing in generated/: {name}")
    for name in sorted(act - exp):
        problems.append(f"not produced by derive/ (stale leftover): {name}")
    for name in sorted(exp & act):
        if (expected / name).read_bytes() != (actual / name).read_bytes():
            problems.append(f"differs: {name}")
    if "differs: manifest.json" in problems and (actual / MANIFEST_NAME).exists():
        old = json.loads((actual / MANIFEST_NAME).read_text())
        new = json.loads((expected / MANIFEST_NAME).read_text())
        if old.get("derive_sources_sha256") != new.get("derive_sources_sha256"):
            problems.append("  the derive/ sources changed since generated/ was written")
        if old.get("tool_versions") != new.get("tool_versions"):
            problems.append(
                f"  tool versions: generated with {old.get('tool_versions')}, now {new.get('tool_versions')}"
            )
    return problems
