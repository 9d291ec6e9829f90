"""Building a fleet problem from the long-form tables: every bad input gets an error naming the
table, row and object; targets without registration information are set aside and reported."""

from __future__ import annotations

import copy

import numpy as np
import pytest

from registration.fleet import BatchOptions, build_problem, fleet_scenario, solve_batch


@pytest.fixture(scope="module")
def scenario():
    return fleet_scenario(5, duration_s=60.0)


def _tables(sc) -> dict:
    return copy.deepcopy(
        {
            "plots": sc.plots,
            "sensors": sc.sensors,
            "navigation": sc.navigation,
            "platforms": sc.platforms,
            "references": sc.references,
        }
    )


def _row_of(plots: dict, sensor: str) -> int:
    return int(np.flatnonzero(plots["sensor"] == sensor)[0])


def test_the_scenario_tables_build(scenario):
    problem = build_problem(**_tables(scenario))
    assert problem.n_plots == problem.n_input_plots == scenario.plots["time"].size
    assert problem.layout.n == len(scenario.truth_state)
    assert not problem.excluded


def test_pandas_frames_are_accepted(scenario):
    frames = scenario.frames()
    problem = build_problem(
        frames["plots"], frames["sensors"], frames["navigation"], frames["platforms"], frames["references"]
    )
    np.testing.assert_array_equal(problem.meas, build_problem(**_tables(scenario)).meas)


def test_unknown_sensor(scenario):
    t = _tables(scenario)
    t["plots"]["sensor"] = t["plots"]["sensor"].astype(object)
    t["plots"]["sensor"][7] = "Z-9"
    with pytest.raises(ValueError, match=r"plots row 7: unknown sensor 'Z-9'"):
        build_problem(**t)


def test_unknown_platform(scenario):
    t = _tables(scenario)
    t["sensors"]["platform"] = t["sensors"]["platform"].astype(object)
    t["sensors"]["platform"][1] = "Q"
    with pytest.raises(ValueError, match=r"sensors row 1: sensor 'A-ESM' is on unknown platform 'Q'"):
        build_problem(**t)


def test_plot_outside_the_navigation_span(scenario):
    t = _tables(scenario)
    row = _row_of(t["plots"], "B-3D")
    t["plots"]["time"][row] = 1e4
    with pytest.raises(
        ValueError,
        match=rf"plots row {row} \(sensor 'B-3D', time 10000 s\) lies outside the "
        r"navigation of platform 'B' \(0 s to 60 s\)",
    ):
        build_problem(**t)


def test_sensor_with_no_channel(scenario):
    t = _tables(scenario)
    for c in ("range", "bearing", "elevation"):
        t["sensors"][f"sigma_{c}"][2] = np.nan
    with pytest.raises(ValueError, match=r"sensors row 2: sensor 'B-3D' measures no channel"):
        build_problem(**t)


@pytest.mark.parametrize(
    "value, message",
    [(-1.0, "expected a standard deviation >= 0"), (0.0, "needs a noise standard deviation > 0")],
)
def test_bad_noise_sigma(scenario, value, message):
    t = _tables(scenario)
    t["sensors"]["sigma_range"][0] = value
    with pytest.raises(ValueError, match=rf"sensors row 0: .*A-3D.*{message}"):
        build_problem(**t)


def test_negative_prior(scenario):
    t = _tables(scenario)
    t["platforms"]["prior_roll"][1] = -0.1
    with pytest.raises(ValueError, match=r"platforms row 1: prior_roll of platform 'B' is -0.1"):
        build_problem(**t)


def test_degrees_for_radians(scenario):
    t = _tables(scenario)
    t["plots"]["bearing"] = np.degrees(t["plots"]["bearing"])
    with pytest.raises(
        ValueError, match=r"bearing .* is outside \[-6.28319, 6.28319\] rad \(these look like degrees"
    ):
        build_problem(**t)


def test_value_in_a_channel_the_sensor_does_not_measure(scenario):
    t = _tables(scenario)
    row = _row_of(t["plots"], "A-ESM")
    t["plots"]["range"][row] = 1000.0
    with pytest.raises(
        ValueError, match=rf"plots row {row}: sensor 'A-ESM' has a range value but does not measure range"
    ):
        build_problem(**t)


def test_plot_with_no_measured_channel(scenario):
    t = _tables(scenario)
    row = _row_of(t["plots"], "C-2D")
    t["plots"]["range"][row] = t["plots"]["bearing"][row] = np.nan
    with pytest.raises(ValueError, match=rf"plots row {row}: plot of sensor 'C-2D' has no measured channel"):
        build_problem(**t)


def test_missing_column_and_unknown_reference_target(scenario):
    t = _tables(scenario)
    del t["plots"]["target"]
    with pytest.raises(ValueError, match=r"plots: missing column 'target'"):
        build_problem(**t)
    t = _tables(scenario)
    t["references"]["target"] = np.full(t["references"]["time"].size, "T99")
    with pytest.raises(ValueError, match=r"references row 0: target 'T99' of the reference has no plots"):
        build_problem(**t)


