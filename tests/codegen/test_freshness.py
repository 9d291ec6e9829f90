"""generated/ is fresh, deterministic, and protected against tampering."""

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


def _run_derive(args, cwd):
    env = dict(os.environ, PYTHONPATH=str(cwd))
    return subprocess.run([sys.executable, "-m", "derive", *args], cwd=cwd, capture_output=True, text=True, env=env)


def test_full_check_passes_on_this_tree():
    proc = _run_derive(["--check"], REPO)
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_changed_derive_source_makes_check_fail_naming_the_command(tmp_path):
    copy = tmp_path / "repo"
    shutil.copytree(REPO / "derive", copy / "derive")
    shutil.copytree(REPO / "generated", copy / "generated")
    src = copy / "derive" / "attitude.py"
    src.write_text(src.read_text().replace("r_ * sp.sin(e_)])", "r_ * sp.sin(e_) * 2])"))
    proc = _run_derive(["--check"], copy)
    assert proc.returncode != 0
    assert "python -m derive" in proc.stdout
    assert "deck2enu" in proc.stdout
    # the fast check notices too
    from derive.emit import derive_sources_sha256

    recorded = json.loads((copy / "generated" / "manifest.json").read_text())["derive_sources_sha256"]
    assert recorded != derive_sources_sha256(copy / "derive")


def test_regeneration_is_deterministic(tmp_path):
    out1, out2 = tmp_path / "g1", tmp_path / "g2"
    assert _run_derive(["--out", str(out1)], REPO).returncode == 0
    assert _run_derive(["--out", str(out2)], REPO).returncode == 0
    files = sorted(p.name for p in out1.iterdir())
    assert files == sorted(p.name for p in out2.iterdir())
    for f in files:
        assert (out1 / f).read_bytes() == (out2 / f).read_bytes(), f


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
    sys.path.insert(0, str(REPO))
    try:
        from derive.emit import emit_all
        from derive.registry import CONSTANTS, all_specs
    finally:
        sys.path.remove(str(REPO))
    out = tmp_path / "generated"
    out.mkdir()
    (out / "keep.txt").write_text("previous artifacts")
    specs = [s for s in all_specs() if s.name in ("geodetic2ecef", "radii_of_curvature")]

    class Broken:
        name = "zz_broken"  # sorted last: fails after the others were written

        def build(self):
            raise RuntimeError("derivation failed")

    with pytest.raises(RuntimeError, match="derivation failed"):
        emit_all([*specs, Broken()], out, CONSTANTS)
    assert [p.name for p in out.iterdir()] == ["keep.txt"]
    assert [p.name for p in tmp_path.iterdir()] == ["generated"]  # no staging folder left behind
    manifest = emit_all(specs, out, CONSTANTS)
    assert sorted(manifest["functions"]) == ["geodetic2ecef", "radii_of_curvature"]
    assert not (out / "keep.txt").exists() and (out / "manifest.json").exists()
