"""Reading and writing recorded tables: CSV and Parquet, units converted only here.

The format follows the suffix: ``.csv`` or ``.parquet`` (``.pq``). CSV is read in blocks of whole
lines (:mod:`registration.io.files.csvrows`, which also counts each line's fields) and Parquet by
record batches, so a reader never holds more than one block of rows (:func:`iter_frames`); CSV
outputs are written with pyarrow (shortest round-trip float text, so a value read back is
bit-for-bit the value written). :func:`to_file_frame` and
:func:`from_file_frame` convert between the data contract (SI units, radians) and the file
columns of :mod:`registration.recorded.reading.columns` (degrees, metres).

Errors: :class:`~registration.recorded.reading.columns.FileFormatError` (a ``ValueError``) for a file that
cannot be read as a table at all (unknown suffix, an empty file, an unterminated quote, not a
Parquet file, ...); row-level problems are the business of :mod:`registration.recorded.reading.rowcheck`,
a CSV line with fewer or more fields than the header included (:mod:`registration.io.files.csvrows`).
"""

from __future__ import annotations

import hashlib
from pathlib import Path
from typing import TYPE_CHECKING, Iterator, Mapping, cast

import numpy as np

from registration.io.files.csvrows import SHAPE_COLUMN, read_csv_blocks
from registration.io.files.tablefile import FileFormatError, file_format, write_frame
from registration.io.files.unreadable import read_error
from registration.recorded.reading.columns import SYNC_COLUMNS, SYNC_FIELDS
from registration.recorded.reading.rowcheck import check_frame, sync_layout

if TYPE_CHECKING:  # pandas is imported where it is used (it is slow to import)
    import pandas as pd

__all__ = [
    "file_format",
    "to_file_frame",
    "from_file_frame",
    "write_table",
    "write_frame",
    "read_table",
    "read_columns",
    "count_rows",
    "iter_frames",
    "scan_file",
]


# --------------------------------------------------------------------------- unit conversion
def to_file_frame(data: Mapping, fields=SYNC_FIELDS):
    """A data-contract mapping (SI, radians) -> pandas DataFrame with unit-named columns."""
    import pandas as pd

    missing = [f.contract_name for f in fields if f.contract_name not in data]
    if missing:
        raise ValueError(
            f"missing column(s) {missing}; expected {[f.contract_name for f in fields]} (SI units, radians)"
        )
    out = {}
    for f in fields:
        v = np.asarray(data[f.contract_name], dtype=np.float64)
        out[f.file_name] = np.degrees(v) if f.unit == "deg" else v
    return pd.DataFrame(out)


