"""An archive of fleet tables cut into partitions for the partitioned batch solver
(:mod:`registration.fleet.batch.partitioned.estimate`, docs/howto/register-an-archive.md).

The target windows are the whole archive's (:mod:`registration.fleet.batch.blocks`: each target's
plotted time span cut into equal windows), so a first pass over the plots (time, sensor and target
columns only) finds each target's span, the targets seen by one sensor only (set aside as
:func:`~registration.fleet.data.problem.build_problem` does) and the time range of every window.
A partition is the windows whose *start* time (s) lies in ``[cuts[k-1], cuts[k])``: every window
lies entirely in one partition, so each window's normal equations are complete inside it. Its plots
are read by time range (the windows' span, with a slack of SLACK_S) and kept when their window is
the partition's, so every plot is in exactly one partition whatever the cuts.

Navigation is read by partition too: per platform the rows from NAV_EXTRA_SAMPLES samples before
``start - margin`` to as many after ``end + margin`` (a pass over the navigation's platform and
time columns finds those times), so the linear and Hermite interpolations at the partition's plot
times, also when a time bias of up to ``margin`` seconds moves them, use the same samples as with
the whole table.

The references are read by partition too; the pass that finds the reference targets also reads
their ``height_offset_prior`` column: when some rows carry it (flight levels' heights sharing one
unknown offset, :mod:`registration.fleet.data.known_targets`), the state
``flight_levels:height_offset`` is in every partition's layout, coupled to the windows of the
partitions whose heights carry it, and its prior is added once, with the other priors.

A *source* gives the tables (:class:`registration.fleet.data.source.FleetSource`): the tables in
memory (SI units, :class:`registration.io.fleet.memory.TablesSource`) or an archive read lazily
(:class:`registration.io.fleet.archive.parquet.ParquetSource`). Its methods:
``plot_batches(columns)``, ``navigation_batches(columns)``, ``reference_batches(columns)``
(iterators of column dicts: numpy arrays, ids also as ``pandas.Categorical``; a column the
table does not have is left out),
``read_plots(lo, hi)``, ``read_navigation(ranges)``, ``read_references(lo, hi)`` (rows with
``lo <= time <= hi``; ranges: platform -> (first, last) time), ``sensors``, ``platforms`` (small
tables), ``token`` (a string naming the data, for caches) and ``name(table)`` (what errors call
the table: its file).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fleet.batch.blocks import window_grid, window_of
from registration.fleet.data.problem import Exclusion

__all__ = [
    "DEFAULT_NAV_MARGIN_S",
    "NAV_EXTRA_SAMPLES",
    "SINGLE_SENSOR",
    "SLACK_S",
    "ArchivePlan",
    "make_plan",
    "navigation_ranges",
    "partition_of",
    "window_index",
]

#: Plots are read this far (s) beyond a partition's windows, so rounding cannot lose one.
SLACK_S = 1e-3
#: Navigation samples read beyond the margin on each side (the Hermite slopes use two neighbours).
NAV_EXTRA_SAMPLES = 3
#: Navigation read beyond a partition's plots (s): the largest time bias it can follow exactly.
DEFAULT_NAV_MARGIN_S = 60.0
#: Why a target seen by one sensor only is set aside (the text of build_problem).
SINGLE_SENSOR = (
    "seen by one sensor only and not a reference: its plots fit any registration errors, so they "
    "carry no registration information"
)


@dataclass(frozen=True, kw_only=True)
class ArchivePlan:
    """The archive's targets, windows and partitions (module docstring).

    ``target_ids`` the targets kept (order of first appearance), with ``t0``, ``t1`` their first
    and last plot times (s); ``all_targets`` every target id (references may name any of them);
    ``excluded`` the targets set aside; ``cuts`` (P - 1,) s the partitions' boundaries on the
    windows' start times; ``plot_ranges`` (P, 2) s the time range each partition's plots are read
    from (NaN: the partition holds no window); ``nav_ranges`` per partition, platform -> (first,
    last) navigation time (s) to read; ``height_offset_prior`` the prior sigma (m) of the flight
    levels' common height offset (module docstring).
    """

    window_s: float
    target_ids: tuple[str, ...]
    all_targets: tuple[str, ...]
    t0: np.ndarray
    t1: np.ndarray
    excluded: tuple[Exclusion, ...]
    cuts: np.ndarray
    plot_ranges: np.ndarray
    nav_ranges: tuple
    n_input_plots: int
    nav_margin_s: float
    token: str
    # the prior sigma (m; inf: none) of the flight levels' common height offset, a state of every
    # partition's layout; None: no reference carries it
    height_offset_prior: float | None = None

    @property
    def n_partitions(self) -> int:
        return int(self.plot_ranges.shape[0])

    @property
    def span(self) -> tuple[np.ndarray, np.ndarray]:
        return self.t0, self.t1


def window_index(plan: ArchivePlan, target: np.ndarray, time: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(window index within its target (M,), window start time (M,) s) of times ``time`` (s) of targets
    ``target`` (M,; indices into plan.target_ids)."""
    count, length, _ = window_grid(plan.t0, plan.t1, plan.window_s)
    w = window_of(plan.t0, count, length, target, time)
    return w, plan.t0[target] + w * length[target]


