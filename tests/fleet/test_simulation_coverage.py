"""The simulated fleet stays valid for any duration: no plot beyond its sensor's coverage (range,
cone of silence overhead, radio horizon), and `fleet simulate --duration-s --targets`."""

import numpy as np
import pandas as pd
import pytest

from registration.cli import main
from registration.fleet import fleet_scenario
from registration.fleet.simulation.coverage import DEFAULT_COVERAGE, horizon_range, visible
from registration.fleet.simulation.scenario import DEFAULT_FLEET, FleetConfig
from registration.fleet.simulation.tracks import Line, random_targets


def test_a_long_scenario_builds_a_valid_problem():
    sc = fleet_scenario(duration_s=8000.0)  # once gave a passive elevation of 90.5 deg
    el = sc.plots["elevation"]
    assert np.nanmax(np.abs(el)) < np.radians(72.0)
    problem = sc.problem()
    assert problem.time.size == sc.plots["time"].size


def test_the_default_scenario_is_unchanged_by_the_coverage():
    assert fleet_scenario().plots["time"].size == 4725  # every plot of 300 s lies inside every coverage


def test_a_target_overhead_falls_silent_inside_the_cone():
    site = {"S": (0.0, 0.0, 10.0)}
    sensors = {"S-3D": ("S", (20.0, np.radians(0.1), np.radians(0.1)), 1.0, 0.0, (0.0, 0.0, 0.0))}
    over = Line(-20e3, 0.0, np.radians(90.0), 200.0, 5000.0)  # straight over the site at t = 100 s, 5 km up
    sc = fleet_scenario(
        duration_s=200.0,
        config=FleetConfig({}, site, sensors, {"T": over}, None),
        angle_bias=0.0,
        range_bias=0.0,
        noise_scale=1e-6,
    )
    t = sc.plots["time"]
    elevation = sc.plots["elevation"]
    assert np.nanmax(elevation) <= DEFAULT_COVERAGE["3d"].max_elevation + 1e-6
    silent = np.setdiff1d(np.arange(200.0), t)
    # inside the cone: horizontal distance below 5 km / tan(70 deg) = 1.82 km, i.e. 9.1 s either side of t =
    # 100 s
    assert silent.min() >= 90 and silent.max() <= 110 and silent.size >= 15
    assert (t < 90).any() and (t > 110).any()


def test_the_radio_horizon_and_the_coverage_mask():
    # the textbook 4/3-earth radar horizon: 4.12 (sqrt(h1) + sqrt(h2)) km, heights in m
    for h1, h2 in ((10.0, 300.0), (25.0, 10000.0), (1.0, 1.0)):
        assert float(horizon_range(np.array(h1), np.array(h2))) == pytest.approx(
            4.12e3 * (h1**0.5 + h2**0.5), rel=3e-3
        )
    cov = DEFAULT_COVERAGE["2d"]
    r = np.array([50e3, 90e3, 50e3, 500e3])
    el = np.radians([1.0, 1.0, 75.0, 1.0])
    mask = visible(cov, r, el, np.full(4, 10.0), np.array([300.0, 300.0, 300.0, 50e3]))
    assert mask.tolist() == [
        True,
        False,
        False,
        False,
    ]  # in view; below the horizon; in the cone; beyond range


def test_random_targets_stay_in_the_area():
    targets = random_targets(30, seed=4)
    assert list(targets)[:2] == ["T1", "T2"] and len(targets) == 30
    t = np.linspace(0.0, 50000.0, 501)
    for track in targets.values():
        enu = track.enu(t)
        assert np.abs(enu[:, :2]).max() < 40e3 + 20e3 and 1e3 <= enu[0, 2] <= 10e3
    with pytest.raises(ValueError, match="number of targets"):
        random_targets(0)
    assert DEFAULT_FLEET.targets.keys() != targets.keys()


def test_fleet_simulate_duration_and_targets(tmp_path):
    out = tmp_path / "sim"
    assert (
        main(
            [
                "fleet",
                "simulate",
                "--duration-s",
                "120",
                "--targets",
                "3",
                "--out",
                str(out),
                "--no-plots",
                "--format",
                "parquet",
            ]
        )
        == 0
    )
    plots = pd.read_parquet(out / "plots.parquet")
    assert set(plots["target"]) == {"T1", "T2", "T3"} and plots["time_s"].max() < 120.0
    assert set(pd.read_parquet(out / "reference.parquet")["target"]) == {"T1"}
    assert main(["fleet", "simulate", "--duration-s", "5", "--out", str(tmp_path / "x")]) == 2
    assert main(["fleet", "simulate", "--targets", "0", "--out", str(tmp_path / "y")]) == 2
