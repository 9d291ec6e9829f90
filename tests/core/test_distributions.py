"""registration.core.distributions gives scipy.stats' values (the reference) to the last bits."""

from __future__ import annotations

import numpy as np

from registration.core.distributions import chi2_logsf, chi2_ppf, chi2_sf, norm_isf

Q = np.array([0.0, 1e-12, 1e-6, 0.01, 0.05, 0.5, 0.9, 0.99, 0.9973, 1 - 1e-9, 1.0])
DOF = np.array([1, 2, 3, 4, 7, 30, 500])
X = np.array([0.0, 1e-8, 0.3, 1.0, 3.84, 9.21, 40.0, 400.0, 5000.0])


def test_chi2_quantiles_and_tails_equal_scipy_stats():
    from scipy import stats  # here, not at collection: it takes a second to import

    q, dof = np.meshgrid(Q, DOF)
    np.testing.assert_allclose(chi2_ppf(q, dof), stats.chi2.ppf(q, dof), rtol=1e-14, atol=0)
    x, dofx = np.meshgrid(X, DOF)
    np.testing.assert_allclose(chi2_sf(x, dofx), stats.chi2.sf(x, dofx), rtol=1e-14, atol=0)
    np.testing.assert_allclose(chi2_logsf(x, dofx), stats.chi2.logsf(x, dofx), rtol=1e-12, atol=0)
    assert float(chi2_ppf(0.95, 1)) == float(stats.chi2.ppf(0.95, 1))  # scalars stay scalars


def test_one_quantile_of_many_degrees_of_freedom_is_the_same_per_value():
    """One q and thousands of dof (a gate per tested pair) are computed once per distinct dof: the
    same numbers, bit for bit, in the shape given."""
    from scipy import special

    dof = np.random.default_rng(1).integers(1, 61, size=(40, 50))
    for q in (0.99, 0.999):
        expected = 2.0 * special.gammaincinv(dof / 2.0, q)
        got = chi2_ppf(q, dof)
        assert got.shape == dof.shape and np.array_equal(got, expected)


def test_normal_upper_quantile_equals_scipy_stats():
    from scipy import stats

    q = np.array([1e-300, 1e-12, 0.0013, 0.025, 0.5, 0.975, 1.0])
    np.testing.assert_allclose(norm_isf(q), stats.norm.isf(q), rtol=1e-14, atol=0)
