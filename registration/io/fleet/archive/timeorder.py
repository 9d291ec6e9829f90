"""An archive's large tables laid out by time for the partitioned solver: :func:`time_ordered`
(docs/howto/register-an-archive.md, "Row groups and memory").

A partition reads the row groups of the plots, navigation and reference files whose ``time_s``
statistics overlap its time range (:class:`~registration.io.fleet.archive.parquet.ParquetSource`), streamed
batch by batch, so memory is bounded whatever the files' layout. Time is another matter: a file
written in one row group (as pandas writes it), or whose row groups each span the whole archive
(rows not in time order), is read whole by every partition, and the run's reading time grows with
the square of the archive. Such a table is copied once, by streaming, into a folder of files, each
holding the rows of one time bucket (buckets of about BUCKET_ROWS rows, from a histogram of the
times), so a partition reads one or two buckets.

The copy changes no result: each row carries its row number in the original table (column
ROW_COLUMN, counting the files of a folder in the dataset's order), and the reader puts a
partition's rows back in that order, so a partition is the same rows in the same order as read
from the original. The copy lives in a work folder (removed by the caller); a process that does not
see it (a worker on another machine) reads the original.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from registration.io.files.unreadable import read_error

__all__ = [
    "BUCKET_ROWS",
    "MAX_GROUP_ROWS",
    "ROW_COLUMN",
    "TimeProfile",
    "needs_copy",
    "time_profile",
    "write_buckets",
]

#: A row group of more rows than this is copied into time buckets.
MAX_GROUP_ROWS = 262_144
#: Rows per time bucket of a copy (about).
BUCKET_ROWS = 131_072
#: The most buckets (files open at once while copying).
MAX_BUCKETS = 256
#: Bins of the time histogram of a table.
HISTOGRAM_BINS = 8192
#: Row groups whose time spans add up to more than this many times the table's span overlap so
#: much that partitions would read most of the table again and again: the table is copied.
OVERLAP_FACTOR = 3.0
#: The column of a copy holding each row's number in the original table.
ROW_COLUMN = "__row"
#: Rows per batch while copying.
COPY_BATCH_ROWS = 262_144


@dataclass(frozen=True)
class TimeProfile:
    """The times of a table: its ``rows``, first and last time ``t0``, ``t1`` (s) and the rows per
    bin ``counts`` (HISTOGRAM_BINS,) of equal bins over [t0, t1]."""

    rows: int
    t0: float
    t1: float
    counts: np.ndarray

    @property
    def bin_s(self) -> float:
        return (self.t1 - self.t0) / self.counts.size if self.t1 > self.t0 else 0.0

    def most_rows(self, length_s: float) -> int:
        """The most rows in any interval of ``length_s`` seconds (bins overlapping it counted whole)."""
        if self.bin_s == 0.0:
            return self.rows
        k = min(self.counts.size, int(np.ceil(length_s / self.bin_s)) + 1)
        c = np.concatenate([[0], np.cumsum(self.counts)])
        return int(np.max(c[k:] - c[:-k])) if k < c.size else self.rows

    def edges(self, rows_per_bucket: int) -> np.ndarray:
        """Bucket edges (K - 1,) s at about every ``rows_per_bucket`` rows (at most MAX_BUCKETS buckets)."""
        n = max(1, min(MAX_BUCKETS, -(-self.rows // max(1, int(rows_per_bucket)))))
        if n == 1 or self.bin_s == 0.0:
            return np.zeros(0)
        c = np.cumsum(self.counts)
        at = np.searchsorted(c, self.rows * np.arange(1, n) / n, side="left")
        return np.unique(self.t0 + (at + 1) * self.bin_s)


def _fragments(dataset):
    return list(dataset.get_fragments())


def _time_batches(dataset, column: str):
    """(fragment path, time batch as float64 numpy) over the table's files, streamed."""
    import pyarrow.parquet as pq

    for fragment in _fragments(dataset):
        try:
            reader = pq.ParquetFile(fragment.path, pre_buffer=False)
            for batch in reader.iter_batches(batch_size=COPY_BATCH_ROWS, columns=[column], use_threads=False):
                yield fragment.path, batch.column(0).to_numpy(zero_copy_only=False).astype(np.float64)
        except Exception as exc:  # pyarrow errors of many kinds
            raise read_error(fragment.path, exc) from exc