def from_file_frame(frame, fields=SYNC_FIELDS) -> dict:
    """A DataFrame with unit-named columns -> data-contract dict of float64 arrays (SI, radians).

    No checks beyond the presence of the columns; see :mod:`registration.recorded.reading.rowcheck` for those.
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


def read_table(path, *, validate: bool = True) -> dict:
    """Read a whole synchronous table into the data contract (SI units, radians).

    For files that fit in memory (the streaming reader is :func:`iter_frames`). With ``validate``
    the rows are checked like :func:`registration.online.validate_data` (first problem raises).
    """
    import pandas as pd

    frames = list(iter_frames(path, SYNC_COLUMNS, chunk_rows=1 << 20))

    frame = (
        pd.concat([f for _, f in frames], ignore_index=True)
        if frames
        else pd.DataFrame(columns=list(SYNC_COLUMNS))
    )
    if validate:
        check_frame(frame, sync_layout(), str(path), first_row=0, mode="stop")
    return from_file_frame(frame)


# --------------------------------------------------------------------------- streaming reader
def read_columns(path) -> list[str]:
    """The column names of a CSV or Parquet file (without reading its rows)."""
    import pandas as pd

    fmt = file_format(path)
    try:
        if fmt == "csv":
            return [str(c).strip() for c in pd.read_csv(path, nrows=0).columns]
        import pyarrow.parquet as pq

        return [str(n).strip() for n in pq.ParquetFile(str(path)).schema_arrow.names]
    except FileNotFoundError as exc:
        raise FileFormatError(f"{path}: no such file") from exc
    except pd.errors.EmptyDataError as exc:
        raise FileFormatError(f"{path}: the file is empty: no header line and no data rows") from exc
    except FileFormatError:
        raise
    except Exception as exc:  # pandas/pyarrow parse errors of many types
        raise read_error(path, exc, f"cannot read the header as {fmt.upper()}", FileFormatError) from exc


def count_rows(path) -> int | None:
    """Rows of a Parquet file from its metadata; None for CSV (unknown without reading it)."""
    if file_format(path) == "parquet":
        import pyarrow.parquet as pq

        try:
            return int(pq.ParquetFile(str(path)).metadata.num_rows)
        except Exception:
            return None
    return None


def iter_frames(path, columns, chunk_rows: int, start_row: int = 0) -> Iterator[tuple[int, pd.DataFrame]]:
    """Yield ``(first_row, DataFrame)`` blocks of exactly ``chunk_rows`` rows (the last may be shorter).

    Only the listed ``columns`` that exist in the file are read (the caller decides what a
    missing column means). Blocks are aligned on absolute row numbers: the first block starts at
    ``start_row`` and every block boundary is ``start_row + i * chunk_rows``, so a run resumed at a
    block boundary sees the same blocks as an uninterrupted one. Memory: one block (plus pandas'
    or pyarrow's own read buffer). A CSV frame with a line of fewer or more fields than the
    header also has the column :data:`~registration.io.files.csvrows.SHAPE_COLUMN` (per row None,
    or its :class:`~registration.io.files.csvrows.RowShape`; NaN in rows of blocks joined to it).
    Raises :class:`FileFormatError` when the file cannot be parsed.
    """
    import pandas as pd

    if chunk_rows < 1:
        raise ValueError("chunk_rows: must be >= 1")
    fmt = file_format(path)
    present = set(read_columns(path))
    wanted = [c for c in columns if c in present]
    try:
        if fmt == "csv":
            source = _csv_frames(path, wanted)
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
            batches = pf.iter_batches(
                batch_size=chunk_rows, row_groups=list(range(g, md.num_row_groups)), columns=names
            )
            source = (b.to_pandas() for b in batches)
        yield from _rechunk(source, base, start_row, chunk_rows, path)
    except FileFormatError:
        raise
    except (UnicodeDecodeError, pd.errors.ParserError, pd.errors.EmptyDataError) as exc:
        raise read_error(path, exc, "cannot be read as CSV", FileFormatError) from exc
    except OSError as exc:
        raise FileFormatError(f"{path}: {exc}") from exc
    except ValueError as exc:  # pandas/pyarrow raise plain ValueErrors for some malformed files
        raise read_error(path, exc, f"cannot be read as {fmt.upper()}", FileFormatError) from exc
    except Exception as exc:
        if type(exc).__module__.startswith(("pyarrow", "pandas")):
            raise read_error(path, exc, f"cannot be read as {fmt.upper()}", FileFormatError) from exc
        raise


def _csv_frames(path, wanted: list[str]) -> Iterator[pd.DataFrame]:
    """The wanted columns of a CSV file, block by block, with the shape of each row
    (:data:`~registration.io.files.csvrows.SHAPE_COLUMN`: a line with fewer or more fields than the
    header is a bad row for :func:`~registration.recorded.reading.rowcheck.check_frame`, not a row whose
    missing cells read as empty or whose extra fields are dropped)."""
    for block in read_csv_blocks(path):
        frame = cast("pd.DataFrame", block)  # read_csv_blocks yields DataFrames, typed as object
        yield frame[[c for c in frame.columns if str(c).strip() in wanted or c == SHAPE_COLUMN]]


def _rechunk(source, base: int, start_row: int, chunk_rows: int, path) -> Iterator[tuple[int, pd.DataFrame]]:
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
            block = (
                pd.concat(pending, ignore_index=True)
                if len(pending) > 1
                else pending[0].reset_index(drop=True)
            )
            out, rest = block.iloc[:chunk_rows], block.iloc[chunk_rows:]
            first = pos - have
            yield first, out.reset_index(drop=True)
            pending, have = ([rest] if len(rest) else []), len(rest)
    if pos < start_row:
        raise FileFormatError(
            f"{path}: has {pos} rows, fewer than the {start_row} already processed (was it changed?)"
        )
    if have:
        block = (
            pd.concat(pending, ignore_index=True) if len(pending) > 1 else pending[0].reset_index(drop=True)
        )
        yield pos - have, block


def scan_file(path, block: int = 1 << 22) -> tuple[str, int]:
    """sha256 (hex) of a file's bytes and its number of newlines (a row estimate for CSV progress)."""
    h, lines = hashlib.sha256(), 0
    try:
        with open(path, "rb") as f:
            while chunk := f.read(block):
                h.update(chunk)
                lines += chunk.count(b"\n")
    except OSError as exc:
        raise FileFormatError(f"{path}: {exc}") from exc
    return h.hexdigest(), lines
