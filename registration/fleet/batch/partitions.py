"""An archive of fleet tables cut into partitions for the partitioned batch solver
(:mod:`registration.fleet.batch.partitioned`, docs/archive.md).

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

A *source* gives the tables: :class:`TablesSource` (in memory, SI units) or
:class:`registration.fleet.batch.archive.ParquetSource` (files read lazily). Its methods:
``plot_batches(columns)``, ``navigation_batches(columns)``, ``reference_batches(columns)`` (iterators
of column dicts), ``read_plots(lo, hi)``, ``read_navigation(ranges)``, ``read_references(lo, hi)``
(rows with ``lo <= time <= hi``; ranges: platform -> (first, last) time), ``sensors``,
``platforms`` (small tables), ``token`` (a string naming the data, for caches) and ``name(table)``
(what errors call the table: its file).
"""

from __future__ import annotations

import uuid
from dataclasses import dataclass

import numpy as np

from registration.fleet.batch.blocks import window_grid, window_of
from registration.fleet.data.problem import Exclusion

__all__ = ["DEFAULT_NAV_MARGIN_S", "NAV_EXTRA_SAMPLES", "SLACK_S", "ArchivePlan", "TablesSource", "make_plan",
           "partition_of", "window_index"]

#: Plots are read this far (s) beyond a partition's windows, so rounding cannot lose one.
SLACK_S = 1e-3
#: Navigation samples read beyond the margin on each side (the Hermite slopes use two neighbours).
NAV_EXTRA_SAMPLES = 3
#: Navigation read beyond a partition's plots (s): the largest time bias it can follow exactly.
DEFAULT_NAV_MARGIN_S = 60.0
#: Why a target seen by one sensor only is set aside (the text of build_problem).
SINGLE_SENSOR = ("seen by one sensor only and not a reference: its plots fit any registration errors, so they "
                 "carry no registration information")


def _columns(table) -> dict | None:
    """A DataFrame or a mapping of columns as a dict of numpy arrays (None stays None)."""
    if table is None:
        return None
    if hasattr(table, "columns") and hasattr(table, "to_dict"):
        return {str(c): table[c].to_numpy() for c in table.columns}
    return {str(k): np.asarray(v) for k, v in table.items()}


def _rows(table: dict, keep: np.ndarray) -> dict:
    return {k: v[keep] for k, v in table.items()}


class TablesSource:
    """The fleet tables in memory (:mod:`registration.fleet.data.tables`: SI units, radians) as a
    partition source (module docstring); ``batch_rows``: rows per batch of the first passes."""

    def __init__(self, plots, sensors, navigation, platforms=None, references=None, batch_rows: int = 1_000_000):
        self.plots, self.navigation = _columns(plots), _columns(navigation)
        self.sensors, self.platforms, self.references = _columns(sensors), _columns(platforms), _columns(references)
        self.batch_rows = int(batch_rows)
        self.token = uuid.uuid4().hex

    @staticmethod
    def name(table: str) -> str:
        return table

    def _batches(self, table: dict | None, columns):
        if table is None:
            return
        n = len(next(iter(table.values())))
        for a in range(0, n, self.batch_rows):
            yield {c: table[c][a:a + self.batch_rows] for c in columns}

    def plot_batches(self, columns):
        return self._batches(self.plots, columns)

    def navigation_batches(self, columns):
        return self._batches(self.navigation, columns)

    def reference_batches(self, columns):
        return self._batches(self.references, columns)

    def read_plots(self, lo: float, hi: float) -> dict:
        t = np.asarray(self.plots["time"], dtype=np.float64)
        return _rows(self.plots, (t >= lo) & (t <= hi))

    def read_references(self, lo: float, hi: float) -> dict | None:
        if self.references is None:
            return None
        t = np.asarray(self.references["time"], dtype=np.float64)
        return _rows(self.references, (t >= lo) & (t <= hi))

    def read_navigation(self, ranges: dict) -> dict:
        pid = np.asarray(self.navigation["platform"]).astype(str)
        t = np.asarray(self.navigation["time"], dtype=np.float64)
        keep = np.zeros(t.size, dtype=bool)
        for p, (a, b) in ranges.items():
            keep |= (pid == p) & (t >= a) & (t <= b)
        return _rows(self.navigation, keep)


