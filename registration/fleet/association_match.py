"""Second association stage: tracklets of different sensors that are the same target, per time
window, under the current registration estimate and its covariance; then the windows' groups
chained into targets.

A tracklet is one sensor track's plots in one window of ``window_s`` seconds (the windows are a
common grid, the same for every sensor). Its plots, corrected by the estimate ``x``, are fitted by
a straight line in ECEF, ``p(t) = a + b tau`` (tau = (t - centre) / half-width), weighted by each
plot's position information (:mod:`registration.fleet.association_geometry`); the fit gives the
line's covariance C and its sensitivity G = d(a, b) / dx to the registration states.

In each window the sensors are taken in turn, those measuring the most channels first; the first
one's tracklets open groups and each next sensor's tracklets are assigned to the groups (a global
assignment, :class:`~registration.fleet.association_geometry.Assigner`) with the cost

    0.5 (d^T S^-1 d + log det S),  d = line_b - line_group,
    S = C_b + C_group + (G_b - G_group) P (G_b - G_group)^T,

the negative log-likelihood (up to a constant) of the two lines being the same target's, with the
registration covariance P carried through both sides' sensitivities (errors shared by both
sides cancel). Gate: chi-square with 6 degrees of freedom at ``gate_probability``; a tracklet
outside every gate opens a group. A group's line is the information-weighted fusion of its
members that measure the most channels.

Groups of consecutive windows are chained where they share sensor tracks (an assignment that
maximises the shared tracks), and a chain is one target.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.stats import chi2

from registration.fleet.association_cost import line_cost, measurement_cost
from registration.fleet.association_geometry import N_COEF, N_LINE, Assigner, PlotGeometry, state_columns
from registration.fleet.problem import FleetProblem

__all__ = ["Tracklets", "make_tracklets", "group_tracklets", "chain_groups"]


@dataclass(frozen=True)
class Tracklets:
    """Per tracklet (T,): ``track`` id, ``window`` index, ``sensor`` index, ``line`` (T, 9) =
    (a, b, c) m, ``cov`` (T, 9, 9), ``G`` (T, 9, n) d line / d states; ``rep`` (T, 3): its first,
    middle and last plot; ``of_plot`` (N,): the tracklet of each plot, -1 for none."""

    track: np.ndarray
    window: np.ndarray
    sensor: np.ndarray
    line: np.ndarray
    cov: np.ndarray
    G: np.ndarray
    rep: np.ndarray
    rep_tau: np.ndarray
    of_plot: np.ndarray


def make_tracklets(problem: FleetProblem, geom: PlotGeometry, track: np.ndarray, window_s: float,
                   min_plots: int) -> Tracklets:
    """Cut the sensor tracks ``track`` (N,) into windows and fit each piece (module docstring)."""
    n = problem.layout.n
    window = np.floor(problem.time / window_s).astype(np.int64)
    in_track = np.flatnonzero(track >= 0)
    order = in_track[np.lexsort((window[in_track], track[in_track]))]
    key_t, key_w = track[order], window[order]
    start = np.flatnonzero(np.r_[True, (key_t[1:] != key_t[:-1]) | (key_w[1:] != key_w[:-1])])
    count = np.diff(np.r_[start, order.size])
    tau = (problem.time[order] - (key_w + 0.5) * window_s) / (0.5 * window_s)
    info = geom.info[order]
    basis = tau[:, None] ** np.arange(N_COEF)[None, :]  # (M, K): 1, tau, tau^2
    outer = basis[:, :, None] * basis[:, None, :]  # (M, K, K)
    N = np.einsum("mab,mij->maibj", outer, info).reshape(-1, N_LINE, N_LINE)
    Ip = (info @ geom.p_ecef[order][..., None])[..., 0]
    rhs = (basis[:, :, None] * Ip[:, None, :]).reshape(-1, N_LINE)
    ID = info @ geom.dp_dx[order]  # (M, 3, 6)
    sens = (basis[:, :, None, None] * ID[:, None]).reshape(-1, N_LINE, 6)
    N, rhs, sens = (np.add.reduceat(v, start, axis=0) for v in (N, rhs, sens))
    keep = count >= min_plots
    cov = np.linalg.inv(N[keep])
    line = (cov @ rhs[keep][..., None])[..., 0]
    local = cov @ sens[keep]  # (T, L, 6) over the plot's state columns
    cols = state_columns(problem)[order[start[keep]]]
    G = np.zeros((int(keep.sum()), N_LINE, n + 1))
    rows = np.arange(cols.shape[0])[:, None]
    for k in range(6):
        G[rows[:, 0], :, cols[:, k]] += local[:, :, k]  # column -1 (absent channel) lands in the spare
    tracklet_of_piece = np.where(keep, np.cumsum(keep) - 1, -1)
    of_plot = np.full(problem.n_plots, -1, dtype=np.int64)
    of_plot[order] = np.repeat(tracklet_of_piece, count)
    first, last = start[keep], start[keep] + count[keep] - 1
    at = np.stack([first, (first + last) // 2, last], axis=1)
    return Tracklets(key_t[first], key_w[first], problem.sensor[order[first]], line, cov, G[:, :, :n], order[at],
                     tau[at], of_plot)


class _Groups:
    """The groups of one window: fused information, information-weighted line and sensitivity."""

    def __init__(self, n: int):
        self.N = np.zeros((0, N_LINE, N_LINE))
        self.h = np.zeros((0, N_LINE))
        self.NG = np.zeros((0, N_LINE, n))
        self.rank = np.zeros(0, dtype=np.int64)

    def line(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        cov = np.linalg.inv(self.N)
        return (cov @ self.h[..., None])[..., 0], cov, cov @ self.NG

    def add(self, g: np.ndarray, tl: Tracklets, b: np.ndarray, rank: int) -> None:
        """Fuse tracklets ``b`` into groups ``g`` (only into groups of the same rank)."""
        fuse = self.rank[g] == rank
        g, b = g[fuse], b[fuse]
        Nb = np.linalg.inv(tl.cov[b])
        self.N[g] += Nb
        self.h[g] += (Nb @ tl.line[b][..., None])[..., 0]
        self.NG[g] += Nb @ tl.G[b]

    def open(self, tl: Tracklets, b: np.ndarray, rank: int) -> np.ndarray:
        Nb = np.linalg.inv(tl.cov[b])
        first = self.N.shape[0]
        self.N = np.concatenate([self.N, Nb])
        self.h = np.concatenate([self.h, (Nb @ tl.line[b][..., None])[..., 0]])
        self.NG = np.concatenate([self.NG, Nb @ tl.G[b]])
        self.rank = np.r_[self.rank, np.full(b.size, rank)]
        return first + np.arange(b.size)


def _window_groups(problem: FleetProblem, x: np.ndarray, tl: Tracklets, members: np.ndarray, P: np.ndarray,
                   gate_probability: float, assigner: Assigner) -> np.ndarray:
    """Group index (within the window) of each tracklet ``members`` of one window."""
    rank = (problem.layout.bias_index >= 0).sum(axis=1)
    groups = _Groups(P.shape[0])
    out = np.full(members.size, -1, dtype=np.int64)
    for s in np.lexsort((np.arange(rank.size), -rank)):
        mine = np.flatnonzero(tl.sensor[members] == s)
        if mine.size == 0:
            continue
        b = members[mine]
        g = np.full(b.size, -1, dtype=np.int64)
        if groups.N.shape[0]:
            line, cov, G = groups.line()
            if rank[s] == 3:
                (d2, logdet), dof = line_cost(tl, b, line, cov, G, P), N_LINE
            else:
                (d2, logdet), dof = measurement_cost(problem, x, tl, b, line, cov, G, P), 3 * int(rank[s])
            gate = float(chi2.ppf(gate_probability, dof))
            cost = np.where(d2 < gate, 0.5 * (d2 + logdet), np.inf)
            g = assigner.assign(cost, 0.5 * (gate + logdet.min(axis=1)))
        matched = g >= 0
        groups.add(g[matched], tl, b[matched], int(rank[s]))
        out[mine[matched]] = g[matched]
        out[mine[~matched]] = groups.open(tl, b[~matched], int(rank[s]))
    return out


def group_tracklets(problem: FleetProblem, x: np.ndarray, tl: Tracklets, P: np.ndarray, gate_probability: float,
                    assigner: Assigner) -> np.ndarray:
    """(T,) group id of each tracklet (unique over all windows), under the estimate ``x`` (n,) and
    its covariance ``P`` (n, n)."""
    group = np.full(tl.track.size, -1, dtype=np.int64)
    order = np.argsort(tl.window, kind="stable")
    bounds = np.flatnonzero(np.r_[True, tl.window[order][1:] != tl.window[order][:-1], True])
    offset = 0
    for a, b in zip(bounds[:-1], bounds[1:]):
        members = order[a:b]
        g = _window_groups(problem, x, tl, members, P, gate_probability, assigner)
        group[members] = offset + g
        offset += int(g.max()) + 1
    return group


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
