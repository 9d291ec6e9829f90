"""Plots files with a ``track`` column and empty ``target`` cells (read by
registration.io.fleet.reading.read), and ``registration fleet register`` on them: the association runs,
associations.csv says per plot its target, the join's distance and why a plot was left out, the
counts per sensor are printed, and ``--method online`` runs the filter on the association's labels."""

import json

import numpy as np
import pandas as pd
import pytest

from registration.cli import main
from registration.fleet.association.simulated.fleets import vessel_fleet
from registration.io import read_fleet_tables, write_fleet_tables
from registration.io.fleet.reading.read import needs_association

NAMES = ("plots", "navigation", "sensors", "platforms", "reference")


@pytest.fixture(scope="module")
def bridge(tmp_path_factory):
    """A bridge log: one ship, its ARPA radar's plots with track numbers, and AIS for 11 of 14
    vessels; a few plots carry the vessel's MMSI as target id, the rest an empty target cell."""
    sim, refs = vessel_fleet(35, duration_s=240.0)
    sc = sim.scenario
    plots = dict(sim.plots)
    ais = np.unique(refs["target"])
    target = np.where(np.isin(sim.true_target, ais[:2]) & (plots["time"] < 60.0), sim.true_target, "")
    plots["target"] = target.astype(str)
    folder = tmp_path_factory.mktemp("bridge")
    write_fleet_tables(folder, plots, sc.navigation, sc.sensors, sc.platforms, refs)
    return folder, sim


def test_track_column_and_empty_targets_are_read_as_no_id(bridge):
    folder, sim = bridge
    raw = pd.read_csv(folder / "plots.csv", dtype=str, keep_default_na=False)
    assert {"track", "target"} <= set(raw.columns) and (raw["target"] == "").any()
    for mode in ("stop", "skip"):
        tables = read_fleet_tables(*(folder / f"{n}.csv" for n in NAMES), on_bad_row=mode)
        assert not tables.rejected
        np.testing.assert_array_equal(tables.plots["target"], raw["target"].to_numpy())
        np.testing.assert_array_equal(tables.plots["track"], raw["track"].to_numpy())
        assert needs_association(tables.plots)
        ref_rows = len(pd.read_csv(folder / "reference.csv"))
        assert tables.references["target"].size == ref_rows  # every reference kept: they are anchors


def _run(folder, out, *extra) -> int:
    return main(["fleet", "register", "--tables", str(folder), "--out", str(out), "--no-plots", *extra])


def test_register_writes_the_associations_and_counts_per_sensor(bridge, tmp_path, capsys):
    folder, sim = bridge
    assert _run(folder, tmp_path / "o") == 0
    text = capsys.readouterr().out
    assert "association:" in text and "sensor ARPA:" in text and "associated" in text
    found = pd.read_csv(tmp_path / "o" / "associations.csv", dtype=str, keep_default_na=False)
    assert list(found.columns) == ["row", "time_s", "sensor", "track", "target", "join", "reason"]
    assert len(found) == sim.true_target.size
    labelled = found["target"] != ""
    assert (found["target"][labelled] == sim.true_target[labelled]).all()  # no wrong join
    assert ((found["reason"] != "") | labelled).all() and (
        found["join"][labelled & (found["reason"] == "")] != ""
    ).all()
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    counts = summary["inputs"]["association"]["by_sensor"]["ARPA"]
    assert counts["given"] > 0 and counts["associated"] > 0
    assert counts["given"] + counts["associated"] + counts["unassociated"] == len(found)


def test_online_runs_on_the_associations_labels(bridge, tmp_path, capsys):
    folder, _ = bridge
    assert _run(folder, tmp_path / "on", "--method", "online") == 0
    text = capsys.readouterr().out
    assert "the association is a batch method" in text and "online filter:" in text
    assert (tmp_path / "on" / "history.csv").exists() and (tmp_path / "on" / "associations.csv").exists()
