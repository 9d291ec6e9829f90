"""The target model of the batch solver: each target's track cut into time windows, the position
in each window a polynomial in time (docs/background/fleet-model.md, "Asynchronous sensors").

Window ``b`` of target ``j`` spans ``[t0, t1]``; with ``tau = (t - centre) / half`` in [-1, 1] the
position is ``p(t) = sum_k P_k(tau) c_bk`` (Legendre polynomials P_0..P_d, c_bk in ECEF m), so
a window is a block of ``3 (d + 1)`` nuisance parameters: the small blocks that the Schur
complement eliminates. A window whose plots and full reference positions fall at fewer than
``d + 1`` distinct instants gets the degree those instants can carry (the unused coefficients
are masked; degrees 1 to 3 share the cubic's four coefficients, the higher ones masked).
``window_s = 0`` makes one block per distinct (target, time) with degree 0: the target position
at every instant where it is measured (synchronous sensors).

Plots are ordered by (block, sensor); a *group* is the plots of one sensor in one block. The
coupling of a block with the registration states is held per group (a ``3 (d + 1) x w`` matrix
over the sensor's ``w`` states: its platform's three attitude errors and its three biases, and
with the extended errors its range gain, time bias and position errors, ``w = 11``;
:meth:`~registration.fleet.data.layout.StateLayout.sensor_states`). For the Schur complement the
groups of a block are laid side by side (``group_rank``, ``local_state``), so each block's
coupling is one dense ``3 (d + 1) x w g`` matrix (g = the most groups in any block).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.polynomial import legendre

from registration.fleet.batch.chunks import ChunkLayout, chunk_layout
from registration.fleet.data.layout import ATTITUDE_COLUMNS, BIAS_COLUMNS, ECCENTRICITY_COLUMNS
from registration.fleet.data.problem import FleetProblem

__all__ = [
    "Blocks",
    "make_blocks",
    "unique_rows",
    "used_state_columns",
    "row_columns",
    "ECC3_COLUMNS",
    "legendre_basis",
    "legendre_basis_rate",
    "target_spans",
    "window_grid",
    "window_of",
]

#: The columns of layout.sensor_states of the eccentric rows without the extended errors
#: (``fleet_rows_ecc3_<n>``): the attitude errors, the biases and the eccentricity terms.
ECC3_COLUMNS = np.r_[ATTITUDE_COLUMNS, BIAS_COLUMNS, ECCENTRICITY_COLUMNS]
#: Two reference/plot times closer than this (s) are the same instant (window_s = 0).
SAME_INSTANT_S = 1e-6


def legendre_basis(tau: np.ndarray, n: int) -> np.ndarray:
    """(N, n) values of P_0..P_{n-1} at tau."""
    return legendre.legvander(tau, n - 1)


def legendre_basis_rate(tau: np.ndarray, n: int) -> np.ndarray:
    """(N, n) derivatives d P_k / d tau of P_0..P_{n-1} at tau."""
    if n == 1:
        return np.zeros((np.size(tau), 1))
    D = np.stack([legendre.legder(e) for e in np.eye(n)], axis=1)  # (n - 1, n): P_k' in P_0..P_{n-2}
    return legendre.legvander(tau, n - 2) @ D


@dataclass(frozen=True, kw_only=True)
class Blocks:
    """The block structure (plots in ``order``, i.e. sorted by block then sensor)."""

    n_coef: int  # d + 1
    order: np.ndarray  # (N,) plot indices of the problem, sorted by (block, sensor)
    block: np.ndarray  # (N,) block of each sorted plot
    basis: np.ndarray  # (N, n_coef) masked Legendre values of each sorted plot
    block_start: np.ndarray  # (B,) first sorted plot of each block
    block_target: np.ndarray  # (B,) target index
    block_centre: np.ndarray  # (B,) s
    block_half: np.ndarray  # (B,) s
    coef_mask: np.ndarray  # (B, n_coef) bool: coefficient used
    group_start: np.ndarray  # (G,) first sorted plot of each (block, sensor) group
    group_block: np.ndarray  # (G,)
    group_sensor: np.ndarray  # (G,)
    group_state: np.ndarray  # (G, w) state indices (layout.sensor_states, state_columns); n_state = none
    group_rank: np.ndarray  # (G,) position of the group among its block's groups
    local_state: np.ndarray  # (B, w max_groups) state indices of each block's groups (n = padding)
    group_block_start: np.ndarray  # (B,) first group of each block
    chunks: ChunkLayout  # the padded rows of the sorted plots, the groups cut into chunks
    ref_index: np.ndarray  # (R',) references used (index into problem.references)
    ref_block: np.ndarray  # (R',)
    ref_basis: np.ndarray  # (R', n_coef)
    patterns: np.ndarray  # (K, w max_groups) the distinct rows of local_state
    block_pattern: np.ndarray  # (B,) the pattern (row of patterns) of each block
    # states after the groups' in local_state, coupled to every block through the references (the
    # flight levels' height offset): 0 or 1
    extra_states: int = 0
    # (w,) the columns of layout.sensor_states that the generated rows hold (ECC3_COLUMNS: the
    # eccentric rows without the extended errors); None: all of them
    state_columns: np.ndarray | None = None
    # the columns of group_state that some sensor has a state in, the only ones coupled to the
    # blocks in the Schur complement (Normal.W, local_state; the others hold only the sink); None: all
    coupled: np.ndarray | None = None

    @property
    def n_blocks(self) -> int:
        return int(self.block_start.shape[0])

    @property
    def width(self) -> int:
        """States per group in the rows (6, or 11 with the extended errors, 13 with the
        eccentricity, 8 with the eccentricity alone)."""
        return int(self.group_state.shape[1])

    @property
    def coupled_width(self) -> int:
        """States per group coupled to the blocks (``width`` without the sink-only columns)."""
        return self.width if self.coupled is None else int(self.coupled.size)

    def basis_at(self, block: np.ndarray, time: np.ndarray) -> np.ndarray:
        """(M, n_coef) masked basis values of times ``time`` (s) in blocks ``block``."""
        tau = (time - self.block_centre[block]) / self.block_half[block]
        return legendre_basis(tau, self.n_coef) * self.coef_mask[block]

    def basis_and_rate_at(self, block: np.ndarray, time: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(basis, rate), each (M, n_coef) and masked: the basis values at times ``time`` (s) in
        blocks ``block`` and their time derivatives (1/s; a window's velocity is ``sum_k rate_k
        c_k``). Written out for P_0..P_3 (checked against numpy's Legendre series in the tests)."""
        if self.n_coef != 4:
            half = self.block_half[block]
            tau = (time - self.block_centre[block]) / half
            mask = self.coef_mask[block]
            return legendre_basis(tau, self.n_coef) * mask, legendre_basis_rate(
                tau, self.n_coef
            ) * mask / half[:, None]
        inv_half = 1.0 / self.block_half[block]
        tau = (time - self.block_centre[block]) * inv_half
        t2 = tau * tau
        mask = self.coef_mask[block]
        basis = np.stack([np.ones_like(tau), tau, 1.5 * t2 - 0.5, (2.5 * t2 - 1.5) * tau], axis=1)
        rate = np.stack(
            [np.zeros_like(tau), inv_half, 3.0 * tau * inv_half, (7.5 * t2 - 1.5) * inv_half], axis=1
        )
        return basis * mask, rate * mask


