"""The compiled tracker loop (``registration._codegen.compiled_tracks``) gives the tracks of its
numpy reference loop (``sensor_tracks(..., compiled=False)``), plot for plot, in every tracker run
of the association: on fleets, seeds, clutter rates and scan periods the benchmark does not use."""

from types import SimpleNamespace

import numpy as np
import pytest

from registration import _codegen
from registration._generated import api as generated
from registration.core.distributions import chi2_ppf
from registration.fleet import associate_and_register, association_scenario
from registration.fleet.association.grouping import tracks, units
from registration.fleet.association.grouping.geometry import Assigner

#: 2-D radars and one 3-D radar (the anchor), at other periods and offsets than the default fleet's.
SENSORS_2D = {
    "S-3D": ("S", (30.0, np.radians(0.1), np.radians(0.1)), 1.5, 0.9, (0.0, 5.0, 12.0)),
    "A-2D": ("A", (40.0, np.radians(0.2), np.nan), 2.0, 0.3, (0.0, -12.0, 18.0)),
    "B-2D": ("B", (35.0, np.radians(0.25), np.nan), 4.0, 1.1, (0.0, -10.0, 18.0)),
    "C-2D": ("C", (40.0, np.radians(0.2), np.nan), 2.5, 0.7, (0.0, -30.0, 22.0)),
    "S-2D": ("S", (30.0, np.radians(0.1), np.nan), 3.0, 0.2, (0.0, 0.0, 10.0)),
}

CASES = {
    "default fleet, crossing, clutter 3 a scan": dict(
        n_targets=8, crossing=True, clutter_per_scan=3.0, p_missed=0.2, seed=11
    ),
    "default fleet, no clutter": dict(n_targets=6, clutter_per_scan=0.0, p_missed=0.05, seed=23),
    "2-D radars at 2-4 s, a 3-D one at 1.5 s": dict(
        n_targets=7, crossing=True, clutter_per_scan=2.0, seed=37, sensors=SENSORS_2D
    ),
}

pytestmark = pytest.mark.skipif(_codegen.backend() != "c", reason="the compiled loop needs the C backend")


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_compiled_loop_gives_the_reference_tracks(case, monkeypatch):
    runs = []
    reference = tracks.sensor_tracks

    def both(*args, **kwargs):
        assigner_c, assigner_py = (type(args[3])() for _ in range(2))
        args_c, args_py = (args[:3] + (a,) + args[4:] for a in (assigner_c, assigner_py))
        compiled = reference(*args_c, **kwargs, compiled=True)
        numpy = reference(*args_py, **kwargs, compiled=False)
        runs.append((compiled, numpy, assigner_c.calls, assigner_py.calls))
        args[3].calls += assigner_c.calls
        return compiled

    monkeypatch.setattr(units, "sensor_tracks", both)
    sim = association_scenario(duration_s=150.0, **CASES[case])
    sc = sim.scenario
    associate_and_register(sim.plots, sc.sensors, sc.navigation, sc.platforms)
    assert runs  # the association ran the tracker (three times on most fleets)
    for compiled, numpy, calls_c, calls_py in runs:
        assert np.array_equal(compiled, numpy)
        assert calls_c == calls_py  # the same assignments were needed
    assert (runs[0][0] >= 0).mean() > 0.5  # most plots in tracks: a test of tracks, not of clutter
    if CASES[case]["clutter_per_scan"] > 0:
        assert sum(r[2] for r in runs) > 0  # the assignment was exercised, not only lone pairs


# Crafted inputs (from a review of the compiled loop): where the two loops could part.
KW = dict(max_speed=10.0, accel_sigma=1.0, gate_probability=0.99, max_missed=2, min_plots=1)


def _both(time, sensor, p_ecef, cov, **over):
    geom = SimpleNamespace(p_ecef=np.asarray(p_ecef, float), cov=np.asarray(cov, float))
    args = (np.asarray(time, float), np.asarray(sensor, dtype=np.int64), geom)
    kw = dict(KW, **over)
    return [tracks.sensor_tracks(*args, Assigner(), **kw, compiled=c) for c in (True, False)]


