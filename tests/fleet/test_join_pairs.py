"""The join test's statistic under later estimates (registration.fleet.association.joining.pairs):
the shortcuts the join passes rely on give the numbers of the plain formulation, bit for bit.

* ``evaluate`` takes the plots left out of ``S = Sc + D P D^T`` after the product; the plain way
  takes them out of r, D and Sc first and forms the product then (padding rows: r and D 0, Sc
  the identity).
* The trimming evaluation's d2 is that of the plots it kept (``choose_joins`` takes it as its
  first round's test instead of evaluating those pairs again).
"""

import numpy as np
import pytest

from registration.core.linalg import forward_solve
from registration.fleet.association.joining.pairs import Pairs, evaluate, kalman_update

LIMITS = np.r_[np.inf, 6.6, 9.2, 11.3]  # chi-square 0.99 quantiles, 1 to 3 channels


def _pairs(rng, c: int, k: int, n: int, outliers: bool = True) -> Pairs:
    """c pairs of k plots (some padding, some 2-D plots without elevation) over n states."""
    m = 3 * k
    n_plots = rng.integers(max(1, k // 2), k + 1, size=c)
    plots = np.where(np.arange(k)[None, :] < n_plots[:, None], rng.integers(0, 10_000, size=(c, k)), -1)
    mask = np.repeat(plots >= 0, 3, axis=1)
    mask[:, 2::3] &= rng.random((c, k)) < 0.7  # no elevation
    A = rng.normal(size=(c, m, m)) * 0.3
    Sc = A @ np.swapaxes(A, 1, 2) + np.eye(m)
    Sc = np.where(mask[:, :, None] & mask[:, None, :], Sc, 0.0) + np.where(mask, 0.0, 1.0)[
        :, :, None
    ] * np.eye(m)
    Sc = 0.5 * (Sc + np.swapaxes(Sc, 1, 2))
    D = np.where(mask[..., None], rng.normal(size=(c, m, n)) * 0.5, 0.0)
    r = np.where(mask, rng.normal(size=(c, m)), 0.0)
    if outliers:  # a stray plot in some pairs
        hit = rng.random(c) < 0.4
        r[hit, 0] += np.where(mask[hit, 0], 40.0, 0.0)
    unit, target = np.arange(c), rng.integers(0, 3, size=c)
    return Pairs(unit, target, r, D, Sc, mask.sum(axis=1), plots, mask)


def _plain(pairs: Pairs, dx: np.ndarray, P: np.ndarray, keep: np.ndarray) -> np.ndarray:
    """d2 with the plots not kept taken out of r, D and Sc before the product."""
    c, m = pairs.r.shape
    k = m // 3
    rows = np.repeat(keep & (pairs.plots >= 0), 3, axis=1)
    both = rows[:, :, None] & rows[:, None, :]
    r = np.where(rows, pairs.r + pairs.D @ dx, 0.0)
    D = np.where(rows[..., None], pairs.D, 0.0)
    Sc = np.where(both, pairs.Sc, 0.0) + np.where(rows, 0.0, 1.0)[:, :, None] * np.eye(3 * k)
    S = Sc + D @ P @ np.swapaxes(D, 1, 2)
    L = np.linalg.cholesky(0.5 * (S + np.swapaxes(S, 1, 2)))
    y = forward_solve(L, r)  # the triangular solve evaluate uses (against numpy's: the last test)
    return np.einsum("ki,ki->k", y, y)


@pytest.mark.parametrize("k, seed", [(20, 1), (3, 2), (1, 3), (20, 4)])
def test_plots_left_out_after_the_product(k, seed):
    rng = np.random.default_rng(seed)
    n = 12
    pairs = _pairs(rng, 40, k, n)
    B = rng.normal(size=(n, n)) * 0.2
    P, dx = B @ B.T + 1e-3 * np.eye(n), rng.normal(size=n) * 0.1
    keep = rng.random((40, k)) < 0.8
    keep[::5] = True  # pairs that lose nothing
    d2, _, kept, _ = evaluate(pairs, dx, P, keep=keep)
    np.testing.assert_array_equal(d2, _plain(pairs, dx, P, kept))
    assert (kept == (keep & (pairs.plots >= 0))).all()


@pytest.mark.parametrize("k, seed", [(20, 5), (3, 6), (20, 7)])
def test_trimmed_statistic_is_that_of_the_plots_kept(k, seed):
    rng = np.random.default_rng(seed)
    n = 10
    pairs = _pairs(rng, 60, k, n)
    B = rng.normal(size=(n, n)) * 0.2
    P, dx = B @ B.T + 1e-3 * np.eye(n), np.zeros(n)
    d2, logdet, kept, dof = evaluate(pairs, dx, P, outlier_limit=LIMITS, max_trim=2)
    assert (~kept & (pairs.plots >= 0)).any()  # some plots were taken out
    again, logdet_again, kept_again, dof_again = evaluate(pairs, dx, P, keep=kept)
    np.testing.assert_array_equal(d2, again)
    np.testing.assert_array_equal(logdet, logdet_again)
    np.testing.assert_array_equal(kept, kept_again)
    np.testing.assert_array_equal(dof, dof_again)
    np.testing.assert_array_equal(d2, _plain(pairs, dx, P, kept))


def test_kalman_update_leaves_out_the_plots_not_kept():
    """The update with some plots left out equals the update of the same pair with those plots as
    padding (their residuals and Jacobian rows changed: they must not count)."""
    rng = np.random.default_rng(8)
    n = 8
    pairs = _pairs(rng, 3, 20, n, outliers=False)
    B = rng.normal(size=(n, n)) * 0.2
    P, dx = B @ B.T + 1e-3 * np.eye(n), rng.normal(size=n) * 0.1
    keep = pairs.plots[0] >= 0
    keep[1] = False
    dx1, P1 = kalman_update(pairs, 0, dx, P, keep)
    r, D = pairs.r.copy(), pairs.D.copy()
    r[0, 3:6] += 100.0
    D[0, 3:6] += 5.0
    changed = Pairs(pairs.unit, pairs.target, r, D, pairs.Sc, pairs.dof, pairs.plots, pairs.mask)
    dx2, P2 = kalman_update(changed, 0, dx, P, keep)
    np.testing.assert_array_equal(dx1, dx2)
    np.testing.assert_array_equal(P1, P2)


@pytest.mark.parametrize(("c", "m", "p"), [(50, 60, None), (300, 3, None), (40, 9, 9), (1, 1, None)])
def test_forward_solve_is_the_triangular_solve(c, m, p):
    """forward_solve (the pairs' L^-1 r and L^-1 I, row by row over all pairs) against numpy's
    general solve of the same triangular systems."""
    rng = np.random.default_rng(m)
    A = rng.normal(size=(c, m, m + 2))
    L = np.linalg.cholesky(A @ np.swapaxes(A, 1, 2))
    b = rng.normal(size=(c, m) if p is None else (c, m, p))
    want = np.linalg.solve(L, b[..., None])[..., 0] if p is None else np.linalg.solve(L, b)
    np.testing.assert_allclose(forward_solve(L, b), want, rtol=1e-10, atol=1e-12 * np.abs(want).max())
