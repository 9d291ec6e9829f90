"""Recorded-data files: CSV and Parquet, with units in the column names (issue 6).

The Python data contract (:data:`registration.state.DATA_COLUMNS`) is in SI units and radians.
Files carry their units in the column names instead, and this module is the only place that
converts between the two:

* a **synchronous table** (one row = one pair of plots of a common target by radar A and radar B
  at the same instant): ``time_s`` and, for each prefix ``a_`` and ``b_``: ``lat_deg``,
  ``lon_deg``, ``alt_m``, ``heading_deg``, ``pitch_deg``, ``roll_deg``, ``range_m``,
  ``bearing_deg``, ``elevation_deg`` (:data:`SYNC_COLUMNS`);
* a **per-sensor plot file** (asynchronous form): ``time_s``, ``range_m``, ``bearing_deg``,
  ``elevation_deg`` and, optionally, the ship's navigation ``lat_deg`` ... ``roll_deg``
  (:data:`PLOT_FIELDS`, :data:`NAV_FIELDS`); the names may carry the sensor's prefix
  (``a_range_m``) to say which radar the file belongs to;
* a **navigation file**: ``time_s`` and the prefixed navigation columns of one or both ships
  (``a_lat_deg`` ... ``b_roll_deg``).

The format follows the suffix: ``.csv`` or ``.parquet`` (``.pq``). CSV is read with pandas in
chunks (``chunksize``) and Parquet by record batches, so a reader never holds more than one
block of rows; CSV outputs are written with pyarrow (shortest round-trip float text, so a value
read back is bit-for-bit the value written).

Errors: :class:`FileFormatError` (a ``ValueError``) for a file that cannot be read as a table at
all (unknown suffix, unreadable CSV line, not a Parquet file, ...). Row-level problems are the
business of :mod:`registration.rowcheck`.
"""

from __future__ import annotations

import csv
import hashlib
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Iterator, Mapping

import numpy as np

from registration.online.contract import DATA_COLUMNS, SENSOR_COLUMNS

__all__ = [
    "FileFormatError", "Field", "SYNC_FIELDS", "SYNC_COLUMNS", "PLOT_FIELDS", "NAV_FIELDS", "file_format",
    "to_file_frame", "from_file_frame", "write_table", "read_table", "read_columns", "iter_frames",
    "file_sha256", "CsvAppender",
]

_UNIT = {"lat": "deg", "lon": "deg", "alt": "m", "heading": "deg", "pitch": "deg", "roll": "deg",
         "range": "m", "bearing": "deg", "elevation": "deg"}
_MEANING = {
    "lat": "geodetic latitude of the radar antenna (WGS-84), north positive",
    "lon": "geodetic longitude of the radar antenna, east positive",
    "alt": "antenna height above the WGS-84 ellipsoid",
    "heading": "measured ship heading, clockwise from true north",
    "pitch": "measured ship pitch (bow up positive)",
    "roll": "measured ship roll (starboard down positive)",
    "range": "measured slant range to the target (> 0)",
    "bearing": "measured target bearing in the deck frame, clockwise from the bow",
    "elevation": "measured target elevation above the deck plane",
}
NAV_KINDS = SENSOR_COLUMNS[:6]
PLOT_KINDS = SENSOR_COLUMNS[6:]


class FileFormatError(ValueError):
    """A file that cannot be read as a table (suffix, CSV syntax, Parquet structure)."""


@dataclass(frozen=True)
class Field:
    """One file column: its name in the file, the contract column and the scale to SI."""

    file_name: str  # e.g. "a_lat_deg"
    kind: str  # "time" or one of SENSOR_COLUMNS
    prefix: str  # "a", "b" or "" (unprefixed)
    unit: str  # "s", "deg" or "m"

    @property
    def contract_name(self) -> str:
        return "time" if self.kind == "time" else f"{self.prefix}_{self.kind}"

    @property
    def scale(self) -> float:
        """Multiply a file value by this to get SI units / radians."""
        return np.pi / 180 if self.unit == "deg" else 1.0

    @property
    def meaning(self) -> str:
        return "timestamp, seconds (any epoch; strictly increasing)" if self.kind == "time" else _MEANING[self.kind]


TIME_FIELD = Field("time_s", "time", "", "s")


def sensor_fields(prefix: str, kinds=SENSOR_COLUMNS) -> tuple[Field, ...]:
    """Fields of one sensor; ``prefix`` '' gives the unprefixed names (``range_m``)."""
    lead = f"{prefix}_" if prefix else ""
    return tuple(Field(f"{lead}{k}_{_UNIT[k]}", k, prefix, _UNIT[k]) for k in kinds)


