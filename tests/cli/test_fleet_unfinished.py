"""`fleet register` and unfinished folders (issue 32, 1): a tables folder that carries the
publication marker is read with a one-line warning; a run that fails because every plot was set
aside (``--on-bad-row skip``) leaves --out exactly as it was."""

import shutil
from pathlib import Path

import pandas as pd
import pytest

from registration.cli import main
from registration.io.output.outfolder import MARKER


@pytest.fixture(scope="module")
def simulated(tmp_path_factory):
    out = tmp_path_factory.mktemp("fleet") / "sim"
    assert main(["fleet", "simulate", "--no-plots", "--duration-s", "60", "--out", str(out)]) == 0
    for name in ("estimates.csv", "summary.json"):
        (out / name).unlink()
    return out


def _snapshot(folder: Path) -> dict:
    return {p.relative_to(folder): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def test_a_folder_with_the_marker_is_read_with_a_warning(simulated, tmp_path, capsys):
    folder = tmp_path / "in"
    shutil.copytree(simulated, folder)
    (folder / MARKER).write_text("publishing: partial-x\n")
    code = main(["fleet", "register", "--tables", str(folder), "--out", str(tmp_path / "out"), "--no-plots"])
    err = capsys.readouterr().err
    assert code == 0, err
    warnings = [line for line in err.splitlines() if "not a finished output" in line]
    assert len(warnings) == 1 and MARKER in warnings[0] and str(folder.resolve()) in warnings[0]
    assert len(warnings[0]) <= 300


def test_no_warning_without_the_marker(simulated, tmp_path, capsys):
    code = main(
        ["fleet", "register", "--tables", str(simulated), "--out", str(tmp_path / "out"), "--no-plots"]
    )
    assert code == 0 and "not a finished output" not in capsys.readouterr().err


def test_skip_with_every_plot_bad_leaves_out_as_it_was(simulated, tmp_path, capsys):
    """Before: exit 2, and --out replaced by rejected.csv alone."""
    out = tmp_path / "out"
    assert main(["fleet", "register", "--tables", str(simulated), "--out", str(out), "--no-plots"]) == 0
    before = _snapshot(out)
    assert "estimates.csv" in {str(p) for p in before}
    folder = tmp_path / "bad"
    shutil.copytree(simulated, folder)
    plots = pd.read_csv(folder / "plots.csv", dtype=str)
    plots["time_s"] = "abc"
    plots.to_csv(folder / "plots.csv", index=False)
    capsys.readouterr()
    argv = [
        "fleet",
        "register",
        "--tables",
        str(folder),
        "--out",
        str(out),
        "--no-plots",
        "--on-bad-row",
        "skip",
    ]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "no valid rows to register" in err and "non_numeric" in err
    assert _snapshot(out) == before
    assert sorted(p.name for p in out.parent.iterdir() if p.name.startswith(out.name)) == [out.name]