@dataclass(frozen=True)
class ArchivePlan:
    """The archive's targets, windows and partitions (module docstring).

    ``target_ids`` the targets kept (order of first appearance), with ``t0``, ``t1`` their first
    and last plot times (s); ``all_targets`` every target id (references may name any of them);
    ``excluded`` the targets set aside; ``cuts`` (P - 1,) s the partitions' boundaries on the
    windows' start times; ``plot_ranges`` (P, 2) s the time range each partition's plots are read
    from (NaN: the partition holds no window); ``nav_ranges`` per partition, platform -> (first,
    last) navigation time (s) to read.
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


def _first_pass(source) -> tuple:
    """Per target in order of first appearance: (ids, first time, last time, plots, sensors seen),
    and the number of plots; ValueError naming the plots file for a time that is not finite."""
    order, t_min, t_max, count, pairs = {}, {}, {}, {}, set()
    n = 0
    for batch in source.plot_batches(("time", "sensor", "target")):
        t = np.asarray(batch["time"], dtype=np.float64)
        if not np.isfinite(t).all():
            row = n + int(np.flatnonzero(~np.isfinite(t))[0])
            raise ValueError(f"{source.name('plots')}: plot row {row}: time {t[row - n]} s is not finite")
        target = np.asarray(batch["target"]).astype(str)
        u, first, inv = np.unique(target, return_index=True, return_inverse=True)
        lo, hi = np.full(u.size, np.inf), np.full(u.size, -np.inf)
        np.minimum.at(lo, inv, t)
        np.maximum.at(hi, inv, t)
        for k in np.argsort(first):
            g = str(u[k])
            order.setdefault(g, len(order))
            t_min[g], t_max[g] = min(t_min.get(g, np.inf), lo[k]), max(t_max.get(g, -np.inf), hi[k])
        counts = np.bincount(inv, minlength=u.size)
        for k in range(u.size):
            count[str(u[k])] = count.get(str(u[k]), 0) + int(counts[k])
        sensor = np.asarray(batch["sensor"]).astype(str)
        pairs |= set(zip(*np.unique(np.stack([target, sensor]), axis=1).tolist()))
        n += t.size
    if n == 0:
        raise ValueError(f"{source.name('plots')}: the table has no rows, so there is nothing to register")
    ids = sorted(order, key=order.get)
    n_sensors = {g: 0 for g in ids}
    for g, _ in pairs:
        n_sensors[g] += 1
    return ids, t_min, t_max, count, n_sensors, n


def _reference_targets(source) -> set:
    out = set()
    for batch in source.reference_batches(("target",)) or ():
        out |= set(np.unique(np.asarray(batch["target"]).astype(str)).tolist())
    return out


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
            raise ValueError(f"partition_s: expected a partition length > 0 s, got {partition_s}")
        cuts = lo + partition_s * np.arange(1, max(1, int(np.ceil((hi - lo) / partition_s)) + 1))
    else:
        p = 1 if partitions is None else int(partitions)
        if p < 1:
            raise ValueError(f"partitions: expected at least 1, got {partitions}")
        cuts = lo + (hi - lo) * np.arange(1, p) / p
    return cuts[cuts <= hi] if cuts.size else cuts, starts, ends


def _navigation_ranges(source, platforms: list[str], plot_ranges: np.ndarray, margin: float) -> tuple:
    """Per partition: platform -> (first, last) navigation time (s) to read (module docstring)."""
    times = {p: [] for p in platforms}
    for batch in source.navigation_batches(("platform", "time")):
        pid = np.asarray(batch["platform"]).astype(str)
        t = np.asarray(batch["time"], dtype=np.float64)
        for p in platforms:
            times[p].append(t[pid == p])
    sorted_t = {p: np.sort(np.concatenate(v)) for p, v in times.items() if v and sum(a.size for a in v)}
    out = []
    for lo, hi in plot_ranges:
        ranges = {}
        if np.isfinite(lo):
            for p, t in sorted_t.items():
                i = max(0, int(np.searchsorted(t, lo - margin, side="right")) - 1 - NAV_EXTRA_SAMPLES)
                j = min(t.size - 1, int(np.searchsorted(t, hi + margin, side="left")) + NAV_EXTRA_SAMPLES)
                ranges[p] = (float(t[i]), float(t[j]))
        out.append(ranges)
    return tuple(out)


def make_plan(source, window_s: float, *, partitions: int | None = None, partition_s: float | None = None,
              nav_margin_s: float = DEFAULT_NAV_MARGIN_S) -> ArchivePlan:
    """The plan of an archive (module docstring): ``partitions`` equal time ranges of the windows'
    start times, or ranges of ``partition_s`` seconds (default: one partition)."""
    if not window_s > 0:
        raise ValueError(f"window_s: the partitioned solver needs target windows (window_s > 0), got {window_s}")
    ids, t_min, t_max, count, n_sensors, n = _first_pass(source)
    refs = _reference_targets(source)
    excluded = tuple(Exclusion(g, SINGLE_SENSOR, count[g], float(t_min[g]), float(t_max[g]))
                     for g in ids if n_sensors[g] == 1 and g not in refs)
    gone = {e.target for e in excluded}
    kept = tuple(g for g in ids if g not in gone)
    if not kept:
        raise ValueError("no plots to register (every target was excluded: "
                         + "; ".join(e.text() for e in excluded) + ")")
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
    nav = _navigation_ranges(source, sensor_platforms, ranges, float(nav_margin_s))
    token = f"{source.token}:{window_s}:{hash((cuts.tobytes(), t0.tobytes(), t1.tobytes()))}"
    return ArchivePlan(float(window_s), kept, tuple(ids), t0, t1, excluded, cuts, ranges, nav, n,
                       float(nav_margin_s), token)
