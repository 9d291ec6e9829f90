"""The identifiable sums of a fleet result: on level platforms the heading error and the bearing
biases are determined only as sums; both results name them from the observability report and give
each with its sigma, in ``rows()`` and ``lines()``, and ``lines()`` labels its sigma."""

import numpy as np
import pytest

from registration.fleet import fleet_scenario, register_online, solve_batch
from registration.fleet.combinations import UNDETERMINED, named_sums

SUMS = {
    "A+A-3D": ("A:heading_error", "A-3D:bearing_bias"),
    "A+A-ESM": ("A:heading_error", "A-ESM:bearing_bias"),
    "B+B-3D": ("B:heading_error", "B-3D:bearing_bias"),
}


@pytest.fixture(scope="module")
def level():
    sc = fleet_scenario(2, ship_motion=False, duration_s=150.0)
    return sc, solve_batch(sc.problem())


@pytest.fixture(scope="module")
def level_online(level):
    sc, _ = level
    return register_online(sc.plots, sc.sensors, sc.navigation, sc.platforms, sc.references, residuals=False)


def _sum_rows(rows):
    return {r["object"]: r for r in rows if r["status"] == "identifiable combination"}


def test_the_report_names_a_sum_per_sensor_of_a_level_platform(level):
    _, result = level
    pairs = named_sums(result.observability)
    for a, b in SUMS.values():
        assert (a, b) in pairs
    assert len(pairs) == len(set(pairs))


def test_batch_rows_give_each_sum_with_a_finite_sigma_where_its_parts_have_none(level):
    sc, result = level
    sums = _sum_rows(result.rows(sc.truth_state))
    assert set(SUMS) <= set(sums), sorted(sums)
    for obj, (a, b) in SUMS.items():
        row = sums[obj]
        assert row["quantity"] == "heading_error+bearing_bias" and row["unit"] == "rad"
        assert row["name"] == f"{a} + {b}"
        value, sigma = result.combination({a: 1, b: 1})
        assert row["estimate"] == value and row["sigma"] == sigma
        assert np.isclose(value, result.value(a) + result.value(b), rtol=0, atol=1e-12)
        assert sigma < np.radians(0.05) and np.isinf(result.sigma_of(a)) and np.isinf(result.sigma_of(b))
        assert row["truth"] == sc.truth_state[a] + sc.truth_state[b]
        assert abs(value - row["truth"]) < 3.5 * sigma


def test_online_result_has_the_same_combination_and_rows(level, level_online):
    _, batch = level
    online = level_online
    for obj, (a, b) in SUMS.items():
        coeffs = {a: 1.0, b: 1.0}
        value, sigma = online.combination(coeffs)
        i, j = online.layout.index(a), online.layout.index(b)
        assert value == online.estimate[i] + online.estimate[j]
        assert np.isclose(
            sigma, np.sqrt(online.covariance[i, i] + online.covariance[j, j] + 2 * online.covariance[i, j])
        )
        # the parts keep the diffuse prior, the sum is known to the batch's precision
        assert online.sigma_of(a) > np.radians(1) and sigma < np.radians(0.05)
        b_value, b_sigma = batch.combination(coeffs)
        assert abs(value - b_value) < 0.5 * b_sigma and abs(sigma / b_sigma - 1) < 0.2
        row = _sum_rows(online.rows())[obj]
        assert (row["estimate"], row["sigma"]) == (value, sigma)


def test_lines_label_the_sigma_and_show_undetermined_and_the_sums(level):
    _, result = level
    lines = result.lines()
    text = "\n".join(lines)
    assert "+-" not in text
    line = next(s for s in lines if s.strip().startswith("heading error of platform A "))
    assert "σ" in line and UNDETERMINED in line and "not identifiable" in line
    line = next(s for s in lines if "heading error of platform A + bearing bias of sensor A-3D" in s)
    assert "σ" in line and "identifiable combination" in line
