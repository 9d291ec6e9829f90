"""The registration state of SPEC section 2: names, labels and units, in one place."""

from __future__ import annotations

import numpy as np

#: State order (SPEC section 2): per sensor, attitude errors then radar biases.
STATE_NAMES = (
    "dC_a", "dphi_a", "dtheta_a", "dr_a", "dq_a", "de_a",
    "dC_b", "dphi_b", "dtheta_b", "dr_b", "dq_b", "de_b",
)
N_STATE = len(STATE_NAMES)
_LABELS = ("heading error", "pitch error", "roll error", "range bias", "bearing bias", "elevation bias")
STATE_LABELS = tuple(f"{lab} {s}" for s in ("A", "B") for lab in _LABELS)
#: True where the state is an angle (radians); the others are ranges (metres).
IS_ANGLE = np.array([True, True, True, False, True, True] * 2)
STATE_UNITS = tuple("rad" if a else "m" for a in IS_ANGLE)

#: The measurement columns of the data contract, per sensor prefix, in ``row`` order.
SENSOR_COLUMNS = ("lat", "lon", "alt", "heading", "pitch", "roll", "range", "bearing", "elevation")
SENSOR_UNITS = ("rad", "rad", "m", "rad", "rad", "rad", "m", "rad", "rad")
DATA_COLUMNS = ("time",) + tuple(f"{p}_{c}" for p in ("a", "b") for c in SENSOR_COLUMNS)


def to_display(values: np.ndarray) -> np.ndarray:
    """Angles in degrees, ranges in metres (for tables and plots only)."""
    values = np.asarray(values, dtype=float)
    return np.where(IS_ANGLE, np.degrees(values), values)


def display_unit(i: int) -> str:
    return "deg" if IS_ANGLE[i] else "m"
