"""Sums over consecutive segments of a stack (the groups of a block, the chunks of a group).

``np.add.reduceat(a, starts, axis=0)`` on a stack of matrices runs one inner loop per segment
and per entry: with segments of one or two matrices of a few hundred entries each, that loop
overhead dominated the normal equations. :func:`segment_sums` gives the same sums (to rounding:
it adds each segment's terms first to last) with one whole-array step per position within the
segments.
"""

from __future__ import annotations

import numpy as np

__all__ = ["segment_sums"]


def segment_sums(a: np.ndarray, starts: np.ndarray) -> np.ndarray:
    """(S, ...) the sums over axis 0 of the segments ``a[starts[s]:starts[s + 1]]`` of ``a`` (the
    last one to the end of ``a``); ``starts`` (S,) increasing, every segment non-empty. Each
    segment's terms are added first to last."""
    out = a[starts]
    if starts.size == 0:
        return out
    lengths = np.diff(np.append(starts, a.shape[0]))
    order = np.argsort(-lengths, kind="stable")  # the longest first: those still going are a prefix
    ordered = -lengths[order]
    for j in range(1, int(lengths.max())):
        more = order[: np.searchsorted(ordered, -j, side="left")]  # the segments longer than j
        out[more] += a[starts[more] + j]
    return out