#: The synchronous table, in contract order (``time`` first).
SYNC_FIELDS = (TIME_FIELD,) + sensor_fields("a") + sensor_fields("b")
SYNC_COLUMNS = tuple(f.file_name for f in SYNC_FIELDS)
#: A per-sensor plot file: the required columns (unprefixed form).
PLOT_FIELDS = (TIME_FIELD,) + sensor_fields("", PLOT_KINDS)
#: The navigation columns of one ship (unprefixed form); prefixed in a navigation file.
NAV_FIELDS = sensor_fields("", NAV_KINDS)
assert tuple(f.contract_name for f in SYNC_FIELDS) == DATA_COLUMNS


def file_format(path) -> str:
    """'csv' or 'parquet' from the file name's suffix."""
    name = str(path).lower()
    if name.endswith(".csv"):
        return "csv"
    if name.endswith((".parquet", ".pq")):
        return "parquet"
    raise FileFormatError(f"{path}: unknown file type; expected a .csv or .parquet file")


# --------------------------------------------------------------------------- unit conversion
def to_file_frame(data: Mapping, fields=SYNC_FIELDS):
    """A data-contract mapping (SI, radians) -> pandas DataFrame with unit-named columns."""
    import pandas as pd

    missing = [f.contract_name for f in fields if f.contract_name not in data]
    if missing:
        raise ValueError(f"missing column(s) {missing}; expected {[f.contract_name for f in fields]} (SI units, radians)")
    out = {}
    for f in fields:
        v = np.asarray(data[f.contract_name], dtype=np.float64)
        out[f.file_name] = np.degrees(v) if f.unit == "deg" else v
    return pd.DataFrame(out)


def from_file_frame(frame, fields=SYNC_FIELDS) -> dict:
    """A DataFrame with unit-named columns -> data-contract dict of float64 arrays (SI, radians).

    No checks beyond the presence of the columns; see :mod:`registration.rowcheck` for those.
    """
    missing = [f.file_name for f in fields if f.file_name not in frame]
    if missing:
        raise ValueError(f"missing column(s) {missing}")
    out = {}
    for f in fields:
        v = np.asarray(frame[f.file_name], dtype=np.float64)
        out[f.contract_name] = np.radians(v) if f.unit == "deg" else v.copy()
    return out


def write_table(data: Mapping, path) -> Path:
    """Write a data-contract mapping (dict of arrays or DataFrame, SI/radians) as a synchronous table.

    The format follows the suffix (``.csv`` or ``.parquet``); the columns are :data:`SYNC_COLUMNS`
    (degrees and metres). This is what ``registration simulate --export FILE`` writes and what
    ``registration register FILE`` reads.
    """
    path = Path(path)
    fmt = file_format(path)
    frame = to_file_frame(data)
    if path.parent and not path.parent.exists():
        path.parent.mkdir(parents=True, exist_ok=True)
    write_frame(frame, path, fmt)
    return path


def write_frame(frame, path, fmt: str | None = None) -> None:
    """Write a DataFrame as CSV (pyarrow: exact float text) or Parquet."""
    import pyarrow as pa

    fmt = fmt or file_format(path)
    table = pa.Table.from_pandas(frame, preserve_index=False)
    if fmt == "csv":
        import pyarrow.csv as pacsv

        pacsv.write_csv(table, str(path))
    else:
        import pyarrow.parquet as pq

        pq.write_table(table, str(path))


def read_table(path, *, validate: bool = True) -> dict:
    """Read a whole synchronous table into the data contract (SI units, radians).

    For files that fit in memory (the streaming reader is :func:`iter_frames`). With ``validate``
    the rows are checked like :func:`registration.online.validate_data` (first problem raises).
    """
    from registration.recorded.rowcheck import check_frame, sync_layout

    frames = list(iter_frames(path, SYNC_COLUMNS, chunk_rows=1 << 20))
    import pandas as pd

    frame = pd.concat([f for _, f in frames], ignore_index=True) if frames else pd.DataFrame(columns=list(SYNC_COLUMNS))
    if validate:
        check_frame(frame, sync_layout(), str(path), first_row=0, mode="stop")
    return from_file_frame(frame)


# --------------------------------------------------------------------------- streaming reader
def read_columns(path) -> list[str]:
    """The column names of a CSV or Parquet file (without reading its rows)."""
    fmt = file_format(path)
    try:
        if fmt == "csv":
            import pandas as pd

            return [str(c).strip() for c in pd.read_csv(path, nrows=0).columns]
        import pyarrow.parquet as pq

        return [str(n).strip() for n in pq.ParquetFile(str(path)).schema_arrow.names]
    except FileNotFoundError as exc:
        raise FileFormatError(f"{path}: no such file") from exc
    except FileFormatError:
        raise
    except Exception as exc:  # pandas/pyarrow parse errors of many types
        raise FileFormatError(f"{path}: cannot read the header as {fmt.upper()}: {exc}") from exc


