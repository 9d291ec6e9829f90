"""A radar's channel in the association (registration.fleet.association.channels): while none of
its plots is joined its own states start from its radar's plus the PSR/SSR difference; and the
per-period solves estimate a sensor's eccentricity terms (they were reported undetermined). The
end-to-end check is tests/io/asterix/test_radar_model_acceptance.py."""

from __future__ import annotations

import numpy as np
import pytest

from registration.fleet.association.channels import channel_pairs, channel_start
from registration.fleet.association.options import AssociationOptions
from registration.fleet.data.layout import make_layout


def _layout(channel: bool):
    """Two 2-D radars R1, R2 with range gains and time biases, and R1.psr a channel of R1."""
    ids = ("R1", "R2", "R1.psr") if channel else ("R1", "R2")
    n = len(ids)
    measured = np.tile([True, True, False], (n, 1))
    extended = np.tile([np.inf, np.inf, np.nan, np.nan, np.nan], (n, 1))
    parent = np.array([-1, -1, 0][:n])
    return make_layout(
        ("R1", "R2"),
        np.zeros((2, 3)),
        ids,
        measured,
        np.full((n, 3), np.inf),
        extended,
        None,
        parent if channel else None,
    )


def _spd(n: int, rng) -> np.ndarray:
    a = rng.normal(size=(n, n))
    return a @ a.T + n * np.eye(n)


def test_the_channel_pairs_are_its_own_biases_and_gain():
    layout = _layout(True)
    sensor, own, theirs = channel_pairs(layout)
    names = np.array(layout.names)
    assert sensor.tolist() == [2, 2, 2]
    assert names[own].tolist() == ["R1.psr:range_bias", "R1.psr:bearing_bias", "R1.psr:range_gain"]
    assert names[theirs].tolist() == ["R1:range_bias", "R1:bearing_bias", "R1:range_gain"]
    assert layout.index("R1:time_bias") in layout.extended_index[2]  # shared, not a pair
    assert channel_pairs(_layout(False))[0].size == 0


def test_a_channel_without_plots_starts_from_its_radar():
    layout = _layout(True)
    rng = np.random.default_rng(3)
    x, P = rng.normal(size=layout.n), _spd(layout.n, rng)
    sigma = AssociationOptions().channel_sigma()
    x1, P1 = channel_start(x, P, layout, np.array([0, 1]), sigma)
    _, own, theirs = channel_pairs(layout)
    np.testing.assert_array_equal(x1[own], x[theirs])
    others = np.setdiff1d(np.arange(layout.n), own)
    np.testing.assert_array_equal(x1[others], x[others])
    np.testing.assert_array_equal(P1[np.ix_(others, others)], P[np.ix_(others, others)])
    np.testing.assert_array_equal(P1[np.ix_(own, others)], P[np.ix_(theirs, others)])
    extra = np.diag([sigma["range_bias"], sigma["bearing_bias"], sigma["range_gain"]]) ** 2
    np.testing.assert_allclose(P1[np.ix_(own, own)], P[np.ix_(theirs, theirs)] + extra)
    assert np.allclose(P1, P1.T) and np.linalg.eigvalsh(P1).min() > 0
    # the difference own - radar has exactly the difference's covariance
    D = np.zeros((3, layout.n))
    D[np.arange(3), own], D[np.arange(3), theirs] = 1.0, -1.0
    np.testing.assert_allclose(D @ P1 @ D.T, extra, atol=1e-9)


@pytest.mark.parametrize("solved", [[0, 1, 2], [1]])
def test_a_channel_with_plots_or_without_its_radar_is_left_alone(solved):
    layout = _layout(True)
    rng = np.random.default_rng(4)
    x, P = rng.normal(size=layout.n), _spd(layout.n, rng)
    x1, P1 = channel_start(x, P, layout, np.array(solved), AssociationOptions().channel_sigma())
    np.testing.assert_array_equal(x1, x)
    np.testing.assert_array_equal(P1, P)


def test_each_period_estimates_the_eccentricity():
    from registration.fleet.periods import solve_periods
    from registration.fleet.simulation.channels import atc_channel_scenario

    s = atc_channel_scenario(6, duration_s=120.0)
    runs = solve_periods(s.plots, s.sensors, s.navigation, s.platforms, s.references, period_s=60.0)
    assert len(runs.periods) == 2
    for p in runs.periods:
        r = p.result
        for name in ("R1:eccentricity_sin", "R1:eccentricity_cos"):
            assert r.status[name] == "identifiable", (p.start_s, name, r.status[name])
            i = r.layout.index(name)
            assert np.isfinite(r.sigma[i]) and abs(r.estimate[i] - s.truth_state[name]) < 3.5 * r.sigma[i]
