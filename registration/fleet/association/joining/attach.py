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
degrees of freedom. :func:`pair_tests` forms r, D and ``R + A C A^T`` once; :func:`.pairs.evaluate`
gives d^2 under any later (x + dx, P') by the linearisation ``r(x + dx) = r + D dx``.
"""

from __future__ import annotations

import numpy as np

from registration._generated import api as generated
from registration.core.distributions import chi2_ppf
from registration.fleet.association.grouping.geometry import state_columns
from registration.fleet.association.joining.curves import Curves
from registration.fleet.association.joining.pairs import Pairs, chunk_size, evaluate, kalman_update
from registration.fleet.data.problem import FleetProblem
from registration.fleet.data.tables import NAV_COLUMNS

__all__ = [
    "Pairs",
    "candidate_plots",
    "pair_tests",
    "evaluate",
    "pair_statistics",
    "kalman_update",
    "lower_bounds",
    "verify_plots",
]

#: Rows (plots) whose windows' ``Y`` over the states are gathered at once in :func:`_chunk_tests`.
WINDOW_ROWS = 512
#: Plots predicted at once in :func:`lower_bounds`.
PREDICT_ROWS = 16384


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


def _predicted(problem: FleetProblem, x: np.ndarray, curves: Curves, target: np.ndarray, plots: np.ndarray):
    """Of the pairs' ``plots`` (C, k; -1 padding, evaluated as the pair's first plot) against their
    ``target`` (C,), per plot (m = C k): the plots (m,), measured and not padding (m, 3), and the
    residuals, Jacobians and state columns of :func:`_residuals`, the window (m,; -1 none), ``A``
    (m, 3, q) and the position's own covariance (m, 3, 3) of the prediction (:meth:`Curves.predict`)."""
    c, k = plots.shape
    valid = plots >= 0
    flat = np.where(valid, plots, plots[:, :1]).reshape(-1)
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
    return flat, problem.mask[flat] & valid.reshape(-1)[:, None], res, J, cols, block, A, cov


def _chunk_tests(problem: FleetProblem, x: np.ndarray, curves: Curves, unit, target, plots) -> Pairs:
    n = problem.layout.n
    c, k = plots.shape
    flat, mask, res, J, cols, block, A, cov = _predicted(problem, x, curves, target, plots)
    m = flat.size
    q = A.shape[2]
    res, J = np.where(mask, res, 0.0), np.where(mask[..., None], J, 0.0)
    Jp, Jx = J[:, :, :3], J[:, :, 3:]
    JA = Jp @ A
    D = np.zeros((m, 3, n + 1))  # J_x - J_p dp/dc Y (the window's Y over all the states, curves.Y_states)
    rows = np.arange(m)
    cols = np.where(cols < 0, n, cols)
    ordered = np.sort(cols, axis=1)
    if ((ordered[:, 1:] == ordered[:, :-1]) & (ordered[:, 1:] < n)).any():  # a state in two groups
        for i in range(cols.shape[1]):
            D[rows, :, cols[:, i]] += Jx[:, :, i]
    else:  # each state once per plot (index n: none, dropped): 0 + J, in one write
        D[rows[:, None], :, cols] = np.swapaxes(Jx, 1, 2) + 0.0
    batch = block >= 0
    G = np.zeros((m, 3, q))
    if batch.any():
        # a few hundred rows at a time: the windows' Y gathered for a whole chunk of short pairs is
        # some 100 MB, written and read once (the same products, row by row)
        at = np.flatnonzero(batch)
        for a in range(0, at.size, WINDOW_ROWS):
            part = at[a : a + WINDOW_ROWS]
            D[part] -= JA[part] @ curves.Y_states[block[part]]
            G[part] = JA[part] @ curves.V_inv[block[part]]
    sigma = np.nan_to_num(problem.sensor_sigma[problem.sensor[flat]], nan=1.0)
    same = (block.reshape(c, k)[:, :, None] == block.reshape(c, k)[:, None, :]) & batch.reshape(c, k)[
        :, :, None
    ]
    # A_i C_b A_j^T between the values of plots i, j in one window b: one batched product per pair
    Sc = (G.reshape(c, 3 * k, q) @ JA.reshape(c, 3 * k, q).transpose(0, 2, 1)).reshape(c, k, 3, k, 3)
    Sc *= same[:, :, None, :, None]
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
    c = chunk_size(plots.shape[1])
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
    c = chunk_size(plots.shape[1])
    d2, dof = np.zeros(unit.size), np.zeros(unit.size, dtype=np.int64)
    for a in range(0, unit.size, c):
        s = slice(a, a + c)
        pairs = _chunk_tests(problem, x, curves, unit[s], target[s], plots[s])
        d2[s], _, _, dof[s] = evaluate(pairs, dx, P, **options)
    return d2, dof


