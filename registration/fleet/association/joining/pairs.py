"""The pairs of (track, anchor target) under test (:class:`Pairs`, formed by :mod:`.attach`) and their
statistic under any later estimate and covariance (:func:`evaluate`, :func:`kalman_update`): the
residuals moved by the linearisation ``r + D dx`` against ``Sc + D P D^T``, plots that are outliers of
a pair taken out by the deletion statistic."""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

from registration.core.linalg import forward_solve

__all__ = ["MAX_PAIR_CHUNK", "PAIR_CHUNK", "Pairs", "chunk_size", "evaluate", "kalman_update"]

#: Pairs of ``test_plots`` (20) plots whose tests are formed in one batch (bounds the memory: about
#: 60 kB per pair); pairs of fewer plots are batched by more, for about the same memory, up to
#: MAX_PAIR_CHUNK (one plot: the single plots' tests; three: the prescreen).
PAIR_CHUNK = 256
MAX_PAIR_CHUNK = 8192


def chunk_size(k: int) -> int:
    """Pairs per batch for pairs of ``k`` plots."""
    return int(min(MAX_PAIR_CHUNK, max(PAIR_CHUNK, PAIR_CHUNK * 400 // max(k * k, 1))))


@dataclass(frozen=True)
class Pairs:
    """Per pair (C,): ``unit``, ``target`` (index into the curves' names), ``r`` (C, m) residuals
    (m/rad, 0 in padding), ``D`` (C, m, n) d r / d states, ``Sc`` (C, m, m) R + A C A^T (1 on the
    diagonal of padding), ``dof`` (C,) values compared, ``plots`` (C, k) the plots tested (-1:
    padding), ``mask`` (C, m) the values measured."""

    unit: np.ndarray
    target: np.ndarray
    r: np.ndarray
    D: np.ndarray
    Sc: np.ndarray
    dof: np.ndarray
    plots: np.ndarray
    mask: np.ndarray

    @property
    def size(self) -> int:
        return int(self.unit.size)

    def take(self, sel: np.ndarray) -> "Pairs":
        return Pairs(**{f.name: getattr(self, f.name)[sel] for f in fields(self)})


def _masked(r: np.ndarray, D: np.ndarray, Sc: np.ndarray, keep: np.ndarray, valid: np.ndarray):
    """(r, D, Sc) of pairs with the plots not in ``keep`` (c, k) taken out (as padding: r and D 0, Sc
    the identity in their rows and columns). Padding (``valid`` (c, k) False) is that already, so only
    the pairs with a valid plot left out are copied and changed (the others are returned as given)."""
    out = np.flatnonzero((valid & ~keep).any(axis=1))
    if out.size == 0:
        return r, D, Sc
    c, k = keep.shape
    rows = np.repeat(keep[out], 3, axis=1)
    both = rows[:, :, None] & rows[:, None, :]
    eye = np.where(rows, 0.0, 1.0)[:, :, None] * np.eye(3 * k)
    r, D, Sc = r.copy(), D.copy(), Sc.copy()
    r[out], D[out] = np.where(rows, r[out], 0.0), np.where(rows[..., None], D[out], 0.0)
    Sc[out] = np.where(both, Sc[out], 0.0) + eye
    return r, D, Sc


def _drop_plots(r: np.ndarray, S: np.ndarray, keep: np.ndarray, valid: np.ndarray):
    """:func:`_masked` applied after the product: (r, S) with ``S = Sc + D P D^T`` (changed in place)
    of pairs with the plots not in ``keep`` taken out. A value of S between two plots kept does not
    depend on the rows taken out, and those rows become the identity's either way, so S needs no
    product again when plots are taken out (nor copies of D and Sc)."""
    out = np.flatnonzero((valid & ~keep).any(axis=1))
    if out.size == 0:
        return r, S
    rows = np.repeat(keep[out], 3, axis=1)
    eye = np.where(rows, 0.0, 1.0)[:, :, None] * np.eye(rows.shape[1])
    S[out] = np.where(rows[:, :, None] & rows[:, None, :], S[out], 0.0) + eye
    r = r.copy()
    r[out] = np.where(rows, r[out], 0.0)
    return r, S


def _deletion(S_chol: np.ndarray, r: np.ndarray, k: int) -> np.ndarray:
    """(c, k) for each plot, how much d^2 falls when it is taken out: ``z_i^T (Q_ii)^-1 z_i`` with
    ``Q = S^-1``, ``z = Q r`` and ``i`` the plot's three rows (chi-square with its channels under the
    model: the outlier test of one plot against all the others)."""
    c, m = r.shape
    L_inv = forward_solve(S_chol, np.broadcast_to(np.eye(m), (c, m, m)))
    Q = np.swapaxes(L_inv, 1, 2) @ L_inv
    z = (Q @ r[..., None])[..., 0].reshape(c, k, 3)
    blocks = Q.reshape(c, k, 3, k, 3)[:, np.arange(k), :, np.arange(k), :].transpose(1, 0, 2, 3)
    return np.einsum("cki,cki->ck", z, np.linalg.solve(blocks, z[..., None])[..., 0])


def _cholesky(S: np.ndarray) -> np.ndarray:
    """Cholesky factors of symmetric (c, m, m) matrices that should be positive definite; one that
    rounding made indefinite (a covariance after many updates) gets its eigenvalues raised to a
    small positive floor first."""
    S = 0.5 * (S + np.swapaxes(S, 1, 2))
    try:
        return np.linalg.cholesky(S)
    except np.linalg.LinAlgError:
        w, v = np.linalg.eigh(S)
        floor = 1e-12 * np.maximum(np.abs(w).max(axis=1, keepdims=True), 1e-300)
        return np.linalg.cholesky((v * np.maximum(w, floor)[:, None, :]) @ np.swapaxes(v, 1, 2))


def evaluate(
    pairs: Pairs,
    dx: np.ndarray,
    P: np.ndarray,
    *,
    outlier_limit: np.ndarray | None = None,
    max_trim: int = 0,
    keep: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(d2 (C,), log det S (C,), plots kept (C, k) bool, values compared (C,)) of the pairs with the
    states moved by ``dx`` (n,) and covariance P (n, n): ``r + D dx`` against ``Sc + D P D^T``. With
    ``outlier_limit`` (per number of channels 0..3, the limit of the deletion statistic) up to
    ``max_trim`` plots of each pair are taken out, worst first, while one exceeds its limit (a
    clutter plot or a stray plot a tracker took does not decide the test). ``keep`` (C, k): the plots
    to use (default all; e.g. those an earlier call kept)."""
    C, m = pairs.r.shape
    k = m // 3
    d2, logdet = np.zeros(C), np.zeros(C)
    keep_all = (pairs.plots >= 0) if keep is None else (keep & (pairs.plots >= 0))
    channels = pairs.mask.reshape(C, k, 3).sum(axis=2)  # measured channels per plot (0 for padding)
    chunk = chunk_size(k)
    for a in range(0, C, chunk):
        s = slice(a, a + chunk)
        D0 = pairs.D[s]
        r0 = pairs.r[s] + D0 @ dx
        keep = keep_all[s].copy()
        S = pairs.Sc[s] + D0 @ P @ np.swapaxes(D0, 1, 2)
        for it in range(max_trim + 1):
            r, S = _drop_plots(r0, S, keep, pairs.plots[s] >= 0)
            L = _cholesky(S)
            y = forward_solve(L, r)
            d2[s], logdet[s] = (
                np.einsum("ki,ki->k", y, y),
                2.0 * np.log(np.diagonal(L, axis1=1, axis2=2)).sum(axis=1),
            )
            if outlier_limit is None or it == max_trim:
                break
            # only a pair well above its mean can hold a plot beyond the outlier limit
            dof = np.where(keep, channels[s], 0).sum(axis=1)
            rows = np.flatnonzero(d2[s] > dof + 0.5 * outlier_limit[1])
            if rows.size == 0:
                break
            delta = np.where(keep[rows], _deletion(L[rows], r[rows], k), 0.0)
            worst = np.argmax(delta, axis=1)
            hit = delta[np.arange(rows.size), worst] > outlier_limit[channels[s][rows, worst]]
            if not hit.any():
                break
            keep[rows[hit], worst[hit]] = False
        keep_all[s] = keep
    dof = np.where(keep_all, channels, 0).sum(axis=1)
    return d2, logdet, keep_all, dof


def kalman_update(
    pairs: Pairs, i: int, dx: np.ndarray, P: np.ndarray, keep: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """The states' correction and covariance after taking pair ``i`` (its plots ``keep`` (k,) bool) as
    a join: the linear Gaussian update ``dx - K (r + D dx)``, ``P - K D P`` with ``K = P D^T S^-1``."""
    keep = pairs.plots[i] >= 0 if keep is None else keep
    r, D, Sc = (
        v[0]
        for v in _masked(
            pairs.r[i : i + 1] + pairs.D[i : i + 1] @ dx,
            pairs.D[i : i + 1],
            pairs.Sc[i : i + 1],
            keep[None, :],
            pairs.plots[i : i + 1] >= 0,
        )
    )
    L = _cholesky((Sc + D @ P @ D.T)[None])[0]
    K = np.linalg.solve(L.T, np.linalg.solve(L, D @ P)).T
    P = P - K @ D @ P
    return dx - K @ r, 0.5 * (P + P.T)
