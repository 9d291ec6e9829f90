"""The time partitions of an association out of core (:mod:`registration.fleet.association.partitioned`):
:func:`make_association_plan`.

The plots' time span is cut every ``partition_s`` seconds from the first plot. Partition ``k``
*owns* the plots with ``cuts[k-1] <= time < cuts[k]`` (the first from the first plot, the last to
the last plot inclusive) and *reads* ``overlap_s`` seconds more on each side, so a track that
crosses a cut is seen whole enough on both sides to be joined to its target there, and the plots
read by two neighbours can tell which of their targets are one (:mod:`.naming`). Navigation is read
per partition as the partitioned solver reads it
(:func:`registration.fleet.batch.partitioned.plan.navigation_ranges`: a margin of
``nav_margin_s`` seconds beyond the plots, for the time biases, and three samples more), and the
references ``nav_margin_s`` seconds beyond the plots.

One pass over the plots' ``time`` and ``target`` columns finds the span, the plots with and without
a target id and the ids; one over the references' ``target`` column the reference ids. A target id is
any non-empty text; an empty cell, NaN or None is no id.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fleet.batch.partitioned.plan import DEFAULT_NAV_MARGIN_S, SLACK_S, navigation_ranges

__all__ = [
    "AssociationPlan",
    "DEFAULT_OVERLAP_S",
    "MAX_ASSOCIATION_PARTITION_S",
    "id_mask",
    "make_association_plan",
]

#: Seconds read beyond a partition's own plots on each side (six 20 s windows: a track crossing a
#: cut has pieces long enough on both sides to be joined to its target).
DEFAULT_OVERLAP_S = 120.0

#: The longest association partition ``fleet register`` makes (s), whatever its registration's
#: partitions: an association's time grows faster than its length (more targets at once). On cuts of
#: the imported ATC day, 2000 s took 7.7 s and 10 600 s took 63.6 s, 1.6 times as much per second
#: (time ~ length^1.27); with 240 s of overlaps read per partition, partitions of 800 to 2000 s cost
#: about the same per second.
MAX_ASSOCIATION_PARTITION_S = 1800.0


@dataclass(frozen=True, kw_only=True)
class AssociationPlan:
    """The partitions of an association (module docstring): ``cuts`` (P - 1,) s; ``read_ranges``
    (P, 2) s the plots each partition reads; ``nav_ranges`` per partition, platform -> (first,
    last) navigation time (s); ``ids`` every target id the plots carry or the references name;
    ``n_plots`` and ``n_without_id`` the plots in all and those without a target id."""

    t0: float
    t1: float
    partition_s: float
    overlap_s: float
    nav_margin_s: float
    cuts: np.ndarray
    read_ranges: np.ndarray
    nav_ranges: tuple
    ids: frozenset
    n_plots: int
    n_without_id: int

    @property
    def n_partitions(self) -> int:
        return int(self.read_ranges.shape[0])

    def owned(self, k: int, time: np.ndarray) -> np.ndarray:
        """(M,) bool: which of times ``time`` (s) partition ``k`` owns (module docstring)."""
        lo = self.cuts[k - 1] if k > 0 else -np.inf
        hi = self.cuts[k] if k < self.cuts.size else np.inf
        return (time >= lo) & (time < hi)

    def shared(self, k: int, time: np.ndarray) -> np.ndarray:
        """(M,) bool: which of times ``time`` (s) both partitions ``k`` and ``k + 1`` read."""
        return (time >= self.read_ranges[k + 1, 0]) & (time <= self.read_ranges[k, 1])


def id_mask(values) -> tuple[np.ndarray, list[str]]:
    """(which rows of a target column carry an id (M,), the ids met): ``values`` a numpy array (str,
    or object with None / NaN) or a ``pandas.Categorical``; an empty text is no id."""
    import pandas as pd

    codes, uniques = pd.factorize(values, use_na_sentinel=True)
    names = [str(u) for u in uniques]
    given = np.array([n != "" for n in names] + [False], dtype=bool)  # code -1 (no value): last
    return given[codes], [n for n in names if n != ""]


def _plot_pass(source) -> tuple[float, float, int, int, set]:
    """(first time, last time, plots, plots without an id, ids) of the plots, in batches."""
    t0, t1, n, missing, ids = np.inf, -np.inf, 0, 0, set()
    for batch in source.plot_batches(("time", "target")):
        t = np.asarray(batch["time"], dtype=np.float64)
        if not np.isfinite(t).all():
            row = n + int(np.flatnonzero(~np.isfinite(t))[0])
            raise ValueError(f"{source.name('plots')}: plot row {row}: time {t[row - n]} s is not finite")
        if t.size:
            t0, t1 = min(t0, float(t.min())), max(t1, float(t.max()))
        if "target" in batch:
            given, names = id_mask(batch["target"])
            ids.update(names)
            missing += int(np.count_nonzero(~given))
        else:
            missing += t.size
        n += t.size
    if n == 0:
        raise ValueError(f"{source.name('plots')}: the table has no rows, so there is nothing to register")
    return t0, t1, n, missing, ids


def make_association_plan(
    source,
    *,
    partition_s: float,
    overlap_s: float = DEFAULT_OVERLAP_S,
    nav_margin_s: float = DEFAULT_NAV_MARGIN_S,
) -> AssociationPlan:
    """The partitions of ``source`` (a :class:`~registration.fleet.data.source.FleetSource`) for an
    association by parts (module docstring). ValueError naming the option for a partition length or
    an overlap that is not a finite number > 0 (>= 0 for the overlap)."""
    if not (np.isfinite(partition_s) and partition_s > 0):
        raise ValueError(f"--partition-s (partition_s): expected a partition length > 0 s, got {partition_s}")
    if not (np.isfinite(overlap_s) and overlap_s >= 0):
        raise ValueError(f"overlap_s: expected an overlap >= 0 s, got {overlap_s}")
    t0, t1, n, missing, ids = _plot_pass(source)
    for batch in source.reference_batches(("target",)) or ():
        ids.update(id_mask(batch["target"])[1])
    cuts = t0 + partition_s * np.arange(1, max(1, int(np.ceil((t1 - t0) / partition_s))))
    cuts = cuts[cuts <= t1]
    lo = np.concatenate([[t0], cuts - overlap_s]).clip(t0, t1)
    hi = np.concatenate([cuts + overlap_s, [t1]]).clip(t0, t1)
    ranges = np.stack([lo - SLACK_S, hi + SLACK_S], axis=1)
    platforms = list(dict.fromkeys(np.asarray(source.sensors["platform"]).astype(str).tolist()))
    nav = navigation_ranges(source, platforms, ranges, float(nav_margin_s))
    return AssociationPlan(
        t0=float(t0),
        t1=float(t1),
        partition_s=float(partition_s),
        overlap_s=float(overlap_s),
        nav_margin_s=float(nav_margin_s),
        cuts=cuts,
        read_ranges=ranges,
        nav_ranges=nav,
        ids=frozenset(ids),
        n_plots=n,
        n_without_id=missing,
    )
