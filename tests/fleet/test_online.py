"""The online fleet filter: agreement with the two-ship filter and with the batch solution,
streaming in chunks bit for bit, a batch result as its prior, large initial errors, the innovation
check, and bad input that leaves the filter unchanged."""

from __future__ import annotations

import numpy as np
import pytest

from registration.fleet import BatchOptions, build_problem, fleet_scenario, solve_batch
from registration.fleet.online.filter import FleetFilter, OnlineOptions
from registration.fleet.online.register import register_online
from registration.fleet.online.update import information_update
from registration.online import RegistrationConfig, register
from registration.online.scenario import ShipMotion, paper_scenario
from tests.fleet.two_ship import STATE_MAP, fleet_tables

#: "Agrees with the two-ship filter": every state within this share of its sigma.
AGREEMENT = 0.1


def _tables(sc) -> dict:
    return dict(
        plots=sc.plots,
        sensors=sc.sensors,
        navigation=sc.navigation,
        platforms=sc.platforms,
        references=sc.references,
    )


def _z(sc, result) -> np.ndarray:
    free = result.layout.free
    return (result.estimate - sc.truth_vector(result.layout))[free] / result.sigma[free]


@pytest.mark.parametrize("seed", [0, 1])
def test_two_ships_agree_with_the_two_ship_filter(seed):
    """Two 3-D radars, one target, synchronous pairs, the two-ship filter's priors and process noise:
    the fleet filter (one epoch per instant) ends where register() ends, state by state."""
    sc = paper_scenario(seed, ship_motion=ShipMotion())
    config = RegistrationConfig()
    two_ship = register(sc.data, config)
    fleet = register_online(
        **fleet_tables(sc.data, config.sigma0, config.prior_sigma),
        options=OnlineOptions(window_s=0.0, q_angle=config.q_sigma[0], q_range=config.q_sigma[3]),
    )
    assert fleet.n_plots_used == 2 * len(sc.data["time"])
    for k, name in enumerate(STATE_MAP.values()):
        sigma = two_ship.final_sigma[k]
        assert abs(fleet.value(name) - two_ship.final[k]) < AGREEMENT * sigma, name
        assert abs(fleet.sigma_of(name) - sigma) < 0.02 * sigma, name
    assert fleet.consistency.status == "consistent", fleet.consistency.message()


@pytest.fixture(scope="module")
def fleet():
    sc = fleet_scenario(4, duration_s=200.0)
    return sc, register_online(**_tables(sc)), solve_batch(sc.problem())


def test_asynchronous_fleet_ends_at_the_batch_solution(fleet):
    sc, online, batch = fleet
    free = batch.layout.free
    assert np.abs((online.estimate - batch.estimate)[free] / batch.sigma[free]).max() < 0.3
    assert np.abs(online.sigma[free] / batch.sigma[free] - 1).max() < 0.05
    assert np.abs(_z(sc, online)).max() < 4.0
    assert online.consistency.ok and online.consistency.status == "consistent", online.consistency.message()
    assert online.status == batch.status
    assert online.residuals.shape == batch.residuals.shape and online.fit_check.ok, online.fit_check.text()
    both = np.isfinite(batch.residuals)
    np.testing.assert_array_equal(np.isfinite(online.residuals), both)
    assert np.abs(online.residuals[both] - batch.residuals[both]).max() < 0.2  # normalised units


def test_history_tracks_the_estimate(fleet):
    sc, online, _ = fleet
    h = online.history
    assert h.time.size == h.estimate.shape[0] == 10  # 200 s in 20 s windows
    assert np.all(np.diff(h.time) > 0)
    np.testing.assert_array_equal(h.estimate[-1], online.estimate)
    t, x, s = h.of(online.layout, "A-3D:range_bias")
    assert s[-1] < s[0] and np.all(np.diff(s) <= 1e-9 * s[0])  # information only ever adds up


def test_streaming_in_chunks_is_bit_identical(fleet):
    sc, online, _ = fleet
    order = np.argsort(sc.plots["time"], kind="stable")
    plots = {k: v[order] for k, v in sc.plots.items()}
    filt = FleetFilter(sc.sensors, sc.navigation, sc.platforms, sc.references)
    n = order.size
    cuts = np.r_[0, np.sort(np.random.default_rng(1).choice(n, 40, replace=False)), n]
    processed = sum(filt.update({k: v[a:b] for k, v in plots.items()}) for a, b in zip(cuts[:-1], cuts[1:]))
    processed += filt.flush()
    assert processed == online.history.time.size
    np.testing.assert_array_equal(filt.estimate, online.estimate)
    np.testing.assert_array_equal(filt.covariance, online.covariance)


def test_a_batch_result_is_a_prior():
    """Batch over the first 100 s, the filter over the rest: as good as the batch over everything,
    from 5 deg and 3 km errors."""
    sc = fleet_scenario(
        2,
        angle_bias=np.radians(5.0),
        range_bias=3000.0,
        heading_error=np.radians(5.0),
        level_error=np.radians(5.0),
        duration_s=240.0,
    )
    early = sc.plots["time"] < 100.0
    first = {k: v[early] for k, v in sc.plots.items()}
    rest = {k: v[~early] for k, v in sc.plots.items()}
    prior = solve_batch(build_problem(first, sc.sensors, sc.navigation, sc.platforms, sc.references))
    online = register_online(rest, sc.sensors, sc.navigation, sc.platforms, sc.references, prior=prior)
    whole = solve_batch(sc.problem())
    free = whole.layout.free
    assert np.abs(online.sigma[free] / whole.sigma[free] - 1).max() < 0.1
    assert np.abs((online.estimate - whole.estimate)[free] / whole.sigma[free]).max() < 0.5
    assert np.abs(_z(sc, online)).max() < 4.0


