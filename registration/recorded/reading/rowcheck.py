"""Row validation of recorded files, with a reason for every bad row.

The numeric rules are those of the Python API: :func:`registration.online.contract.cell_problems` decides,
for every value converted to SI units and radians, whether it is finite, inside its column's
limits (latitude and angles, altitude) and, for a range, > 0. This module adds what only a file
can get wrong (a missing column, a cell that is not a number) and the timestamp rule, and turns
each problem into a reason in the file's own units.

Reasons (``code``: meaning):

* ``short_row`` / ``long_row``: the row's CSV line has fewer / more fields than the header (a line
  cut short by a recorder that stopped mid-write, a missing line break); checked first, so the
  cells a short line lacks are never read as empty (:mod:`registration.io.files.csvrows`);
* ``missing_column``: the file lacks a required column (every row gets this reason);
* ``non_numeric``: the cell is not a number (text, a boolean, a date, ...);
* ``non_finite``: the cell is empty, NaN or infinite;
* ``out_of_range``: a latitude or angle (or altitude) outside its limits;
* ``non_positive_range``: a range <= 0 m;
* ``time_backwards`` / ``time_duplicate``: the timestamp is below / equal to that of the previous
  accepted row (timestamps must be strictly increasing);
* ``filter_non_finite``: (set by the filter pass) the filter step for this row would have produced
  non-finite values, so the row was not used.

A row with several problems gets the first one, in column order (time first), a short or long
line before any; the timestamp order is checked only on rows that are otherwise valid, against
the last accepted row. In ``stop`` mode the first bad row raises :class:`BadRowError` naming file,
row, column and reason; in ``skip`` mode the block comes back with the row flagged, and the caller
writes it to ``rejected.csv``.
Rows are numbered from 0 (the first data row; a CSV header line is not a row).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field

import numpy as np

from registration.io.files.csvrows import SHAPE_COLUMN
from registration.io.files.ledger import RejectedRow
from registration.online.contract import (
    LIMITS,
    N_ROW,
    PROBLEM_NON_FINITE,
    PROBLEM_NON_POSITIVE,
    SENSOR_COLUMNS,
    SENSOR_ROW,
    SENSORS,
    cell_problems,
)
from registration.recorded.reading.columns import (
    NAV_KINDS,
    PLOT_KINDS,
    SYNC_FIELDS,
    TIME_FIELD,
    Field,
    sensor_fields,
)

__all__ = [
    "BadRowError",
    "Layout",
    "CheckedBlock",
    "Rejection",
    "check_frame",
    "sync_layout",
    "plot_layout",
    "nav_layout",
]

_NON_NUMERIC, _MISSING = 10, 11  # file-level codes beside contract.cell_problems' 1..3


class BadRowError(ValueError):
    """A bad row in ``stop`` mode: names the file, the row (from 0), the column and the reason."""

    def __init__(self, file: str, row: int, column: str, code: str, reason: str):
        self.file, self.row, self.column, self.code, self.reason = file, row, column, code, reason
        super().__init__(
            f"{file}: row {row}, column {column!r}: {reason} [{code}]; "
            "fix the row, or pass --on-bad-row skip to set bad rows aside in rejected.csv"
        )


@dataclass(frozen=True)
class Layout:
    """What a file must hold: its fields (time first) and where each lands in an 18-value row."""

    name: str  # "synchronous table", "plot file of radar A", ...
    fields: tuple[Field, ...]
    slots: tuple[int, ...]  # per non-time field: its index in the (K, 18) contract row

    @property
    def columns(self) -> tuple[str, ...]:
        return tuple(f.file_name for f in self.fields)


def _slot(sensor: str, kind: str) -> int:
    return SENSOR_ROW[sensor].start + SENSOR_COLUMNS.index(kind)


def sync_layout() -> Layout:
    return Layout("synchronous table", SYNC_FIELDS, tuple(range(N_ROW)))


def plot_layout(sensor: str, prefixed: bool, with_nav: bool) -> Layout:
    """A per-sensor plot file of radar ``sensor`` ('a' or 'b'), optionally with the ship's navigation."""
    kinds = (PLOT_KINDS + NAV_KINDS) if with_nav else PLOT_KINDS
    fields = (TIME_FIELD,) + sensor_fields(sensor if prefixed else "", kinds)
    return Layout(f"plot file of radar {sensor.upper()}", fields, tuple(_slot(sensor, k) for k in kinds))


