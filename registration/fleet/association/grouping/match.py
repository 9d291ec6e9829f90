"""Second association stage: the tracklets, and the chaining of the windows' groups into targets.

A tracklet is one sensor track's plots in one window of ``window_s`` seconds (the windows are a
common grid, the same for every sensor). Its plots, corrected by the estimate ``x``, are fitted by
a quadratic in time in ECEF, ``p(t) = a + b tau + c tau^2`` (tau = (t - centre) / half-width;
a straight line would miss a 3 km turn at 160 m/s by 100 m over 20 s), weighted by each plot's
position information (:mod:`registration.fleet.association.grouping.geometry`); the fit gives the curve's
covariance C and its sensitivity G = d(a, b, c) / dx to the registration states. The grouping of
the tracklets across sensors, window by window, is :mod:`registration.fleet.association.grouping.groups`.

Groups of consecutive windows are chained where they share sensor tracks (an assignment that
maximises the shared tracks), and a chain is one target.

Time: a plot's time here is the time its target was seen, the reported time minus its sensor's
estimated time bias (:attr:`PlotGeometry.time`; the reported time when no sensor has one), so
the windows and tau are on one time axis for all sensors. With a time bias ``dt`` a plot's
sensitivity has two parts. Its position moves with the platform's motion (the plot geometry's
column). Its time stamp ``t - dt`` moves too, by ``-d(dt)``: the tracklet's curve, fitted to
samples all shifted by the same amount, is its own curve shifted in time, ``p(tau + d(dt) / h)``
(h the half-width), so the curve's sensitivity to ``dt`` gains the curve's derivative,
``(b, 2c, 0) / h`` in the coefficients ``(a, b, c)``: the target's own motion, which the tracklet
carries and the single plot cannot.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.core.distributions import chi2_ppf
from registration.fleet.association.grouping.geometry import (
    N_COEF,
    N_LINE,
    TIME_BIAS_SLOT,
    Assigner,
    PlotGeometry,
    state_columns,
)
from registration.fleet.data.problem import FleetProblem

__all__ = ["Tracklets", "make_tracklets", "chain_groups", "time_shift_sensitivity"]


@dataclass(frozen=True)
class Tracklets:
    """Per tracklet (T,): ``track`` id, ``window`` index, ``sensor`` index, ``line`` (T, 9) =
    (a, b, c) m, ``cov`` (T, 9, 9), ``G`` (T, 9, n) d line / d states; ``rep`` (T, 3): its first,
    middle and last plot, ``rep_tau`` (T, 3) their tau, ``rep_nav`` (T, 3, 6) and ``rep_rate``
    (T, 3, 6) their platform's navigation (rad, m) and its rate (rad/s, m/s) at the time they were
    seen; ``of_plot`` (N,): the tracklet of each plot, -1 for none; ``half_width`` (s) of the
    windows (tau = (t - centre) / half_width)."""

    track: np.ndarray
    window: np.ndarray
    sensor: np.ndarray
    line: np.ndarray
    cov: np.ndarray
    G: np.ndarray
    rep: np.ndarray
    rep_tau: np.ndarray
    of_plot: np.ndarray
    rep_nav: np.ndarray
    rep_rate: np.ndarray
    half_width: float


def _piece_starts(track: np.ndarray, window: np.ndarray) -> np.ndarray:
    """Where each (track, window) piece starts in plots sorted by track and window."""
    if track.size == 0:
        return np.zeros(0, dtype=np.int64)
    return np.flatnonzero(np.r_[True, (track[1:] != track[:-1]) | (window[1:] != window[:-1])])


def _fit_pieces(geom: PlotGeometry, order: np.ndarray, start: np.ndarray, tau: np.ndarray):
    """Information-weighted quadratic fit of each piece (plots ``order`` split at ``start``):
    (coefficients (K, L), covariance (K, L, L), sensitivity (K, L, w) to the plots' w states
    (the plot geometry's columns only), fit chi-square (K,))."""
    at = geom.rows(order)
    info = geom.info[at]
    power = tau[:, None] ** np.arange(2 * N_COEF - 1)[None, :]  # (M, 5): 1, tau, ..., tau^4
    basis = power[:, :N_COEF]  # (M, C): 1, tau, tau^2
    # N = sum over plots of kron(basis basis^T, info): sum tau^k info per piece first, then place
    # the sums in the blocks (a, b) with a + b = k
    moments = np.add.reduceat(power[:, :, None, None] * info[:, None], start, axis=0)  # (K, 5, 3, 3)
    a, b = np.divmod(np.arange(N_COEF * N_COEF), N_COEF)
    N = (
        moments[:, a + b]
        .reshape(-1, N_COEF, N_COEF, 3, 3)
        .transpose(0, 1, 3, 2, 4)
        .reshape(-1, N_LINE, N_LINE)
    )
    p = geom.p_ecef[at]
    rhs = (basis[:, :, None] * (info @ p[..., None])[..., 0][:, None, :]).reshape(-1, N_LINE)
    sens = (basis[:, :, None, None] * (info @ geom.dp_dx[at])[:, None]).reshape(
        -1, N_LINE, geom.dp_dx.shape[2]
    )
    rhs, sens = (np.add.reduceat(v, start, axis=0) for v in (rhs, sens))
    cov = np.linalg.inv(N)
    line = (cov @ rhs[..., None])[..., 0]
    piece = np.cumsum(np.isin(np.arange(order.size), start)) - 1
    fitted = np.einsum("mc,mci->mi", basis, line[piece].reshape(-1, N_COEF, 3))
    v = p - fitted
    chi = np.add.reduceat(np.einsum("mi,mij,mj->m", v, info, v), start)
    return line, cov, cov @ sens, chi


def make_tracklets(
    problem: FleetProblem,
    geom: PlotGeometry,
    track: np.ndarray,
    window_s: float,
    min_plots: int,
    gate_probability: float | None,
) -> Tracklets:
    """Cut the sensor tracks ``track`` (N,) into windows and fit each piece (module docstring);
    ``geom`` covers at least the plots in a track.
    Pieces of fewer than ``min_plots`` plots are left out, and, when ``gate_probability`` is given,
    pieces no quadratic fits (chi-square of the fit, from the sensor noise alone, above that
    quantile: mostly a track that swapped targets where two crossed). The test ignores the
    registration's uncertainty, so it is only meaningful once the estimate is close: an angle
    bias in a rolling deck frame moves the plots back and forth with the roll (a 5 deg bias under
    4 deg of roll: about 0.35 deg), which no quadratic follows. Only pieces of sensors measuring
    all three channels are tested: the deck-plane positions of a 2-D radar's plots wobble with the
    roll whatever the estimate."""
    n = problem.layout.n
    seen = problem.time.copy()
    seen[geom.plots] = geom.time  # the time each plot was seen (module docstring)
    window = np.floor(seen / window_s).astype(np.int64)
    in_track = np.flatnonzero(track >= 0)
    order = in_track[np.lexsort((window[in_track], track[in_track]))]
    start = _piece_starts(track[order], window[order])
    count = np.diff(np.r_[start, order.size])
    order = order[np.repeat(count >= min_plots, count)]  # pieces long enough (a quadratic needs 3 scans)
    key_t, key_w = track[order], window[order]
    start = _piece_starts(key_t, key_w)
    count = np.diff(np.r_[start, order.size])
    tau = (seen[order] - (key_w + 0.5) * window_s) / (0.5 * window_s)
    line, cov, local, chi = _fit_pieces(geom, order, start, tau)
    values = np.add.reduceat(problem.mask[order].sum(axis=1), start)
    dof = values - N_LINE
    keep = np.ones(start.size, dtype=bool)
    full = problem.mask[order[start]].all(axis=1)  # a 2-D radar's deck-plane positions wobble with the roll
    if gate_probability is not None:
        keep &= ~full | (dof < 1) | (chi < chi2_ppf(gate_probability, np.maximum(dof, 1)))
    line, cov, local = line[keep], cov[keep], local[keep]
    cols = state_columns(problem, order[start[keep]])
    if cols.shape[1] > TIME_BIAS_SLOT:  # the time stamps move with the time bias: the curve's own motion
        local[:, :, TIME_BIAS_SLOT] += time_shift_sensitivity(line, 0.5 * window_s)
    G = np.zeros((int(keep.sum()), N_LINE, n + 1))
    rows = np.arange(cols.shape[0])
    for k in range(cols.shape[1]):
        G[rows, :, cols[:, k]] += local[:, :, k]  # column -1 (absent channel) lands in the spare
    tracklet_of_piece = np.where(keep, np.cumsum(keep) - 1, -1)
    of_plot = np.full(problem.n_plots, -1, dtype=np.int64)
    of_plot[order] = np.repeat(tracklet_of_piece, count)
    first, last = start[keep], start[keep] + count[keep] - 1
    at = np.stack([first, (first + last) // 2, last], axis=1)
    rep_rows = geom.rows(order[at])
    return Tracklets(
        key_t[first],
        key_w[first],
        problem.sensor[order[first]],
        line,
        cov,
        G[:, :, :n],
        order[at],
        tau[at],
        of_plot,
        geom.nav[rep_rows],
        geom.rate[rep_rows],
        0.5 * window_s,
    )


def time_shift_sensitivity(line: np.ndarray, half_width: float) -> np.ndarray:
    """(K, 9) d line / d(time bias) of quadratics ``line`` (K, 9) = (a, b, c) m whose samples are
    stamped at the reported time minus the time bias: (b, 2c, 0) / ``half_width`` (m/s), the
    curve's motion (module docstring)."""
    out = np.zeros_like(line)
    out[:, :6] = np.concatenate([line[:, 3:6], 2.0 * line[:, 6:9]], axis=1) / half_width
    return out


def chain_groups(tl: Tracklets, group: np.ndarray, assigner: Assigner) -> np.ndarray:
    """(G,) chain id of each group: groups of consecutive windows sharing the most sensor tracks
    are chained (one-to-one, at least one shared track)."""
    n_groups = int(group.max()) + 1 if group.size else 0
    chain = np.arange(n_groups)
    windows = np.unique(tl.window)
    for w0, w1 in zip(windows[:-1], windows[1:]):
        if w1 != w0 + 1:
            continue
        a, b = np.flatnonzero(tl.window == w0), np.flatnonzero(tl.window == w1)
        shared = np.intersect1d(tl.track[a], tl.track[b])
        if shared.size == 0:
            continue
        ga, gb = np.unique(group[a]), np.unique(group[b])
        count = np.zeros((ga.size, gb.size))
        ia = group[a][np.isin(tl.track[a], shared)]
        ib = group[b][np.isin(tl.track[b], shared)]
        ta = tl.track[a][np.isin(tl.track[a], shared)]
        tb = tl.track[b][np.isin(tl.track[b], shared)]
        ia, ib = ia[np.argsort(ta)], ib[np.argsort(tb)]
        np.add.at(count, (np.searchsorted(ga, ia), np.searchsorted(gb, ib)), 1.0)
        col = assigner.assign(np.where(count > 0, -count, np.inf), np.zeros(ga.size))
        linked = np.flatnonzero(col >= 0)
        chain[gb[col[linked]]] = chain[ga[linked]]
    return chain
