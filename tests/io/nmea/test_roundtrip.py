"""The imported tables written as files read back with the fleet reader, and registered: the batch
solve recovers the simulated radar range bias, bearing bias and clock offset.

The plots carry sensor-local ``track`` ids; until the fleet reader takes a ``track`` column, the
round trip renames it to ``target`` with the simulation's track -> MMSI map (the association the
engine will make)."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest

from registration.fleet import solve_batch
from registration.io import read_fleet_tables
from registration.io.nmea import import_nmea
from tests.io.nmea.bridgelog import PLATFORM


def _write(result, log, folder):
    written = result.write(folder)
    plots = pd.read_csv(written["plots"], dtype={"track": str})
    plots = plots.rename(columns={"track": "target"})
    plots["target"] = [log.track_mmsi.get(t, f"T{t}") for t in plots.target]
    plots.to_csv(written["plots"], index=False)
    return written


def test_written_tables_read_back(bridge, tmp_path):
    log, _, result = bridge
    written = _write(result, log, tmp_path)
    assert set(written) == {
        "plots",
        "navigation",
        "sensors",
        "platforms",
        "reference",
        "targets",
        "rejected",
        "summary",
    }
    tables = read_fleet_tables(
        written["plots"],
        written["navigation"],
        written["sensors"],
        written["platforms"],
        written["reference"],
        targets=written["targets"],
    )
    assert tables.notes == [] and tables.rejected == []
    assert len(tables.plots["time"]) == len(result.plots) and len(tables.references["time"]) == len(
        result.reference
    )
    assert np.allclose(tables.navigation["roll"], np.radians(result.navigation.roll_deg))
    assert np.allclose(tables.plots["bearing"], np.radians(result.plots.bearing_deg))
    assert json.loads(written["summary"].read_text()) == json.loads(json.dumps(result.summary))
    assert np.isinf(tables.references["sigma_up"]).all() and len(tables.targets["target"]) == len(
        result.targets
    )
    assert pd.read_csv(written["rejected"]).shape == (len(result.rejected), 4)


def test_registration_recovers_the_radar_errors(bridge, tmp_path):
    log, path, _ = bridge
    result = import_nmea(path, PLATFORM, log.sensors, platform_priors={"prior_heading_deg": 0.0})
    written = _write(result, log, tmp_path)
    tables = read_fleet_tables(
        written["plots"],
        written["navigation"],
        written["sensors"],
        written["platforms"],
        written["reference"],
        targets=written["targets"],
    )
    fit = solve_batch(tables.problem())
    c = log.config
    for state, truth in (
        ("RADAR:range_bias", c.range_bias_m),
        ("RADAR:bearing_bias", c.bearing_bias_rad),
        ("RADAR:time_bias", c.clock_offset_s),
    ):
        value, sigma = fit.value(state), fit.sigma_of(state)
        assert abs(value - truth) < 3.5 * sigma, (state, value, truth, sigma)
        assert (
            sigma
            < {"RADAR:range_bias": 2.0, "RADAR:bearing_bias": np.radians(0.01), "RADAR:time_bias": 0.05}[
                state
            ]
        )
    assert fit.value("OWN:roll_error") == pytest.approx(0.0, abs=3.5 * fit.sigma_of("OWN:roll_error"))
