"""The online registration's data contract: the 12-state vector, the 18-value row, limits and checks.

A row holds one synchronous pair of plots of a common target, radar A then radar B, each as
``lat, lon, alt, heading, pitch, roll, range, bearing, elevation`` (SI units, radians; the
data-mapping column names are ``a_lat`` ... ``b_elevation`` beside ``time`` in seconds). The state
holds per ship the heading, pitch and roll errors and the radar's range, bearing and elevation
biases (Wang et al. 2011, the state of eq. (18)). Every entry point (batch, streaming, files)
checks rows with :func:`cell_problems`, so they apply the same rules.
"""

from __future__ import annotations

import operator
from typing import Mapping

import numpy as np

from registration.core.angles import wrap_angle
from registration.core.validation import ALTITUDE_LIMITS_M, degree_hint

__all__ = [
    "STATE_NAMES",
    "STATE_LABELS",
    "STATE_UNITS",
    "IS_ANGLE",
    "N_STATE",
    "SENSORS",
    "SENSOR_COLUMNS",
    "DATA_COLUMNS",
    "ROW_COLUMNS",
    "N_ROW",
    "SENSOR_ROW",
    "SENSOR_STATE",
    "NAV",
    "ATTITUDE",
    "PLOT",
    "LIMITS",
    "PROBLEM_OK",
    "PROBLEM_NON_FINITE",
    "PROBLEM_OUT_OF_RANGE",
    "PROBLEM_NON_POSITIVE",
    "cell_problems",
    "check_rows",
    "check_times",
    "row_error",
    "validate_data",
    "row_from_mapping",
    "correct_rows",
    "to_display",
    "display_unit",
]

#: The radars of a row, in order, and the prefixes of their columns.
SENSORS = ("a", "b")
#: State order: per sensor, attitude errors then radar biases.
STATE_NAMES = (
    "dC_a",
    "dphi_a",
    "dtheta_a",
    "dr_a",
    "dq_a",
    "de_a",
    "dC_b",
    "dphi_b",
    "dtheta_b",
    "dr_b",
    "dq_b",
    "de_b",
)
N_STATE = len(STATE_NAMES)
STATE_LABELS = tuple(
    f"{lab} {s.upper()}"
    for s in SENSORS
    for lab in ("heading error", "pitch error", "roll error", "range bias", "bearing bias", "elevation bias")
)
#: True where the state is an angle (radians); the others are ranges (metres).
IS_ANGLE = np.array([True, True, True, False, True, True] * 2)
STATE_UNITS = tuple("rad" if a else "m" for a in IS_ANGLE)

#: The measurement columns of one sensor, in row order.
SENSOR_COLUMNS = ("lat", "lon", "alt", "heading", "pitch", "roll", "range", "bearing", "elevation")
#: Contract names of the 18 row columns (``time`` excluded), in row order.
ROW_COLUMNS = tuple(f"{p}_{c}" for p in SENSORS for c in SENSOR_COLUMNS)
DATA_COLUMNS = ("time",) + ROW_COLUMNS
N_ROW = len(ROW_COLUMNS)
#: Named slices: a sensor's 9 values in the row, and within them navigation, attitude and plot.
SENSOR_ROW = {s: slice(9 * i, 9 * i + 9) for i, s in enumerate(SENSORS)}
SENSOR_STATE = {s: slice(6 * i, 6 * i + 6) for i, s in enumerate(SENSORS)}
NAV, ATTITUDE, PLOT = slice(0, 6), slice(3, 6), slice(6, 9)

#: Accepted window (low, high, unit text) of each column kind, SI units; ranges must be > 0 m.
LIMITS = {
    "lat": (-np.pi / 2, np.pi / 2, "rad (latitude, [-pi/2, pi/2])"),
    "lon": (-2 * np.pi, 2 * np.pi, "rad"),
    "alt": (*ALTITUDE_LIMITS_M, "m above the WGS-84 ellipsoid"),
    "heading": (-2 * np.pi, 2 * np.pi, "rad"),
    "pitch": (-np.pi / 2, np.pi / 2, "rad"),
    "roll": (-np.pi / 2, np.pi / 2, "rad"),
    "bearing": (-2 * np.pi, 2 * np.pi, "rad"),
    "elevation": (-np.pi / 2, np.pi / 2, "rad"),
}

