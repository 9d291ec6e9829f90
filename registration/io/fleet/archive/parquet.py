"""An archive of fleet tables as Parquet files, read lazily by time range: :class:`ParquetSource`, a
:class:`~registration.fleet.data.source.FleetSource` for
:func:`registration.fleet.batch.partitioned.solve_batch_partitioned` on archives too large for memory
(docs/howto/register-an-archive.md).

The folder holds ``plots``, ``navigation`` and (optional) ``reference`` each as one Parquet file
(``plots.parquet``) or a folder of them (``plots/``, a dataset: the files together are the table,
in any order), and ``sensors``, (optional) ``platforms`` and (optional) ``targets`` (the surface
targets) as Parquet or CSV files (small: read whole). A partition's plots, references and
navigation are read row group by row group: only the groups whose statistics on ``time_s`` (and
``platform``) overlap the partition, each streamed in batches of BATCH_ROWS rows and filtered batch
by batch, so memory holds the partition's rows and one batch whatever the size of a row group.
Nothing read is kept for the next call (row groups once kept on the copies of the source that
Dask workers unpickle per task piled up there: 9.6 GiB per worker on plots in one row group).
Tables whose row groups do not follow time are read through a copy by time buckets
(:meth:`ParquetSource.time_ordered`, :mod:`registration.io.fleet.archive.timeorder`). The first passes
get text columns as ``pandas.Categorical`` (no Python string per row). Plots of one target
window may lie in several files in any order: a partition reads them from every file, so the answer
is the same. Navigation rows are sorted by time per platform after reading.

The files hold the fleet files' columns in file units
(:data:`registration.io.fleet.reading.cells.FILE_COLUMNS`: degrees, metres, seconds); the source gives the
tables' columns (SI units, radians). The small tables are read and checked cell by cell by the
reader of every fleet file (:func:`registration.io.fleet.reading.cells.read_file`), so a bad cell there is
the error the in-memory run gives. A file that cannot be read, when the run starts or in the
middle of it, is a one-line ValueError naming it.
"""

from __future__ import annotations

import copy
import os
import uuid
from pathlib import Path
from typing import Iterable, Iterator, Mapping

import numpy as np

from registration.io.files.unreadable import read_error
from registration.io.fleet.archive.timeorder import (
    ROW_COLUMN,
    TimeProfile,
    needs_copy,
    time_profile,
    write_buckets,
)
from registration.io.fleet.reading.cells import FILE_COLUMNS, read_file

__all__ = ["LAZY_TABLES", "ParquetSource"]

#: The tables read by time range; the others are read whole.
LAZY_TABLES = ("plots", "navigation", "reference")
#: Rows per batch when a partition's rows are streamed out of a row group.
BATCH_ROWS = 65_536


def _identity(path: str) -> tuple | None:
    """(size, modification time) of a file: a file rewritten in the middle of a run is read again."""
    try:
        st = os.stat(path)
    except OSError:
        return None
    return st.st_size, st.st_mtime_ns


def _array(column):
    """A pyarrow array as numpy, or text without nulls as a pandas.Categorical."""
    import pandas as pd
    import pyarrow as pa

    if (pa.types.is_string(column.type) or pa.types.is_large_string(column.type)) and column.null_count == 0:
        encoded = column.dictionary_encode()
        return pd.Categorical.from_codes(
            encoded.indices.to_numpy(zero_copy_only=False), encoded.dictionary.to_pylist()
        )
    return column.to_numpy(zero_copy_only=False)