def time_profile(dataset, column: str = "time_s") -> TimeProfile:
    """The :class:`TimeProfile` of a Parquet dataset's ``column`` (two streamed passes over it:
    the range, then the histogram; times that are not finite are left out)."""
    rows, t0, t1 = 0, np.inf, -np.inf
    for _, t in _time_batches(dataset, column):
        rows += t.size
        f = t[np.isfinite(t)]
        if f.size:
            t0, t1 = min(t0, float(f.min())), max(t1, float(f.max()))
    counts = np.zeros(HISTOGRAM_BINS, dtype=np.int64)
    if rows and np.isfinite(t0):
        for _, t in _time_batches(dataset, column):
            f = t[np.isfinite(t)]
            counts += np.histogram(f, HISTOGRAM_BINS, (t0, t1 if t1 > t0 else t0 + 1.0))[0]
    return TimeProfile(rows, float(t0) if rows else 0.0, float(t1) if rows else 0.0, counts)


def needs_copy(dataset, column: str = "time_s", key: str | None = None) -> bool:
    """True when the table's row groups are too large (MAX_GROUP_ROWS) or overlap too much in time
    (OVERLAP_FACTOR) for partitions to read only their part (module docstring). With ``key`` (the
    navigation's ``platform``), groups of one key value are compared with the other groups of that
    value only: a file sorted by platform, then time, is in order."""
    rows, unknown = 0, False
    spans: dict = {}  # key value (None: several or unknown) -> [sum of spans, first, last]
    for fragment in _fragments(dataset):
        fragment.ensure_complete_metadata()
        for g in fragment.row_groups:
            rows += g.num_rows
            if g.num_rows > MAX_GROUP_ROWS:
                return True
            stats = g.statistics or {}
            s, k = stats.get(column), stats.get(key) if key is not None else None
            if s is None or s.get("min") is None:
                unknown = True
                continue
            one = k["min"] if k is not None and k.get("min") is not None and k["min"] == k["max"] else None
            acc = spans.setdefault(one, [0.0, np.inf, -np.inf])
            acc[0] += float(s["max"]) - float(s["min"])
            acc[1], acc[2] = min(acc[1], float(s["min"])), max(acc[2], float(s["max"]))
    if rows <= MAX_GROUP_ROWS:
        return False
    return unknown or any(a[0] > OVERLAP_FACTOR * max(a[2] - a[1], 0.0) for a in spans.values())


def write_buckets(dataset, folder: Path, column: str = "time_s", rows_per_bucket: int | None = None) -> Path:
    """Copy the table ``dataset`` into ``folder`` (made; returned) as files ``bucket-00000.parquet``
    ..., one per time bucket, by streaming, each row with its original row number in ROW_COLUMN
    (module docstring), buckets of about ``rows_per_bucket`` rows (default BUCKET_ROWS). Rows
    whose time is not finite go to the first bucket."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    edges = time_profile(dataset, column).edges(rows_per_bucket or BUCKET_ROWS)
    schema = dataset.schema.append(pa.field(ROW_COLUMN, pa.int64()))
    folder.mkdir(parents=True, exist_ok=True)
    writers: dict[int, pq.ParquetWriter] = {}
    row = 0
    try:
        for fragment in _fragments(dataset):
            try:
                reader = pq.ParquetFile(fragment.path, pre_buffer=False)
                batches = reader.iter_batches(batch_size=COPY_BATCH_ROWS, use_threads=False)
                for batch in batches:
                    table = pa.Table.from_batches([batch])
                    n = table.num_rows
                    table = table.append_column(ROW_COLUMN, pa.array(np.arange(row, row + n), pa.int64()))
                    row += n
                    if table.schema != schema:
                        table = table.select(schema.names).cast(schema)
                    t = table.column(column).to_numpy(zero_copy_only=False).astype(np.float64)
                    bucket = np.searchsorted(edges, np.nan_to_num(t, nan=-np.inf), side="right")
                    order = np.argsort(bucket, kind="stable")
                    bounds = np.searchsorted(bucket[order], np.arange(edges.size + 2))
                    for b in np.flatnonzero(np.diff(bounds)).tolist():
                        if b not in writers:
                            writers[b] = pq.ParquetWriter(str(folder / f"bucket-{b:05d}.parquet"), schema)
                        writers[b].write_table(table.take(order[bounds[b] : bounds[b + 1]]))
            except Exception as exc:  # pyarrow and OS errors of many kinds
                raise read_error(fragment.path, exc) from exc
    finally:
        for w in writers.values():
            w.close()
    if not writers:  # an empty table: one empty file keeps the schema
        pq.write_table(schema.empty_table(), str(folder / "bucket-00000.parquet"))
    return folder