def nav_layout(sensors: tuple[str, ...]) -> Layout:
    """A navigation file with the prefixed navigation columns of the given ships."""
    fields = (TIME_FIELD,) + tuple(f for s in sensors for f in sensor_fields(s, NAV_KINDS))
    slots = tuple(_slot(s, k) for s in sensors for k in NAV_KINDS)
    return Layout(f"navigation file of ship(s) {', '.join(s.upper() for s in sensors)}", fields, slots)


#: A row set aside: the rejected-row record of every table reader, with the row's cells as JSON text.
Rejection = RejectedRow


@dataclass
class CheckedBlock:
    """One validated block. ``values`` (K, F) in SI units/radians in layout field order (time first)."""

    first_row: int
    values: np.ndarray
    accepted: np.ndarray  # (K,) bool
    rejections: list[Rejection] = field(default_factory=list)
    last_time: float | None = None  # time of the last accepted row after this block

    @property
    def n_rows(self) -> int:
        return len(self.accepted)


def _to_float(col) -> tuple[np.ndarray, np.ndarray]:
    """Column -> (float64 values, non-numeric mask). Never raises."""
    import pandas as pd

    dtype = getattr(col, "dtype", None)
    kind = getattr(dtype, "kind", "O")
    if kind in "iuf":
        try:
            return np.asarray(col, dtype=np.float64), np.zeros(len(col), dtype=bool)
        except (TypeError, ValueError, OverflowError):
            pass
    if kind in "bcmM":  # booleans, complex numbers, dates: not measurements
        return np.full(len(col), np.nan), np.ones(len(col), dtype=bool)
    values = np.full(len(col), np.nan)
    non_numeric = np.zeros(len(col), dtype=bool)
    raw = list(col)
    try:
        conv = pd.to_numeric(pd.Series(raw, dtype=object), errors="coerce")
        if getattr(conv.dtype, "kind", "O") not in "iuf":
            raise TypeError("not a real dtype")
        values = np.asarray(conv, dtype=np.float64)
        for k in np.flatnonzero(np.isnan(values)).tolist():
            non_numeric[k] = not _is_missing(raw[k]) and not _is_nan_text(raw[k])
        for i, v in enumerate(raw):  # booleans and complex numbers hidden in an object column
            if isinstance(v, (bool, np.bool_, complex, np.complexfloating)):
                values[i], non_numeric[i] = np.nan, True
        return values, non_numeric
    except Exception:
        pass
    for i, v in enumerate(raw):  # cell by cell, for what pandas cannot convert in one go
        if _is_missing(v):
            continue
        if isinstance(v, (bool, np.bool_, complex, np.complexfloating, bytes)):
            non_numeric[i] = True
            continue
        try:
            values[i] = float(v)
        except (TypeError, ValueError, OverflowError):
            non_numeric[i] = True
    return values, non_numeric


def _is_missing(v) -> bool:
    if v is None:
        return True
    try:
        return bool(v != v) if isinstance(v, float) else (v is getattr(__import__("pandas"), "NA"))
    except Exception:
        return False


def _is_nan_text(v) -> bool:
    return isinstance(v, str) and v.strip().lower() in ("nan", "")


def _fmt(v: float) -> str:
    return repr(float(v)) if math.isfinite(v) else str(v)


def _limits_text(f: Field) -> tuple[float, float, str]:
    lo, hi, _ = LIMITS[f.kind]
    if f.unit == "deg":
        lo, hi = round(np.degrees(lo), 9), round(np.degrees(hi), 9)
    what = {"lat": "latitude", "alt": "altitude above the ellipsoid"}.get(f.kind, "angle")
    return lo, hi, f"{f.unit} ({what})"


def _reason(f: Field, code: int, raw, si: float) -> tuple[str, str]:
    if code == _MISSING:
        return "missing_column", f"the file has no column {f.file_name!r}"
    if code == _NON_NUMERIC:
        return "non_numeric", f"value {str(raw)[:60]!r} is not a number (expected {f.unit})"
    if code == PROBLEM_NON_FINITE:
        v = si / f.scale if f.kind != "time" else si
        text = "is empty or NaN" if v != v else f"{v} is not finite"
        return "non_finite", f"value {text}; expected a finite number in {f.unit}"
    if code == PROBLEM_NON_POSITIVE:
        return "non_positive_range", f"value {_fmt(si)} must be > 0 m (slant range)"
    lo, hi, unit = _limits_text(f)
    v = si / f.scale
    return "out_of_range", f"value {_fmt(v)} is outside [{lo:g}, {hi:g}] {unit}"