#: Problem codes of :func:`cell_problems`, in the order of precedence within one cell.
PROBLEM_OK, PROBLEM_NON_FINITE, PROBLEM_OUT_OF_RANGE, PROBLEM_NON_POSITIVE = 0, 1, 2, 3

_KIND = [SENSOR_COLUMNS[j % 9] for j in range(N_ROW)]
_IS_RANGE = np.array([k == "range" for k in _KIND])
_LOW = np.array([-np.inf if k == "range" else LIMITS[k][0] for k in _KIND])
_HIGH = np.array([np.inf if k == "range" else LIMITS[k][1] for k in _KIND])


def cell_problems(block: np.ndarray) -> np.ndarray:
    """Problem code of every cell of a (K, 18) block in row order (SI units, radians).

    0: fine; 1: not finite; 2: outside the column's :data:`LIMITS`; 3: a range that is not > 0 m.
    A non-finite cell is reported as non-finite only.
    """
    block = np.asarray(block, dtype=np.float64)
    with np.errstate(invalid="ignore"):
        out_of_range = (block < _LOW) | (block > _HIGH)
        non_positive = _IS_RANGE & (block <= 0)
    codes = np.where(
        non_positive, PROBLEM_NON_POSITIVE, np.where(out_of_range, PROBLEM_OUT_OF_RANGE, PROBLEM_OK)
    ).astype(np.int8)
    codes[~np.isfinite(block)] = PROBLEM_NON_FINITE
    return codes


def row_error(row: int, column: str, value, expected: str) -> ValueError:
    """The error for one bad cell: ``row R, column 'C': value V <expected>``."""
    return ValueError(f"row {row}, column {column!r}: value {value!r} {expected}")


def check_rows(block: np.ndarray, first_row: int = 0) -> None:
    """Check a (K, 18) block of rows; raise ValueError naming the first bad row and column."""
    codes = cell_problems(block)
    if not codes.any():
        return
    r, c = (int(v) for v in np.argwhere(codes)[0])  # first bad cell in row-major order
    code = codes[r, c]
    if code == PROBLEM_NON_FINITE:
        msg = "is not finite; expected a number"
    elif code == PROBLEM_NON_POSITIVE:
        msg = "must be > 0 m (slant range)"
    else:
        lo, hi, unit = LIMITS[_KIND[c]]
        msg = f"is outside [{lo:g}, {hi:g}] {unit}"
        if unit.startswith("rad"):
            msg += degree_hint(block[:, c], max(abs(lo), abs(hi)))
    raise row_error(first_row + r, ROW_COLUMNS[c], float(block[r, c]), msg)


def check_times(times: np.ndarray, first_row: int = 0, previous: float | None = None) -> None:
    """Raise ValueError naming the first time (s) that is not finite or does not increase."""
    if not np.isfinite(times).all():
        r = int(np.argmax(~np.isfinite(times)))
        raise row_error(first_row + r, "time", float(times[r]), "is not finite; expected seconds")
    prev = np.concatenate([[-np.inf if previous is None else previous], times[:-1]])
    if (times <= prev).any():
        r = int(np.argmax(times <= prev))
        raise row_error(
            first_row + r,
            "time",
            float(times[r]),
            f"does not increase (previous: {prev[r]!r}); timestamps must be strictly increasing",
        )


def validate_data(data: Mapping) -> tuple[np.ndarray, np.ndarray]:
    """Check a data mapping (dict of arrays or DataFrame); return ``time (K,)`` in s and ``rows (K, 18)``.

    Raises ValueError naming the row and column of the first problem: a missing column, a
    non-finite value, a latitude or angle out of range, a non-positive range, or a timestamp that
    does not increase.
    """
    missing = [c for c in DATA_COLUMNS if c not in data]
    if missing:
        raise ValueError(
            f"missing column(s) {missing}; expected {list(DATA_COLUMNS)} (SI units, radians)"
            + _file_columns_hint(data)
        )
    cols = []
    for name in DATA_COLUMNS:
        try:
            cols.append(np.asarray(data[name], dtype=np.float64))
        except (TypeError, ValueError) as exc:
            raise ValueError(f"column {name!r}: expected numbers ({exc})") from exc
        if cols[-1].ndim != 1:
            raise ValueError(
                f"column {name!r}: expected a 1-D array with one value per row, got "
                + ("a single value" if cols[-1].ndim == 0 else f"shape {cols[-1].shape}")
            )
    k = cols[0].shape
    for name, col in zip(DATA_COLUMNS, cols):
        if col.shape != k:
            raise ValueError(
                f"column {name!r}: {col.shape[0]} values, but 'time' has {k[0]}; one value per row"
            )
    if k[0] == 0:
        raise ValueError("data has no rows")
    time = cols[0]
    check_times(time)
    rows = np.stack(cols[1:], axis=1)
    check_rows(rows)
    return time, rows


