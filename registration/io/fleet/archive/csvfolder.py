"""A folder of fleet CSV files as an archive for the partitioned solver (docs/howto/register-an-archive.md,
"Files"):
:func:`parquet_from_csv` converts it, block by block, into a Parquet folder that
:class:`registration.io.fleet.archive.parquet.ParquetSource` reads.

The plots, navigation and reference CSV files are read in blocks of whole lines
(:func:`registration.io.files.csvrows.read_csv_blocks`, ``block_bytes`` each), every block checked
cell by cell as the ordinary reader checks a whole file
(:func:`registration.io.fleet.reading.cells.check_frame`:
the same errors naming the file, the file row, the column and its unit; the first bad row of a
file stops the run, as ``--on-bad-row stop`` does) and written as one row group of
``<table>.parquet`` in file units. Memory is bounded by a block. The sensors, platforms and targets files
(small) are read whole by the ordinary reader and copied. Tables given as Parquet are linked.

The checks that need a whole file are made on what the blocks leave: the radians-in-degree-columns
check (:func:`~registration.io.fleet.reading.checks.radians_check`, on the largest value per column and
the count), unknown sensors and platforms. The heading check runs per block (a block holds
thousands of navigation rows). Plots without a target id keep an empty ``target`` (they are
associated partition by partition, :mod:`registration.fleet.association.partitioned`). Row groups
follow the file's order, so a plots file in time order keeps each partition's reads small.
"""

from __future__ import annotations

import math
import os
import re
import shutil
from pathlib import Path
from typing import Any

import numpy as np

from registration.fleet.data.tables import DEFAULT_REFERENCE_SIGMA
from registration.io.fleet.folder import tables_in_folder
from registration.io.fleet.reading.cells import FILE_COLUMNS, check_frame, read_file
from registration.io.fleet.reading.checks import attitude_check

__all__ = ["csv_tables", "parquet_from_csv"]

_IDS = {"sensor": str, "platform": str, "target": str, "track": str, "kind": str}
#: Per table: the degree columns whose values are checked together for radians, and their bound.
_RADIANS = {
    "plots": (("bearing_deg", 2 * math.pi),),
    "reference": (("lat_deg", math.pi / 2), ("lon_deg", 2 * math.pi)),
    "navigation": (("lat_deg", math.pi / 2), ("lon_deg", 2 * math.pi)),
}


def csv_tables(folder) -> bool:
    """True when the archive folder gives some lazily read table (plots, navigation, reference) as CSV."""
    folder = Path(folder)
    return any(
        (folder / f"{n}.csv").is_file()
        and not (folder / f"{n}.parquet").exists()
        and not (folder / n).is_dir()
        for n in ("plots", "navigation", "reference")
    )


class _Radians:
    """The radians check of :func:`~registration.io.fleet.reading.checks.radians_check` over a file's blocks:
    per column the values given, the largest magnitude and its file row, whether some value is not 0."""

    def __init__(self, table: str):
        self.columns = _RADIANS.get(table, ())
        self.n = {c: 0 for c, _ in self.columns}
        self.peak = {c: (-1.0, 0, 0.0) for c, _ in self.columns}
        self.nonzero = False

    def add(self, numbers: dict, first_row: int) -> None:
        for c, _ in self.columns:
            v = numbers.get(c)
            if v is None:
                continue
            finite = np.isfinite(v)
            self.n[c] += int(finite.sum())
            if finite.any():
                r = int(np.nanargmax(np.abs(v)))
                if abs(v[r]) > self.peak[c][0]:
                    self.peak[c] = (abs(float(v[r])), first_row + r, float(v[r]))
                self.nonzero |= bool(np.any(v[finite] != 0))

    def check(self, path: Path) -> None:
        from registration.io.fleet.reading.checks import MIN_UNIT_CHECK_VALUES

        cols = [c for c, _ in self.columns]
        if not cols or min(self.n.values()) < MIN_UNIT_CHECK_VALUES or not self.nonzero:
            return
        if all(self.peak[c][0] <= bound for c, bound in self.columns):
            peak, row, value = self.peak[cols[0]]
            raise ValueError(
                f"{path}: row {row}, column {cols[0]!r}: all {self.n[cols[0]]} values of "
                f"{' and '.join(repr(n) for n in cols)} lie within +-{peak:.3g} (the largest here, "
                f"{value:.4g}): radians? These columns are in degrees"
            )


def _shifted(exc: ValueError, first_row: int) -> ValueError:
    """An error of a block naming a row, with the block's row made the file's."""
    return ValueError(
        re.sub(r": row (\d+),", lambda m: f": row {int(m.group(1)) + first_row},", str(exc), count=1)
    )


def _first_bad(read, extra: list) -> None:
    """Raise the earliest bad row of a block (as the ordinary reader's stop mode names it)."""
    rejected = read.bad.rejected() + extra
    if rejected:
        r = min(rejected, key=lambda r: r.row)
        raise ValueError(f"{r.file}: row {r.row}, column {r.column!r}: {r.reason}")


def _unknown(path: Path, read, column: str, known: set, other: Path, first_row: int) -> list:
    from registration.io.fleet.reading.rejects import RejectedRow

    values = np.asarray(read.table[column]).astype(str)
    bad = np.flatnonzero(~np.isin(values, list(known)) & read.bad.ok())
    rows = read.file_rows if read.file_rows is not None else first_row + np.arange(values.size)
    return [
        RejectedRow(
            str(path),
            int(rows[i]),
            column,
            f"unknown_{column}",
            f"unknown {column} {str(values[i])!r}; {other} lists {sorted(known)}",
        )
        for i in bad[:1]
    ]


