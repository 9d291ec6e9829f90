"""The association names the real cause when it anchors nothing or leaves a sensor's plots without
a target: one sensor without a reference, no references at all, no target ids; not the windows
(the advice to give a longer --window-s that a one-radar recording met before)."""

import re
import shutil

import pandas as pd
import pytest

from registration.cli import main
from registration.cli.errors import MAX_MESSAGE

ALL = ("A-3D", "A-ESM", "B-3D", "C-3D", "C-2D", "S-2D")


@pytest.fixture(scope="module")
def fleet(tmp_path_factory):
    """The built-in fleet for 60 s with 4 targets: six sensors, references of every target."""
    out = tmp_path_factory.mktemp("fleet") / "sim"
    argv = ["fleet", "simulate", "--no-plots", "--duration-s", "60", "--targets", "4", "--out", str(out)]
    assert main(argv) == 0
    return out


def _tables(fleet, folder, sensors, references=False, target=None, every_s=None):
    """A tables folder with the plots of ``sensors`` only; ``target``: None drops the column, '' empties
    it; ``every_s``: only the plots at multiples of it; ``references``: True copies them, a number
    shifts their times by it (s)."""
    folder.mkdir()
    for name in ("navigation.csv", "platforms.csv", "sensors.csv"):
        shutil.copy(fleet / name, folder / name)
    plots = pd.read_csv(fleet / "plots.csv", dtype={"sensor": str, "target": str})
    plots = plots[plots["sensor"].isin(sensors)]
    if every_s is not None:
        plots = plots[plots["time_s"] % every_s == 0]
    plots = plots.drop(columns="target") if target is None else plots.assign(target=target)
    plots.to_csv(folder / "plots.csv", index=False)
    if references is not False:
        refs = pd.read_csv(fleet / "reference.csv")
        refs["time_s"] += 0.0 if references is True else references
        refs.to_csv(folder / "reference.csv", index=False)
    return folder, len(plots)


def _refused(folder, tmp_path, capsys) -> str:
    out = tmp_path / "out"
    assert main(["fleet", "register", "--tables", str(folder), "--out", str(out), "--no-plots"]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and len(err) <= MAX_MESSAGE, err
    assert "window" not in err, err  # the windows are not the cause
    assert not out.exists()
    return err


def test_one_sensor_without_a_reference_is_named_not_the_windows(fleet, tmp_path, capsys):
    """Plots 12 s apart: before, 'windows of 20 s hold at most 1.7 plots ... give longer windows'."""
    folder, n = _tables(fleet, tmp_path / "t", ["A-3D"], every_s=12)
    err = _refused(folder, tmp_path, capsys)
    assert f"all {n} plots are of one sensor, 'A-3D'" in err
    assert "no references (ADS-B, AIS)" in err and "no target ids (no target column)" in err
    assert err.endswith("give references, target ids or a second sensor's plots")


def test_no_references_at_all_with_no_position_fixing_sensor(fleet, tmp_path, capsys):
    """Three sensors, none of them measures range, bearing and elevation, and no reference."""
    folder, _ = _tables(fleet, tmp_path / "t", ["A-ESM", "C-2D", "S-2D"])
    err = _refused(folder, tmp_path, capsys)
    assert "no sensor of the 3 with plots fixes a position alone; no references (ADS-B, AIS)" in err
    assert err.endswith("give references, target ids or a position-fixing sensor's plots")


def test_no_ids_and_references_outside_the_plots_time(fleet, tmp_path, capsys):
    """An empty target column, and references 1000 s after the plots: neither anchors a target."""
    folder, _ = _tables(fleet, tmp_path / "t", ["A-ESM", "C-2D"], references=1000.0, target="")
    err = _refused(folder, tmp_path, capsys)
    assert "no target ids (empty target column)" in err
    found = re.search(r"references at ([\d.]+) to ([\d.]+) s, plots at ([\d.]+) to ([\d.]+) s", err)
    assert found, err
    r0, r1, p0, p1 = map(float, found.groups())
    assert r0 > p1 and r1 > r0 >= 1000.0 and p1 > p0


def test_references_that_meet_the_plots_are_an_anchor(fleet, tmp_path, capsys):
    """The same tables with the references at their times: the run goes on (exit 0)."""
    folder, _ = _tables(fleet, tmp_path / "t", ["A-ESM", "C-2D"], references=True, target="")
    out = tmp_path / "out"
    assert main(["fleet", "register", "--tables", str(folder), "--out", str(out), "--no-plots"]) == 0


def test_one_sensor_with_a_reference_for_one_target_notes_the_rest(fleet, tmp_path, capsys):
    """One sensor, a reference of one target only: the other targets' plots are left, and a note says
    why (their sensor is the only one and no reference is near them)."""
    folder, _ = _tables(fleet, tmp_path / "t", ["A-3D"])
    all_refs = pd.read_csv(fleet / "reference.csv")
    all_refs[all_refs["target"] == "T1"].to_csv(folder / "reference.csv", index=False)
    out = tmp_path / "out"
    assert main(["fleet", "register", "--tables", str(folder), "--out", str(out), "--no-plots"]) == 0
    stdout = capsys.readouterr().out
    left = pd.read_csv(out / "associations.csv")
    n = int((left["reason"] == "no_anchor").sum())
    assert n > 0
    notes = [line for line in stdout.splitlines() if line.strip().startswith("note: sensor 'A-3D'")]
    assert len(notes) == 1 and len(notes[0]) <= MAX_MESSAGE, notes
    assert f"{n} plots without a target" in notes[0]
    assert "no reference near them" in notes[0] and "'A-3D' the only sensor with plots" in notes[0]
    assert "window" not in notes[0]