def _file_columns_hint(data) -> str:
    """A pointer to the file reader when ``data`` carries
    file column names (``*_deg``, ``*_m``, ``time_s``)."""
    names = [str(c) for c in (data.columns if hasattr(data, "columns") else data)]
    if any(n.endswith(("_deg", "_m")) or n == "time_s" for n in names):
        return (
            "; these are the file columns (degrees, metres): read the file with "
            "registration.recorded.read_table(path), which converts them to this contract"
        )
    return ""


_ROW_CELLS = operator.itemgetter(*ROW_COLUMNS)
#: The last pandas index seen by :func:`_plain_row` and the positions of the row columns in it.
_SERIES_POSITIONS: tuple = (None, None)


def _series_positions(index) -> np.ndarray:
    """Positions of :data:`ROW_COLUMNS` in a pandas index (looked up once per index object:
    the rows of ``DataFrame.iterrows()`` share theirs); KeyError if one is missing."""
    global _SERIES_POSITIONS
    seen, positions = _SERIES_POSITIONS
    if seen is not index:
        positions = index.get_indexer(ROW_COLUMNS)
        if (positions < 0).any():
            raise KeyError("missing column")
        _SERIES_POSITIONS = (index, positions)
    return positions


def _plain_row(row) -> np.ndarray | None:
    """The 18 values of a mapping row (dict or pandas Series) whose cells are single numbers, in
    one conversion (the same float64 values as the cell-by-cell path); None for anything else,
    which the cell-by-cell path then converts or names."""
    try:
        if hasattr(row, "to_numpy") and hasattr(row, "index"):  # a pandas Series: label lookups are slow
            cells = row.to_numpy()[_series_positions(row.index)]
        else:
            cells = _ROW_CELLS(row)
        values = np.array(cells, dtype=np.float64)
    except Exception:  # noqa: BLE001 - any problem: the cell-by-cell path says what it is
        return None
    return values if values.shape == (N_ROW,) else None


def row_from_mapping(row: Mapping | np.ndarray) -> np.ndarray:
    """One row as 18 float64 values: from a mapping with the contract columns or a sequence in row order."""
    if isinstance(row, (np.ndarray, list, tuple)):
        arr = np.asarray(row, dtype=np.float64)
        if arr.shape != (N_ROW,):
            raise ValueError(
                f"row: expected {N_ROW} values in contract order (a_lat ... b_elevation), got shape "
                f"{arr.shape}"
            )
        return arr
    values = _plain_row(row)
    if values is not None:
        return values
    missing = [c for c in ROW_COLUMNS if c not in row]
    if missing:
        raise ValueError(f"row: missing column(s) {missing}" + _file_columns_hint(row))
    values = np.empty(N_ROW)
    for j, c in enumerate(ROW_COLUMNS):
        try:
            cell = np.asarray(row[c], dtype=np.float64).reshape(-1)
        except (TypeError, ValueError) as exc:
            raise ValueError(f"row: column {c!r}: expected a number ({exc})") from exc
        if cell.size != 1:
            raise ValueError(
                f"row: column {c!r} holds {cell.size} values; update() takes one row (use update_block for "
                "several)"
            )
        values[j] = cell[0]
    return values


def correct_rows(rows: np.ndarray, estimates: np.ndarray) -> np.ndarray:
    """Rows (K, 18) corrected by estimates (K, 12): attitude and plot minus the errors, bearings wrapped."""
    out = np.array(rows, dtype=np.float64)
    for s in SENSORS:
        cols = out[:, SENSOR_ROW[s]]
        cols[:, ATTITUDE.start :] -= estimates[:, SENSOR_STATE[s]]
        cols[:, 7] = wrap_angle(cols[:, 7])
    return out


def to_display(values: np.ndarray) -> np.ndarray:
    """State values with angles in degrees and ranges in metres (for tables and plots only)."""
    values = np.asarray(values, dtype=float)
    return np.where(IS_ANGLE, np.degrees(values), values)


def display_unit(i: int) -> str:
    """'deg' or 'm': the display unit of state ``i``."""
    return "deg" if IS_ANGLE[i] else "m"
