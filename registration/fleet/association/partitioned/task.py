"""One partition of an association out of core: :func:`associate_part`, a pure function of the
source, the plan, the partition's index and the options (so a Dask worker can run it, and run it
again after a lost worker, with the same answer).

The partition's plots (its own and the overlaps, :mod:`.parts`), the navigation and the references
of that time range are read from the source and associated in memory by
:func:`~registration.fleet.association.associate.associate_and_register`, exactly as a run in
memory associates a recording of that length, except for its last registration of the accepted
plots, which the partitioned solver does for all partitions at once (the labels are set before
it). A partition whose plots all carry a target id keeps them, unread by the association. A
partition that cannot be associated (its plots without an id meet no anchor: one sensor, no
reference, no id in that time) keeps the ids its plots carry, and says why.
"""

from __future__ import annotations

import time as clock
from dataclasses import dataclass
from typing import Any

import numpy as np

from registration.fleet.association.associate import associate_and_register
from registration.fleet.association.options import AssociationOptions
from registration.fleet.association.partitioned.parts import AssociationPlan, id_mask
from registration.fleet.batch.partitioned.task import read_source

__all__ = ["PartLabels", "associate_part"]


@dataclass(frozen=True)
class PartLabels:
    """What one partition's association gives, per plot it read (in the source's order of the rows
    with ``read_ranges[index, 0] <= time <= read_ranges[index, 1]``): ``time`` (M,) s, ``labels``
    (M,) the target ('' none), ``given`` (M,) whether the plot carried an id; ``associated``
    whether the association ran (False: no plot without an id, or it could not: ``notes`` say
    why); ``converged`` its passes converged; ``seconds`` its wall time."""

    index: int
    time: np.ndarray
    labels: np.ndarray
    given: np.ndarray
    associated: bool
    converged: bool
    seconds: float
    notes: tuple[str, ...]


def _given_labels(target, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(the ids as labels (n,) str, '' none; which rows carry one (n,))."""
    if target is None:
        return np.full(n, "", dtype=object).astype(str), np.zeros(n, dtype=bool)
    given, _ = id_mask(target)
    labels = np.where(given, np.asarray(target, dtype=object), "").astype(str)
    return labels, given


def associate_part(source: Any, plan: AssociationPlan, k: int, options: AssociationOptions) -> PartLabels:
    """Associate partition ``k`` of ``plan`` (module docstring); ``source`` a
    :class:`~registration.fleet.data.source.FleetSource`."""
    t_start = clock.perf_counter()
    lo, hi = plan.read_ranges[k]
    plots = dict(read_source(source, "plots", source.read_plots, lo, hi))
    t = np.asarray(plots["time"], dtype=np.float64)
    labels, given = _given_labels(plots.get("target"), t.size)
    if given.all():
        return PartLabels(k, t, labels, given, False, True, clock.perf_counter() - t_start, ())
    refs = read_source(source, "reference", source.read_references, lo, hi)
    if refs is not None and np.asarray(refs["time"]).size == 0:
        refs = None
    navigation = read_source(source, "navigation", source.read_navigation, plan.nav_ranges[k])
    try:
        result = associate_and_register(
            plots,
            source.sensors,
            navigation,
            source.platforms,
            refs,
            options,
            targets=source.targets,
            final_registration=False,  # the partitioned solver registers the labels of all partitions
        )
    except ValueError as exc:
        note = (
            f"partition {k} ({lo:.0f} s to {hi:.0f} s): its {int(np.count_nonzero(~given))} plots "
            f"without a target id stay without one: {exc}"
        )
        return PartLabels(k, t, labels, given, False, False, clock.perf_counter() - t_start, (note,))
    return PartLabels(
        k,
        t,
        np.asarray(result.labels).astype(str),
        given,
        True,
        bool(result.converged),
        clock.perf_counter() - t_start,
        tuple(f"partition {k}: {n}" for n in result.notes),
    )
