"""One name per target across the partitions of an association out of core: :func:`merge_labels`.

A target id the plots carry or a reference names (an *anchor*) is the same target in every
partition: a track that crosses a cut and is joined to an anchor on both sides keeps its name. A
target the association confirmed without an anchor (two position-fixing sensors seeing it
together) gets a new name in each partition that sees it. The plots two neighbouring partitions
both read (the overlap, :mod:`.parts`) tell which of those are one target: each such target is
linked to the target of the other partition that holds most of its shared plots (at least
MIN_SHARED of them), and linked targets are one, named by the anchor among them or, with none, a new
name ``a1``, ``a2``, ... (not a target id of the data) in the order of their first plot. A group
that links two different anchors is left apart (each of its new targets keeps a name of its own),
and counted.

Each plot takes the label of the partition that owns it (:meth:`.parts.AssociationPlan.owned`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fleet.association.grouping.confirm import new_names
from registration.fleet.association.partitioned.parts import AssociationPlan
from registration.fleet.association.partitioned.task import PartLabels

__all__ = ["MIN_SHARED", "MergedLabels", "merge_labels"]

#: Shared plots that link a target of one partition to one of its neighbour's.
MIN_SHARED = 3


@dataclass(frozen=True)
class MergedLabels:
    """Per partition, the labels of the plots it owns (in its read order, '' none), and how many
    new targets were linked across cuts (``links``) or left apart between two anchors
    (``conflicts``); ``new_targets`` the new names given."""

    owned: tuple[np.ndarray, ...]
    links: int
    conflicts: int
    new_targets: int


class _Union:
    def __init__(self) -> None:
        self.parent: dict = {}

    def find(self, x):
        self.parent.setdefault(x, x)
        while self.parent[x] != x:
            self.parent[x] = self.parent[self.parent[x]]
            x = self.parent[x]
        return x

    def union(self, a, b) -> None:
        self.parent[self.find(a)] = self.find(b)


def _nodes(part: PartLabels, anchors: frozenset, rows: np.ndarray) -> list:
    """The node of each plot ``rows`` of ``part``: (-1, id) for an anchor, (k, label) for a new
    target, None for no label."""
    out = []
    for label in part.labels[rows].tolist():
        out.append(None if label == "" else ((-1, label) if label in anchors else (part.index, label)))
    return out


def _links(plan: AssociationPlan, a: PartLabels, b: PartLabels) -> list[tuple]:
    """The pairs of nodes linked across the cut between partitions ``a`` and ``b`` (module docstring)."""
    ra, rb = np.flatnonzero(plan.shared(a.index, a.time)), np.flatnonzero(plan.shared(a.index, b.time))
    if ra.size != rb.size or not np.array_equal(a.time[ra], b.time[rb]):
        raise RuntimeError(
            f"partitions {a.index} and {b.index} read different plots where they overlap: the plots "
            "table changed during the run"
        )
    counts: dict = {}
    for x, y in zip(_nodes(a, plan.ids, ra), _nodes(b, plan.ids, rb)):
        if x is not None and y is not None and (x[0] >= 0 or y[0] >= 0):
            counts[(x, y)] = counts.get((x, y), 0) + 1
    best: dict = {}
    for (x, y), c in counts.items():
        for node, other in ((x, y), (y, x)):
            if node[0] >= 0 and c >= MIN_SHARED and c > best.get(node, (0, None))[0]:
                best[node] = (c, other)
    return [(node, other) for node, (_, other) in best.items()]


def merge_labels(plan: AssociationPlan, parts: list[PartLabels]) -> MergedLabels:
    """The labels of the plots each partition owns, one name per target (module docstring);
    ``parts`` in the order of the partitions."""
    union = _Union()
    links = 0
    for a, b in zip(parts, parts[1:]):
        for x, y in _links(plan, a, b):
            union.union(x, y)
            links += 1
    groups: dict = {}
    first: dict = {}
    for part in parts:
        labels = part.labels
        new = (labels != "") & ~np.isin(labels, list(plan.ids))
        for label in np.unique(labels[new]).tolist():
            node = (part.index, label)
            groups.setdefault(union.find(node), []).append(node)
            first[node] = float(part.time[labels == label].min())
    anchors_of: dict = {}
    for node in list(union.parent):
        if node[0] < 0:
            anchors_of.setdefault(union.find(node), set()).add(node[1])
    names: dict = {}
    conflicts = 0
    free = []
    for root, members in groups.items():
        anchors = anchors_of.get(root, set())
        if len(anchors) == 1:
            names.update({m: next(iter(anchors)) for m in members})
        elif len(anchors) > 1:
            conflicts += 1
            free.extend([[m] for m in members])
        else:
            free.append(members)
    free.sort(key=lambda ms: min(first[m] for m in ms))
    for members, name in zip(free, new_names(len(free), set(plan.ids))):
        names.update({m: name for m in members})
    owned = []
    for part in parts:
        labels = part.labels[plan.owned(part.index, part.time)]
        unique, inverse = np.unique(labels, return_inverse=True)
        renamed = np.array([names.get((part.index, u), u) for u in unique.tolist()] or [""])
        owned.append(renamed[inverse].astype(str) if labels.size else labels.astype(str))
    return MergedLabels(tuple(owned), links, conflicts, len(free))
