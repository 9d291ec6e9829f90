"""generated/ is fresh, deterministic, and protected against tampering.

One full regeneration per test session (``python -m derive --check --fresh``, the ``derivation``
fixture of tests/conftest.py, shared with the codegen tests that need the derived specs) serves
the freshness check and the determinism check; the stale-source test emits only the derive
module it changes.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from registration import _codegen
from registration._codegen import artifacts

REPO = Path(__file__).resolve().parents[2]
REGEN = "python -m derive"
EMIT_ONE_MODULE = """
import sys
from pathlib import Path
from importlib import import_module
from derive.emit import emit_all
from derive.registry import CONSTANTS, VARIANTS
emit_all(import_module("derive." + sys.argv[1]).specs(), Path(sys.argv[2]), CONSTANTS, VARIANTS)
"""


def _derive_env(root: Path) -> dict:
    return dict(os.environ, PYTHONPATH=str(root), PYTHONHASHSEED="0")


def _emit_modules(jobs: list[tuple[Path, str, Path]]) -> None:
    """Emit the specs of one derive module per job (derive root, module, output folder), in parallel
    subprocesses under the hash seed ``python -m derive`` uses."""
    procs = [
        subprocess.Popen(
            [sys.executable, "-c", EMIT_ONE_MODULE, module, str(out)],
            cwd=root,
            env=_derive_env(root),
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        for root, module, out in jobs
    ]
    for proc in procs:
        _, err = proc.communicate()
        assert proc.returncode == 0, err


def test_manifest_matches_derive_sources():
    """Fast staleness check: the manifest records the sha256 of derive/*.py."""
    from derive.emit import derive_sources_sha256

    recorded = json.loads((REPO / "generated" / "manifest.json").read_text())["derive_sources_sha256"]
    assert recorded == derive_sources_sha256(), f"generated/ is stale: run `{REGEN}` and commit generated/"


def test_manifest_records_tools_and_artifacts():
    m = _codegen.manifest()
    assert set(m["tool_versions"]) == {"casadi", "sympy", "python"}
    import casadi
    import sympy

    assert m["tool_versions"]["casadi"] == casadi.__version__
    assert m["tool_versions"]["sympy"] == sympy.__version__
    for name, meta in m["functions"].items():
        for kind in ("casadi", "c"):
            path = _codegen.generated_dir() / meta["artifacts"][kind]["file"]
            assert hashlib.sha256(path.read_bytes()).hexdigest() == meta["artifacts"][kind]["sha256"], name
            assert b"DO NOT EDIT" in path.read_bytes()[:400]
        assert meta["inputs"] and meta["outputs"]
    for name, meta in m["modules"].items():  # the typed API (generated/api.py)
        path = _codegen.generated_dir() / meta["file"]
        assert hashlib.sha256(path.read_bytes()).hexdigest() == meta["sha256"], name
        assert b"DO NOT EDIT" in path.read_bytes()[:400]


def test_full_check_passes_on_this_tree(derivation):
    assert derivation.returncode == 0, derivation.stdout + derivation.stderr
    assert "generated/ is fresh" in derivation.stdout
    assert (derivation.fresh / "manifest.json").exists()  # the fresh generation was kept for the tests below


def test_regeneration_is_deterministic(derivation):
    """The checked-in generated/ was written by an earlier, independent run of ``python -m derive``:
    byte equality with the fixture's fresh run shows two runs give the same bytes."""
    fresh = derivation.fresh
    files = sorted(p.name for p in fresh.iterdir() if p.is_file())
    assert "manifest.json" in files and len(files) > 2
    assert files == sorted(p.name for p in (REPO / "generated").iterdir() if p.is_file())
    for f in files:
        assert (fresh / f).read_bytes() == (REPO / "generated" / f).read_bytes(), (
            f"{f}: two generations differ "
            f"(derive/ changed without `{REGEN}`, or emission is not deterministic)"
        )


def test_changed_derive_source_makes_check_fail_naming_the_command(tmp_path, capsys):
    from derive.__main__ import check
    from derive.emit import derive_sources_sha256

    copy = tmp_path / "repo"
    shutil.copytree(REPO / "derive", copy / "derive", ignore=shutil.ignore_patterns("__pycache__"))
    src = copy / "derive" / "attitude.py"
    changed = src.read_text().replace("r_ * sp.sin(e_)])", "r_ * sp.sin(e_) * 2])")
    assert changed != src.read_text()
    src.write_text(changed)
    # the fast check notices
    recorded = json.loads((REPO / "generated" / "manifest.json").read_text())["derive_sources_sha256"]
    assert recorded != derive_sources_sha256(copy / "derive")
    # the full check: the changed module's functions, emitted before and after the change
    before, after = tmp_path / "before", tmp_path / "after"
    _emit_modules([(REPO, "attitude", before), (copy, "attitude", after)])
    assert check(after, before) == 1
    out = capsys.readouterr().out
    assert "python -m derive" in out
    assert "differs: deck2enu.c" in out and "differs: deck2enu.casadi" in out
    assert "deck2enu_rotation" not in out  # no radar measurement in it: unchanged, not blamed
    assert "the derive/ sources changed" in out
    assert check(before, before) == 0


def test_fresh_folder_goes_with_check_only():
    from derive.__main__ import parse_args

    with pytest.raises(SystemExit):
        parse_args(["--fresh", "elsewhere"])
    with pytest.raises(SystemExit):
        parse_args(["--check", "--fresh", "generated", "--out", "generated"])
    assert parse_args(["--check", "--fresh", "elsewhere"]).fresh == Path("elsewhere")


def test_tampered_artifact_is_refused(tmp_path, monkeypatch):
    copy = tmp_path / "generated"
    shutil.copytree(_codegen.generated_dir(), copy)
    target = copy / "geodetic2ecef.casadi"
    target.write_bytes(target.read_bytes().replace(b"a", b"b", 1))
    monkeypatch.setattr(artifacts, "generated_dir", lambda: copy)  # the name read_artifact calls
    artifacts.manifest.cache_clear()
    try:
        with pytest.raises(_codegen.ArtifactError, match="does not match manifest"):
            _codegen.GeneratedFunction("geodetic2ecef", force_backend="casadi").casadi
    finally:
        artifacts.manifest.cache_clear()


def test_failed_derivation_leaves_previous_artifacts_intact(tmp_path):
    """A derivation that raises half-way must not wipe the existing output folder."""
    from derive import geodesy
    from derive.emit import emit_all
    from derive.registry import CONSTANTS, VARIANTS

    out = tmp_path / "generated"
    out.mkdir()
    (out / "keep.txt").write_text("previous artifacts")
    specs = [s for s in geodesy.specs() if s.name in ("geodetic2ecef", "radii_of_curvature")]  # not all: fast

    class Broken:
        name = "zz_broken"  # sorted last: fails after the others were written

        def build(self):
            raise RuntimeError("derivation failed")

    with pytest.raises(RuntimeError, match="derivation failed"):
        emit_all([*specs, Broken()], out, CONSTANTS, VARIANTS)
    assert [p.name for p in out.iterdir()] == ["keep.txt"]
    assert [p.name for p in tmp_path.iterdir()] == ["generated"]  # no staging folder left behind
    manifest = emit_all(specs, out, CONSTANTS, VARIANTS)
    assert sorted(manifest["functions"]) == ["geodetic2ecef", "radii_of_curvature"]
    assert not (out / "keep.txt").exists() and (out / "manifest.json").exists()
