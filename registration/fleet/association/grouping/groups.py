"""The groups of tracklets (:mod:`registration.fleet.association.grouping.match`): in every window at once,
sensor after sensor (those measuring the most channels first), each sensor's tracklets are
assigned to the window's groups by one global assignment per window, with the costs of
:mod:`registration.fleet.association.grouping.cost`; a tracklet outside every gate opens a group.

A group's curve is the information-weighted fusion of its members that measure the most channels
(a 2-D radar joining a group a 3-D radar opened does not move it: its plots have no height).
"""

from __future__ import annotations

import numpy as np

from registration.core.distributions import chi2_ppf
from registration.fleet.association.grouping.cost import (
    group_covariances,
    joint_covariance,
    line_cost,
    measurement_cost,
)
from registration.fleet.association.grouping.geometry import N_LINE, Assigner, state_columns
from registration.fleet.data.problem import FleetProblem

__all__ = ["group_tracklets"]

#: Pairs whose costs are computed in one batch (bounds the memory: about 10 kB per pair).
PAIR_CHUNK = 4096


class _Groups:
    """All windows' groups: window (G,), fused information N (G, L, L), N line (G, L), N G (G, L, n),
    rank (G,): the channels measured by the members whose plots are fused."""

    def __init__(self, n: int):
        self.window = np.zeros(0, dtype=np.int64)
        self.N = np.zeros((0, N_LINE, N_LINE))
        self.h = np.zeros((0, N_LINE))
        self.NG = np.zeros((0, N_LINE, n))
        self.rank = np.zeros(0, dtype=np.int64)

    def curves(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Each group's curve (G, L), its covariance (G, L, L) and sensitivity (G, L, n)."""
        cov = np.linalg.inv(self.N)
        return (cov @ self.h[..., None])[..., 0], cov, cov @ self.NG

    def add(self, g: np.ndarray, tl, b: np.ndarray, rank: int) -> None:
        """Fuse tracklets ``b`` into groups ``g`` (distinct; only into groups of the same rank)."""
        fuse = self.rank[g] == rank
        g, b = g[fuse], b[fuse]
        Nb = np.linalg.inv(tl.cov[b])
        self.N[g] += Nb
        self.h[g] += (Nb @ tl.line[b][..., None])[..., 0]
        self.NG[g] += Nb @ tl.G[b]

    def open(self, tl, b: np.ndarray, rank: int) -> np.ndarray:
        """New groups of tracklets ``b``; their indices."""
        Nb = np.linalg.inv(tl.cov[b])
        first = self.N.shape[0]
        self.window = np.r_[self.window, tl.window[b]]
        self.N = np.concatenate([self.N, Nb])
        self.h = np.concatenate([self.h, (Nb @ tl.line[b][..., None])[..., 0]])
        self.NG = np.concatenate([self.NG, Nb @ tl.G[b]])
        self.rank = np.r_[self.rank, np.full(b.size, rank)]
        return first + np.arange(b.size)


def _pairs(b_window: np.ndarray, g_window: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """All (tracklet, group) index pairs of the same window."""
    g_order = np.argsort(g_window, kind="stable")
    lo = np.searchsorted(g_window[g_order], b_window, side="left")
    hi = np.searchsorted(g_window[g_order], b_window, side="right")
    n = hi - lo
    bi = np.repeat(np.arange(b_window.size), n)
    offset = np.arange(bi.size) - np.repeat(np.cumsum(n) - n, n)
    return bi, g_order[np.repeat(lo, n) + offset]


def _costs(problem: FleetProblem, x, tl, b: np.ndarray, gi: np.ndarray, curves, P, full: bool):
    """(d2, logdet) of the pairs (tracklets ``b``, all of one sensor; groups ``gi``), in chunks."""
    line, cov, G = curves
    cols = state_columns(problem, tl.rep[b[:1], 0])[0]
    groups = group_covariances(cov, G, P, cols)
    if full:  # the tracklets' sensitivity to their sensor's w states, their only nonzero columns
        G_b = np.where(cols >= 0, tl.G[:, :, np.maximum(cols, 0)], 0.0)
    d2, logdet = np.empty(b.size), np.empty(b.size)
    for a in range(0, b.size, PAIR_CHUNK):
        s = slice(a, a + PAIR_CHUNK)
        g = gi[s]
        joint = joint_covariance(groups, g)
        if full:
            d2[s], logdet[s] = line_cost(tl, b[s], G_b[b[s]], line[g], joint)
        else:
            d2[s], logdet[s] = measurement_cost(problem, x, tl, b[s], cols, line[g], joint)
    return d2, logdet


def _assign_windows(
    b: np.ndarray,
    bi: np.ndarray,
    gi: np.ndarray,
    cost: np.ndarray,
    no_match: np.ndarray,
    window: np.ndarray,
    assigner: Assigner,
) -> np.ndarray:
    """(B,) the group given to each tracklet ``b`` (-1: none), one assignment per window."""
    out = np.full(b.size, -1, dtype=np.int64)
    pair_window = window[bi]
    order = np.argsort(pair_window, kind="stable")
    bounds = np.flatnonzero(np.r_[True, pair_window[order][1:] != pair_window[order][:-1], True])
    for lo, hi in zip(bounds[:-1], bounds[1:]):
        sel = order[lo:hi]
        rows, r_idx = np.unique(bi[sel], return_inverse=True)
        cols, c_idx = np.unique(gi[sel], return_inverse=True)
        matrix = np.full((rows.size, cols.size), np.inf)
        matrix[r_idx, c_idx] = cost[sel]
        col = assigner.assign(matrix, no_match[rows])
        ok = col >= 0
        out[rows[ok]] = cols[col[ok]]
    return out


def group_tracklets(
    problem: FleetProblem, x: np.ndarray, tl, P: np.ndarray, gate_probability: float, assigner: Assigner
) -> np.ndarray:
    """(T,) group id of each tracklet (unique over all windows), under the estimate ``x`` (n,) and
    its covariance ``P`` (n, n)."""
    rank = (problem.layout.bias_index >= 0).sum(axis=1)
    groups = _Groups(P.shape[0])
    group = np.full(tl.track.size, -1, dtype=np.int64)
    for s in np.lexsort((np.arange(rank.size), -rank)):
        b = np.flatnonzero(tl.sensor == s)
        if b.size == 0:
            continue
        bi, gi = _pairs(tl.window[b], groups.window)
        g = np.full(b.size, -1, dtype=np.int64)
        if bi.size:
            full = bool(rank[s] == 3)
            d2, logdet = _costs(problem, x, tl, b[bi], gi, groups.curves(), P, full)
            gate = float(chi2_ppf(gate_probability, N_LINE if full else 3 * int(rank[s])))
            cost = np.where(d2 < gate, 0.5 * (d2 + logdet), np.inf)
            best = np.full(b.size, np.inf)
            np.minimum.at(best, bi, logdet)
            g = _assign_windows(b, bi, gi, cost, 0.5 * (gate + best), tl.window[b], assigner)
        matched = g >= 0
        groups.add(g[matched], tl, b[matched], int(rank[s]))
        group[b[matched]] = g[matched]
        group[b[~matched]] = groups.open(tl, b[~matched], int(rank[s]))
    return group
