"""Recorder framings of ASTERIX data blocks: each reader walks a file's records and gives where the
data blocks of each record lie, with the record's time stamp where the framing has one.

Layouts (docs/reference/asterix-framings.md; octets big-endian unless said):

- ``gps``: the Croatia Control "GPS" recording (the ``asterix`` tool's ``-G``): a 2200-octet file
  header (not read), then per data block the block itself and a 10-octet trailer whose octets 6-8
  are the time of day in 1/128 s.
- ``ioss`` (jASTERIX ``ioss``; the ``asterix`` tool's ``-F`` FINAL is the same layout): per record a
  16-bit length counting the whole record, 1 octet (line), 1 octet board number, 1 octet recording
  day, 24-bit time of day in 10 ms, the data blocks, 4 padding octets (A5 A5 A5 A5).
- ``ioss_seq`` (jASTERIX): as ``ioss`` with a 32-bit sequence number after the length.
- ``oradis`` (the ``asterix`` tool's ``-O``): per record a 16-bit length counting the whole record,
  a 32-bit time the tool does not interpret (nor does this reader), the data blocks.
- ``rff`` (jASTERIX): a 128-octet file header (start and end date-time as text, 20 octets each),
  then per record a 32-bit time in ms since the start, a 16-bit little-endian length of the
  data blocks, the data blocks.

HDLC frames (``-H``) are read by :mod:`registration.io.asterix.capture.hdlc`.
"""

from __future__ import annotations

import datetime as dt
import re
from dataclasses import dataclass, field

import numpy as np

__all__ = ["Framed", "walk_gps", "walk_ioss", "walk_ioss_seq", "walk_oradis", "walk_rff", "GPS_HEADER"]

#: Octets of the GPS recording's file header and of its per-block trailer.
GPS_HEADER, GPS_TRAILER = 2200, 10
#: Octets of the RFF file header.
RFF_HEADER = 128


@dataclass
class Framed:
    """A framing walked. Per record (R,): ``start``, ``end`` (the octets holding its data blocks),
    ``head`` (offset of the record's own header), ``time`` (s; meaning by ``clock``: 'utc' UTC s
    since 1970, 'time_of_day' s since midnight UTC, 'none' NaN). ``problems``: (offset, record
    number from 1, reason) of what does not walk (the walk stops there, or resumes for HDLC);
    ``cut`` whether the last problem is a record cut off by the end of the file; ``notes``."""

    start: np.ndarray
    end: np.ndarray
    head: np.ndarray
    time: np.ndarray
    clock: str
    problems: list = field(default_factory=list)
    notes: list = field(default_factory=list)
    cut: bool = False

    @classmethod
    def of(cls, rows: list, clock: str, problems: list, cut: bool = False) -> "Framed":
        """From rows of (start, end, head, time)."""
        a = np.array(rows, dtype=np.float64).reshape(-1, 4)
        i = a[:, :3].astype(np.int64)
        return cls(i[:, 0], i[:, 1], i[:, 2], a[:, 3], clock, problems, [], cut)


def _be(mv: memoryview, p: int, k: int) -> int:
    return int.from_bytes(mv[p : p + k], "big")


def walk_gps(mv: memoryview, n: int, limit: int | None = None) -> Framed:
    """The GPS recording: header, then (data block, 10-octet trailer) to the end."""
    rows: list = []
    problems: list = []
    p, cut = GPS_HEADER, False
    if n < GPS_HEADER + 3 + GPS_TRAILER:
        problems.append((0, 0, f"{n} bytes, too few for the 2200-byte header and one block"))
    while p < n and (limit is None or len(rows) < limit):
        k = len(rows) + 1
        length = _be(mv, p + 1, 2) if p + 3 <= n else 0
        if p + 3 > n or length < 3 or p + length + GPS_TRAILER > n:
            what = (
                f"{n - p} bytes left, too few for a data block header"
                if p + 3 > n
                else f"a data block of {length} bytes (below 3)"
                if length < 3
                else f"a data block of {length} bytes and its 10-byte trailer run past the end "
                f"({n - p} bytes left)"
            )
            problems.append((p, k, f"GPS record {k}: {what}"))
            cut = p + 3 > n or length >= 3
            break
        t = _be(mv, p + length + 6, 3) / 128.0
        rows.append((p, p + length, p, t))
        p += length + GPS_TRAILER
    return Framed.of(rows, "time_of_day", problems, cut)