def partition_of(plan: ArchivePlan, target: np.ndarray, time: np.ndarray) -> np.ndarray:
    """(M,) the partition of the windows that times ``time`` (s) of targets ``target`` fall in."""
    return np.searchsorted(plan.cuts, window_index(plan, target, time)[1], side="right")


def _codes(values) -> tuple[np.ndarray, list[str]]:
    """(code of each value (M,), the values' ids as strings in order of first appearance)."""
    import pandas as pd

    if not isinstance(values, pd.Categorical):
        values = np.asarray(values)
    codes, unique = pd.factorize(values, use_na_sentinel=False)
    names = [str(u) for u in unique]
    ids = list(dict.fromkeys(names))
    if len(ids) != len(names):  # values that differ but read the same as text (1 and "1")
        pos = {g: i for i, g in enumerate(ids)}
        codes = np.array([pos[g] for g in names], dtype=np.int64)[codes]
    return np.asarray(codes, dtype=np.int64), ids


def _first_pass(source) -> tuple:
    """Per target in order of first appearance: (ids, first time, last time, plots, sensors seen),
    and the number of plots; ValueError naming the plots file for a time that is not finite."""
    order: dict[str, int] = {}
    t_min: dict[str, float] = {}
    t_max: dict[str, float] = {}
    count: dict[str, int] = {}
    pairs: set[tuple[str, str]] = set()
    n = 0
    for batch in source.plot_batches(("time", "sensor", "target")):
        t = np.asarray(batch["time"], dtype=np.float64)
        if not np.isfinite(t).all():
            row = n + int(np.flatnonzero(~np.isfinite(t))[0])
            raise ValueError(f"{source.name('plots')}: plot row {row}: time {t[row - n]} s is not finite")
        inv, u = _codes(batch["target"])
        lo, hi = np.full(len(u), np.inf), np.full(len(u), -np.inf)
        np.minimum.at(lo, inv, t)
        np.maximum.at(hi, inv, t)
        counts = np.bincount(inv, minlength=len(u))
        for k, g in enumerate(u):
            order.setdefault(g, len(order))
            t_min[g], t_max[g] = min(t_min.get(g, np.inf), lo[k]), max(t_max.get(g, -np.inf), hi[k])
            count[g] = count.get(g, 0) + int(counts[k])
        sensor, s_ids = _codes(batch["sensor"])
        both = np.unique(inv * len(s_ids) + sensor)
        pairs |= {(u[c // len(s_ids)], s_ids[c % len(s_ids)]) for c in both.tolist()}
        n += t.size
    if n == 0:
        raise ValueError(f"{source.name('plots')}: the table has no rows, so there is nothing to register")
    ids = sorted(order, key=lambda g: order[g])
    n_sensors = {g: 0 for g in ids}
    for g, _ in pairs:
        n_sensors[g] += 1
    return ids, t_min, t_max, count, n_sensors, n


def _reference_pass(source) -> tuple[set, float | None]:
    """(the reference targets, the prior sigma (m) of the flight levels' common height offset or
    None when no reference carries it): one pass over the references' target and
    ``height_offset_prior`` columns. ValueError naming the reference file when the prior differs
    between rows or is negative (as the in-memory reader's check; each partition checks its rows'
    other rules)."""
    out: set = set()
    priors: list[np.ndarray] = []
    for batch in source.reference_batches(("target", "height_offset_prior")) or ():
        out |= set(_codes(batch["target"])[1])
        if "height_offset_prior" in batch:
            prior = np.asarray(batch["height_offset_prior"], dtype=np.float64)
            priors.append(np.unique(prior[~np.isnan(prior)]))
    values = np.unique(np.concatenate(priors)) if priors else np.zeros(0)
    if values.size == 0:
        return out, None
    if values.size > 1 or not values[0] >= 0:
        raise ValueError(
            f"{source.name('reference')}: height_offset_prior {values.tolist()} m: the prior sigma of the "
            "one height offset of the flight levels must be >= 0 and the same on every row"
        )
    return out, float(values[0])


def _cuts(t0: np.ndarray, t1: np.ndarray, window_s: float, partitions: int | None, partition_s: float | None):
    """(cuts (P - 1,) s, every window's start (W,) s and end (W,) s)."""
    count, length, _ = window_grid(t0, t1, window_s)
    tg = np.repeat(np.arange(t0.size), count)
    w = np.arange(tg.size) - np.repeat(np.cumsum(count) - count, count)
    starts = t0[tg] + w * length[tg]
    ends = starts + length[tg]
    lo, hi = float(starts.min()), float(starts.max())
    if partition_s is not None:
        if not partition_s > 0:
            raise ValueError(
                f"--partition-s (partition_s): expected a partition length > 0 s, got {partition_s}"
            )
        cuts = lo + partition_s * np.arange(1, max(1, int(np.ceil((hi - lo) / partition_s)) + 1))
    else:
        p = 1 if partitions is None else int(partitions)
        if p < 1:
            raise ValueError(f"partitions: expected at least 1, got {partitions}")
        cuts = lo + (hi - lo) * np.arange(1, p) / p
    return cuts[cuts <= hi] if cuts.size else cuts, starts, ends


def navigation_ranges(source, platforms: list[str], plot_ranges: np.ndarray, margin: float) -> tuple:
    """Per partition: platform -> (first, last) navigation time (s) to read (module docstring).

    Per platform, the sample NAV_EXTRA_SAMPLES before the last one at or before ``start - margin``
    (the first sample if there are fewer) and as many after the first one at or after ``end +
    margin`` (the last if fewer): found in one pass over the navigation's batches, keeping per
    partition the NAV_EXTRA_SAMPLES + 1 nearest times on each side, so memory does not grow with
    the navigation."""
    m = NAV_EXTRA_SAMPLES + 1
    live = np.isfinite(plot_ranges[:, 0])
    a = plot_ranges[live, 0] - margin  # (K,)
    b = plot_ranges[live, 1] + margin
    lows = {p: np.full((a.size, m), -np.inf) for p in platforms}  # the m largest times <= a, ascending
    highs = {p: np.full((b.size, m), np.inf) for p in platforms}  # the m smallest times >= b, ascending
    first = {p: np.inf for p in platforms}
    last = {p: -np.inf for p in platforms}
    for batch in source.navigation_batches(("platform", "time")):
        code, ids = _codes(batch["platform"])
        t_all = np.asarray(batch["time"], dtype=np.float64)
        for c, p in enumerate(ids):
            if p not in lows:
                continue
            t = np.sort(t_all[code == c])
            if t.size == 0:
                continue
            first[p], last[p] = min(first[p], t[0]), max(last[p], t[-1])
            i = np.searchsorted(t, a, side="right")  # t[i - m .. i - 1]: the batch's m largest <= a
            j = np.searchsorted(t, b, side="left")  # t[j .. j + m - 1]: its m smallest >= b
            k = np.arange(m)
            lo_idx, hi_idx = i[:, None] - m + k, j[:, None] + k
            lo = np.where(lo_idx >= 0, t[np.clip(lo_idx, 0, t.size - 1)], -np.inf)
            hi = np.where(hi_idx < t.size, t[np.clip(hi_idx, 0, t.size - 1)], np.inf)
            lows[p] = np.sort(np.concatenate([lows[p], lo], axis=1), axis=1)[:, -m:]
            highs[p] = np.sort(np.concatenate([highs[p], hi], axis=1), axis=1)[:, :m]
    out, at = [], 0
    for ok in live:
        ranges = {}
        if ok:
            for p in platforms:
                if not np.isfinite(first[p]):
                    continue
                lo, hi = lows[p][at, 0], highs[p][at, -1]
                ranges[p] = (
                    float(lo if np.isfinite(lo) else first[p]),
                    float(hi if np.isfinite(hi) else last[p]),
                )
            at += 1
        out.append(ranges)
    return tuple(out)


def make_plan(
    source,
    window_s: float,
    *,
    partitions: int | None = None,
    partition_s: float | None = None,
    nav_margin_s: float = DEFAULT_NAV_MARGIN_S,
) -> ArchivePlan:
    """The plan of an archive (module docstring): ``partitions`` equal time ranges of the windows'
    start times, or ranges of ``partition_s`` seconds (default: one partition)."""
    if not window_s > 0:
        raise ValueError(
            f"window_s: the partitioned solver needs target windows (window_s > 0), got {window_s}"
        )
    ids, t_min, t_max, count, n_sensors, n = _first_pass(source)
    refs, offset_prior = _reference_pass(source)
    excluded = tuple(
        Exclusion(g, SINGLE_SENSOR, count[g], float(t_min[g]), float(t_max[g]))
        for g in ids
        if n_sensors[g] == 1 and g not in refs
    )
    gone = {e.target for e in excluded}
    kept = tuple(g for g in ids if g not in gone)
    if not kept:
        raise ValueError(
            "no plots to register (every target was excluded: " + "; ".join(e.text() for e in excluded) + ")"
        )
    t0 = np.array([t_min[g] for g in kept])
    t1 = np.array([t_max[g] for g in kept])
    cuts, starts, ends = _cuts(t0, t1, window_s, partitions, partition_s)
    part = np.searchsorted(cuts, starts, side="right")
    n_part = cuts.size + 1
    lo = np.full(n_part, np.inf)
    hi = np.full(n_part, -np.inf)
    np.minimum.at(lo, part, starts)
    np.maximum.at(hi, part, ends)
    ranges = np.where(np.isfinite(lo)[:, None], np.stack([lo - SLACK_S, hi + SLACK_S], axis=1), np.nan)
    sensor_platforms = list(dict.fromkeys(np.asarray(source.sensors["platform"]).astype(str).tolist()))
    nav = navigation_ranges(source, sensor_platforms, ranges, float(nav_margin_s))
    token = f"{source.token}:{window_s}:{hash((cuts.tobytes(), t0.tobytes(), t1.tobytes()))}"
    return ArchivePlan(
        window_s=float(window_s),
        target_ids=kept,
        all_targets=tuple(ids),
        t0=t0,
        t1=t1,
        excluded=excluded,
        cuts=cuts,
        plot_ranges=ranges,
        nav_ranges=nav,
        n_input_plots=n,
        nav_margin_s=float(nav_margin_s),
        token=token,
        height_offset_prior=offset_prior,
    )
