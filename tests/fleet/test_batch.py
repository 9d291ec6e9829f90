"""Batch maximum-likelihood fleet registration on simulated fleets: truth recovered within the
reported uncertainty, convergence from zero with large errors, asynchronous sensors, the
chi-square check, reference targets and level platforms in the observability report."""

from __future__ import annotations

import numpy as np
import pytest

from registration.fleet import BatchOptions, fleet_scenario, solve_batch
from registration.fleet.simulation.scenario import TARGETS, FleetConfig


def _z(sc, result) -> np.ndarray:
    """Estimation error over reported sigma of the estimated states."""
    free = result.layout.free
    return (result.estimate - sc.truth_vector(result.layout))[free] / result.sigma[free]


def _nees(sc, result) -> float:
    free = result.layout.free
    err = (result.estimate - sc.truth_vector(result.layout))[free]
    return float(err @ np.linalg.solve(result.covariance[np.ix_(free, free)], err))


@pytest.fixture(scope="module")
def noisy():
    sc = fleet_scenario(0)
    return sc, solve_batch(sc.problem())


def test_the_scenario_is_asynchronous(noisy):
    """No two sensors ever share an instant: the target windows carry the asynchrony."""
    sc, result = noisy
    t, s = sc.plots["time"], sc.plots["sensor"]
    times = {sid: set(np.round(t[s == sid], 6)) for sid in np.unique(s)}
    sids = sorted(times)
    assert all(not times[a] & times[b] for i, a in enumerate(sids) for b in sids[i + 1 :])
    assert result.converged


def test_noisy_data_within_the_reported_uncertainty(noisy):
    """24 estimated states: the joint NEES inside its two-sided 99.9 % chi-square band and every
    state within 4 sigma (a 0.15 % chance for 24 honest estimates)."""
    from scipy.stats import chi2

    sc, result = noisy
    n = result.layout.free.size
    assert chi2.ppf(0.0005, n) < _nees(sc, result) < chi2.ppf(0.9995, n)
    assert np.abs(_z(sc, result)).max() < 4.0
    assert result.chi_square.ok, result.chi_square.text()
    assert all(result.status[name] in ("identifiable", "fixed") for name in result.layout.names)


def test_nearly_noise_free_data_recover_the_truth():
    """Noise (and the stated sigmas) 1000 times smaller: the truth within 3 sigma, and sigma tiny.

    The model's own approximations must then shrink too: navigation at 200 Hz (linear
    interpolation of the roll errs by h^2) and 5 s target windows (a cubic's error on a turning
    target falls as the window^4): at 10 Hz and 20 s they would be visible at this noise level."""
    sc = fleet_scenario(1, noise_scale=1e-3, duration_s=120.0, nav_rate_hz=200.0)
    result = solve_batch(sc.problem(), BatchOptions(window_s=5.0))
    free = result.layout.free
    err = (result.estimate - sc.truth_vector(result.layout))[free]
    assert np.abs(err / result.sigma[free]).max() < 3.0
    units = np.array(result.layout.units)[free]
    assert np.abs(err[units == "rad"]).max() < np.radians(0.001) and np.abs(err[units == "m"]).max() < 0.05


def test_converges_from_zero_with_5_degree_and_3_km_errors():
    sc = fleet_scenario(
        2,
        angle_bias=np.radians(5.0),
        range_bias=3000.0,
        heading_error=np.radians(5.0),
        level_error=np.radians(5.0),
        duration_s=150.0,
    )
    result = solve_batch(sc.problem())
    assert result.converged and result.iterations < 30
    assert np.abs(_z(sc, result)).max() < 4.0
    assert result.chi_square.ok, result.chi_square.text()


