"""Time alignment (registration.core.alignment): exactness, convergence, noise propagation, clocks, errors.

Statistics. The Monte Carlo checks use many independent noise columns K sharing one clock (the
fit is linear, so each column is an independent replicate). For white Gaussian noise of variance
s^2 the fitted value at an instant has variance s^2 * variance_factor; the sample variance over K
columns then has relative standard deviation sqrt(2 / K). Tolerances are 5 such standard
deviations (false-alarm probability ~ 1e-6 per check), while a wrong variance factor (for
example forgetting the degree, or using 1/n) is off by tens of percent.
"""

from __future__ import annotations

import numpy as np
import pytest
from numpy.polynomial import Polynomial

from registration.core.alignment import REASON_EXTRAPOLATION, REASON_ILL_CONDITIONED, REASON_TOO_FEW, align


def _irregular_times(rng, n, t0=0.0, mean_dt=0.05):
    return t0 + np.cumsum(rng.uniform(0.3, 1.7, n) * mean_dt)


@pytest.mark.parametrize("degree", [0, 1, 2, 3, 4])
@pytest.mark.parametrize("window", ["half_window_s", "n_nearest"])
def test_reproduces_polynomials_up_to_the_degree_exactly(degree, window):
    rng = np.random.default_rng(degree)
    t = _irregular_times(rng, 400, t0=100.0)  # offset start: conditioning must not depend on absolute time
    coeffs = rng.normal(size=(degree + 1, 3)) * [1.0, 50.0, 1e-3]  # three columns, very different scales
    y = np.stack([Polynomial(coeffs[:, k])(t - 105.0) for k in range(3)], axis=1)
    tau = rng.uniform(t[20], t[-20], 200)
    kw = {"half_window_s": 0.4} if window == "half_window_s" else {"n_nearest": degree + 4}
    res = align(t, y, tau, degree=degree, **kw)
    truth = np.stack([Polynomial(coeffs[:, k])(tau - 105.0) for k in range(3)], axis=1)
    scale = np.abs(y).max(axis=0)
    assert res.valid.all()
    err = np.abs(res.y - truth).max(axis=0)
    assert np.all(err <= 1e-10 * scale), err / scale


def test_a_polynomial_above_the_degree_is_not_reproduced():
    """Negative control for the exactness test: the basis really is limited to the degree."""
    t = np.linspace(0, 10, 201)
    y = (t - 5.0) ** 3
    res = align(t, y, np.array([5.01, 6.33]), degree=2, half_window_s=0.5)
    assert np.abs(res.y[:, 0] - np.array([5.01 - 5.0, 1.33]) ** 3).max() > 1e-4


def test_agrees_with_numpy_polynomial_fit_on_the_same_window():
    rng = np.random.default_rng(3)
    t = _irregular_times(rng, 300)
    y = np.sin(3 * t) + rng.normal(0, 0.1, t.size)
    tau = rng.uniform(t[10], t[-10], 50)
    res = align(t, y, tau, degree=3, half_window_s=0.3)
    for k, tk in enumerate(tau):
        sel = np.abs(t - tk) <= 0.3
        ref = Polynomial.fit(t[sel], y[sel], 3)(tk)
        assert res.y[k, 0] == pytest.approx(ref, abs=1e-10)
        assert res.n_samples[k] == sel.sum()


@pytest.mark.parametrize("degree", [1, 2, 3])
def test_error_on_a_smooth_trajectory_shrinks_as_sampling_gets_denser(degree):
    """Noise-free sinusoid, window of the 2(d+1) nearest samples: the window shrinks with the
    sample spacing h and the error falls like h^(d+1) (at least, odd terms cancel when centred)."""
    omega = 2 * np.pi / 8.0  # the pitch period of the landing scenario
    tau = np.linspace(5.0, 55.0, 301) + 0.0123
    errs = []
    rates = [5.0, 10.0, 20.0, 40.0, 80.0]
    for rate in rates:
        t = np.arange(0, 60, 1 / rate)
        res = align(t, np.sin(omega * t), tau, degree=degree, n_nearest=2 * (degree + 1))
        errs.append(np.sqrt(np.mean((res.y[:, 0] - np.sin(omega * tau)) ** 2)))
    errs = np.array(errs)
    assert np.all(np.diff(errs) < 0), errs
    # each doubling of the rate gains at least 2^(d+1) / 2 (half the asymptotic order, for margin)
    assert np.all(errs[:-1] / errs[1:] > 2 ** (degree + 1) / 2), errs[:-1] / errs[1:]


