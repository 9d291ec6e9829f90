"""The batch solver's plots laid out in padded rows (:class:`ChunkLayout`): each group's plots (one
sensor in one window, :mod:`registration.fleet.batch.blocks`) cut into *chunks*, so that the sums
``Z^T Z`` over a group's rows are small dense matrix products
(:func:`registration.fleet.batch.normal.normal_equations`).

A chunk of C plots is C rows: its group's plots, then copies of a real plot that weigh 0
(padding). The chunks of one size form a *class*; a class's rows are contiguous, so its products
are one batched matrix product without copying. One size for every chunk wasted many rows: the
groups' sizes spread with the sensors' scan rates and with where the windows cut them (a sensor
split into two channels halves its groups and spreads their sizes from 1 to the whole), and with
chunks of 8, over half the rows of such a problem were padding (every padded row is evaluated by
the generated rows' kernel and multiplied out). So each group is cut into chunks of MAX_CHUNK
plots and its remainder into one chunk of the smallest class that holds it, the classes' sizes
chosen for the fewest padded rows plus CLASS_COST_ROWS per class (:func:`class_sizes`): most
problems' groups then fill their chunks exactly.

Rows are in class order (largest chunks first), then group order; a group's chunks are its plots
in order (its full chunks, then its remainder's), so the sums over a group's chunks add the same
rows in the same order whatever the classes.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

__all__ = ["CLASS_COST_ROWS", "MAX_CHUNK", "ChunkLayout", "chunk_layout", "class_sizes"]

#: The largest chunk (plots); longer groups are cut into chunks of this size and a remainder.
MAX_CHUNK = 32
#: The cost of a class of chunks beyond that of its rows, in rows: a class takes one batched matrix
#: product in the positions and one in the normal equations per evaluation (a few microseconds
#: each, as the kernel and products of some 30 rows).
CLASS_COST_ROWS = 32


@dataclass(frozen=True, kw_only=True)
class ChunkLayout:
    """The padded rows of the sorted plots (module docstring). Chunks are numbered in class order
    (the rows' order): the chunks of class k are ``chunk_start[k]`` to ``chunk_start[k + 1]``, each
    of ``sizes[k]`` rows, the class's rows from ``row_start[k]``."""

    sizes: tuple[int, ...]  # plots per chunk of each class, decreasing
    chunk_start: np.ndarray  # (K + 1,) first chunk of each class, then the number of chunks
    slot: np.ndarray  # (N,) row of each sorted plot
    group_chunks: np.ndarray  # (n_chunks,) the chunks of each group in turn, in its plots' order
    group_first: np.ndarray  # (G,) first entry of each group in group_chunks

    @property
    def n_chunks(self) -> int:
        return int(self.chunk_start[-1])

    @property
    def row_start(self) -> np.ndarray:
        """(K + 1,) first row of each class, then the number of rows."""
        return np.r_[0, np.cumsum(np.diff(self.chunk_start) * np.array(self.sizes, dtype=np.int64))]

    @property
    def n_rows(self) -> int:
        return int(self.row_start[-1])

    @property
    def in_group_order(self) -> bool:
        """True when the chunks are numbered in group order (group_chunks is 0, 1, 2, ...)."""
        return bool(np.array_equal(self.group_chunks, np.arange(self.n_chunks)))

    @property
    def one_per_group(self) -> bool:
        """True when every group is one chunk."""
        return self.group_first.size == self.n_chunks

    def first_rows(self) -> np.ndarray:
        """(n_chunks,) first row of each chunk."""
        return _first_rows(self.sizes, self.chunk_start)

    def chunk_first_of_rows(self) -> np.ndarray:
        """(n_rows,) first row of the chunk each row is in."""
        return np.repeat(self.first_rows(), np.repeat(self.sizes, np.diff(self.chunk_start)))

    def classes(self) -> Iterator[tuple[int, slice, slice]]:
        """Per class: (plots per chunk, its rows, its chunks), the slices in rows and chunks."""
        rows = self.row_start
        for k, size in enumerate(self.sizes):
            yield size, slice(rows[k], rows[k + 1]), slice(self.chunk_start[k], self.chunk_start[k + 1])


def _first_rows(sizes: tuple[int, ...], chunk_start: np.ndarray) -> np.ndarray:
    """(n_chunks,) first row of each chunk of classes of ``sizes`` plots from ``chunk_start``."""
    rows = np.repeat(np.array(sizes, dtype=np.int64), np.diff(chunk_start))
    return np.cumsum(rows) - rows


def class_sizes(sizes: np.ndarray) -> tuple[int, ...]:
    """The chunk sizes (decreasing) of the classes for groups of ``sizes`` plots (module
    docstring): a group is cut into ``s // MAX_CHUNK`` chunks of MAX_CHUNK and its remainder, if
    any, into one chunk of the smallest class at least that long; the classes make the fewest
    padded rows plus CLASS_COST_ROWS per class. MAX_CHUNK is a class when some group is that long
    (its remainders may join it without the class cost).

    Each class is a run of the distinct remainder lengths (ascending) topped by its longest, so
    the best runs are a shortest path over those lengths (at most MAX_CHUNK - 1 of them)."""
    full = bool((sizes >= MAX_CHUNK).any())
    rem = sizes % MAX_CHUNK
    counts = np.bincount(rem[rem > 0], minlength=MAX_CHUNK)
    length = np.flatnonzero(counts)  # the distinct remainder lengths, ascending
    held = np.r_[0, np.cumsum(counts[length])]  # remainders up to each length
    k = length.size
    best, cut = np.zeros(k + 1), np.zeros(k + 1, dtype=np.int64)
    for i in range(1, k + 1):  # lengths j .. i - 1 in one class of length[i - 1]
        cost = best[:i] + CLASS_COST_ROWS + length[i - 1] * (held[i] - held[:i])
        cut[i] = int(np.argmin(cost))
        best[i] = cost[cut[i]]
    top = k  # remainder lengths from index top on go to the full chunks' class
    if full:
        cost = best + MAX_CHUNK * (held[k] - held)
        top = int(np.argmin(cost))
    out = [MAX_CHUNK] if full else []
    i = top
    while i > 0:
        out.append(int(length[i - 1]))
        i = int(cut[i])
    return tuple(out)


def chunk_layout(group_start: np.ndarray, n: int) -> ChunkLayout:
    """The :class:`ChunkLayout` of ``n`` sorted plots in groups starting at ``group_start`` (G,)."""
    sizes = np.diff(np.r_[group_start, n]).astype(np.int64)
    classes = class_sizes(sizes)
    size_of = np.array(classes, dtype=np.int64)
    full, rem = sizes // MAX_CHUNK, sizes % MAX_CHUNK
    # the class of each group's remainder chunk: the smallest at least as long (-1: none)
    ascending = size_of[::-1]
    rem_class = np.where(rem > 0, size_of.size - 1 - np.searchsorted(ascending, rem), -1)
    n_in = full + (rem > 0)  # chunks of each group
    group_first = np.cumsum(n_in) - n_in
    group = np.repeat(np.arange(sizes.size), n_in)
    within = np.arange(group.size) - group_first[group]
    klass = np.where(within < full[group], 0, rem_class[group])  # class of each chunk, group order
    order = np.argsort(klass, kind="stable")  # chunk numbers in class order
    group_chunks = np.empty(order.size, dtype=np.int64)
    group_chunks[order] = np.arange(order.size)
    chunk_start = np.r_[0, np.cumsum(np.bincount(klass, minlength=size_of.size))].astype(np.int64)
    # each plot: its chunk within its group and its place in that chunk
    plot_group = np.repeat(np.arange(sizes.size), sizes)
    pos = np.arange(n) - group_start[plot_group]
    in_full = pos < full[plot_group] * MAX_CHUNK
    chunk = np.where(in_full, pos // MAX_CHUNK, full[plot_group])
    place = np.where(in_full, pos % MAX_CHUNK, pos - full[plot_group] * MAX_CHUNK)
    slot = _first_rows(classes, chunk_start)[group_chunks[group_first[plot_group] + chunk]] + place
    return ChunkLayout(
        sizes=classes, chunk_start=chunk_start, slot=slot, group_chunks=group_chunks, group_first=group_first
    )
