"""Angles: wrapping to (-pi, pi]. Radians inside the package; degrees only at the edges
(``numpy.radians`` / ``numpy.degrees`` convert, no hand-written constants)."""

from __future__ import annotations

import numpy as np

__all__ = ["wrap_angle"]


def wrap_angle(a) -> np.ndarray:
    """Angles (rad) wrapped to (-pi, pi]; float64 array of the input's shape.

    Values already in (-pi, pi] are returned unchanged (bit for bit), so small angles keep their
    full precision; others are reduced modulo 2 pi.
    """
    a = np.asarray(a, dtype=np.float64)
    w = np.mod(a + np.pi, 2.0 * np.pi) - np.pi
    w = np.where(w == -np.pi, np.pi, w)
    return np.where((a > -np.pi) & (a <= np.pi), a, w)