class ParquetSource:
    """The fleet tables of ``folder`` (module docstring) as a
    :class:`~registration.fleet.data.source.FleetSource`; ``batch_rows``: rows per batch of the
    first passes; ``notes``: what was noted while the archive was made (a CSV archive's conversion)."""

    #: The tables are read from files partition by partition.
    in_memory = False

    def __init__(self, folder, batch_rows: int = 200_000, notes: Iterable[str] = ()):
        self.folder = Path(folder)
        self.notes = list(notes)
        self.batch_rows = int(batch_rows)
        self.paths = {
            name: self._find(name)
            for name in ("plots", "navigation", "sensors", "platforms", "reference", "targets")
        }
        for name in ("plots", "navigation", "sensors"):
            if self.paths[name] is None:
                raise ValueError(
                    f"{self.folder}: no {name} table ({name}.parquet or a folder {name}/ of Parquet files)"
                )
        self.sensors = read_file("sensors", Path(str(self.paths["sensors"])), False).table
        self.platforms = self._whole("platforms")
        self.targets = self._whole("targets")
        self.token = uuid.uuid4().hex
        self.copies: dict[str, Path] = {}

    def __getstate__(self):
        return {k: v for k, v in self.__dict__.items() if k not in ("_datasets", "_stats")}

    def _find(self, name: str) -> Path | None:
        for candidate in (self.folder / f"{name}.parquet", self.folder / name, self.folder / f"{name}.csv"):
            if candidate.exists() and (candidate.suffix != ".csv" or name not in LAZY_TABLES):
                return candidate
        return None

    def name(self, table: str) -> str:
        path = self.paths.get("reference" if table == "references" else table)
        return str(path) if path is not None else table

    def _convert(self, table: str, frame: dict) -> dict:
        """File columns to the tables' columns (module docstring)."""
        out = {}
        for file_col, col, unit, *_ in FILE_COLUMNS[table]:
            if file_col in frame:
                v = frame[file_col]
                out[col] = np.radians(np.asarray(v, dtype=np.float64)) if unit == "deg" else v
        return out

    def _file_column(self, table: str, column: str) -> str:
        for file_col, col, *_ in FILE_COLUMNS[table]:
            if col == column:
                return file_col
        return column

    def _whole(self, name: str) -> dict | None:
        """A small table, checked cell by cell (module docstring); None when the folder has none."""
        path = self.paths[name]
        return None if path is None else read_file(name, path, False).table

    def _dataset(self, name: str, path: Path | None = None):
        """The Parquet dataset of table ``name`` (``path``: of its time-ordered copy)."""
        import pyarrow.dataset as ds

        path = self.paths[name] if path is None else path
        cache = self.__dict__.setdefault("_datasets", {})
        if str(path) not in cache:
            try:
                cache[str(path)] = ds.dataset(str(path), format="parquet")
            except Exception as exc:  # pyarrow errors of many kinds
                raise read_error(path, exc) from exc
        return cache[str(path)]

    def _copy(self, name: str) -> Path | None:
        """The time-ordered copy of table ``name`` when there is one and this process sees it."""
        path = self.copies.get(name)
        return path if path is not None and path.is_dir() else None

    def plot_profile(self) -> TimeProfile:
        """The plots' times: rows, first and last time, histogram (streamed; module
        registration.io.fleet.archive.timeorder)."""
        return time_profile(self._dataset("plots"), self._file_column("plots", "time"))

    def time_ordered(self, folder) -> ParquetSource:
        """This archive with each of its plots, navigation and reference tables whose row groups do
        not follow time (one large group, or groups that overlap in time) copied by time buckets into
        ``folder`` (registration.io.fleet.archive.timeorder): partitions then read only their buckets, and get
        the same rows in the same order. The first passes still read the original files. ``self``
        when no table needs it; the caller removes ``folder``."""
        copies = {}
        for name in LAZY_TABLES:
            if self.paths[name] is None:
                continue
            data, column = self._dataset(name), self._file_column(name, "time")
            key = self._file_column(name, "platform") if name == "navigation" else None
            try:
                needed = needs_copy(data, column, key)
            except Exception as exc:  # pyarrow errors of many kinds
                raise read_error(self.paths[name], exc) from exc
            if needed:
                copies[name] = write_buckets(data, Path(folder) / name, column)
        if not copies:
            return self
        out = copy.copy(self)
        out.__dict__.pop("_datasets", None)
        out.__dict__.pop("_stats", None)
        out.copies = {**self.copies, **copies}
        return out

    def _batches(self, name: str, columns: Iterable[str]) -> Iterator[dict]:
        """Batches of ``columns`` (table names; those of them the table has) as dicts of arrays;
        text columns without nulls as ``pandas.Categorical`` (no Python string per row: the first
        passes over 10^7 rows would otherwise leave their memory fragmented)."""
        if self.paths[name] is None:
            return
        data = self._dataset(name)
        have = set(data.schema.names)
        files = [f for f in (self._file_column(name, c) for c in columns) if f in have]
        for fragment in data.get_fragments():
            try:
                for batch in fragment.to_batches(
                    columns=files,
                    batch_size=self.batch_rows,
                    schema=data.schema,
                    batch_readahead=1,
                    fragment_readahead=1,
                ):
                    yield self._convert(name, {c: _array(batch.column(c)) for c in files})
            except Exception as exc:  # pyarrow errors of many kinds
                raise read_error(fragment.path, exc) from exc

    def plot_batches(self, columns: Iterable[str]) -> Iterator[dict]:
        return self._batches("plots", columns)

    def navigation_batches(self, columns: Iterable[str]) -> Iterator[dict]:
        return self._batches("navigation", columns)

    def reference_batches(self, columns: Iterable[str]) -> Iterator[dict]:
        return self._batches("reference", columns)

    def _row_groups(self, name: str) -> list:
        """[(fragment, [(row group id, statistics)])] of table ``name``, kept per process while no file
        of the table changes (size and modification time)."""
        copied = self._copy(name)
        path = self.paths[name] if copied is None else copied
        stats = self.__dict__.setdefault("_stats", {})
        found = stats.get(str(path))
        if found is not None and all(_identity(f.path) == ident for f, _, ident in found):
            return found  # (_identity of a removed file is None: read the table again)
        self.__dict__.get("_datasets", {}).pop(str(path), None)
        out = []
        for fragment in self._dataset(name, path).get_fragments():
            try:
                ident = _identity(fragment.path)
                fragment.ensure_complete_metadata()
                out.append((fragment, [(g.id, g.statistics) for g in fragment.row_groups], ident))
            except Exception as exc:  # pyarrow and OS errors of many kinds
                raise read_error(fragment.path, exc) from exc
        stats[str(path)] = out
        return out

    def _read_groups(self, name: str, overlaps, expression) -> dict:
        """The rows of table ``name`` matching ``expression``, file columns: the row groups whose
        statistics ``overlaps(stats)`` accepts (stats: file column -> {min, max}; None when the file
        has none), each streamed in batches of BATCH_ROWS rows and filtered batch by batch, so
        memory holds the rows kept and one batch, whatever the size of a row group. Nothing is
        kept for the next call."""
        import pyarrow as pa
        import pyarrow.parquet as pq

        fragments = self._row_groups(name)  # first: a changed file is opened again
        copied = self._copy(name)
        schema = self._dataset(name, copied).schema
        tables = []
        for fragment, groups, _ in fragments:
            ids = [gid for gid, stats in groups if overlaps(stats or {})]
            if not ids:
                continue
            try:
                reader = pq.ParquetFile(fragment.path, pre_buffer=False, buffer_size=1 << 20)
                for batch in reader.iter_batches(batch_size=BATCH_ROWS, row_groups=ids, use_threads=False):
                    part = pa.Table.from_batches([batch]).filter(expression)
                    if part.num_rows:
                        tables.append(part if part.schema == schema else part.cast(schema))
            except Exception as exc:  # pyarrow errors of many kinds
                raise read_error(fragment.path, exc) from exc
        table = pa.concat_tables(tables) if tables else schema.empty_table()
        if copied is not None:  # the original's row order (module registration.io.fleet.archive.timeorder)
            table = table.take(np.argsort(table.column(ROW_COLUMN).to_numpy(), kind="stable"))
            table = table.drop_columns([ROW_COLUMN])
        return {c: table.column(c).to_numpy(zero_copy_only=False) for c in table.column_names}

    def _time_range(self, name: str, lo: float, hi: float, convert: bool = True) -> dict:
        import pyarrow.dataset as ds

        col = self._file_column(name, "time")
        t = ds.field(col)

        def overlaps(stats) -> bool:
            s = stats.get(col)
            return s is None or s["min"] is None or (s["max"] >= lo and s["min"] <= hi)

        rows = self._read_groups(name, overlaps, (t >= float(lo)) & (t <= float(hi)))
        return self._convert(name, rows) if convert else rows

    def read_plots(self, lo: float, hi: float) -> dict:
        return self._time_range("plots", lo, hi)

    def read_file_rows(self, table: str, lo: float, hi: float) -> dict:
        """The rows of ``table`` (``plots`` or ``reference``) with ``lo <= time <= hi`` (s), as
        :meth:`read_plots` reads them, but the file's columns in file units (degrees): for copying
        rows exactly. Empty without the table."""
        return {} if self.paths[table] is None else self._time_range(table, lo, hi, convert=False)

    def file_schema(self, table: str):
        """The pyarrow schema of ``table``'s files (None without the table)."""
        return None if self.paths[table] is None else self._dataset(table).schema

    def with_tables(self, **folders) -> ParquetSource:
        """This archive with the tables ``folders`` (name -> a Parquet file or folder of them, time
        ordered by row group, e.g. ``plots=...``) instead of its own: a new token, the other tables
        and copies shared."""
        out = copy.copy(self)
        for cache in ("_datasets", "_stats"):
            out.__dict__.pop(cache, None)
        out.paths = {**self.paths, **{k: Path(v) for k, v in folders.items()}}
        out.copies = {k: v for k, v in self.copies.items() if k not in folders}
        out.token = uuid.uuid4().hex
        return out

    def read_references(self, lo: float, hi: float) -> dict | None:
        return None if self.paths["reference"] is None else self._time_range("reference", lo, hi)

    def read_navigation(self, ranges: Mapping[str, tuple[float, float]]) -> dict:
        import pyarrow.dataset as ds

        t_col, p_col = self._file_column("navigation", "time"), self._file_column("navigation", "platform")
        t, p = ds.field(t_col), ds.field(p_col)
        expression = None
        for pid, (a, b) in ranges.items():
            term = (p == pid) & (t >= float(a)) & (t <= float(b))
            expression = term if expression is None else expression | term
        if expression is None:
            expression = t < -np.inf

        def overlaps(stats) -> bool:
            ts, ps = stats.get(t_col), stats.get(p_col)
            return any(
                (ts is None or ts["min"] is None or (ts["max"] >= a and ts["min"] <= b))
                and (ps is None or not isinstance(ps["min"], str) or ps["min"] <= str(pid) <= ps["max"])
                for pid, (a, b) in ranges.items()
            )

        out = self._convert("navigation", self._read_groups("navigation", overlaps, expression))
        order = np.lexsort(
            (np.asarray(out["time"], dtype=np.float64), np.asarray(out["platform"]).astype(str))
        )
        return {k: np.asarray(v)[order] for k, v in out.items()}