def _walk_counted(
    mv: memoryview, n: int, limit: int | None, name: str, head: int, tail: int, time_at: int | None
) -> Framed:
    """Records of a 16-bit length counting the whole record, ``head`` octets before the data blocks
    and ``tail`` after; the 24-bit time of day in 10 ms at ``time_at`` (None: no time)."""
    rows: list = []
    problems: list = []
    p, cut = 0, False
    while p < n and (limit is None or len(rows) < limit):
        k = len(rows) + 1
        length = _be(mv, p, 2) if p + 2 <= n else 0
        if p + 2 > n or length < head + tail + 3 or p + length > n:
            what = (
                f"record of {length} bytes (below {head + tail + 3}, its header, trailer and a data block)"
                if p + 2 <= n and length < head + tail + 3
                else f"record of {length} bytes runs past the end ({n - p} bytes left)"
            )
            problems.append((p, k, f"{name} record {k}: {what}"))
            cut = p + 2 > n or length >= head + tail + 3
            break
        t = _be(mv, p + time_at, 3) / 100.0 if time_at is not None else np.nan
        rows.append((p + head, p + length - tail, p, t))
        p += length
    return Framed.of(rows, "time_of_day" if time_at is not None else "none", problems, cut)


def walk_ioss(mv: memoryview, n: int, limit: int | None = None) -> Framed:
    """IOSS / FINAL records: length, line, board, day, time (10 ms), data blocks, 4 padding octets."""
    return _walk_counted(mv, n, limit, "IOSS", 8, 4, 5)


def walk_ioss_seq(mv: memoryview, n: int, limit: int | None = None) -> Framed:
    """IOSS records with a 32-bit sequence number after the length."""
    return _walk_counted(mv, n, limit, "IOSS (sequence numbered)", 12, 4, 9)


def walk_oradis(mv: memoryview, n: int, limit: int | None = None) -> Framed:
    """ORADIS records: length, 32-bit time (not read), data blocks."""
    return _walk_counted(mv, n, limit, "ORADIS", 6, 0, None)


_DATE = re.compile(r"(\d{1,4})[-./](\d{1,2})[-./](\d{1,4})[ T_]+(\d{1,2}):(\d{2}):(\d{2})(?:[.,](\d+))?")


def parse_header_time(text: str) -> float | None:
    """UTC s since 1970 of a date-time written as text (year first or day first, '-', '.' or '/'
    between the date's numbers, optional fraction of the second), or None."""
    m = _DATE.search(text)
    if m is None:
        return None
    a, b, c, hh, mm, ss, frac = m.groups()
    year, month, day = (int(a), int(b), int(c)) if len(a) == 4 else (int(c), int(b), int(a))
    try:
        when = dt.datetime(year, month, day, int(hh), int(mm), int(ss), tzinfo=dt.timezone.utc)
    except ValueError:
        return None
    return when.timestamp() + (float("0." + frac) if frac else 0.0)


def walk_rff(mv: memoryview, n: int, limit: int | None = None) -> Framed:
    """RFF: 128-octet header (start, end date-time as text), then (32-bit ms since the start, 16-bit
    little-endian length, data blocks). The byte order of the ms is taken from the file: the one
    in which they start lowest and advance (jASTERIX reads them big-endian)."""
    rows: list = []
    raw_ms: list = []
    problems: list = []
    p, cut = RFF_HEADER, False
    if n < RFF_HEADER + 9:
        problems.append((0, 0, f"{n} bytes, too few for the 128-byte header and one record"))
    while p < n and (limit is None or len(rows) < limit):
        k = len(rows) + 1
        length = int.from_bytes(mv[p + 4 : p + 6], "little") if p + 6 <= n else 0
        if p + 6 > n or length < 3 or p + 6 + length > n:
            problems.append(
                (p, k, f"RFF record {k}: a record of {length} bytes (below 3 or past the end, {n - p} left)")
            )
            cut = p + 6 > n or length >= 3
            break
        raw_ms.append(bytes(mv[p : p + 4]))
        rows.append((p + 6, p + 6 + length, p, np.nan))
        p += 6 + length
    framed = Framed.of(rows, "utc", problems, cut)
    start = parse_header_time(bytes(mv[: min(20, n)]).decode("latin-1"))
    if not rows:
        return framed
    stamps = np.frombuffer(b"".join(raw_ms), dtype=np.uint8).reshape(-1, 4)
    big = stamps.astype(np.int64) @ np.array([1 << 24, 1 << 16, 1 << 8, 1])
    little = stamps.astype(np.int64) @ np.array([1, 1 << 8, 1 << 16, 1 << 24])
    ms = big if _advance(big) >= _advance(little) else little
    if start is None:
        framed.clock = "none"
        framed.notes.append("the RFF header's start time is not a date-time; the record times are not used")
    else:
        framed.time = start + ms / 1000.0
    return framed


def _advance(ms: np.ndarray) -> tuple:
    """How well a sequence of ms advances: (share of steps not backward, minus the first value)."""
    steps = np.diff(ms)
    return (float((steps >= 0).mean()) if steps.size else 1.0, -float(ms[0]))