def test_estimates_per_object(noisy):
    sc, result = noisy
    rows = {(r["object"], r["quantity"]): r for r in result.rows(sc.truth_state)}
    assert rows[("S", "heading_error")]["status"] == "fixed" and rows[("S", "heading_error")]["sigma"] == 0.0
    assert ("C-2D", "elevation_bias") not in rows and ("C-2D", "range_bias") in rows
    row = rows[("A-ESM", "bearing_bias")]
    assert row["label"] == "bearing bias of sensor A-ESM" and row["unit"] == "rad"
    assert abs(row["estimate"] - row["truth"]) < 4 * row["sigma"]


def test_fused_targets_and_residual_table(noisy):
    sc, result = noisy
    ft = result.targets
    for tid in ("T2", "T4"):
        t, p, cov = ft.of(tid)
        d = p - sc.target_ecef(tid, t)
        nees = np.einsum("ni,nij,nj->n", d, np.linalg.inv(cov), d)
        assert 2.0 < nees.mean() < 4.0  # 3 expected; instants share the registration error, so loose
    assert result.residuals.shape == (sc.plots["time"].size, 3)
    unmeasured = ~np.isfinite(sc.plots["range"])
    assert (
        np.isnan(result.residuals[unmeasured, 0]).all()
        and np.isfinite(result.residuals[~unmeasured, 0]).all()
    )
    assert 0.9 < np.nanstd(result.residuals) < 1.1
    by_target, by_sensor = result.residual_check("target"), result.residual_check("sensor")
    assert set(by_target) == set(sc.config.targets) and set(by_sensor) == set(sc.config.sensors)
    assert all(0.8 < mean < 1.1 for mean, _ in list(by_target.values()) + list(by_sensor.values()))


def test_a_solve_without_fused_targets_is_the_same_solve(noisy):
    """``fused=False`` (the association's solves between passes) leaves the fused positions out and
    nothing else: the same estimate, covariance and residuals, bit for bit."""
    sc, result = noisy
    lean = solve_batch(sc.problem(), fused=False)
    assert lean.targets.target.size == 0 and lean.targets.covariance.shape == (0, 3, 3)
    assert result.targets.target.size > 0
    assert np.array_equal(lean.estimate, result.estimate) and np.array_equal(
        lean.covariance, result.covariance
    )
    assert np.array_equal(lean.residuals, result.residuals, equal_nan=True)
    with pytest.raises(ValueError, match="no fused positions"):
        lean.targets.of("T2")


def test_a_window_too_long_for_the_manoeuvres_shows_in_the_residuals():
    """At 1/100 of the noise, 60 s windows cannot follow the circling targets (a cubic over 50 deg
    of T1's circle errs by several metres): their residuals stand out, the straight-flying T2's do not."""
    sc = fleet_scenario(6, noise_scale=0.01, duration_s=120.0)
    check = solve_batch(sc.problem(), BatchOptions(window_s=60.0)).residual_check("target")
    assert check["T1"][0] > 3.0 and check["T5"][0] > 2.0 and check["T2"][0] < 1.3


SITE = {"S": (0.0, 0.0, 50.0)}
#: Two 3-D radars at one surveyed site, 5 m apart: their common biases move every target alike.
TWIN = {
    "R1": ("S", (20.0, np.radians(0.1), np.radians(0.1)), 1.0, 0.0, (0.0, 0.0, 10.0)),
    "R2": ("S", (30.0, np.radians(0.15), np.radians(0.15)), 1.5, 0.4, (5.0, 0.0, 12.0)),
}


