"""The fleet tables of a registration opened once, as a
:class:`~registration.fleet.data.source.FleetSource`: :func:`open_fleet_tables`, the one way from
``fleet register --tables DIR`` (or ``--plots FILE`` ...) to the solver, in memory or by parts.

In memory, the files are read whole and checked cell by cell (a
:class:`~registration.io.fleet.read.FleetTables`, for :func:`~registration.fleet.batch.solve.solve_batch`
through its problem). Lazily (``lazy=True``, the partitioned solve of an archive too large for
memory), the folder is a :class:`~registration.io.fleet.archive.ParquetSource`; CSV files in it are
first converted block by block into a temporary Parquet folder
(:func:`~registration.io.fleet.csvarchive.parquet_from_csv`), removed when the context ends.
"""

from __future__ import annotations

import tempfile
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator, Mapping

from registration.io.fleet.archive import ParquetSource
from registration.io.fleet.csvarchive import csv_tables, parquet_from_csv
from registration.io.fleet.folder import REQUIRED_TABLES, TABLE_NAMES, tables_in_folder
from registration.io.fleet.read import FleetTables, read_fleet_tables

__all__ = ["open_fleet_tables", "table_paths"]


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
