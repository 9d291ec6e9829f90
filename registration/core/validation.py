"""Input checks shared by every public function: clear errors naming the field, index and unit."""

from __future__ import annotations

import numpy as np

__all__ = ["as_float_array", "check_finite", "check_range", "check_positive", "check_latitude", "check_angle",
           "broadcast_1d", "degree_hint", "DEGREE_HINT", "HALF_PI"]

HALF_PI = np.pi / 2


def as_float_array(name: str, value) -> np.ndarray:
    try:
        arr = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name}: expected numbers, got {type(value).__name__} ({exc})") from exc
    return arr


def _first_bad(mask: np.ndarray) -> str:
    idx = np.argwhere(mask)[0]
    return str(tuple(int(i) for i in idx)) if mask.ndim > 1 else str(int(idx[0])) if mask.ndim == 1 else "scalar"


def check_finite(name: str, arr: np.ndarray, unit: str) -> None:
    bad = ~np.isfinite(arr)
    if bad.any():
        i = _first_bad(bad)
        v = arr[tuple(np.argwhere(bad)[0])] if arr.ndim else arr
        raise ValueError(f"{name}: non-finite value {v} at index {i}; expected a finite number in {unit}")


#: The one wording of the hint given when radians were expected and degrees seem to have come.
DEGREE_HINT = " (these look like degrees: convert with numpy.radians)"


def degree_hint(arr: np.ndarray, limit: float) -> str:
    """:data:`DEGREE_HINT` when the largest |value| lies in (limit, 360], else ''."""
    with np.errstate(invalid="ignore"):
        peak = np.nanmax(np.abs(arr)) if np.size(arr) else 0.0
    return DEGREE_HINT if limit < peak <= 360.0 else ""


def check_range(name: str, arr: np.ndarray, low: float, high: float, unit: str, *, angle: bool = False) -> None:
    """Raise if any value lies outside [low, high]; hint when radians were expected and degrees came."""
    if arr.size and np.min(arr) >= low and np.max(arr) <= high:  # fast path (NaN/inf fail it)
        return
    check_finite(name, arr, unit)
    bad = (arr < low) | (arr > high)
    if bad.any():
        i = _first_bad(bad)
        v = arr[tuple(np.argwhere(bad)[0])] if arr.ndim else arr
        hint = degree_hint(arr, max(abs(low), abs(high))) if angle else ""
        raise ValueError(f"{name}: value {v} at index {i} is outside [{low:g}, {high:g}] {unit}{hint}")


def check_positive(name: str, arr: np.ndarray, unit: str) -> None:
    if arr.size and np.min(arr) > 0 and np.isfinite(np.max(arr)):  # fast path
        return
    check_finite(name, arr, unit)
    bad = arr <= 0
    if bad.any():
        i = _first_bad(bad)
        v = arr[tuple(np.argwhere(bad)[0])] if arr.ndim else arr
        raise ValueError(f"{name}: value {v} at index {i} must be > 0 {unit}")


def check_latitude(name: str, arr: np.ndarray) -> None:
    check_range(name, arr, -HALF_PI, HALF_PI, "rad (latitude, [-pi/2, pi/2])", angle=True)


def check_angle(name: str, arr: np.ndarray, bound: float = 2 * np.pi) -> None:
    """Angles in radians; anything beyond +-bound is rejected (degrees passed as radians, say)."""
    check_range(name, arr, -bound, bound, "rad", angle=True)


def broadcast_1d(**arrays: np.ndarray) -> int:
    """Check that 0-d or 1-d arrays broadcast to a common length N; return N (1 if all scalars)."""
    n, first = None, None
    for key, arr in arrays.items():
        if arr.ndim > 1:
            raise ValueError(f"{key}: expected a scalar or a 1-D array, got shape {arr.shape}")
        if arr.ndim == 1 and arr.shape[0] != 1:
            if n is None:
                n, first = arr.shape[0], key
            elif arr.shape[0] != n:
                raise ValueError(f"{key}: has {arr.shape[0]} values but {first} has {n}; lengths must match")
    return 1 if n is None else n
