"""The join test of a track (a unit, :mod:`..grouping.units`) against an anchor target (:mod:`.curves`), in
the track's own measurement channels, under the registration estimate ``x`` and its covariance P.

For up to ``test_plots`` plots of the track spread over its part within the target's span, the
residuals ``r`` (measured minus predicted from the target's position at the time each plot was
seen, by the generated ``fleet_residual`` or ``fleet_residual_ext``; J = d r / d(p, the sensor's
states)) are stacked into one vector of m values. Its covariance is the full

    S = R + A C A^T + D P D^T,   A = J_p dp/dc,   D = J_x - A Y   (registered targets; D = J_x for references)

over all m values: ``R`` the sensor noise, ``C`` the target curve's own covariance (windows
shared by several plots correlate them), ``P`` the registration covariance through the bias,
attitude, gain, time-bias and position Jacobians of the sensor **and** of the sensors that fixed the
target's curve. A constant offset that the states explain costs little; a shape that they do not
explain costs much. The statistic ``d^2 = r^T S^-1 r`` is gated at the chi-square quantile of m
degrees of freedom. :func:`pair_tests` forms r, D and ``R + A C A^T`` once; :func:`evaluate`
gives d^2 under any later (x + dx, P') by the linearisation ``r(x + dx) = r + D dx``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration._generated import api as generated
from registration.core.distributions import chi2_ppf
from registration.fleet.association.grouping.geometry import state_columns
from registration.fleet.association.joining.curves import Curves
from registration.fleet.data.problem import FleetProblem
from registration.fleet.data.tables import NAV_COLUMNS

__all__ = [
    "Pairs",
    "candidate_plots",
    "pair_tests",
    "evaluate",
    "pair_statistics",
    "kalman_update",
    "verify_plots",
]

#: Pairs of ``test_plots`` (20) plots whose tests are formed in one batch (bounds the memory: about
#: 60 kB per pair); pairs of fewer plots are batched by more, for about the same memory, up to
#: MAX_PAIR_CHUNK (one plot: the single plots' tests; three: the prescreen).
PAIR_CHUNK = 256
MAX_PAIR_CHUNK = 8192


def _chunk(k: int) -> int:
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
        return Pairs(
            *(getattr(self, f)[sel] for f in ("unit", "target", "r", "D", "Sc", "dof", "plots", "mask"))
        )


def candidate_plots(
    problem: FleetProblem,
    x: np.ndarray,
    unit_of_plot: np.ndarray,
    units: np.ndarray,
    curves: Curves,
    *,
    k: int,
    min_plots: int,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, dict]:
    """The pairs (unit of ``units``, anchor target) worth testing: at least ``min_plots`` of the
    unit's plots inside the target's predicted span. Returns (unit (C,), target (C,), plots (C, k)
    spread evenly over the covered plots, -1 padding; per target, the covered plots (bool over
    the problem's plots))."""
    sel = np.flatnonzero(np.isin(unit_of_plot, units) & (unit_of_plot >= 0))
    if sel.size == 0:
        z = np.zeros(0, dtype=np.int64)
        return z, z, np.zeros((0, k), dtype=np.int64), {j: z for j in range(curves.n_targets)}
    t_seen = problem.seen(x, sel)[0]
    order = np.lexsort((t_seen, unit_of_plot[sel]))
    sel, t_seen = sel[order], t_seen[order]
    out_u, out_t, out_p, covered_by = [], [], [], {}
    for j in range(curves.n_targets):
        cov = curves.covered(j, problem.time[sel], t_seen)
        covered_by[j] = sel[cov]
        u = unit_of_plot[sel[cov]]
        ids, start, count = np.unique(u, return_index=True, return_counts=True)
        ok = count >= min_plots
        ids, start, count = ids[ok], start[ok], count[ok]
        if ids.size == 0:
            continue
        take = np.minimum(count, k)
        idx = np.full((ids.size, k), -1, dtype=np.int64)
        col = np.arange(k)[None, :]
        spread = start[:, None] + np.floor((col + 0.5) * count[:, None] / take[:, None]).astype(np.int64)
        idx = np.where(col < take[:, None], sel[cov][np.minimum(spread, cov.sum() - 1)], -1)
        out_u.append(ids)
        out_t.append(np.full(ids.size, j))
        out_p.append(idx)
    if not out_u:
        return (
            np.zeros(0, dtype=np.int64),
            np.zeros(0, dtype=np.int64),
            np.zeros((0, k), dtype=np.int64),
            covered_by,
        )
    return np.concatenate(out_u), np.concatenate(out_t), np.concatenate(out_p), covered_by


def _residuals(problem: FleetProblem, x: np.ndarray, plots: np.ndarray, p: np.ndarray, v: np.ndarray):
    """(residual (M, 3), J (M, 3, 3 + w), state columns (M, w), -1 absent) of the plots against
    target positions ``p`` (M, 3) m moving at ``v`` (M, 3) m/s, at the time each plot was seen."""
    xs = np.append(np.asarray(x, dtype=np.float64), 0.0)
    cols = state_columns(problem, plots)
    att, bias = xs[cols[:, :3]], xs[cols[:, 3:6]]
    meas = problem.meas[plots]
    lever = problem.sensor_lever[problem.sensor[plots]]
    ports = dict(att_err=att, bias=bias, lever_deck=lever, r=meas[:, 0], q=meas[:, 1], e=meas[:, 2])
    if cols.shape[1] == 6:
        fit = generated.fleet_residual(p_ecef=p, **dict(zip(NAV_COLUMNS, problem.nav[plots].T)), **ports)
        res, J = fit.residual, fit.J
    else:
        _, nav, rate = problem.seen(x, plots)
        gain, pos_err = xs[cols[:, 6]], xs[cols[:, 8:11]]
        nav_ports = dict(zip(NAV_COLUMNS, nav.T))
        ext = dict(v_ecef=v, nav_rate=rate, gain=gain, dt=0.0, pos_err=pos_err)
        fit_ext = (
            generated.fleet_residual_ecc(p_ecef=p, **nav_ports, **ext, ecc=xs[cols[:, 11:13]], **ports)
            if cols.shape[1] > 11  # and the eccentricity
            else generated.fleet_residual_ext(p_ecef=p, **nav_ports, **ext, **ports)
        )
        res, J = fit_ext.residual, fit_ext.J
    return np.asarray(res).reshape(-1, 3), np.asarray(J).reshape(-1, 3, 3 + cols.shape[1]), cols


def _chunk_tests(problem: FleetProblem, x: np.ndarray, curves: Curves, unit, target, plots) -> Pairs:
    n = problem.layout.n
    c, k = plots.shape
    valid = plots >= 0
    flat = np.where(valid, plots, plots[:, :1]).reshape(-1)
    ok = valid.reshape(-1)
    t_seen = problem.seen(x, flat)[0]
    m = flat.size
    q = curves.V_inv.shape[1] if curves.V_inv.size else 12
    p, v, block = np.zeros((m, 3)), np.zeros((m, 3)), np.full(m, -1, dtype=np.int64)
    A, cov = np.zeros((m, 3, q)), np.zeros((m, 3, 3))
    tgt = np.repeat(target, k)
    for j in np.unique(target):
        rows = np.flatnonzero(tgt == j)
        pr = curves.predict(int(j), problem.time[flat[rows]], t_seen[rows])
        p[rows], v[rows], block[rows], A[rows], cov[rows] = pr.p, pr.v, pr.block, pr.A, pr.cov
    res, J, cols = _residuals(problem, x, flat, p, v)
    mask = problem.mask[flat] & ok[:, None]
    res, J = np.where(mask, res, 0.0), np.where(mask[..., None], J, 0.0)
    Jp, Jx = J[:, :, :3], J[:, :, 3:]
    JA = Jp @ A
    D = np.zeros((m, 3, n + 1))  # J_x - J_p dp/dc Y (the window's Y over all the states, curves.Y_states)
    rows = np.arange(m)
    cols = np.where(cols < 0, n, cols)
    for i in range(cols.shape[1]):
        D[rows, :, cols[:, i]] += Jx[:, :, i]
    batch = block >= 0
    G = np.zeros((m, 3, q))
    if batch.any():
        b = block[batch]
        D[batch] -= JA[batch] @ curves.Y_states[b]
        G[batch] = JA[batch] @ curves.V_inv[b]
    sigma = np.nan_to_num(problem.sensor_sigma[problem.sensor[flat]], nan=1.0)
    same = (block.reshape(c, k)[:, :, None] == block.reshape(c, k)[:, None, :]) & batch.reshape(c, k)[
        :, :, None
    ]
    Sc = (
        np.einsum("ckaq,cjbq->ckajb", G.reshape(c, k, 3, q), JA.reshape(c, k, 3, q))
        * same[:, :, None, :, None]
    )
    own = Jp @ cov @ np.swapaxes(Jp, 1, 2) + sigma[:, :, None] ** 2 * np.eye(3)
    diag = np.arange(k)
    Sc[:, diag, :, diag, :] += np.swapaxes(own.reshape(c, k, 3, 3), 0, 1)
    Sc = Sc.reshape(c, 3 * k, 3 * k)
    mk = mask.reshape(c, 3 * k)
    Sc = np.where(mk[:, :, None] & mk[:, None, :], Sc, 0.0) + np.where(mk, 0.0, 1.0)[:, :, None] * np.eye(
        3 * k
    )
    r = res.reshape(c, 3 * k)
    D = D.reshape(c, k, 3, n + 1).reshape(c, 3 * k, n + 1)[:, :, :n]
    return Pairs(unit, target, r, D, 0.5 * (Sc + np.swapaxes(Sc, 1, 2)), mk.sum(axis=1), plots, mk)


def pair_tests(
    problem: FleetProblem,
    x: np.ndarray,
    curves: Curves,
    unit: np.ndarray,
    target: np.ndarray,
    plots: np.ndarray,
) -> Pairs:
    """The tests of the pairs (``unit`` (C,), ``target`` (C,), their ``plots`` (C, k), -1 padding) under
    the estimate ``x`` (n,): residuals, their Jacobian D and ``R + A C A^T`` (module docstring)."""
    c = _chunk(plots.shape[1])
    parts = [
        _chunk_tests(problem, x, curves, unit[a : a + c], target[a : a + c], plots[a : a + c])
        for a in range(0, unit.size, c)
    ]
    if not parts:
        n, k = problem.layout.n, plots.shape[1]
        z = np.zeros(0, dtype=np.int64)
        return Pairs(
            z,
            z,
            np.zeros((0, 3 * k)),
            np.zeros((0, 3 * k, n)),
            np.zeros((0, 3 * k, 3 * k)),
            z,
            plots,
            np.zeros((0, 3 * k), dtype=bool),
        )
    return Pairs(
        *(
            np.concatenate([getattr(p, f) for p in parts])
            for f in ("unit", "target", "r", "D", "Sc", "dof", "plots", "mask")
        )
    )


def pair_statistics(
    problem: FleetProblem,
    x: np.ndarray,
    curves: Curves,
    unit: np.ndarray,
    target: np.ndarray,
    plots: np.ndarray,
    dx: np.ndarray,
    P: np.ndarray,
    **options,
) -> tuple[np.ndarray, np.ndarray]:
    """(d2 (C,), values compared (C,)) of the pairs: :func:`pair_tests` and :func:`evaluate` (with its
    ``options``) one batch at a time, the tests not kept (the single plots' many pairs)."""
    c = _chunk(plots.shape[1])
    d2, dof = np.zeros(unit.size), np.zeros(unit.size, dtype=np.int64)
    for a in range(0, unit.size, c):
        s = slice(a, a + c)
        pairs = _chunk_tests(problem, x, curves, unit[s], target[s], plots[s])
        d2[s], _, _, dof[s] = evaluate(pairs, dx, P, **options)
    return d2, dof


def _masked(r: np.ndarray, D: np.ndarray, Sc: np.ndarray, keep: np.ndarray):
    """(r, D, Sc) of pairs with the plots not in ``keep`` (c, k) taken out (as padding: r and D 0, Sc
    the identity in their rows and columns)."""
    c, k = keep.shape
    rows = np.repeat(keep, 3, axis=1)
    both = rows[:, :, None] & rows[:, None, :]
    eye = np.where(rows, 0.0, 1.0)[:, :, None] * np.eye(3 * k)
    return np.where(rows, r, 0.0), np.where(rows[..., None], D, 0.0), np.where(both, Sc, 0.0) + eye


def _deletion(S_chol: np.ndarray, r: np.ndarray, k: int) -> np.ndarray:
    """(c, k) for each plot, how much d^2 falls when it is taken out: ``z_i^T (Q_ii)^-1 z_i`` with
    ``Q = S^-1``, ``z = Q r`` and ``i`` the plot's three rows (chi-square with its channels under the
    model: the outlier test of one plot against all the others)."""
    c, m = r.shape
    L_inv = np.linalg.solve(S_chol, np.broadcast_to(np.eye(m), (c, m, m)))
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
    chunk = _chunk(k)
    for a in range(0, C, chunk):
        s = slice(a, a + chunk)
        D0 = pairs.D[s]
        r0 = pairs.r[s] + D0 @ dx
        keep = keep_all[s].copy()
        for it in range(max_trim + 1):
            r, D, Sc = _masked(r0, D0, pairs.Sc[s], keep)
            L = _cholesky(Sc + D @ P @ np.swapaxes(D, 1, 2))
            y = np.linalg.solve(L, r[..., None])[..., 0]
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
        )
    )
    L = _cholesky((Sc + D @ P @ D.T)[None])[0]
    K = np.linalg.solve(L.T, np.linalg.solve(L, D @ P)).T
    P = P - K @ D @ P
    return dx - K @ r, 0.5 * (P + P.T)


def verify_plots(
    problem: FleetProblem,
    x: np.ndarray,
    curves: Curves,
    unit: np.ndarray,
    target: np.ndarray,
    plots: np.ndarray,
    dx: np.ndarray,
    P: np.ndarray,
    probability: float,
) -> np.ndarray:
    """(M,) bool: each plot (``plots`` (M,) of ``unit`` joined to ``target``) alone passes the chi-square
    ``1 - probability`` gate of its channels against the target under the states ``x + dx`` and
    their covariance P: the plots of a join that are not the target (clutter, a stray plot a tracker
    took) are found before they are registered."""
    if plots.size == 0:
        return np.zeros(0, dtype=bool)
    d2, dof = pair_statistics(problem, x, curves, unit, target, plots[:, None], dx, P)
    return (dof > 0) & (d2 < chi2_ppf(1.0 - probability, np.maximum(dof, 1)))