def _reference_rows(path: Path, read) -> list:
    """The reference file's own rules (as the ordinary reader's): a position as lat/lon/alt or x/y/z,
    every cell of it given."""
    from registration.io.fleet.reading.rejects import RejectedRow

    columns = set(read.columns)
    if not ({"lat_deg", "lon_deg", "alt_m"} <= columns or {"x_m", "y_m", "z_m"} <= columns):
        raise ValueError(f"{path}: give the known positions as lat_deg, lon_deg, alt_m or as x_m, y_m, z_m")
    ok = read.bad.ok()
    rows = read.file_rows
    for column in ("x_m", "y_m", "z_m") if "x_m" in columns else ("lat_deg", "lon_deg", "alt_m"):
        bad = np.flatnonzero(ok & np.isnan(read.numbers[column]))
        if bad.size:
            row = int(bad[0]) if rows is None else int(rows[bad[0]])
            return [
                RejectedRow(
                    str(path),
                    row,
                    column,
                    "non_finite",
                    f"empty or NaN; a number ({column.rsplit('_', 1)[1]}) is required for the position",
                )
            ]
    return []


def _block_table(name: str, read) -> Any:
    """A checked block as a pyarrow table of the file's columns in file units."""
    import pyarrow as pa

    cols = {}
    for column, key, unit, *_ in FILE_COLUMNS[name]:
        if column in read.columns:
            cols[column] = (
                pa.array(np.asarray(read.table[key]).astype(str), pa.string())
                if unit == "id"
                else pa.array(read.numbers[column], pa.float64())
            )
    if name == "reference" and "sigma_m" in cols:
        sigma = read.numbers["sigma_m"]
        cols["sigma_m"] = pa.array(np.where(np.isnan(sigma), DEFAULT_REFERENCE_SIGMA, sigma), pa.float64())
    return pa.table(cols)


def _convert(name: str, path: Path, target: Path, context: dict, block_bytes: int) -> list[str]:
    """One lazily read CSV table into ``target`` (module docstring); its notes."""
    import pyarrow.parquet as pq

    from registration.io.files.csvrows import read_csv_blocks

    writer, first_row, notes, radians = None, 0, [], _Radians(name)
    block: Any  # a DataFrame
    try:
        for block in read_csv_blocks(path, dtype={k: v for k, v in _IDS.items()}, block_bytes=block_bytes):
            block.columns = [str(c).strip() for c in block.columns]
            n_block = len(block)
            read = check_frame(
                name,
                path,
                block,
                True,
                context["platforms"] if name == "navigation" else None,
                first_row,
                whole_file=False,
            )
            extra = []
            if name == "plots":
                extra = _unknown(path, read, "sensor", context["sensors"], context["sensors_path"], first_row)
            if name == "reference":
                extra = _reference_rows(path, read)
            _first_bad(read, extra)
            radians.add(read.numbers, first_row)
            if name == "navigation":
                try:
                    notes += attitude_check(path, read.numbers, read.table["platform"])
                except ValueError as exc:
                    raise _shifted(exc, first_row) from exc
                notes += read.notes
            table = _block_table(name, read)
            writer = writer or pq.ParquetWriter(str(target), table.schema)
            writer.write_table(table)
            first_row += n_block
    finally:
        if writer is not None:
            writer.close()
    if first_row == 0:
        raise ValueError(
            f"{path}: no data rows (the file holds only a header); the {name} file needs at least one row"
        )
    radians.check(path)
    return list(dict.fromkeys(notes))


def parquet_from_csv(folder, temp, block_bytes: int | None = None) -> list[str]:
    """The fleet tables of ``folder`` (CSV files by their standard names, or some as Parquet) as a
    Parquet archive in the folder ``temp`` (module docstring); the readers' notes. ValueError naming
    the file, row, column and unit for a bad row."""
    from registration.io.files.csvrows import BLOCK_BYTES

    folder, temp = Path(folder), Path(temp)
    paths = tables_in_folder(folder)
    for name, path in paths.items():
        if path is not None and path.suffix != ".csv":
            os.symlink(path.resolve(), temp / f"{name}.parquet")
    small = {
        n: p
        for n in ("sensors", "platforms", "targets")
        if (p := paths[n]) is not None and p.suffix == ".csv"
    }
    sensors = read_file("sensors", small["sensors"], False) if "sensors" in small else None
    for name in ("platforms", "targets"):  # checked here: their errors name the file's row
        if name in small:
            read_file(name, small[name], False)
    for name, path in small.items():
        shutil.copyfile(path, temp / f"{name}.csv")
    context = {
        "sensors": set() if sensors is None else set(sensors.table["sensor"].tolist()),
        "platforms": set() if sensors is None else set(sensors.table["platform"].tolist()),
        "sensors_path": paths["sensors"],
    }
    notes = []
    for name in ("plots", "navigation", "reference"):
        path = paths[name]
        if path is None or path.suffix != ".csv":
            continue
        if sensors is None and name in ("plots", "navigation"):
            raise ValueError(
                f"{path}: a CSV archive needs its sensors table as CSV too (found {paths['sensors']})"
            )
        notes += _convert(name, path, temp / f"{name}.parquet", context, block_bytes or BLOCK_BYTES)
    return notes