def test_noisy_error_shrinks_with_density_as_predicted_by_the_variance_factor():
    """Fixed 0.5 s window: denser sampling averages more noise; RMSE ~ sigma sqrt(variance_factor)."""
    rng = np.random.default_rng(11)
    sigma, K = 1e-3, 2000
    tau = np.linspace(2.0, 8.0, 25)
    rmses, preds = [], []
    for rate in (10.0, 20.0, 40.0, 80.0):
        t = np.arange(0, 10, 1 / rate)
        truth = np.sin(0.5 * t)
        y = truth[:, None] + rng.normal(0, sigma, (t.size, K))
        res = align(t, y, tau, degree=2, half_window_s=0.25)
        err = res.y - np.sin(0.5 * tau)[:, None]
        rmses.append(np.sqrt(np.mean(err**2)))
        preds.append(sigma * np.sqrt(np.mean(res.variance_factor)))
    rmses, preds = np.array(rmses), np.array(preds)
    assert np.all(np.diff(rmses) < 0)
    # K * 25 values (25 instants, correlated at most within a window): 5 sigma of sqrt(2/K) in variance
    assert np.all(np.abs(rmses**2 / preds**2 - 1) < 5 * np.sqrt(2 / K)), rmses / preds


def test_variance_factor_matches_monte_carlo_per_instant():
    rng = np.random.default_rng(5)
    t = _irregular_times(rng, 200)
    K = 20000
    y = rng.normal(0, 1, (t.size, K))
    tau = np.linspace(t[5], t[-5], 7)
    res = align(t, y, tau, degree=2, half_window_s=0.2)
    sample_var = res.y.var(axis=1)
    tol = 5 * np.sqrt(2 / K)
    assert np.all(np.abs(sample_var / res.variance_factor - 1) < tol)
    # sanity: degree 0 over n samples is the mean, variance 1/n
    res0 = align(t, y[:, :2], tau, degree=0, half_window_s=0.2)
    assert res0.variance_factor == pytest.approx(1 / res0.n_samples)


def test_clock_offset_is_removed():
    """A clock reading true time + 30 ms: aligned with the offset, a smooth signal is exact to the
    fit's accuracy; ignoring the offset costs offset x slope."""
    t_true = np.arange(0, 20, 0.04)
    f = lambda x: 3.0 * x + 0.2 * x**2  # noqa: E731 (a polynomial of the fitted degree: exact)
    t_clock = t_true + 0.030
    tau = np.linspace(2, 18, 40)
    good = align(t_clock, f(t_true), tau, degree=2, half_window_s=0.3, clock_offset_s=0.030)
    bad = align(t_clock, f(t_true), tau, degree=2, half_window_s=0.3)
    assert np.abs(good.y[:, 0] - f(tau)).max() < 1e-9
    slope = 3.0 + 0.4 * tau
    assert bad.y[:, 0] - f(tau) == pytest.approx(-0.030 * slope + 0.2 * 0.03**2, abs=1e-9)


def test_angle_columns_are_unwrapped_and_wrapped_back():
    t = np.arange(0, 4, 0.05)
    phase = np.pi - 0.3 + 0.2 * t  # crosses +pi at t = 1.5 s
    y = np.stack([np.angle(np.exp(1j * phase)), t], axis=1)
    tau = np.array([1.4, 1.5, 1.6, 3.0])
    res = align(t, y, tau, degree=1, half_window_s=0.2, angle_columns=[0])
    expect = np.angle(np.exp(1j * (np.pi - 0.3 + 0.2 * tau)))
    assert np.angle(np.exp(1j * (res.y[:, 0] - expect))) == pytest.approx(0, abs=1e-12)
    assert np.all((res.y[:, 0] > -np.pi) & (res.y[:, 0] <= np.pi))
    assert res.y[:, 1] == pytest.approx(tau)


# --------------------------------------------------------------------------- bad input
T = np.arange(0, 2, 0.1)
Y = np.sin(T)


def test_unsorted_timestamps_are_refused():
    t = T.copy()
    t[[4, 5]] = t[[5, 4]]
    with pytest.raises(ValueError, match=r"t: timestamps not sorted: t\[4\]"):
        align(t, Y, [1.0], half_window_s=0.3)


