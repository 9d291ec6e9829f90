"""Outputs that grow block by block and can be cut back to the length a checkpoint recorded.

:class:`CsvAppender` (one CSV file) and :class:`PartsWriter` (a folder of Parquet parts) carry
``size`` (bytes, or parts) and ``rows``; :func:`open_appender` picks one by format.
:class:`ParquetFileWriter` writes one Parquet file in pieces; :func:`write_json_atomic` replaces a
JSON file whole. Every write that a checkpoint may refer to is fsync'ed first (``sync``).
"""

from __future__ import annotations

import csv
import io
import os
from pathlib import Path
from typing import BinaryIO

import numpy as np

from registration.io.files.jsonfile import write_json
from registration.io.output.checkpoint import CheckpointError

__all__ = ["CsvAppender", "PartsWriter", "ParquetFileWriter", "open_appender", "write_json_atomic"]


class CsvAppender:
    """An output CSV that grows block by block and can be cut back to a recorded length.

    ``size`` and ``rows`` describe what has been written; :meth:`sync` makes it durable (flush +
    fsync) before a checkpoint records them; :meth:`open` with ``resume=(size, rows)`` truncates
    the file to that length (refusing when the file is shorter: rows would be missing).
    """

    def __init__(
        self, path, columns: list[str], *, resume: tuple[int, int] | None = None, keep_existing: bool = False
    ):
        self.path = Path(path)
        self.columns = list(columns)
        self._f: BinaryIO
        self.rows: int | None
        header = (",".join(_csv_quote(c) for c in self.columns) + "\n").encode()
        if resume is not None:
            size, rows = resume
            actual = self.path.stat().st_size if self.path.exists() else -1
            if actual < size:
                raise CheckpointError(
                    f"{self.path} holds {max(actual, 0)} bytes but the checkpoint recorded {size}: the "
                    "output was truncated or replaced after the checkpoint, so rows would be lost; delete "
                    "the checkpoint to start over"
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
        import pyarrow as pa
        import pyarrow.csv as pacsv

        if not len(frame):
            return
        buf = io.BytesIO()
        pacsv.write_csv(
            pa.Table.from_pandas(frame, preserve_index=False),
            buf,
            write_options=pacsv.WriteOptions(include_header=False),
        )
        self._write(buf.getvalue(), len(frame))

    def append_rows(self, rows: list[list]) -> None:
        """Append rows of text/number cells with Python's csv module (quoted as needed)."""
        if not rows:
            return
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
                raise CheckpointError(
                    f"{self.path}: part(s) {missing[:3]} recorded by the checkpoint are missing; delete the "
                    "checkpoint to start over"
                )
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


def open_appender(path, columns: list[str], fmt: str, resume: tuple[int, int] | None = None):
    """A :class:`CsvAppender` (``fmt`` 'csv') or :class:`PartsWriter` ('parquet'), resumed at ``resume``."""
    if fmt == "csv":
        return CsvAppender(path, columns, resume=resume)
    return PartsWriter(path, columns, resume=resume)


class ParquetFileWriter:
    """One Parquet file written a DataFrame at a time; :meth:`close` makes it durable.

    With nothing appended, :meth:`close` writes an empty table with ``empty_columns`` (float64).
    """

    def __init__(self, path, empty_columns):
        self.path = Path(path)
        self._empty_columns = list(empty_columns)
        self._writer = None

    def append_frame(self, frame) -> None:
        import pyarrow as pa
        import pyarrow.parquet as pq

        table = pa.Table.from_pandas(frame, preserve_index=False)
        if self._writer is None:
            self._writer = pq.ParquetWriter(str(self.path), table.schema)
        self._writer.write_table(table)

    def sync(self) -> None:
        """Nothing to do: a Parquet file is complete (and fsync'ed) only by :meth:`close`."""

    def close(self) -> None:
        import pandas as pd
        import pyarrow as pa
        import pyarrow.parquet as pq

        if self._writer is not None:
            self._writer.close()
        else:
            empty = pd.DataFrame({c: np.empty(0) for c in self._empty_columns})
            pq.write_table(pa.Table.from_pandas(empty, preserve_index=False), str(self.path))
        with open(self.path, "rb") as f:
            os.fsync(f.fileno())


def write_json_atomic(path: Path, obj) -> None:
    """Write ``obj`` as indented JSON to ``path`` through a fsync'ed temporary file and a rename."""
    write_json(path, obj, atomic=True)
