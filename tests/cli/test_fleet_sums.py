"""`registration fleet register` on level platforms: the identifiable sums printed and written
(console, estimates.csv, summary.json), one sigma convention (σ, 1 sigma) across console, CSV and
JSON, and one representation of an undetermined sigma (an empty CSV cell, JSON null)."""

import contextlib
import io
import json
import re

import numpy as np
import pandas as pd
import pytest

from registration.cli import main
from registration.fleet import fleet_scenario
from registration.io import write_fleet_tables

TABLES = ("plots", "navigation", "sensors", "platforms", "reference")
SUMS = {"A+A-3D", "A+A-ESM", "B+B-3D"}


@pytest.fixture(scope="module")
def tables(tmp_path_factory):
    folder = tmp_path_factory.mktemp("level")
    sc = fleet_scenario(2, ship_motion=False, duration_s=150.0)
    write_fleet_tables(folder, sc.plots, sc.navigation, sc.sensors, sc.platforms, sc.references, "csv")
    return folder


def _args(tables, out, *extra):
    args = ["fleet", "register", "--out", str(out), "--no-plots", *extra]
    for name in TABLES:
        args += [f"--{name}", str(tables / f"{name}.csv")]
    return args


@pytest.fixture(scope="module")
def batch(tables, tmp_path_factory):
    out = tmp_path_factory.mktemp("batch") / "out"
    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        assert main(_args(tables, out)) == 0
    return out, buffer.getvalue()


def _table_line(text, obj, state):
    return next(
        line for line in text.splitlines() if re.match(rf"\s+{re.escape(obj)}\s+{re.escape(state)}\s", line)
    )


def test_sums_are_printed_and_written_with_their_sigma(batch):
    out, text = batch
    est = pd.read_csv(out / "estimates.csv")
    sums = est[est["status"] == "identifiable combination"].set_index("object")
    assert SUMS <= set(sums.index), sorted(sums.index)
    parts = est.set_index(["object", "state"])
    for obj in SUMS:
        platform, sensor = obj.split("+")
        row = sums.loc[obj]
        assert row["state"] == "heading_error+bearing_bias" and row["unit"] == "deg"
        assert 0 < row["sigma"] < 0.05
        total = (
            parts.loc[(platform, "heading_error"), "estimate"]
            + parts.loc[(sensor, "bearing_bias"), "estimate"]
        )
        assert np.isclose(row["estimate"], total, rtol=0, atol=1e-9)
        line = _table_line(text, obj, "heading_error+bearing_bias")
        assert "identifiable combination" in line and f"{row['sigma']:.3g}" in line
    summary = json.loads((out / "summary.json").read_text())
    written = {(e["object"], e["state"]): e for e in summary["estimates"]}
    for obj in SUMS:
        e = written[(obj, "heading_error+bearing_bias")]
        assert e["status"] == "identifiable combination" and e["sigma"] == pytest.approx(
            sums.loc[obj, "sigma"], rel=1e-12
        )


def test_one_sigma_convention_on_console_csv_and_json(batch):
    out, text = batch
    header = next(line for line in text.splitlines() if line.strip().startswith("object"))
    assert "σ" in header and "2σ" not in header
    est = pd.read_csv(out / "estimates.csv").set_index(["object", "state"])
    summary = json.loads((out / "summary.json").read_text())
    written = {(e["object"], e["state"]): e for e in summary["estimates"]}
    for key in (("A-3D", "range_bias"), ("S-2D", "bearing_bias"), ("A", "pitch_error")):
        sigma = est.loc[key, "sigma"]
        assert f"{sigma:.3g}" in _table_line(text, *key)  # the console prints the CSV's sigma
        assert written[key]["sigma"] == pytest.approx(sigma, rel=1e-12)


def test_an_undetermined_sigma_is_empty_in_csv_null_in_json_and_named_on_the_console(batch):
    out, text = batch
    raw = (out / "estimates.csv").read_text().splitlines()
    row = next(line for line in raw if line.startswith('"A","heading_error"'))
    assert ",," in row and "inf" not in row, row
    est = pd.read_csv(out / "estimates.csv").set_index(["object", "state"])
    assert np.isnan(est.loc[("A", "heading_error"), "sigma"])
    assert est.loc[("A", "heading_error"), "status"] == "not identifiable"
    summary = json.loads((out / "summary.json").read_text())
    written = {(e["object"], e["state"]): e for e in summary["estimates"]}
    assert written[("A", "heading_error")]["sigma"] is None
    assert "undetermined" in _table_line(text, "A", "heading_error")


def test_online_prints_and_writes_the_sums(tables, tmp_path, capsys):
    assert main(_args(tables, tmp_path / "online", "--method", "online")) == 0
    text = capsys.readouterr().out
    est = pd.read_csv(tmp_path / "online" / "estimates.csv")
    sums = est[est["status"] == "identifiable combination"].set_index("object")
    assert SUMS <= set(sums.index)
    heading = est.set_index(["object", "state"]).loc[("A", "heading_error"), "sigma"]
    assert heading > 1 and (sums.loc[list(SUMS), "sigma"] < 0.05).all()  # the parts keep the diffuse prior
    assert "identifiable combination" in _table_line(text, "A+A-3D", "heading_error+bearing_bias")
