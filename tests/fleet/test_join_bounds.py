"""The bound the single plots' tests screen with (registration.fleet.association.joining.attach.lower_bounds):
never above the statistic it bounds, on the real candidates of an association with clutter (one plot
per pair, and three), and the single plots joined are those of the tests without the screen."""

import dataclasses

import numpy as np
import pytest

from registration.core.distributions import chi2_ppf
from registration.fleet import associate_and_register, association_scenario
from registration.fleet.association.joining import attach, singles
from registration.fleet.association.simulated.fleets import rolling_fleet


def _scenario(name: str):
    if name == "crossing, clutter":
        return association_scenario(
            5,
            crossing=True,
            angle_bias=np.radians(2.0),
            p_missed=0.1,
            clutter_per_scan=1.0,
            duration_s=150.0,
            seed=3,
        )
    # rolling ships, a passive sensor, time biases and range gains (the extended errors' residuals)
    return rolling_fleet(7, duration_s=300.0, clutter_share=0.05, time_bias=0.3, range_gain=3e-4)


@pytest.fixture(scope="module", params=["crossing, clutter", "rolling, time bias + gain, clutter"])
def candidates(request):
    """The arguments of the single plots' screen in an association with clutter: 5 crossing targets
    of the default fleet, and a fleet with the extended errors (not the one the bound was measured on)."""
    sim = _scenario(request.param)
    sc = sim.scenario
    seen = []
    real = singles.lower_bounds
    singles.lower_bounds = lambda *args: seen.append(args) or real(*args)
    try:
        result = associate_and_register(sim.plots, sc.sensors, sc.navigation, sc.platforms)
    finally:
        singles.lower_bounds = real
    assert len(seen) == 1
    return sim, result, seen[0]


def _statistics(args, plots):
    problem, x, curves, target, _, P = args
    return attach.pair_statistics(problem, x, curves, plots[:, 0], target, plots, np.zeros(x.size), P)


@pytest.mark.parametrize(
    "p_scale, c_scale, y_scale",
    [(1.0, 1.0, 1.0), (1e4, 1.0, 1.0), (1e4, 1.0, 0.0), (1.0, 1e4, 1.0), (1e2, 1.0, 1e3)],
)
def test_the_bound_is_below_the_statistic_of_single_plots(candidates, p_scale, c_scale, y_scale):
    """Also with the registration's covariance, the curves' or their motion with the states (Y) made
    larger: each term of the trace bound then dominates in turn (leaving one out makes the bound
    exceed the statistic)."""
    _, _, (problem, x, curves, target, plots, P) = candidates
    curves = dataclasses.replace(curves, V_inv=curves.V_inv * c_scale, Y=curves.Y * y_scale)
    args = (problem, x, curves, target, plots, P * p_scale)
    bound, dof = attach.lower_bounds(*args)
    d2, dof_test = _statistics(args, plots)
    assert plots.shape[0] > 1000
    assert np.array_equal(dof, dof_test)
    assert np.all(bound <= d2 * (1 + 1e-9))
    if p_scale == c_scale == y_scale == 1.0:
        gate = chi2_ppf(0.99, np.maximum(dof, 1))
        far = bound >= gate
        assert far.mean() > 0.5  # most candidates are clutter, or plots of another target
        assert (d2 < gate).any() and not (far & (d2 < gate)).any()


def test_the_bound_is_below_the_statistic_of_pairs_of_three(candidates):
    _, _, args = candidates
    problem, x, curves, target, plots, P = args
    order = np.argsort(target, kind="stable")
    t, p = target[order], plots[order, 0]
    n = (t.size // 3) * 3
    t3, p3 = t[:n].reshape(-1, 3), p[:n].reshape(-1, 3)
    same = (t3 == t3[:, :1]).all(axis=1)
    t3, p3 = t3[same, 0], p3[same]
    p3[::4, 2] = -1  # padding
    bound, dof = attach.lower_bounds(problem, x, curves, t3, p3, P)
    d2, dof_test = _statistics((problem, x, curves, t3, p3, P), p3)
    assert np.array_equal(dof, dof_test)
    assert np.all(bound <= d2 * (1 + 1e-9))


def test_the_screen_changes_no_single_plot(candidates, monkeypatch):
    sim, screened, _ = candidates
    sc = sim.scenario
    monkeypatch.setattr(
        singles,
        "lower_bounds",
        lambda problem, x, curves, target, plots, P: (
            np.zeros(plots.shape[0]),
            attach.lower_bounds(problem, x, curves, target, plots, P)[1],
        ),
    )
    plain = associate_and_register(sim.plots, sc.sensors, sc.navigation, sc.platforms)
    assert np.array_equal(plain.labels, screened.labels)
    assert np.array_equal(plain.batch.estimate, screened.batch.estimate)