@pytest.mark.parametrize("table", ["plots", "navigation", "references"])
def test_times_beyond_the_limit_are_refused(scenario, table):
    """A time of 1e308 s once reached the windows' microsecond ticks and overflowed there."""
    t = _tables(scenario)
    t[table]["time"] = np.asarray(t[table]["time"], dtype=float).copy()
    t[table]["time"][0] = 1e308
    with pytest.raises(ValueError, match=r"row 0.*1e\+?308.*1e\+11 s"):
        build_problem(**t)


def _with_extra_target(t: dict, target: str, sensor: str, rows: np.ndarray) -> None:
    for k, v in t["plots"].items():
        extra = v[rows].copy()
        if k == "target":
            extra = np.full(rows.size, target)
        t["plots"][k] = np.concatenate([v.astype(object) if k in ("sensor", "target") else v, extra])


def test_a_target_seen_by_one_sensor_only_is_reported_and_excluded(scenario):
    t = _tables(scenario)
    rows = np.flatnonzero((t["plots"]["sensor"] == "C-3D") & (t["plots"]["target"] == "T2"))
    _with_extra_target(t, "LONE", "C-3D", rows)
    problem = build_problem(**t)
    assert [e.target for e in problem.excluded] == ["LONE"]
    assert (
        "seen by one sensor only" in problem.excluded[0].text() and problem.excluded[0].n_plots == rows.size
    )
    assert "LONE" not in problem.target_ids and problem.n_plots == problem.n_input_plots - rows.size
    # a reference target is kept even when one sensor sees it
    ref = {"target": np.array(["LONE"]), "time": np.array([10.0]), "x": [1.0], "y": [2.0], "z": [3.0]}
    t["references"] = ref
    assert "LONE" in build_problem(**t).target_ids


def test_singular_geometry_is_reported_and_set_aside(scenario):
    """Where only the passive angle sensor sees T2 (20 s to 40 s), its position is not determined:
    those windows are excluded with the reason, the rest is registered."""
    t = _tables(scenario)
    p = t["plots"]
    gap = (p["target"] == "T2") & (p["time"] >= 20.0) & (p["time"] < 40.0) & (p["sensor"] != "A-ESM")
    for k in p:
        p[k] = p[k][~gap]
    result = solve_batch(build_problem(**t), BatchOptions(window_s=10.0))
    singular = [e for e in result.excluded if e.reason.startswith("singular geometry")]
    assert singular and all(e.target == "T2" and 20.0 <= e.t_start and e.t_end < 40.0 for e in singular)
    assert "A-ESM" in singular[0].reason and result.converged
    excluded = (p["target"] == "T2") & (p["time"] >= 20.0) & (p["time"] < 40.0)
    assert np.isnan(result.residuals[excluded]).all()
    assert np.isfinite(result.residuals[~excluded, 1]).all()  # every other plot has a bearing residual


def test_nothing_left_to_register(scenario):
    t = _tables(scenario)
    keep = t["plots"]["sensor"] == "A-3D"
    for k in t["plots"]:
        t["plots"][k] = t["plots"][k][keep]
    t["references"] = None
    with pytest.raises(ValueError, match=r"no plots to register .*seen by one sensor only"):
        solve_batch(build_problem(**t))


def test_navigation_is_interpolated_across_north_and_a_site_is_constant():
    """Heading 179 deg then -179 deg: half way it is 180 deg, not 0; a one-row site holds always."""
    nav = {
        "platform": np.array(["A", "A", "S"]),
        "time": np.array([0.0, 10.0, 0.0]),
        "lat": np.array([0.6, 0.6002, 0.61]),
        "lon": np.array([3.1415, -3.1415, 0.2]),
        "alt": np.array([10.0, 10.0, 50.0]),
        "heading": np.radians([179.0, -179.0, 0.0]),
        "pitch": np.array([0.0, 0.02, 0.0]),
        "roll": np.zeros(3),
    }
    sensors = {
        "sensor": np.array(["a", "s"]),
        "platform": np.array(["A", "S"]),
        "sigma_bearing": np.array([0.01, 0.01]),
    }
    plots = {
        "time": np.array([5.0, 5.0, 123.0]),
        "sensor": np.array(["a", "s", "s"]),
        "target": np.array(["T", "T", "T"]),
        "bearing": np.array([0.1, 0.2, 0.3]),
    }
    problem = build_problem(plots, sensors, nav)
    a, s = problem.nav[0], problem.nav[1]
    np.testing.assert_allclose([a[0], abs(a[1]), abs(a[3]), a[4]], [0.6001, np.pi, np.pi, 0.01], atol=1e-12)
    np.testing.assert_array_equal(problem.nav[2], s)
    np.testing.assert_allclose(s[:3], [0.61, 0.2, 50.0])
