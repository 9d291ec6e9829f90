"""The typed Python API of the generated functions: the text of ``generated/api.py``.

One wrapper per generated function, with keyword-only inputs named as in the spec, type hints,
and a docstring giving each input's and output's name, shape and unit; it returns a NamedTuple
of the named outputs and calls the runtime loader (``registration._codegen.get``) with the
inputs in the spec's order. Functions emitted once per T variant (``plot2ecef_standard``,
``plot2ecef_paper``, ...) share one output type and get one more wrapper that takes the variant
as the keyword ``t_variant`` (``plot2ecef(t_variant=..., ...)``).

The text is already in the project's style (``ruff format``, 110 columns) and depends only on
the manifest's function metadata, so it is as deterministic as the rest of ``generated/``.
"""

from __future__ import annotations

import textwrap

__all__ = ["API_NAME", "api_text"]

API_NAME = "api.py"
WIDTH = 110
#: The variant kind whose functions get a dispatching wrapper, and that wrapper's keyword.
FAMILY_KIND = "t_variant"


def class_name(name: str) -> str:
    """``fleet_rows_ext_4`` -> ``FleetRowsExt4Outputs``: the NamedTuple of a function's outputs."""
    return "".join(part[:1].upper() + part[1:] for part in name.split("_")) + "Outputs"


def core_shape(shape: list[int]) -> str:
    """The numpy shape of one point of a port: () for a scalar, (r,) for a vector, else (r, c)."""
    rows, cols = shape
    if (rows, cols) == (1, 1):
        return "()"
    return f"({rows},)" if cols == 1 else f"({rows}, {cols})"


def batched_shape(shape: list[int]) -> str:
    """The numpy shape of an output over N points: (N,), (N, r) or (N, r, c)."""
    core = core_shape(shape)
    return "(N,)" if core == "()" else "(N, " + core[1:].removesuffix(",)").removesuffix(")") + ")"


def families(functions: dict, variants: list[str]) -> dict[str, list[str]]:
    """Base name -> its functions ``{base}_{variant}`` for every variant, when they have the same ports."""
    out: dict[str, list[str]] = {}
    for name in sorted(functions):
        for variant in variants:
            base = name.removesuffix(f"_{variant}")
            if base == name or base in out:
                continue
            members = [f"{base}_{v}" for v in variants]
            if all(m in functions for m in members):
                ports = [(functions[m]["inputs"], functions[m]["outputs"]) for m in members]
                if all(p == ports[0] for p in ports) and base not in functions:
                    out[base] = members
    return out


def _wrap(text: str, indent: str) -> list[str]:
    return textwrap.wrap(text, WIDTH - len(indent), break_on_hyphens=False) or [""]


def _port_lines(ports: list[dict], batched: bool) -> list[str]:
    lines = []
    for port in ports:
        shape = batched_shape(port["shape"]) if batched else core_shape(port["shape"])
        unit = f" [{port['unit']}]" if port["unit"] else ""
        lines += [" " * 8 + line for line in _wrap(f"{port['name']}: {shape}{unit}", " " * 8)]
    return lines


def _docstring(summary: str, meta: dict) -> list[str]:
    indent = " " * 4
    body = [indent + line for line in _wrap(summary, indent + '"""')]
    body += ["", indent + "Inputs, each at this shape or with one more leading axis of N points:"]
    body += _port_lines(meta["inputs"], batched=False)
    body += [indent + "Outputs, over the N points (N = 1 when no input has the leading axis):"]
    body += _port_lines(meta["outputs"], batched=True)
    body[0] = indent + '"""' + body[0].lstrip()
    return [*body, indent + '"""']


def _signature(name: str, params: list[str], returns: str) -> list[str]:
    one_line = f"def {name}(*, {', '.join(params)}) -> {returns}:"
    if len(one_line) <= WIDTH:
        return [one_line]
    inner = ", ".join(params)
    if len(" " * 4 + "*, " + inner) <= WIDTH:
        return [f"def {name}(", f"    *, {inner}", f") -> {returns}:"]
    return [f"def {name}(", "    *,", *(f"    {p}," for p in params), f") -> {returns}:"]