def count_rows(path) -> int | None:
    """Rows of a Parquet file from its metadata; None for CSV (unknown without reading it)."""
    if file_format(path) == "parquet":
        import pyarrow.parquet as pq

        try:
            return int(pq.ParquetFile(str(path)).metadata.num_rows)
        except Exception:
            return None
    return None


def iter_frames(path, columns, chunk_rows: int, start_row: int = 0) -> Iterator[tuple[int, "object"]]:
    """Yield ``(first_row, DataFrame)`` blocks of exactly ``chunk_rows`` rows (the last may be shorter).

    Only the listed ``columns`` that exist in the file are read (the caller decides what a
    missing column means). Blocks are aligned on absolute row numbers: the first block starts at
    ``start_row`` and every block boundary is ``start_row + i * chunk_rows``, so a run resumed at a
    block boundary sees the same blocks as an uninterrupted one. Memory: one block (plus pandas'
    or pyarrow's own read buffer). Raises :class:`FileFormatError` when the file cannot be parsed.
    """
    import pandas as pd

    if chunk_rows < 1:
        raise ValueError("chunk_rows: must be >= 1")
    fmt = file_format(path)
    present = set(read_columns(path))
    wanted = [c for c in columns if c in present]
    try:
        if fmt == "csv":
            # every column is parsed (no usecols): with usecols pandas silently drops the extra fields
            # of a malformed line instead of reporting it
            source = (f[[c for c in f.columns if str(c).strip() in wanted]]
                      for f in pd.read_csv(path, chunksize=chunk_rows, index_col=False, skipinitialspace=True))
            base = 0
        else:
            import pyarrow.parquet as pq

            # pre_buffer=False: with pyarrow's default read-ahead the process keeps growing with the
            # file (measured: +60 MiB per million rows); without it memory stays flat
            pf = pq.ParquetFile(str(path), pre_buffer=False)
            md = pf.metadata
            base, g = 0, 0
            while g < md.num_row_groups and base + md.row_group(g).num_rows <= start_row:
                base += md.row_group(g).num_rows
                g += 1
            names = [n for n in pf.schema_arrow.names if n.strip() in wanted]
            batches = pf.iter_batches(batch_size=chunk_rows, row_groups=list(range(g, md.num_row_groups)), columns=names)
            source = (b.to_pandas() for b in batches)
        yield from _rechunk(source, base, start_row, chunk_rows, path)
    except FileFormatError:
        raise
    except (UnicodeDecodeError, pd.errors.ParserError, pd.errors.EmptyDataError) as exc:
        raise FileFormatError(f"{path}: cannot be read as CSV: {exc}") from exc
    except OSError as exc:
        raise FileFormatError(f"{path}: {exc}") from exc
    except ValueError as exc:  # pandas/pyarrow raise plain ValueErrors for some malformed files
        raise FileFormatError(f"{path}: cannot be read as {fmt.upper()}: {exc}") from exc
    except Exception as exc:
        if type(exc).__module__.startswith(("pyarrow", "pandas")):
            raise FileFormatError(f"{path}: cannot be read as {fmt.upper()}: {exc}") from exc
        raise


def _rechunk(source, base: int, start_row: int, chunk_rows: int, path) -> Iterator[tuple[int, object]]:
    import pandas as pd

    pending, have, pos = [], 0, base  # pos: absolute row of the next row from source
    for frame in source:
        frame.columns = [str(c).strip() for c in frame.columns]
        if pos < start_row:
            skip = min(len(frame), start_row - pos)
            frame, pos = frame.iloc[skip:], pos + skip
            if not len(frame):
                continue
        pending.append(frame)
        have += len(frame)
        pos += len(frame)
        while have >= chunk_rows:
            block = pd.concat(pending, ignore_index=True) if len(pending) > 1 else pending[0].reset_index(drop=True)
            out, rest = block.iloc[:chunk_rows], block.iloc[chunk_rows:]
            first = pos - have
            yield first, out.reset_index(drop=True)
            pending, have = ([rest] if len(rest) else []), len(rest)
    if pos < start_row:
        raise FileFormatError(f"{path}: has {pos} rows, fewer than the {start_row} already processed (was it changed?)")
    if have:
        block = pd.concat(pending, ignore_index=True) if len(pending) > 1 else pending[0].reset_index(drop=True)
        yield pos - have, block


def file_sha256(path, block: int = 1 << 20) -> str:
    h = hashlib.sha256()
    try:
        with open(path, "rb") as f:
            while chunk := f.read(block):
                h.update(chunk)
    except OSError as exc:
        raise FileFormatError(f"{path}: {exc}") from exc
    return h.hexdigest()