def _row_values(frame, i: int, columns) -> str:
    out = {}
    for c in columns:
        if c in frame:
            v = frame[c].iloc[i]
            if isinstance(v, (float, np.floating)) and not math.isfinite(v):
                v = str(float(v))
            elif isinstance(v, (np.integer, np.floating)):
                v = v.item()
            elif not isinstance(v, (int, float, str)) or isinstance(v, bool):
                v = str(v)
            out[c] = v
    return json.dumps(out)


def check_frame(
    frame, layout: Layout, file: str, *, first_row: int, mode: str = "stop", last_time: float | None = None
) -> CheckedBlock:
    """Validate one block of a file; see the module docstring for the rules and reasons.

    ``last_time``: time (s) of the last accepted row before this block (None at the start).
    Returns a :class:`CheckedBlock`; in ``stop`` mode raises :class:`BadRowError` for the first
    bad row instead.
    """
    if mode not in ("stop", "skip"):
        raise ValueError(f"mode: expected 'stop' or 'skip', got {mode!r}")
    k = len(frame)
    nf = len(layout.fields)
    values = np.full((k, nf), np.nan)
    codes = np.zeros((k, nf), dtype=np.int8)
    for j, f in enumerate(layout.fields):
        if f.file_name not in frame:
            codes[:, j] = _MISSING
            continue
        v, bad = _to_float(frame[f.file_name])
        values[:, j] = v * f.scale if f.scale != 1.0 else v
        codes[bad, j] = _NON_NUMERIC
    # numeric rules of the Python API, applied to the SI values placed in a contract row
    block = np.zeros((k, N_ROW))
    block[:, [_slot(s, "range") for s in SENSORS]] = 1.0  # ranges of absent sensors: a valid placeholder
    block[:, list(layout.slots)] = values[:, 1:]
    problems = cell_problems(block)[:, list(layout.slots)]
    sub = codes[:, 1:]
    sub[sub == 0] = problems[sub == 0]
    t = values[:, 0]
    tcode = codes[:, 0]
    tcode[(tcode == 0) & ~np.isfinite(t)] = PROBLEM_NON_FINITE

    shapes = frame[SHAPE_COLUMN].to_numpy() if SHAPE_COLUMN in frame else np.full(k, None)
    shaped = frame[SHAPE_COLUMN].notna().to_numpy() if SHAPE_COLUMN in frame else np.zeros(k, dtype=bool)
    field_bad = codes.any(axis=1) | shaped
    # timestamp order among the rows that are otherwise valid (see module docstring)
    prev = np.full(k, -np.inf if last_time is None else last_time)
    cand = np.flatnonzero(~field_bad)
    if cand.size:
        tc = t[cand]
        start = -np.inf if last_time is None else last_time
        running = np.maximum.accumulate(np.concatenate([[start], tc]))[:-1]
        prev[cand] = running
    order_bad = ~field_bad & (t <= prev)
    accepted = ~field_bad & ~order_bad
    new_last = float(t[accepted][-1]) if accepted.any() else last_time

    rejections: list[RejectedRow] = []
    bad_rows = np.flatnonzero(~accepted)
    for i in bad_rows:
        if shaped[i]:  # the line's fields do not match the header: its cells are not trusted
            column, code, reason = shapes[i].column, shapes[i].code, shapes[i].reason()
        elif field_bad[i]:
            j = int(np.argmax(codes[i] != 0))
            f = layout.fields[j]
            raw = frame[f.file_name].iloc[i] if f.file_name in frame else None
            code, reason = _reason(f, int(codes[i, j]), raw, values[i, j])
            column = f.file_name
        else:
            column = TIME_FIELD.file_name
            if t[i] == prev[i]:
                code, reason = (
                    "time_duplicate",
                    f"time {_fmt(t[i])} s is duplicated: the previous accepted row has the same time",
                )
            else:
                code, reason = (
                    "time_backwards",
                    f"time {_fmt(t[i])} s goes backwards: the previous accepted row is at {_fmt(prev[i])} s",
                )
        if mode == "stop":
            raise BadRowError(file, first_row + int(i), column, code, reason)
        cells = _row_values(frame, int(i), layout.columns)
        rejections.append(RejectedRow(file, first_row + int(i), column, code, reason, cells))
    return CheckedBlock(
        first_row=first_row, values=values, accepted=accepted, rejections=rejections, last_time=new_last
    )