def _call(result: str, target: str, args: list[str]) -> list[str]:
    inner = ", ".join(args)
    if len(f"    outputs = get({target})({inner})") <= WIDTH:
        call = [f"    outputs = get({target})({inner})"]
    elif len(" " * 8 + inner) <= WIDTH:
        call = [f"    outputs = get({target})(", f"        {inner}", "    )"]
    else:
        call = [f"    outputs = get({target})(", *(f"        {a}," for a in args), "    )"]
    return [*call, f"    return {result}(*outputs)"]


def _outputs_class(cls: str, about: str, meta: dict) -> list[str]:
    lines = ["", "", f"class {cls}(NamedTuple):", f'    """The outputs of {about}, by name."""', ""]
    for port in meta["outputs"]:
        lines.append(f"    {port['name']}: Array")
        unit = f" [{port['unit']}]" if port["unit"] else ""
        lines += [f'    """{line}"""' for line in _wrap(f"{batched_shape(port['shape'])}{unit}", " " * 10)]
    return lines


def _function(name: str, meta: dict, cls: str, *, family: list[str] | None = None) -> list[str]:
    inputs = [p["name"] for p in meta["inputs"]]
    params = [f"{p}: ArrayLike" for p in inputs]
    if family is None:
        doc = _docstring(meta["doc"], meta)
        target = f'"{name}"'
    else:
        params.insert(0, f"{FAMILY_KIND}: str")
        choices = [m.removeprefix(name + "_") for m in family]
        summary = (
            f"The generated function ``{name}_{{{FAMILY_KIND}}}``, {FAMILY_KIND} one of "
            + ", ".join(f'"{c}"' for c in choices)
            + f'. That of "{choices[0]}": {meta["doc"]}'
        )
        doc = _docstring(summary, meta)
        target = f'f"{name}_{{{FAMILY_KIND}}}"'
    return ["", "", *_signature(name, params, cls), *doc, *_call(cls, target, inputs)]


def _header(header_lines: list[str]) -> list[str]:
    return [
        f'"""{header_lines[0]}',
        *header_lines[1:],
        "",
        "Typed wrappers of the generated functions: keyword-only inputs named, shaped and documented as",
        "derive/ declares them, and a NamedTuple of the named outputs. Each calls",
        "``registration._codegen.get(name)`` with the inputs in the function's order, so the results are",
        "those of the generated function, bit for bit.",
        '"""',
        "",
        "from __future__ import annotations",
        "",
        "from typing import NamedTuple",
        "",
        "import numpy as np",
        "from numpy.typing import ArrayLike, NDArray",
        "",
        "from registration._codegen import get",
        "",
        "#: A float64 array: every output of a generated function.",
        "Array = NDArray[np.float64]",
    ]


def api_text(functions: dict, variants: dict, header_lines: list[str]) -> bytes:
    """The text of ``generated/api.py`` from the manifest's ``functions`` (name -> metadata) and
    ``variants`` (kind -> variant names)."""
    grouped = families(functions, list(variants.get(FAMILY_KIND, ())))
    member_class = {m: class_name(base) for base, members in grouped.items() for m in members}
    names: list[str] = []
    body: list[str] = []
    for base, members in grouped.items():
        meta = functions[members[0]]
        cls = class_name(base)
        body += _outputs_class(cls, f"``{base}_{{{FAMILY_KIND}}}``", meta)
        body += _function(base, meta, cls, family=members)
        names += [cls, base]
    for name in sorted(functions):
        cls = member_class.get(name, class_name(name))
        if name not in member_class:
            body += _outputs_class(cls, f":func:`{name}`", functions[name])
            names.append(cls)
        body += _function(name, functions[name], cls)
        names.append(name)
    exports = ["", "__all__ = [", *(f'    "{n}",' for n in ["Array", *names]), "]"]
    return ("\n".join([*_header(header_lines), *exports, *body]) + "\n").encode()
