"""The fleet tables of a registration opened once, as a
:class:`~registration.fleet.data.source.FleetSource`: :func:`open_fleet_tables`, the one way from
``fleet register --tables DIR`` (or ``--plots FILE`` ...) to the solver, in memory or by parts.

In memory, the files are read whole and checked cell by cell (a
:class:`~registration.io.fleet.reading.read.FleetTables`, for
:func:`~registration.fleet.batch.solve.solve_batch`
through its problem). Lazily (``lazy=True``, the partitioned solve of an archive too large for
memory), the folder is a :class:`~registration.io.fleet.archive.parquet.ParquetSource`; CSV files in it are
first converted block by block into a temporary Parquet folder
(:func:`~registration.io.fleet.archive.csvfolder.parquet_from_csv`), removed when the context ends.
"""

from __future__ import annotations

import tempfile
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator, Mapping

from registration.io.fleet.archive.csvfolder import csv_tables, parquet_from_csv
from registration.io.fleet.archive.parquet import ParquetSource
from registration.io.fleet.folder import REQUIRED_TABLES, TABLE_NAMES, tables_in_folder
from registration.io.fleet.reading.read import FleetTables, read_fleet_tables

__all__ = ["open_fleet_tables", "plot_count", "table_paths"]


def table_paths(folder: Path | str | None, given: Mapping[str, Path | None]) -> dict[str, Path | None]:
    """The tables' paths: from the folder ``folder`` (``--tables DIR``) by their standard names, each
    overridden by ``given[name]``; without a folder, ``given`` (the required tables given by option)."""
    if folder is not None:
        return tables_in_folder(folder, dict(given))
    missing = [f"--{n}" for n in REQUIRED_TABLES if given.get(n) is None]
    if missing:
        raise ValueError(
            f"the arguments {', '.join(missing)} are required (or give --tables DIR, the folder of an import)"
        )
    return {name: given.get(name) for name in TABLE_NAMES}


@contextmanager
def open_fleet_tables(
    folder: Path | str | None,
    given: Mapping[str, Path | None] | None = None,
    *,
    on_bad_row: str = "stop",
    lazy: bool = False,
) -> Iterator[FleetTables | ParquetSource]:
    """The tables of ``folder`` (and of ``given``: table name -> file, overriding the folder's) as a
    source (module docstring): read whole and checked (``on_bad_row``: :func:`read_fleet_tables`),
    or with ``lazy`` the archive ``folder`` read by parts, its tables by their standard names only
    (``given`` is not used; the source's notes: the CSV conversion's)."""
    if not lazy:
        paths = table_paths(folder, given or {})
        files = (paths[n] for n in ("plots", "navigation", "sensors", "platforms", "reference"))
        yield read_fleet_tables(*files, targets=paths["targets"], on_bad_row=on_bad_row)
        return
    if folder is None:
        raise ValueError("an archive read by parts is a folder of tables: give its folder")
    folder = Path(folder)
    if not csv_tables(folder):
        yield ParquetSource(folder)
        return
    with tempfile.TemporaryDirectory(prefix="registration-csv-archive-") as temp:
        notes = parquet_from_csv(folder, Path(temp))
        yield ParquetSource(Path(temp), notes=notes)


def plot_count(folder: Path | str, given: Mapping[str, Path | None] | None = None) -> tuple[int, bool]:
    """(rows of the plots table of ``folder`` (or ``given["plots"]``), whether every row has a
    target id) without reading the table: a Parquet file's or folder's metadata (the ids: the
    ``target`` column's null counts and smallest value, an empty text being no id), or one streamed
    pass over a CSV file's ``target`` column. For choosing between a run in memory and by partitions."""
    import pyarrow.parquet as pq

    path = table_paths(folder, given or {})["plots"] if folder is not None or given else None
    if path is None:
        raise ValueError("no plots table: give --tables DIR or --plots FILE")
    path = Path(path)
    if path.suffix == ".csv":
        return _csv_count(path)
    files = sorted(path.rglob("*.parquet")) if path.is_dir() else [path]
    rows, ids = 0, True
    for f in files:
        try:
            meta = pq.ParquetFile(f).metadata
        except Exception as exc:  # pyarrow and OS errors of many kinds
            from registration.io.files.unreadable import read_error

            raise read_error(f, exc) from exc
        rows += meta.num_rows
        names = [meta.schema.column(i).name for i in range(meta.num_columns)]
        if "target" not in names:
            ids = False
            continue
        col = names.index("target")
        for g in range(meta.num_row_groups):
            stats = meta.row_group(g).column(col).statistics
            if stats is None or not stats.has_null_count or stats.null_count > 0:
                ids = False
            elif stats.has_min_max and stats.min in ("", b""):  # an empty id is no id
                ids = False
    return rows, ids


def _csv_count(path: Path) -> tuple[int, bool]:
    """(data rows, every row with a target id) of a CSV plots file, streamed."""
    import pyarrow as pa
    import pyarrow.csv as pacsv

    from registration.io.files.unreadable import read_error

    try:
        with open(path, "rb") as f:
            header = f.readline().decode("utf-8", "replace").strip().split(",")
        if "target" not in [h.strip().strip('"') for h in header]:
            rows = 0
            with open(path, "rb") as f:
                for block in iter(lambda: f.read(1 << 22), b""):
                    rows += block.count(b"\n")
            return max(0, rows - 1), False
        reader = pacsv.open_csv(
            str(path),
            convert_options=pacsv.ConvertOptions(
                include_columns=["target"], column_types={"target": pa.string()}, strings_can_be_null=True
            ),
        )
        rows, ids = 0, True
        for batch in reader:
            rows += batch.num_rows
            ids = ids and batch.column(0).null_count == 0
        return rows, ids
    except Exception as exc:  # pyarrow and OS errors of many kinds
        raise read_error(path, exc) from exc