def lower_bounds(
    problem: FleetProblem, x: np.ndarray, curves: Curves, target: np.ndarray, plots: np.ndarray, P: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """(a lower bound of d^2 (C,), values compared (C,)) of the pairs (``target`` (C,), ``plots`` (C, k),
    -1 padding) under the estimate ``x`` and covariance ``P``, without forming ``D`` or ``S``: with the
    values whitened by the sensors' sigmas (W), ``d^2 >= |W r|^2 / tr(W S W)``, and the trace bounded
    by ``tr(W R W) + tr(W J_p cov J_p^T W) + lambda(C_b) |W A|_F^2 + lambda(P~) |W D diag(s)|_F^2``
    (``s`` the states' sigmas, ``P~`` their correlation matrix, ``lambda`` the largest eigenvalue),
    ``|W D diag(s)|_F <= sum_i s_i |W J_x,i| + |W A|_F |Y_b diag(s)|_F``. A pair whose bound is beyond
    its gate fails its test for certain: the clutter plots the single plots' tests meet, kilometres
    from every target, need neither the state columns of every window nor the products with P."""
    n = problem.layout.n
    s = np.sqrt(np.clip(np.diag(P), 0.0, None))
    inv_s = np.divide(1.0, s, out=np.zeros_like(s), where=s > 0)
    lam_P = max(float(np.linalg.eigvalsh(P * inv_s[:, None] * inv_s[None, :])[-1]), 0.0)
    s_all = np.append(s, 0.0)  # column n: no state
    y_norm, lam_C = np.zeros(0), np.zeros(0)
    if curves.V_inv.size:
        y_norm = np.sqrt(((curves.Y_states * s_all) ** 2).sum(axis=(1, 2)))
        lam_C = np.maximum(np.linalg.eigvalsh(curves.V_inv)[:, -1], 0.0)
    c, k = plots.shape
    bound, dof = np.zeros(c), np.zeros(c, dtype=np.int64)
    step = max(1, PREDICT_ROWS // k)
    for a in range(0, c, step):
        sl = slice(a, a + step)
        flat, mask, res, J, cols, block, A, cov = _predicted(problem, x, curves, target[sl], plots[sl])
        sigma = np.nan_to_num(problem.sensor_sigma[problem.sensor[flat]], nan=1.0)
        w = np.where(mask, 1.0 / sigma, 0.0)
        Jp = J[:, :, :3] * w[:, :, None]
        wr2 = ((res * w) ** 2).sum(axis=1)
        wa = np.sqrt(((Jp @ A) ** 2).sum(axis=(1, 2)))
        own = np.einsum("mij,mjk,mik->m", Jp, cov, Jp) + 3.0  # W R W: 1 per channel (1 where not measured)
        jx_norm = np.sqrt(((J[:, :, 3:] * w[:, :, None]) ** 2).sum(axis=1))  # (m, w) per state column
        jx = (jx_norm * s_all[np.where(cols < 0, n, cols)]).sum(axis=1)
        win = block >= 0
        lc, yn = np.zeros(flat.size), np.zeros(flat.size)
        lc[win], yn[win] = lam_C[block[win]], y_norm[block[win]]
        trace = own + lc * wa**2 + lam_P * (jx + wa * yn) ** 2
        rows = flat.size // k
        bound[sl] = wr2.reshape(rows, k).sum(axis=1) / trace.reshape(rows, k).sum(axis=1)
        dof[sl] = mask.reshape(rows, 3 * k).sum(axis=1)
    return bound, dof


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
