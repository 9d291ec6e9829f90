"""The association of an archive partition by partition: :func:`associate_partitioned`.

The plots without a target id of an archive too large for memory (or of any
:class:`~registration.fleet.data.source.FleetSource`) are associated in time partitions with
overlaps (:mod:`.parts`), each in memory as a run of that length would be (:mod:`.task`, on the
workers of a ``dask.distributed`` client when one is given), and their targets named once across the
cuts (:mod:`.naming`). The result says per partition which label each plot it owns has; the
plots with a label are what the partitioned solver
(:func:`registration.fleet.batch.partitioned.solve_batch_partitioned`) then registers. Memory is
bounded by one partition and the labels (a text per plot).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import partial
from typing import Any

import numpy as np

from registration.core.parallel import map_chunks
from registration.fleet.association.options import AssociationOptions
from registration.fleet.association.partitioned.naming import MergedLabels, merge_labels
from registration.fleet.association.partitioned.parts import (
    DEFAULT_OVERLAP_S,
    AssociationPlan,
    make_association_plan,
)
from registration.fleet.association.partitioned.task import PartLabels, associate_part

__all__ = ["PartitionedAssociation", "Spans", "associate_partitioned"]


@dataclass(frozen=True)
class PartitionedAssociation:
    """An association by partitions (module docstring): the ``plan``, per partition the labels of
    the plots it owns (``owned``, in the source's row order, '' none) and what its association said
    (``parts``: the labels are dropped from them, their counts kept), and the naming's counts."""

    plan: AssociationPlan
    owned: tuple[np.ndarray, ...]
    parts: tuple[PartLabels, ...]
    merged: MergedLabels
    spans: Spans

    @property
    def n_labelled(self) -> int:
        return int(sum(np.count_nonzero(o != "") for o in self.owned))

    @property
    def n_targets(self) -> int:
        return int(np.unique(np.concatenate([o[o != ""] for o in self.owned] or [np.zeros(0, str)])).size)

    @property
    def notes(self) -> tuple[str, ...]:
        return tuple(n for p in self.parts for n in p.notes)

    def summary(self) -> dict:
        """The figures a run reports (JSON-ready)."""
        return {
            "partitions": self.plan.n_partitions,
            "partition_s": self.plan.partition_s,
            "overlap_s": self.plan.overlap_s,
            "plots": self.plan.n_plots,
            "plots_without_id": self.plan.n_without_id,
            "plots_labelled": self.n_labelled,
            "targets": self.n_targets,
            "partitions_associated": int(sum(p.associated for p in self.parts)),
            "partitions_converged": int(sum(p.converged for p in self.parts if p.associated)),
            "new_targets": self.merged.new_targets,
            "links_across_cuts": self.merged.links,
            "conflicts_across_cuts": self.merged.conflicts,
            "seconds_per_partition": [round(p.seconds, 3) for p in self.parts],
            "notes": list(self.notes),
        }


@dataclass(frozen=True)
class Spans:
    """Per target labelled: its first and last plot times ``t0``, ``t1`` (s), and the ``margin_s``
    beyond them within which its reference positions are used (the window, as in memory:
    :func:`registration.fleet.association.problems.labelled_problem`)."""

    targets: np.ndarray
    t0: np.ndarray
    t1: np.ndarray
    margin_s: float

    def keep_references(self, target: np.ndarray, time: np.ndarray) -> np.ndarray:
        """(M,) bool: the reference rows (target ids ``target``, times ``time`` s) a registration of
        the labelled plots uses."""
        if self.targets.size == 0:
            return np.zeros(np.shape(target), dtype=bool)
        target = np.asarray(target).astype(str)
        k = np.clip(np.searchsorted(self.targets, target), 0, self.targets.size - 1)
        known = self.targets[k] == target
        return known & (time >= self.t0[k] - self.margin_s) & (time <= self.t1[k] + self.margin_s)


def _spans(plan: AssociationPlan, parts: list[PartLabels], owned: tuple, margin_s: float) -> Spans:
    """The labelled targets' plot spans (:class:`Spans`)."""
    import pandas as pd

    frame = pd.DataFrame(
        {
            "target": np.concatenate(owned),
            "time": np.concatenate([p.time[plan.owned(p.index, p.time)] for p in parts]),
        }
    )
    g = frame[frame["target"] != ""].groupby("target", sort=True)["time"].agg(["min", "max"])
    return Spans(g.index.to_numpy().astype(str), g["min"].to_numpy(), g["max"].to_numpy(), float(margin_s))


def _run(source, plan: AssociationPlan, options: AssociationOptions, k: int) -> PartLabels:
    return associate_part(source, plan, k, options)


def associate_partitioned(
    source: Any,
    options: AssociationOptions | None = None,
    *,
    partition_s: float,
    overlap_s: float = DEFAULT_OVERLAP_S,
    client=None,
    progress: bool = False,
) -> PartitionedAssociation | None:
    """Associate the plots without a target id of ``source`` partition by partition (module
    docstring): partitions of ``partition_s`` seconds, each reading ``overlap_s`` seconds more on
    both sides; ``client`` a ``dask.distributed`` client whose workers associate the partitions
    (the source is pickled to them), None: in this process. None when every plot carries a target
    id (nothing to associate)."""
    options = options or AssociationOptions()
    plan = make_association_plan(source, partition_s=partition_s, overlap_s=overlap_s)
    if plan.n_without_id == 0:
        return None
    parts = map_chunks(
        partial(_run, source, plan, options),
        range(plan.n_partitions),
        client,
        progress=progress,
        desc="association partitions",
    )
    merged = merge_labels(plan, parts)
    spans = _spans(plan, parts, merged.owned, options.window_s)
    kept = tuple(
        PartLabels(
            p.index, p.time[:0], p.labels[:0], p.given[:0], p.associated, p.converged, p.seconds, p.notes
        )
        for p in parts
    )
    return PartitionedAssociation(plan, merged.owned, kept, merged, spans)