def target_spans(target: np.ndarray, time: np.ndarray, n_targets: int) -> tuple[np.ndarray, np.ndarray]:
    """(first, last) plot time (s) of each of ``n_targets`` targets (inf, -inf for a target without plots)."""
    t0 = np.full(n_targets, np.inf)
    t1 = np.full(n_targets, -np.inf)
    np.minimum.at(t0, target, time)
    np.maximum.at(t1, target, time)
    return t0, t1


def window_grid(t0: np.ndarray, t1: np.ndarray, window_s: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per target with plots from ``t0`` to ``t1`` (s): (number of windows, window length (s), first
    window key): the span cut into equal windows of at most ``window_s`` s."""
    span = t1 - t0
    count = np.maximum(1, np.ceil(span / window_s - 1e-9)).astype(np.int64)
    length = np.where(span > 0, span / count, 1.0)
    offset = np.concatenate([[0], np.cumsum(count)[:-1]])
    return count, length, offset


def window_of(
    t0: np.ndarray, count: np.ndarray, length: np.ndarray, target: np.ndarray, time: np.ndarray
) -> np.ndarray:
    """(M,) index of the window (0 .. count - 1 of its target) that time ``time`` (s) of target
    ``target`` falls in."""
    return np.clip(np.floor((time - t0[target]) / length[target]), 0, count[target] - 1).astype(np.int64)


def _window_keys(target, time, ref_target, ref_time, n_targets: int, window_s: float, span=None):
    """Window key of each plot and reference (-1: reference outside its target's plot span), and
    per target the first time t0 (s), window length (s) and first key. ``span``: (t0, t1) per
    target if given (the whole archive's, for a partition of it), else those of these plots."""
    t0, t1 = target_spans(target, time, n_targets) if span is None else span
    count, length, offset = window_grid(t0, t1, window_s)

    def keys(tg, t):
        return offset[tg] + window_of(t0, count, length, tg, t)

    inside = (ref_time >= t0[ref_target] - SAME_INSTANT_S) & (ref_time <= t1[ref_target] + SAME_INSTANT_S)
    return keys(target, time), np.where(inside, keys(ref_target, ref_time), -1), t0, length, offset


def _instant_keys(target, time, ref_target, ref_time):
    """One key per distinct (target, time) instant (window_s = 0), shared by plots and references."""
    tg = np.r_[target, ref_target].astype(np.int64)
    rounded = np.round(np.r_[time, ref_time] / SAME_INSTANT_S).astype(np.int64)
    order = np.lexsort((rounded, tg))
    new = np.r_[True, (np.diff(tg[order]) != 0) | (np.diff(rounded[order]) != 0)]
    key = np.empty(tg.size, dtype=np.int64)
    key[order] = np.cumsum(new) - 1
    return key[: time.size], key[time.size :]


def _block_geometry(problem: FleetProblem, window_s: float, degree: int, span=None):
    """Block of each plot and reference (-1: none), and per block: target, centre, half-width, degree."""
    target, time = problem.target, problem.time
    ref_target, ref_time = problem.ref_target, problem.references.time
    if window_s == 0:
        key, ref_key = _instant_keys(target, time, ref_target, ref_time)
    else:
        key, ref_key, t0, length, offset = _window_keys(
            target, time, ref_target, ref_time, len(problem.target_ids), window_s, span
        )
    uniq, block = np.unique(key, return_inverse=True)
    pos = np.clip(np.searchsorted(uniq, ref_key), 0, uniq.size - 1)
    ref_block = np.where(uniq[pos] == ref_key, pos, -1)
    first = np.zeros(uniq.size, dtype=np.int64)
    first[block[::-1]] = np.arange(time.size)[::-1]
    if window_s == 0:
        return (
            block,
            ref_block,
            target[first],
            time[first],
            np.ones(uniq.size),
            np.zeros(uniq.size, dtype=np.int64),
        )
    b_target = target[first]
    w = uniq - offset[b_target]
    centre = t0[b_target] + (w + 0.5) * length[b_target]
    # the instants of the window's plots and of its full reference positions (a height alone
    # fixes one axis only): a window whose plots miss scans but whose target reports its position
    # every second keeps its cubic, else a constant over the window misfits those reports by km
    full = (ref_block >= 0) & np.isfinite(problem.references.sigma)
    b_all = np.r_[block, ref_block[full]]
    ticks = np.round(np.r_[time, ref_time[full]] / SAME_INSTANT_S).astype(np.int64)
    order = np.lexsort((ticks, b_all))
    first_of_instant = np.r_[True, (np.diff(b_all[order]) != 0) | (np.diff(ticks[order]) != 0)]
    n_times = np.bincount(b_all[order][first_of_instant], minlength=uniq.size)
    return block, ref_block, b_target, centre, 0.5 * length[b_target], np.minimum(degree, n_times - 1)


def unique_rows(a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(the distinct rows of ``a`` (R, L) in lexicographic order (K, L), the row of each row of ``a``
    among them (R,)): ``np.unique(a, axis=0, return_inverse=True)``, by one lexsort (np.unique on
    rows took a millisecond for a few hundred blocks, as much as a solver iteration's products)."""
    if a.shape[0] == 0:
        return a[:0], np.zeros(0, dtype=np.int64)
    order = np.lexsort(a.T[::-1])
    s = a[order]
    new = np.r_[True, (s[1:] != s[:-1]).any(axis=1)]
    inverse = np.empty(a.shape[0], dtype=np.int64)
    inverse[order] = np.cumsum(new) - 1
    return s[new], inverse


def _local_states(group_block: np.ndarray, group_state: np.ndarray, n_blocks: int, n_state: int):
    """Each group's rank within its block and, per block, the state indices of its groups side by
    side (w per group, padded with the sink index ``n_state`` up to the largest block)."""
    n_in = np.bincount(group_block, minlength=n_blocks)
    first_group = np.r_[0, np.cumsum(n_in)[:-1]]
    rank = np.arange(group_block.size) - first_group[group_block]
    local = np.full(
        (n_blocks, max(int(n_in.max(initial=1)), 1), group_state.shape[1]), n_state, dtype=np.int64
    )
    local[group_block, rank] = group_state
    return rank, local.reshape(n_blocks, -1)


def used_state_columns(problem: FleetProblem) -> np.ndarray | None:
    """The columns of ``layout.sensor_states`` in which some sensor of ``problem`` has a state (the
    eccentric model's extended columns hold only the sink when no sensor has extended errors);
    None when every column has one."""
    layout = problem.layout
    every = layout.sensor_states(np.arange(len(problem.sensor_ids)), problem.sensor_platform)
    used = np.flatnonzero((every != layout.n).any(axis=0))
    return None if used.size == every.shape[1] else used


def row_columns(problem: FleetProblem) -> tuple[np.ndarray | None, np.ndarray | None]:
    """(Blocks.state_columns, Blocks.coupled) of ``problem``: the rows without the extended errors
    (ECC3_COLUMNS) when some sensor has an eccentricity and none has an extended error, and the
    columns among the rows' that some sensor has a state in (:func:`used_state_columns`)."""
    used = used_state_columns(problem)
    if used is None:
        return None, None
    rows = None
    if problem.layout.eccentric and np.isin(used, ECC3_COLUMNS).all():
        rows = ECC3_COLUMNS
    held = np.arange(problem.layout.width) if rows is None else rows
    coupled = np.searchsorted(held, used)
    return rows, None if coupled.size == held.size else coupled


def make_blocks(problem: FleetProblem, window_s: float, degree: int, span=None) -> Blocks:
    """The block structure of ``problem`` for windows of ``window_s`` s and polynomials of ``degree``.
    ``span``: (first, last) time (s) per target of ``problem.target_ids`` to cut the windows from
    (default: the problem's own plots; a partition of an archive gives the archive's, so that its
    windows are the archive's)."""
    block, ref_block, b_target, centre, half, b_degree = _block_geometry(problem, window_s, degree, span)
    n_blocks = centre.size
    order = np.lexsort((problem.sensor, block))
    block_sorted, sensor_sorted = block[order], problem.sensor[order]
    block_start = np.flatnonzero(np.r_[True, np.diff(block_sorted) != 0])
    change = np.r_[True, (np.diff(block_sorted) != 0) | (np.diff(sensor_sorted) != 0)]
    group_start = np.flatnonzero(change)
    group_block, group_sensor = block_sorted[group_start], sensor_sorted[group_start]
    layout = problem.layout
    columns, coupled = row_columns(problem)
    group_state = layout.sensor_states(group_sensor, problem.sensor_platform)
    if columns is not None:
        group_state = group_state[:, columns]
    n_coef = 1 if degree == 0 else 4  # the basis sizes of the generated rows functions
    coef_mask = np.arange(n_coef)[None, :] <= b_degree[:, None]
    tau = (problem.time[order] - centre[block_sorted]) / half[block_sorted]
    basis = legendre_basis(tau, n_coef) * coef_mask[block_sorted]
    rank, local_state = _local_states(
        group_block, group_state if coupled is None else group_state[:, coupled], n_blocks, layout.n
    )
    extra = int(layout.height_offset_index >= 0)
    if extra:  # the height offset, coupled to each block by its flight-level heights (Normal.H)
        local_state = np.column_stack([local_state, np.full(n_blocks, layout.height_offset_index)])
    ref_index = np.flatnonzero(ref_block >= 0)
    ref_block = ref_block[ref_index]
    ref_tau = (problem.references.time[ref_index] - centre[ref_block]) / half[ref_block]
    ref_basis = legendre_basis(ref_tau, n_coef) * coef_mask[ref_block]
    group_block_start = np.flatnonzero(np.r_[True, np.diff(group_block) != 0])
    patterns, inverse = unique_rows(local_state)
    return Blocks(
        n_coef=n_coef,
        order=order,
        block=block_sorted,
        basis=basis,
        block_start=block_start,
        block_target=b_target,
        block_centre=centre,
        block_half=half,
        coef_mask=coef_mask,
        group_start=group_start,
        group_block=group_block,
        group_sensor=group_sensor,
        group_state=group_state,
        group_rank=rank,
        local_state=local_state,
        group_block_start=group_block_start,
        chunks=chunk_layout(group_start, order.size),
        ref_index=ref_index,
        ref_block=ref_block,
        ref_basis=ref_basis,
        patterns=patterns,
        block_pattern=inverse,
        extra_states=extra,
        state_columns=columns,
        coupled=coupled,
    )
