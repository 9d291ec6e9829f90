"""One fleet file read: its columns checked cell by cell in file units (degrees, metres, seconds)
and converted to the columns of :mod:`registration.fleet.data.tables` (SI units, radians), with its bad
rows (:class:`~registration.io.fleet.reading.rejects.BadRows`) and what it notes. The files, their columns
and the rules: :mod:`registration.io.fleet.reading.read`; the whole-file checks:
:mod:`registration.io.fleet.reading.checks`. A CSV line with fewer or more fields than the header is a
bad row (``short_row``, ``long_row``) before any of its cells is looked at.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from registration.io.files.csvrows import NA_TEXTS
from registration.io.files.unreadable import read_error
from registration.io.fleet.reading.checks import attitude_check, radians_check, sigma_notes
from registration.io.fleet.reading.rejects import BadRows
from registration.io.fleet.schema import FLEET_FILES, HELD, INF_ALLOWED, POSITIVE, held

__all__ = ["FILE_COLUMNS", "MEASURED", "OPTIONAL_IDS", "FileRead", "check_frame", "read_file"]

#: Per table: (file column, table column, unit, required, (low, high) accepted in file units), the
#: columns of :data:`registration.io.fleet.schema.FLEET_FILES` without their texts. unit "id" = an
#: identifier; "deg" columns are converted to radians.
FILE_COLUMNS: dict[str, tuple[tuple[str, str, str, bool, tuple[float, float] | None], ...]] = {
    name: tuple((c.file, c.column, c.unit, c.required, c.limits) for c in table.columns)
    for name, table in FLEET_FILES.items()
}
#: The measured columns of the plots: an empty cell is "not measured", a NaN (the text ``nan``) a
#: bad row (``non_finite``).
MEASURED = ("range_m", "bearing_deg", "elevation_deg")
#: Id columns of a table whose empty cells mean "no id" (not an error): a plot without a target id is
#: associated (registration.fleet.association), one without a track id is tracked by the association.
OPTIONAL_IDS = {"plots": ("target", "track", "kind"), "targets": ("name",), "sensors": ("channel_of",)}


def _read_frame(path: Path):
    """A CSV or Parquet file (or a folder of Parquet files) as a DataFrame, id columns as text; a CSV
    frame with a line of fewer or
    more fields than the header also has the column SHAPE_COLUMN (:mod:`registration.io.files.csvrows`)."""
    import pandas as pd

    from registration.io.files.csvrows import read_csv_blocks
    from registration.io.files.tablefile import file_format

    frame: Any  # a DataFrame
    fmt = "parquet" if path.is_dir() else file_format(path)  # a folder: a Parquet dataset
    if not path.exists():
        raise ValueError(f"{path}: no such file")
    try:
        if fmt == "csv":
            blocks = list(
                read_csv_blocks(
                    path,
                    dtype={
                        "sensor": str,
                        "platform": str,
                        "target": str,
                        "track": str,
                        "kind": str,
                        "channel_of": str,
                    },
                    nan_text=MEASURED,
                )
            )
            frame = pd.concat(blocks, ignore_index=True) if len(blocks) > 1 else blocks[0]
        else:
            frame = pd.read_parquet(path)
    except Exception as exc:  # pandas/pyarrow parse errors of many types
        if str(exc).startswith(f"{path}: "):  # our own CSV reader's error names the file already
            raise ValueError(str(exc)) from exc
        raise read_error(path, exc, f"cannot read it as {fmt.upper()}") from exc
    frame.columns = [str(c).strip() for c in frame.columns]
    return frame


def _id_column(bad: BadRows, frame, column: str, required: bool = True) -> np.ndarray:
    """An id column as text; an empty cell is a bad row (``empty_id``) when ``required``, else ''."""
    values = frame[column]
    missing = values.isna().to_numpy()
    if required:
        bad.add(column, "empty_id", missing, lambda r: "empty; every row needs an id")
    text = np.array([str(v).strip() for v in values], dtype=object).astype(str)
    return np.where(missing, "", text) if text.size else text


def _float_or_nan(cell: object) -> float:
    """A cell as float() reads its text (a huge integer is inf), NaN where it is not a number."""
    try:
        return float(str(cell).strip())
    except ValueError:
        return math.nan


def _number_column(bad: BadRows, frame, column: str, unit: str, required: bool, limits) -> np.ndarray:
    """Numbers in file units; NaN for an empty optional cell. Problems name file, row, column, unit."""
    import pandas as pd

    raw = frame[column]
    try:
        values = pd.to_numeric(raw, errors="coerce").to_numpy(dtype=np.float64)
    except OverflowError:  # pandas, on an integer of hundreds of digits: cell by cell, as float() reads it
        values = np.array([_float_or_nan(v) for v in raw], dtype=np.float64)
    text = raw.astype(str).str.strip()
    given = raw.notna().to_numpy() & ~text.isin(["", "nan", "NaN"]).to_numpy()
    if column in MEASURED:
        bad.add(
            column,
            "non_finite",
            raw.notna().to_numpy() & text.isin(NA_TEXTS).to_numpy(),
            lambda r: (
                f"{raw.iloc[r]!r} is not a measurement ({unit}); leave the cell empty where the sensor "
                "does not measure it"
            ),
        )
    bad.add(
        column, "non_numeric", given & np.isnan(values), lambda r: f"{raw.iloc[r]!r} is not a number ({unit})"
    )
    if required:
        bad.add(
            column, "non_finite", np.isnan(values), lambda r: f"empty or NaN; a number ({unit}) is required"
        )
    lo, hi = limits if limits is not None else (-math.inf, math.inf)
    strict = column in POSITIVE
    finite_only = not ((column.startswith("prior_") or column in INF_ALLOWED) and hi == math.inf)
    out = ((values <= lo) if strict else (values < lo)) | (values > hi) | (finite_only & np.isinf(values))
    span = f"{'(' if strict else '['}{lo:g}, {hi:g}]"

    def code(r: int) -> str:
        if np.isinf(values[r]):
            return "non_finite"
        return "non_positive_range" if column == "range_m" and values[r] <= 0 else "out_of_range"

    bad.add(column, code, out, lambda r: f"{values[r]:g} {unit} is outside {span} {unit}")
    if held(column):
        size = np.abs(values)
        beyond = ~out & np.isfinite(values) & (size > 0) & ((size < HELD[0]) | (size > HELD[1]))
        bad.add(
            column,
            "out_of_range",
            beyond,
            lambda r: (
                f"{values[r]:g} {unit} cannot be held: a sigma or prior lies within [{HELD[0]:g}, "
                f"{HELD[1]:g}] {unit} (a prior may also be 0 or inf), as the solve squares and inverts it"
            ),
        )
    return values


@dataclass
class FileRead:
    """One fleet file read: its ``table`` (SI units, radians), its ``bad`` rows, its ``numbers`` in file
    units (NaN where bad), its ``columns``, ``notes``, and ``file_rows``, the file row of each table
    row where rows were left out (navigation rows of platforms without sensors), else None."""

    table: dict
    bad: BadRows
    numbers: dict
    columns: list
    notes: list
    file_rows: np.ndarray | None = None


def _used_platforms(frame, shapes, platforms: set, path: Path):
    """The navigation rows of ``platforms`` (and those without an id, which are bad rows): (frame,
    shapes, their file rows or None, notes naming the platforms left out)."""
    ids = frame["platform"]
    keep = ids.isna().to_numpy() | ids.astype(str).str.strip().isin(platforms).to_numpy()
    if keep.all():
        return frame, shapes, None, []
    extra = sorted({str(v).strip() for v in ids[~keep].unique()})
    rows = np.flatnonzero(keep)
    note = (
        f"{path}: platform(s) {extra} carry no sensor; their {int((~keep).sum())} navigation rows are "
        "ignored "
        f"(platforms used: {sorted(platforms)})"
    )
    return (
        frame.iloc[rows].reset_index(drop=True),
        None if shapes is None else shapes.iloc[rows].reset_index(drop=True),
        rows,
        [note],
    )


def read_file(name: str, path: Path, skip: bool, platforms: set | None = None) -> FileRead:
    """One file -> :class:`FileRead` (table columns of :mod:`registration.fleet.data.tables`); ``skip``
    False: the first bad cell raises. ``platforms``: for the navigation, the platforms used."""
    return check_frame(name, path, _read_frame(path), skip, platforms)


def check_frame(
    name: str,
    path: Path,
    frame,
    skip: bool,
    platforms: set | None = None,
    first_row: int = 0,
    whole_file: bool = True,
) -> FileRead:
    """:func:`read_file` on rows already read: ``frame`` (a DataFrame of :func:`_read_frame`'s kind, or
    a block of :func:`~registration.io.files.csvrows.read_csv_blocks`) holds the file's data rows
    from ``first_row`` on, and the errors and bad rows name file rows. ``whole_file`` False: the
    checks that need the whole file (radians in degree columns, attitudes, sigma notes) are left to
    the caller, and an empty block is not an error."""
    from registration.io.files.csvrows import SHAPE_COLUMN

    shapes = frame.pop(SHAPE_COLUMN) if SHAPE_COLUMN in frame.columns else None
    spec = FILE_COLUMNS[name]
    missing = [c for c, _, _, req, _ in spec if req and c not in frame.columns]
    if missing:
        raise ValueError(
            f"{path}: missing column(s) {missing}; the {name} table has columns "
            f"{[c for c, *_ in spec]} (columns found: {list(frame.columns)})"
        )
    known = {c for c, *_ in spec}
    unknown = [c for c in frame.columns if c not in known]
    if unknown:
        raise ValueError(f"{path}: unknown column(s) {unknown}; the {name} table has columns {sorted(known)}")
    if len(frame) == 0 and whole_file:
        raise ValueError(
            f"{path}: no data rows (the file holds only a header); the {name} file needs at least one row"
        )
    notes, file_rows = [], None
    if platforms is not None:
        frame, shapes, file_rows, notes = _used_platforms(frame, shapes, platforms, path)
    if first_row:
        file_rows = first_row + (np.arange(len(frame)) if file_rows is None else file_rows)
    bad = BadRows(path, len(frame), skip, file_rows)
    if shapes is not None:  # first: the cells a short line lacks are not empty cells
        shape = shapes.to_numpy()
        bad.add(
            lambda r: shape[r].column,
            lambda r: shape[r].code,
            shapes.notna().to_numpy(),
            lambda r: shape[r].reason(),
        )
    numbers, out = {}, {}
    for column, key, unit, required, limits in spec:
        if column not in frame.columns:
            continue
        if unit == "id":
            out[key] = _id_column(bad, frame, column, column not in OPTIONAL_IDS.get(name, ()))
            continue
        numbers[column] = _number_column(bad, frame, column, unit, required, limits)
        out[key] = np.radians(numbers[column]) if unit == "deg" else numbers[column]
        if column.startswith("prior_"):
            out[key] = np.where(np.isnan(out[key]), np.inf, out[key])  # empty: no prior
        elif column.startswith("lever_"):
            out[key] = np.where(np.isnan(out[key]), 0.0, out[key])  # empty: the default, 0
    ok = bad.ok()
    numbers = {c: np.where(ok, v, np.nan) for c, v in numbers.items()}
    if whole_file:
        radians_check(path, numbers)
        if name == "navigation":
            notes += attitude_check(path, numbers, out["platform"])
        elif name == "sensors":
            notes += sigma_notes(path, numbers, out["sensor"])
    return FileRead(out, bad, numbers, list(frame.columns), notes, file_rows)