@pytest.mark.parametrize("reference", [None, "T1"])
def test_reference_targets_make_absolute_biases_observable(reference):
    config = FleetConfig({}, SITE, TWIN, {k: TARGETS[k] for k in ("T1", "T2", "T3")}, reference)
    sc = fleet_scenario(4, duration_s=150.0, config=config)
    result = solve_batch(sc.problem())
    assert result.converged
    if reference is None:
        texts = " ".join(c.text for c in result.observability.unobservable)
        for ch in ("range", "bearing", "elevation"):
            pair = sorted([f"{ch} bias of sensor R1", f"{ch} bias of sensor R2"])
            assert (
                f"{pair[0]} and {pair[1]} enter only as their difference" in texts
                or f"{pair[1]} and {pair[0]} enter only as their difference" in texts
            ), texts
        assert all(
            result.status[f"{s}:{ch}_bias"] == "not identifiable" for s in TWIN for ch in ("range", "bearing")
        )
        diff, sigma = result.combination({"R1:range_bias": 1, "R2:range_bias": -1})
        truth = sc.truth_state["R1:range_bias"] - sc.truth_state["R2:range_bias"]
        assert np.isfinite(sigma) and abs(diff - truth) < 3 * sigma
        assert np.isinf(result.combination({"R1:range_bias": 1})[1])
    else:
        assert not result.observability.unobservable and not result.observability.weak
        assert np.abs(_z(sc, result)).max() < 3.5


def test_level_platforms_report_heading_and_bearing_sums():
    """Without pitch and roll a ship's heading error and its sensors' bearing biases are seen only
    as sums: named per platform, each sum estimated with a finite sigma, the parts with none."""
    sc = fleet_scenario(2, ship_motion=False, duration_s=150.0)
    result = solve_batch(sc.problem())
    text = " ".join(c.text for c in result.observability.unobservable + result.observability.weak)
    assert "heading error of platform B and bearing bias of sensor B-3D enter only as their sum" in text
    assert "A:heading_error + A-3D:bearing_bias, A:heading_error + A-ESM:bearing_bias" in text
    for platform, sensor in (("A", "A-3D"), ("A", "A-ESM"), ("B", "B-3D"), ("C", "C-3D")):
        value, sigma = result.combination({f"{platform}:heading_error": 1, f"{sensor}:bearing_bias": 1})
        truth = sc.truth_state[f"{platform}:heading_error"] + sc.truth_state[f"{sensor}:bearing_bias"]
        assert sigma < np.radians(0.05) and abs(value - truth) < 3.5 * sigma
    assert result.status["B:heading_error"] == "not identifiable" and np.isinf(
        result.sigma_of("B:heading_error")
    )
    assert result.status["S-2D:bearing_bias"] == "identifiable"  # the surveyed site's heading is fixed


def test_a_warm_start_reaches_the_same_optimum_in_fewer_iterations(noisy):
    sc, cold = noisy
    warm = solve_batch(
        sc.problem(), x0=cold.estimate + 0.5 * cold.sigma * np.where(np.isfinite(cold.sigma), 1, 0)
    )
    free = cold.layout.free
    assert warm.converged and warm.iterations < cold.iterations
    assert np.abs((warm.estimate - cold.estimate)[free] / cold.sigma[free]).max() < 0.01
    with pytest.raises(ValueError, match="x0"):
        solve_batch(sc.problem(), x0=np.zeros(3))


def test_instant_covariance_is_the_kronecker_product_form():
    """The fused positions' covariance per instant, (basis (x) I3) cov_c (basis (x) I3)^T, summed over
    the pairs of coefficients without gathering each instant's window covariance."""
    from registration.fleet.batch.covariance import instant_covariance

    rng = np.random.default_rng(3)
    for K in (1, 4):
        A = rng.normal(size=(6, 3 * K, 3 * K + 2))
        cov_c = A @ A.transpose(0, 2, 1)
        block = rng.integers(0, 6, size=50)
        basis = rng.uniform(-1, 1, size=(50, K))
        basis[:5, -1] = 0.0  # a masked coefficient
        B = (basis[:, None, :, None] * np.eye(3)[None, :, None, :]).reshape(-1, 3, 3 * K)
        expected = B @ cov_c[block] @ B.transpose(0, 2, 1)
        np.testing.assert_allclose(instant_covariance(basis, block, cov_c), expected, rtol=1e-12, atol=1e-12)
