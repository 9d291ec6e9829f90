"""`fleet register` sets aside plots it cannot use, with a note, in both --on-bad-row modes (issue
31, 6 and 7): plots outside their platform's navigation (a bridge log cut after a TTM), exactly
duplicated plot rows; it exits 2 only when no plot is left."""

import shutil

import pandas as pd
import pytest

from registration.cli import main
from tests.io.nmea.bridgelog import BridgeLogConfig, simulate_bridge_log


@pytest.fixture(scope="module")
def simulated(tmp_path_factory):
    out = tmp_path_factory.mktemp("fleet") / "sim"
    assert main(["fleet", "simulate", "--no-plots", "--duration-s", "60", "--out", str(out)]) == 0
    for name in ("estimates.csv", "summary.json"):
        (out / name).unlink()
    return out


def _register(folder, out, *extra):
    return main(["fleet", "register", "--tables", str(folder), "--out", str(out), "--no-plots", *extra])


def test_a_bridge_log_that_ends_with_a_ttm_registers(tmp_path, capsys):
    """Before: exit 2, the last TTM 0.36 s after the last navigation fix."""
    log = simulate_bridge_log(BridgeLogConfig(seed=5, duration_s=120.0))
    path = log.write(tmp_path / "bridge.nmea")
    sensors = log.write_sensors(tmp_path / "SENSORS.csv")
    lines = path.read_text().splitlines(keepends=True)
    last_ttm = max(i for i, line in enumerate(lines) if "TTM," in line)
    path.write_text("".join(lines[: last_ttm + 1]))  # cut: no fix after the last TTM
    out = tmp_path / "imp"
    argv = ["import", "nmea", str(path), "--platform", "OWN", "--sensors", str(sensors), "--out", str(out)]
    assert main(argv) == 0
    nav = pd.read_csv(out / "navigation.csv")
    plots = pd.read_csv(out / "plots.csv")
    outside = int((plots["time_s"] > nav["time_s"].max()).sum())
    capsys.readouterr()
    assert _register(out, tmp_path / "reg") == 0
    text = capsys.readouterr().out
    if outside:  # the import keeps them (until it sets them aside itself)
        assert f"{outside} plot row(s) outside their platform's navigation time span set aside" in text
        rejected = pd.read_csv(tmp_path / "reg" / "rejected.csv")
        assert set(rejected["reason_code"]) == {"outside_navigation"} and len(rejected) == outside


@pytest.mark.parametrize("mode", ["stop", "skip"])
def test_plots_outside_the_navigation_are_set_aside_with_a_note(simulated, tmp_path, capsys, mode):
    folder = tmp_path / "in"
    shutil.copytree(simulated, folder)
    nav = pd.read_csv(folder / "navigation.csv", dtype={"platform": str})
    nav[~((nav["platform"] == "A") & (nav["time_s"] > 55))].to_csv(folder / "navigation.csv", index=False)
    assert _register(folder, tmp_path / "out", "--on-bad-row", mode) == 0
    out = capsys.readouterr().out
    rejected = pd.read_csv(tmp_path / "out" / "rejected.csv")
    n = len(rejected)
    assert n > 0 and set(rejected["reason_code"]) == {"outside_navigation"}
    assert f"note: {folder / 'plots.csv'}: {n} plot row(s) outside" in out
    summary = (tmp_path / "out" / "summary.json").read_text()
    assert "outside_navigation" in summary


def test_no_plot_inside_the_navigation_exits_2(simulated, tmp_path, capsys):
    folder = tmp_path / "in"
    shutil.copytree(simulated, folder)
    plots = pd.read_csv(folder / "plots.csv", dtype=str)
    sensors = pd.read_csv(folder / "sensors.csv", dtype=str)
    moving = sensors["sensor"][sensors["platform"] != "S"]  # S: a fixed site, at all times
    plots = plots[plots["sensor"].isin(moving)]
    plots["time_s"] = plots["time_s"].astype(float) + 1000.0
    plots.to_csv(folder / "plots.csv", index=False)
    assert _register(folder, tmp_path / "out") == 2
    err = capsys.readouterr().err
    assert "no valid rows to register" in err and "outside_navigation" in err
    assert len(err.strip().replace(str(folder), "DIR")) <= 300 and not (tmp_path / "out").exists()


@pytest.mark.parametrize("mode", ["stop", "skip"])
def test_duplicated_plot_rows_are_set_aside_with_a_count(simulated, tmp_path, capsys, mode):
    """Before: used, each counting twice in the solve."""
    folder = tmp_path / "in"
    shutil.copytree(simulated, folder)
    plots = pd.read_csv(folder / "plots.csv", dtype=str)
    pd.concat([plots, plots.iloc[5:25]], ignore_index=True).to_csv(folder / "plots.csv", index=False)
    assert _register(folder, tmp_path / "out", "--on-bad-row", mode) == 0
    out = capsys.readouterr().out
    assert "20 plot row(s) exactly duplicated" in out
    rejected = pd.read_csv(tmp_path / "out" / "rejected.csv")
    assert set(rejected["reason_code"]) == {"duplicate"} and list(rejected["row"]) == list(
        range(len(plots), len(plots) + 20)
    )
    assert rejected["reason"].iloc[0] == "the same plot as row 5, in every column"
    assert _register(simulated, tmp_path / "base") == 0
    for name in ("estimates.csv",):  # the same as the file without the duplicates, bit for bit
        assert (tmp_path / "out" / name).read_bytes() == (tmp_path / "base" / name).read_bytes()