def test_a_plot_on_the_cheap_bound_counts_alike_in_both_loops():
    """The bound |v|^2 < gate (tr P-_pp + tr R) decides which pairs' log det enter a track's
    no-match cost: both loops must sum |v|^2 in the same order. Plot B lies on the bound to the
    last bits, plot A inside the gate."""
    gate = float(chi2_ppf(KW["gate_probability"], 3))
    z0, R0, RA, RB = np.array([1000.0, 2000.0, 3000.0]), 100.0 * np.eye(3), 1e4 * np.eye(3), np.eye(3)
    x, P = generated.cv_start(z=z0, R=R0, max_speed=KW["max_speed"])
    xp, Pp = generated.cv_predict(x=x, P=P, dt=1.0, accel_sigma=KW["accel_sigma"])
    xp, Pp = xp.reshape(6), Pp.reshape(6, 6)
    bound = gate * ((Pp[0, 0] + Pp[1, 1] + Pp[2, 2]) + np.trace(RB))
    rng = np.random.default_rng(0)
    split = 0
    for _ in range(3000):
        d = rng.normal(size=3)
        zB = xp[:3] + d / np.linalg.norm(d) * np.sqrt(bound)
        zB = zB + rng.integers(-3, 4, 3) * np.spacing(zB)
        v = zB - xp[:3]
        if (v[0] * v[0] + v[1] * v[1] + v[2] * v[2] < bound) != (np.einsum("i,i->", v, v) < bound):
            split += 1
        compiled, numpy = _both([0.0, 1.0, 1.0], [0, 0, 0], [z0, xp[:3] + [30.0, 0, 0], zB], [R0, RA, RB])
        assert np.array_equal(compiled, numpy), (zB, compiled, numpy)
    assert split > 0  # the case is exercised: some of these plots sit where the sum's order matters


def test_a_covariance_that_is_not_positive_definite_makes_no_pair_in_either_loop():
    bad = np.diag([1e6, 1e6, -1e6 + 1.0])  # trace > 0: past the cheap bound; log det NaN
    compiled, numpy = _both(
        [0, 1, 1], [0, 0, 0], [[0, 0, 0], [5, 0, 0], [2000, 0, 0]], [100 * np.eye(3)] * 2 + [bad]
    )
    assert np.array_equal(compiled, numpy) and compiled[1] == compiled[0] and compiled[2] != compiled[0]


def test_no_plots_no_tracks():
    for out in _both(np.zeros(0), np.zeros(0), np.zeros((0, 3)), np.zeros((0, 3, 3))):
        assert out.shape == (0,)


@pytest.mark.parametrize(
    "change, message",
    [
        (dict(sensor=np.array([0, -1])), ">= 0"),
        (dict(step_plots=np.array([1, 2])), "plot indices"),
        (dict(bounds=np.array([0, 1])), "bounds"),
        (dict(cov=np.zeros((2, 3))), "must agree"),
        (
            dict(sensor=np.array([1, 0]), bounds=np.array([0, 2]), step_plots=np.array([0, 1])),
            "sorted by sensor",
        ),
    ],
)
def test_the_compiled_loop_refuses_arrays_that_do_not_fit(change, message):
    arrays = dict(
        bounds=np.array([0, 1, 2]),
        step_plots=np.array([0, 1]),
        p_ecef=np.zeros((2, 3)),
        cov=np.broadcast_to(np.eye(3), (2, 3, 3)),
        time=np.array([0.0, 1.0]),
        sensor=np.array([0, 0]),
    )
    arrays.update(change)
    with pytest.raises(ValueError, match=message):
        _codegen.compiled_tracks(
            **arrays, gate=11.3, forbidden=1e12, accel_sigma=1.0, max_speed=10.0, max_missed=2
        )
