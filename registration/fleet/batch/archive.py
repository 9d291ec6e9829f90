"""An archive of fleet tables as Parquet files, read lazily by time range: :class:`ParquetSource`, the
source of :func:`registration.fleet.batch.partitioned.solve_batch_partitioned` for archives too large
for memory (docs/archive.md).

The folder holds ``plots``, ``navigation`` and (optional) ``reference`` each as one Parquet file
(``plots.parquet``) or a folder of them (``plots/``, a dataset: the files together are the
table, in any order), and ``sensors`` and (optional) ``platforms`` as Parquet or CSV files
(small: read whole). A partition's plots, references and navigation are read with a filter on
``time_s`` (and ``platform``), so pyarrow reads only the row groups whose statistics overlap the
partition: memory is bounded by the partition when the files' row groups follow time (write the
plots sorted by time, in row groups of 10^5 rows or so). Plots of one target window may lie in
several files in any order: a partition reads them from every file, so the answer is the same.
Navigation rows are sorted by time per platform after reading.

Columns are converted from file units by ``file_columns`` (per table: (file column, table column,
unit, ...) tuples, unit "deg" converted to radians: the fleet files' columns,
``registration.io.fleet.cells.FILE_COLUMNS``); without it the files hold the tables' own columns
(SI units). A file that cannot be read, when the run starts or in the middle of it, is a one-line
ValueError naming it.
"""

from __future__ import annotations

import uuid
from pathlib import Path

import numpy as np

__all__ = ["LAZY_TABLES", "ParquetSource"]

#: The tables read by time range; the others are read whole.
LAZY_TABLES = ("plots", "navigation", "reference")


def _one_line(exc: Exception) -> str:
    return " ".join(str(exc).split()) or type(exc).__name__


class ParquetSource:
    """The fleet tables of ``folder`` (module docstring) as a partition source
    (:mod:`registration.fleet.batch.partitions`); ``batch_rows``: rows per batch of the first passes."""

    def __init__(self, folder, file_columns: dict | None = None, batch_rows: int = 200_000):
        self.folder = Path(folder)
        self.file_columns = file_columns
        self.batch_rows = int(batch_rows)
        self.paths = {name: self._find(name) for name in ("plots", "navigation", "sensors", "platforms", "reference")}
        for name in ("plots", "navigation", "sensors"):
            if self.paths[name] is None:
                raise ValueError(f"{self.folder}: no {name} table ({name}.parquet or a folder {name}/ of Parquet files)")
        self.sensors = self._whole("sensors")
        self.platforms = self._whole("platforms") if self.paths["platforms"] is not None else None
        self.token = uuid.uuid4().hex

    def __getstate__(self):
        return {k: v for k, v in self.__dict__.items() if k != "_datasets"}

    def _find(self, name: str) -> Path | None:
        for candidate in (self.folder / f"{name}.parquet", self.folder / name, self.folder / f"{name}.csv"):
            if candidate.exists() and (candidate.suffix != ".csv" or name not in LAZY_TABLES):
                return candidate
        return None

    def name(self, table: str) -> str:
        path = self.paths.get("reference" if table == "references" else table)
        return str(path) if path is not None else table

    def _spec(self, table: str) -> tuple:
        if self.file_columns is None:
            return ()
        return self.file_columns["reference" if table == "references" else table]

    def _convert(self, table: str, frame: dict) -> dict:
        """File columns to the tables' columns (module docstring)."""
        spec = self._spec(table)
        if not spec:
            return frame
        out = {}
        for file_col, col, unit, *_ in spec:
            if file_col in frame:
                v = frame[file_col]
                out[col] = np.radians(np.asarray(v, dtype=np.float64)) if unit == "deg" else v
        return out

    def _file_column(self, table: str, column: str) -> str:
        for file_col, col, *_ in self._spec(table):
            if col == column:
                return file_col
        return column

    def _whole(self, name: str) -> dict:
        import pandas as pd

        path = self.paths[name]
        try:
            frame = pd.read_csv(path) if path.suffix == ".csv" else pd.read_parquet(path)
        except Exception as exc:  # pandas/pyarrow errors of many kinds
            raise ValueError(f"{path}: cannot be read ({_one_line(exc)})") from exc
        return self._convert(name, {str(c): frame[c].to_numpy() for c in frame.columns})

    def _dataset(self, name: str):
        import pyarrow.dataset as ds

        cache = self.__dict__.setdefault("_datasets", {})
        if name not in cache:
            try:
                cache[name] = ds.dataset(str(self.paths[name]), format="parquet")
            except Exception as exc:  # pyarrow errors of many kinds
                raise ValueError(f"{self.paths[name]}: cannot be read ({_one_line(exc)})") from exc
        return cache[name]

    def _read(self, name: str, columns=None, expression=None) -> dict:
        """The rows of table ``name`` matching ``expression``, file columns; a file that fails is named."""
        data = self._dataset(name)
        cols = None if columns is None else [c for c in columns if c in data.schema.names]
        try:
            table = data.to_table(columns=cols, filter=expression, batch_readahead=1, fragment_readahead=1)
        except Exception:  # find the file that fails and name it
            for fragment in data.get_fragments():
                try:
                    fragment.to_table(columns=cols, filter=expression, schema=data.schema)
                except Exception as exc:
                    raise ValueError(f"{fragment.path}: cannot be read ({_one_line(exc)})") from exc
            raise
        return {c: table.column(c).to_numpy(zero_copy_only=False) for c in table.column_names}

    def _batches(self, name: str, columns):
        if self.paths[name] is None:
            return
        data = self._dataset(name)
        files = [self._file_column(name, c) for c in columns]
        for fragment in data.get_fragments():
            try:
                for batch in fragment.to_batches(columns=files, batch_size=self.batch_rows, schema=data.schema,
                                                 batch_readahead=1, fragment_readahead=1):
                    yield self._convert(name, {c: batch.column(c).to_numpy(zero_copy_only=False) for c in files})
            except Exception as exc:  # pyarrow errors of many kinds
                raise ValueError(f"{fragment.path}: cannot be read ({_one_line(exc)})") from exc

    def plot_batches(self, columns):
        return self._batches("plots", columns)

    def navigation_batches(self, columns):
        return self._batches("navigation", columns)

    def reference_batches(self, columns):
        return self._batches("reference", columns)

    def _time_range(self, name: str, lo: float, hi: float) -> dict:
        import pyarrow.dataset as ds

        t = ds.field(self._file_column(name, "time"))
        return self._convert(name, self._read(name, None, (t >= float(lo)) & (t <= float(hi))))

    def read_plots(self, lo: float, hi: float) -> dict:
        return self._time_range("plots", lo, hi)

    def read_references(self, lo: float, hi: float) -> dict | None:
        return None if self.paths["reference"] is None else self._time_range("reference", lo, hi)

    def read_navigation(self, ranges: dict) -> dict:
        import pyarrow.dataset as ds

        t, p = ds.field(self._file_column("navigation", "time")), ds.field(self._file_column("navigation", "platform"))
        expression = None
        for pid, (a, b) in ranges.items():
            term = (p == pid) & (t >= float(a)) & (t <= float(b))
            expression = term if expression is None else expression | term
        if expression is None:
            expression = t < -np.inf
        out = self._convert("navigation", self._read("navigation", None, expression))
        order = np.lexsort((np.asarray(out["time"], dtype=np.float64), np.asarray(out["platform"]).astype(str)))
        return {k: np.asarray(v)[order] for k, v in out.items()}