def test_duplicate_timestamps_are_refused():
    t = T.copy()
    t[7] = t[6]
    with pytest.raises(ValueError, match="t: duplicate timestamp .* indices 6 and 7"):
        align(t, Y, [1.0], half_window_s=0.3)


def test_nan_sample_is_refused():
    y = np.stack([Y, Y], axis=1)
    y[3, 1] = np.nan
    with pytest.raises(ValueError, match=r"y: non-finite sample nan at index 3, column 1"):
        align(T, y, [1.0], half_window_s=0.3)


def test_nan_time_is_refused():
    t = T.copy()
    t[2] = np.nan
    with pytest.raises(ValueError, match="t: non-finite time"):
        align(t, Y, [1.0], half_window_s=0.3)
    with pytest.raises(ValueError, match="t_eval: non-finite time"):
        align(T, Y, [1.0, np.nan], half_window_s=0.3)


def test_window_with_fewer_samples_than_the_basis_needs():
    with pytest.raises(ValueError, match=r"holds 2 sample\(s\) but degree 2 needs at least 3"):
        align(T, Y, [1.05], degree=2, half_window_s=0.06)
    res = align(T, Y, [1.05, 1.0], degree=2, half_window_s=0.11, strict=False)
    assert res.valid.tolist() == [False, True]
    assert res.reason[0] == REASON_TOO_FEW and np.isnan(res.y[0, 0])
    assert res.invalid_instants.tolist() == [1.05]
    with pytest.raises(ValueError, match="n_nearest: expected an integer >= degree \\+ 1 = 3"):
        align(T, Y, [1.0], degree=2, n_nearest=2)
    with pytest.raises(ValueError, match="too few samples|needs at least"):
        align(T[:2], Y[:2], [0.05], degree=2, n_nearest=3)


def test_extrapolation_beyond_the_limit_is_refused():
    with pytest.raises(ValueError, match=r"lies 0.1 s outside .* max_extrapolation_s = 0.05 s"):
        align(T, Y, [T[-1] + 0.1], degree=1, half_window_s=0.3, max_extrapolation_s=0.05)
    ok = align(T, Y, [T[-1] + 0.05], degree=1, half_window_s=0.3, max_extrapolation_s=0.05)
    assert ok.valid.all() and ok.extrapolation_s[0] == pytest.approx(0.05)
    res = align(T, Y, [-0.15, 1.0], degree=1, half_window_s=0.3, strict=False)
    assert res.reason.tolist() == [REASON_EXTRAPOLATION, ""]


def test_clustered_window_is_refused_as_ill_conditioned():
    """Two of a degree-2 window's three samples 1e-10 s apart: the fit is refused, not returned."""
    t = np.array([0.0, 1e-10, 1.0, 5.0, 6.0, 7.0])
    y = np.arange(6.0) ** 2
    with pytest.raises(ValueError, match=r"too clustered \(condition number > 1e\+08\)"):
        align(t, y, [0.5], degree=2, half_window_s=1.0)
    res = align(t, y, [0.5, 6.0], degree=2, half_window_s=1.0, strict=False)
    assert res.reason.tolist() == [REASON_ILL_CONDITIONED, ""]
    assert np.isnan(res.y[0, 0]) and np.isnan(res.variance_factor[0])
    assert res.y[1, 0] == pytest.approx(16.0, abs=1e-9) and res.variance_factor[1] == pytest.approx(1.0)


def test_bad_options_are_refused():
    with pytest.raises(ValueError, match="exactly one of half_window_s"):
        align(T, Y, [1.0])
    with pytest.raises(ValueError, match="exactly one of half_window_s"):
        align(T, Y, [1.0], half_window_s=0.3, n_nearest=5)
    with pytest.raises(ValueError, match="degree: expected an integer >= 0"):
        align(T, Y, [1.0], degree=-1, half_window_s=0.3)
    with pytest.raises(ValueError, match="half_window_s: expected a finite number > 0 s"):
        align(T, Y, [1.0], half_window_s=0.0)
    with pytest.raises(ValueError, match=r"y: expected shape \(20,\) or \(20, K\)"):
        align(T, Y[:-1], [1.0], half_window_s=0.3)
    with pytest.raises(ValueError, match="angle_columns: column 3 does not exist"):
        align(T, Y, [1.0], half_window_s=0.3, angle_columns=[3])
