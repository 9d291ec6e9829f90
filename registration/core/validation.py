"""Input checks shared by every public function: clear errors naming the field, index and unit."""

from __future__ import annotations

import numpy as np

__all__ = [
    "as_float_array",
    "check_finite",
    "check_range",
    "check_positive",
    "check_latitude",
    "check_angle",
    "check_altitude",
    "broadcast_1d",
    "degree_hint",
    "DEGREE_HINT",
    "HALF_PI",
    "LATITUDE_SLACK",
    "ALTITUDE_LIMITS_M",
    "TIME_LIMIT_S",
]

HALF_PI = np.pi / 2
#: Latitudes up to this much beyond +-pi/2 (rad) are accepted and clipped: float32 pi/2 rounds
#: 4.4e-8 rad above the float64 value.
LATITUDE_SLACK = 1e-7
#: Accepted heights above the WGS-84 ellipsoid (m), for platforms and targets alike: from below the
#: deepest ocean trench to the top of low Earth orbit.
ALTITUDE_LIMITS_M = (-12_000.0, 1_000_000.0)
#: Accepted times (s), plots, navigation and references alike: within +-1e11 s, which holds Unix
#: seconds to the year 5138 and keeps the microsecond ticks the windows are keyed on within int64.
TIME_LIMIT_S = 1.0e11


def as_float_array(name: str, value) -> np.ndarray:
    """``value`` as float64; refuses None, booleans, strings and other non-numbers, naming ``name``."""
    arr = np.asarray(value, dtype=object) if value is None else np.asarray(value)
    if arr.dtype.kind in "biufc" and arr.dtype.kind not in "bc":
        return arr.astype(np.float64, copy=False)
    if arr.dtype.kind == "O":
        converted: np.ndarray | None
        try:
            converted = arr.astype(np.float64)
        except (TypeError, ValueError):
            converted = None
        if converted is not None and not any(
            v is None or isinstance(v, (bool, np.bool_, str))
            for v in np.ravel(np.asarray(value, dtype=object))
        ):
            return converted
    if value is None or isinstance(value, (str, bytes, bool, np.bool_)):
        what = repr(value)
    else:
        what = f"a {type(value).__name__} holding non-numbers (None, booleans or strings)"
    raise ValueError(f"{name}: expected numbers, got {what}")


def _at(mask: np.ndarray) -> str:
    """' at index i' for the first True of mask, or '' for a scalar."""
    if mask.ndim == 0:
        return ""
    idx = np.argwhere(mask)[0]
    return f" at index {tuple(int(i) for i in idx) if mask.ndim > 1 else int(idx[0])}"


def check_finite(name: str, arr: np.ndarray, unit: str) -> None:
    bad = ~np.isfinite(arr)
    if bad.any():
        v = arr[tuple(np.argwhere(bad)[0])] if arr.ndim else arr
        raise ValueError(f"{name}: non-finite value {v}{_at(bad)}; expected a finite number in {unit}")


#: The one wording of the hint given when radians were expected and degrees seem to have come.
DEGREE_HINT = " (these look like degrees: convert with numpy.radians)"


def degree_hint(arr: np.ndarray, limit: float) -> str:
    """:data:`DEGREE_HINT` when the largest |value| lies in (limit, 360], else ''."""
    with np.errstate(invalid="ignore"):
        peak = np.nanmax(np.abs(arr)) if np.size(arr) else 0.0
    return DEGREE_HINT if limit < peak <= 360.0 else ""


def check_range(
    name: str, arr: np.ndarray, low: float, high: float, unit: str, *, angle: bool = False
) -> None:
    """Raise if any value lies outside [low, high]; hint when radians were expected and degrees came."""
    if arr.size and np.min(arr) >= low and np.max(arr) <= high:  # fast path (NaN/inf fail it)
        return
    check_finite(name, arr, unit)
    bad = (arr < low) | (arr > high)
    if bad.any():
        v = arr[tuple(np.argwhere(bad)[0])] if arr.ndim else arr
        hint = degree_hint(arr, max(abs(low), abs(high))) if angle else ""
        raise ValueError(f"{name}: value {v}{_at(bad)} is outside [{low:g}, {high:g}] {unit}{hint}")


def check_positive(name: str, arr: np.ndarray, unit: str) -> None:
    if arr.size and np.min(arr) > 0 and np.isfinite(np.max(arr)):  # fast path
        return
    check_finite(name, arr, unit)
    bad = arr <= 0
    if bad.any():
        v = arr[tuple(np.argwhere(bad)[0])] if arr.ndim else arr
        raise ValueError(f"{name}: value {v}{_at(bad)} must be > 0 {unit}")


def check_latitude(name: str, arr: np.ndarray) -> np.ndarray:
    """Latitudes in rad within [-pi/2, pi/2] (float32 rounding tolerated); returns them clipped to it."""
    check_range(
        name,
        arr,
        -HALF_PI - LATITUDE_SLACK,
        HALF_PI + LATITUDE_SLACK,
        "rad (latitude, [-pi/2, pi/2])",
        angle=True,
    )
    if arr.size and np.max(np.abs(arr)) > HALF_PI:
        return np.clip(arr, -HALF_PI, HALF_PI)
    return arr


def check_altitude(name: str, arr: np.ndarray) -> None:
    """Heights in m above the WGS-84 ellipsoid within :data:`ALTITUDE_LIMITS_M`."""
    check_range(name, arr, *ALTITUDE_LIMITS_M, "m above the WGS-84 ellipsoid")


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