def test_large_errors_without_prior_are_found_by_iterating_the_first_epochs():
    sc = fleet_scenario(
        2,
        angle_bias=np.radians(5.0),
        range_bias=3000.0,
        heading_error=np.radians(5.0),
        level_error=np.radians(5.0),
        duration_s=150.0,
    )
    filt = FleetFilter(sc.sensors, sc.navigation, sc.platforms, sc.references)
    order = np.argsort(sc.plots["time"])
    filt.update({k: v[order] for k, v in sc.plots.items()})
    filt.flush()
    result = filt.result()
    assert filt.n_linearisations > result.history.time.size  # some epochs were linearised again
    assert np.abs(_z(sc, result)).max() < 4.0
    assert result.consistency.status == "consistent", result.consistency.message()


def test_wrong_noise_model_fails_the_innovation_check():
    """Sigmas stated 5 times too small: the check says so loudly instead of passing quietly."""
    sc = fleet_scenario(4, duration_s=100.0)
    sensors = dict(sc.sensors)
    for c in ("sigma_range", "sigma_bearing", "sigma_elevation"):
        sensors[c] = np.asarray(sensors[c]) / 5.0
    result = register_online(sc.plots, sensors, sc.navigation, sc.platforms, sc.references)
    assert not result.consistency.ok and result.consistency.mean > 10  # the gate: ~25 expected
    assert not result.verdict.ok and result.verdict.mean > 10  # the verdict, at the final estimate: ~23


def test_out_of_order_plots_are_refused_and_leave_the_filter_unchanged(fleet):
    sc, _, _ = fleet
    order = np.argsort(sc.plots["time"])
    plots = {k: v[order] for k, v in sc.plots.items()}
    filt = FleetFilter(sc.sensors, sc.navigation, sc.platforms, sc.references)
    late = plots["time"] >= 60.0
    filt.update({k: v[late] for k, v in plots.items()})
    x, P = filt.estimate, filt.covariance
    with pytest.raises(ValueError, match=r"plots row 0: time .* epoch already processed"):
        filt.update({k: v[~late][:5] for k, v in plots.items()})
    np.testing.assert_array_equal(filt.estimate, x)
    np.testing.assert_array_equal(filt.covariance, P)


def test_bad_input_names_the_object(fleet):
    sc, _, batch = fleet
    filt = FleetFilter(sc.sensors, sc.navigation, sc.platforms, sc.references)
    plots = {k: v[:3].copy() for k, v in sc.plots.items()}
    plots["sensor"] = np.array(["nope", *plots["sensor"][1:]])
    with pytest.raises(ValueError, match=r"plots row 0: unknown sensor 'nope'"):
        filt.update(plots)
    plots = {k: v[:3].copy() for k, v in sc.plots.items()}
    plots["time"] = plots["time"] + 1e4
    with pytest.raises(ValueError, match="outside the navigation of platform"):
        filt.update(plots)
    other = fleet_scenario(0, duration_s=50.0, config=sc.config)
    sensors = {k: v[:-1] for k, v in other.sensors.items()}  # one sensor fewer: other states
    with pytest.raises(ValueError, match="prior: its states"):
        FleetFilter(sensors, sc.navigation, sc.platforms, prior=batch)
    with pytest.raises(ValueError, match="q_angle"):
        OnlineOptions(q_angle=-1.0)


def test_a_target_seen_by_one_sensor_is_reported():
    sc = fleet_scenario(4, duration_s=60.0)
    plots = {k: v.copy() for k, v in sc.plots.items()}
    plots["target"] = np.where(plots["sensor"] == "S-2D", "LONE", plots["target"].astype(str))
    result = register_online(plots, sc.sensors, sc.navigation, sc.platforms, sc.references)
    assert any(e.target == "LONE" for e in result.excluded)
    assert result.n_plots_used < result.n_plots_read


def test_information_update_equals_the_information_form():
    """P+ = (P^-1 + L)^-1 and x+ = x + P+ b, in rad/m scales far apart."""
    rng = np.random.default_rng(3)
    n = 5
    scale = np.array([0.01, 0.01, 1000.0, 0.02, 500.0])
    A = rng.normal(size=(12, n)) / scale
    L = A.T @ A
    b = A.T @ rng.normal(size=12)
    P = np.diag((0.5 * scale) ** 2)
    x = rng.normal(size=n) * scale
    x1, P1, nis, dof = information_update(x, P, L, b, np.arange(n), scale)
    P_info = np.linalg.inv(np.linalg.inv(P) + L)
    np.testing.assert_allclose(P1, P_info, rtol=1e-9, atol=0)
    np.testing.assert_allclose(x1, x + P_info @ b, rtol=1e-9, atol=1e-12 * scale.max())
    assert dof == n and nis >= 0
    assert np.all(np.linalg.eigvalsh(P1 / scale[:, None] / scale[None, :]) > 0)


def test_two_ships_batch_and_online_share_the_problem():
    """The same tables give the batch and the online filter one layout (a prior fits)."""
    sc = paper_scenario(0)
    config = RegistrationConfig()
    tables = fleet_tables(sc.data, config.sigma0, config.prior_sigma)
    batch = solve_batch(build_problem(**tables), BatchOptions(window_s=0))
    online = register_online(**tables, options=OnlineOptions(window_s=0.0), prior=batch)
    assert online.layout.names == batch.layout.names


def test_nees_over_monte_carlo_runs_is_consistent():
    """Ten fleets from zero: the mean NEES of the estimated states inside its 95 % band."""
    from examples.fleet_online_nees import main

    out = main(["--runs", "10", "--duration", "120"])
    lo, hi = out["band"]
    assert lo < out["online"] < hi, out