# --------------------------------------------------------------------------- appendable outputs
class CsvAppender:
    """An output CSV that grows block by block and can be cut back to a recorded length.

    ``size`` and ``rows`` describe what has been written; :meth:`sync` makes it durable (flush +
    fsync) before a checkpoint records them; :meth:`open` with ``resume=(size, rows)`` truncates
    the file to that length (refusing when the file is shorter: rows would be missing).
    """

    def __init__(self, path, columns: list[str], *, resume: tuple[int, int] | None = None, keep_existing: bool = False):
        self.path = Path(path)
        self.columns = list(columns)
        header = (",".join(_csv_quote(c) for c in self.columns) + "\n").encode()
        if resume is not None:
            size, rows = resume
            actual = self.path.stat().st_size if self.path.exists() else -1
            if actual < size:
                from registration.recorded.checkpoint import CheckpointError

                raise CheckpointError(
                    f"{self.path} holds {max(actual, 0)} bytes but the checkpoint recorded {size}: the output was "
                    "truncated or replaced after the checkpoint, so rows would be lost; delete the checkpoint to start over"
                )
            self._f = open(self.path, "r+b")
            self._f.truncate(size)
            self._f.seek(size)
            self.rows = rows
        elif keep_existing and self.path.exists() and self.path.stat().st_size > 0:
            self._f = open(self.path, "r+b")
            self._f.seek(0, os.SEEK_END)
            self.rows = None  # unknown: counted by the writer of the existing part
        else:
            self._f = open(self.path, "wb")
            self._f.write(header)
            self.rows = 0
        self.size = self._f.tell()

    def append_frame(self, frame) -> None:
        """Append a DataFrame whose columns are :attr:`columns` (numbers), without a header."""
        import io

        import pyarrow as pa
        import pyarrow.csv as pacsv

        if not len(frame):
            return
        buf = io.BytesIO()
        pacsv.write_csv(pa.Table.from_pandas(frame, preserve_index=False), buf,
                        write_options=pacsv.WriteOptions(include_header=False))
        self._write(buf.getvalue(), len(frame))

    def append_rows(self, rows: list[list]) -> None:
        """Append rows of text/number cells with Python's csv module (quoted as needed)."""
        if not rows:
            return
        import io

        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerows(rows)
        self._write(buf.getvalue().encode(), len(rows))

    def _write(self, data: bytes, n: int) -> None:
        self._f.write(data)
        self.size += len(data)
        if self.rows is not None:
            self.rows += n

    def sync(self) -> None:
        self._f.flush()
        os.fsync(self._f.fileno())

    def close(self) -> None:
        if not self._f.closed:
            self._f.flush()
            self._f.close()


def _csv_quote(text: str) -> str:
    return f'"{text}"' if any(ch in text for ch in ',"\n') else text


class PartsWriter:
    """A Parquet output that grows block by block: a folder of part files ``part-NNNNNN.parquet``.

    Each part is written to a temporary name, fsync'ed and renamed, so a part is either whole or
    absent. ``size`` counts the parts; ``open`` with ``resume=(parts, rows)`` deletes later parts.
    ``pandas.read_parquet(folder)`` reads the parts in order as one table.
    """

    def __init__(self, path, columns: list[str], *, resume: tuple[int, int] | None = None):
        self.path = Path(path)
        self.columns = list(columns)
        self.path.mkdir(parents=True, exist_ok=True)
        for tmp in self.path.glob("*.tmp"):
            tmp.unlink()
        if resume is None:
            for part in self.path.glob("part-*.parquet"):
                part.unlink()
            self.size, self.rows = 0, 0
        else:
            self.size, self.rows = resume
            present = {p.name for p in self.path.glob("part-*.parquet")}
            missing = [self._name(i) for i in range(self.size) if self._name(i) not in present]
            if missing:
                from registration.recorded.checkpoint import CheckpointError

                raise CheckpointError(f"{self.path}: part(s) {missing[:3]} recorded by the checkpoint are missing; delete the checkpoint to start over")
            for name in present:
                if int(name[5:11]) >= self.size:
                    (self.path / name).unlink()

    @staticmethod
    def _name(i: int) -> str:
        return f"part-{i:06d}.parquet"

    def append_frame(self, frame) -> None:
        import pyarrow as pa
        import pyarrow.parquet as pq

        if not len(frame):
            return
        final = self.path / self._name(self.size)
        tmp = final.with_name(final.name + ".tmp")
        pq.write_table(pa.Table.from_pandas(frame, preserve_index=False), str(tmp))
        with open(tmp, "rb") as f:
            os.fsync(f.fileno())
        os.replace(tmp, final)
        self.size += 1
        self.rows += len(frame)

    def sync(self) -> None:
        try:
            fd = os.open(self.path, os.O_RDONLY)
            try:
                os.fsync(fd)
            finally:
                os.close(fd)
        except OSError:
            pass

    def close(self) -> None:
        pass
