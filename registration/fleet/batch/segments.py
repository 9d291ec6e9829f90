"""Sums over consecutive segments of a stack (the groups of a block, the chunks of a group).

``np.add.reduceat(a, starts, axis=0)`` on a stack of matrices runs one inner loop per segment
and per entry: with segments of one or two matrices of a few hundred entries each, that loop
overhead dominated the normal equations. :func:`segment_sums` gives the same sums, bit for bit,
with one whole-array step per position within the segments.
"""

from __future__ import annotations

import numpy as np

__all__ = ["MAX_SEGMENT_ROWS", "segment_sums"]


#: Rows per segment up to which :func:`segment_sums` adds them itself (longer: ``np.add.reduceat``,
#: which then sums a segment's rows after its first pairwise).
MAX_SEGMENT_ROWS = 8


def segment_sums(a: np.ndarray, starts: np.ndarray, index: np.ndarray | None = None) -> np.ndarray:
    """(S, ...) the sums over axis 0 of the segments ``a[starts[s]:starts[s + 1]]`` of ``a`` (the
    last one to the end of ``a``); ``starts`` (S,) increasing from 0, every segment non-empty.
    With ``index``: the segments of ``a[index]``, taken from ``a`` as they are added (the chunks of
    the groups, numbered in another order), the same numbers as without it on ``a[index]``.

    The same numbers as ``np.add.reduceat(a, starts, axis=0)``, bit for bit: each segment's first
    row plus the sum, in order, of its other rows (as reduceat adds them), the k-th rows of all
    segments at once. reduceat's cost is per segment, and most groups (a sensor in a window) hold
    one or two chunks, most windows two or three groups: this costs a few array operations per row
    of the longest segment instead."""
    rows = a.shape[0] if index is None else index.size
    if starts.size == 0:
        return a[starts]
    length = np.diff(np.append(starts, rows))
    if length.max() > MAX_SEGMENT_ROWS:
        return np.add.reduceat(a if index is None else a[index], starts, axis=0)

    def take(i: np.ndarray) -> np.ndarray:
        return a[i] if index is None else a[index[i]]

    out = take(starts)
    more = np.flatnonzero(length > 1)
    if more.size:
        tail = take(starts[more] + 1)
        for k in range(2, int(length.max())):
            longer = np.flatnonzero(length[more] > k)
            tail[longer] += take(starts[more[longer]] + k)
        out[more] += tail
    return out
