"""Table files in general: the format from the suffix, exact writing, and the shared vocabulary of
rejected rows.

Every table the package reads or writes is CSV or Parquet, told apart by the suffix (``.csv``,
``.parquet`` or ``.pq``). CSV is written with pyarrow, whose float text is the shortest that reads
back to the same double, so a value read back is bit for bit the value written.

The reason codes of a rejected row (:data:`REASON_CODES`) and the errors for a file that cannot be
read as a table (:class:`FileFormatError`) or that leaves no valid row (:class:`NoValidRowsError`)
are shared by every reader: ``registration register`` (:mod:`registration.recorded`), the fleet
table files (:mod:`registration.io.fleet`) and the format importers.
"""

from __future__ import annotations

from pathlib import Path
from typing import Mapping

__all__ = [
    "FileFormatError",
    "NoValidRowsError",
    "REASON_CODES",
    "file_format",
    "write_frame",
    "write_tables",
]

#: Reason codes of a rejected row, common to all readers (readers may add their own beside them).
REASON_CODES = (
    "missing_column",
    "non_numeric",
    "non_finite",
    "out_of_range",
    "non_positive_range",
    "time_backwards",
    "time_duplicate",
    "filter_non_finite",
    "short_row",
    "long_row",
)


class FileFormatError(ValueError):
    """A file that cannot be read as a table (suffix, CSV syntax, Parquet structure)."""


class NoValidRowsError(ValueError):
    """Nothing is left to register: every row was rejected (listed in rejected.csv) or nothing was paired."""


def file_format(path) -> str:
    """'csv' or 'parquet' from the file name's suffix."""
    name = str(path).lower()
    if name.endswith(".csv"):
        return "csv"
    if name.endswith((".parquet", ".pq")):
        return "parquet"
    raise FileFormatError(f"{path}: unknown file type; expected a .csv or .parquet file")


def write_frame(frame, path, fmt: str | None = None) -> None:
    """Write a DataFrame as CSV (pyarrow: exact float text) or Parquet; ``fmt`` defaults to the suffix's."""
    import pyarrow as pa

    fmt = fmt or file_format(path)
    table = pa.Table.from_pandas(frame, preserve_index=False)
    if fmt == "csv":
        import pyarrow.csv as pacsv

        pacsv.write_csv(table, str(path))
    else:
        import pyarrow.parquet as pq

        pq.write_table(table, str(path))


def write_tables(folder, frames: Mapping, fmt: str = "csv") -> dict[str, Path]:
    """The folder writer: each DataFrame of ``frames`` (name -> frame) written as ``folder/<name>.<fmt>``
    with :func:`write_frame` (CSV floats that read back exactly, or Parquet), in the order given;
    ``folder`` must exist. Returns name -> path. An operating-system error names the file it was
    writing (its ``filename``)."""
    if fmt not in ("csv", "parquet"):
        raise ValueError(f"fmt: expected 'csv' or 'parquet', got {fmt!r}")
    written = {}
    for name, frame in frames.items():
        path = Path(folder) / f"{name}.{fmt}"
        try:
            write_frame(frame, path, fmt)
        except OSError as exc:
            if exc.filename is None:
                exc.filename = str(path)
            raise
        written[name] = path
    return written
