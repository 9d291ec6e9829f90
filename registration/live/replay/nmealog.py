"""An NMEA 0183 log as datagrams: one per line (its text and CR LF, whatever the file's line ends),
blank lines left out, read a piece of lines at a time.

A line's time is that of the last *anchor* at or before it: the sentences the NMEA importer times
the log by (GGA, GNS, RMC, ZDA, ``$PASHR``; :mod:`registration.io.nmea.clock`), read by the
importer's own functions (:func:`~registration.io.nmea.lines.read_lines`,
:func:`~registration.io.nmea.fixes.read_fixes`, :func:`~registration.io.nmea.attitude.read_pashr`).
Times are times of day (s since midnight UTC). A file without any anchor so far is timed by the
lines' reception times (tag block ``c:`` or a logger's prefix, unix seconds), when they have them.
Lines before the first time take the next datagrams' pace from the first one timed.
"""

from __future__ import annotations

from typing import Iterator

import numpy as np

from registration.io.files.limits import BoundedLedger
from registration.io.nmea.attitude import read_pashr
from registration.io.nmea.errors import LEDGER_COLUMNS
from registration.io.nmea.fixes import read_fixes
from registration.io.nmea.lines import SentenceLog, read_lines
from registration.live.replay.stream import ByteStream, Datagrams

__all__ = ["nmea_datagrams", "looks_like_nmea", "line_times"]

#: The share of a log's first non-blank lines that must be sentences with a correct checksum.
MIN_SENTENCE_SHARE = 0.5
#: The longest line (octets) kept whole; a longer stretch without a line end is cut.
MAX_LINE = 1 << 20


def _split(data: bytes) -> list[bytes]:
    lines = data.split(b"\n")
    if lines and lines[-1] == b"":
        lines.pop()
    return lines


def looks_like_nmea(path: str, head_bytes: int) -> bool:
    """Whether the first ``head_bytes`` octets of ``path`` (decompressed) read as an NMEA log: text
    lines, at least half of the non-blank ones a sentence with a correct checksum."""
    with ByteStream(path) as stream:
        data = stream.read(head_bytes)
    if not stream.done:
        data = data[: data.rfind(b"\n") + 1]
    lines = [line.decode("latin-1") for line in _split(data)]
    texts = [line for line in lines if line.strip()]
    if not texts:
        return False
    log = read_lines(texts, path, BoundedLedger(LEDGER_COLUMNS, 1, [path]))
    return len(log.sentence) >= MIN_SENTENCE_SHARE * len(texts)


def line_times(log: SentenceLog, first_line: int, n_lines: int, timed_by_reception: bool) -> np.ndarray:
    """Time of day (s; NaN: none yet) of lines ``first_line .. first_line + n_lines - 1`` of ``log``:
    that of the last anchor at or before each (or, ``timed_by_reception``, of the last line with a
    reception time, in unix s)."""
    ledger = BoundedLedger(LEDGER_COLUMNS, 1, log.files)
    if timed_by_reception:
        which = np.flatnonzero(np.isfinite(log.received))
        at, tod = log.line[which], log.received[which]
    else:
        fixes, dates = read_fixes(log, ledger)
        pashr = read_pashr(log, ledger)
        kinds: list = [fixes[k] for k in ("GGA", "GNS", "RMC")] + [dates, pashr]
        index = np.concatenate([k.index for k in kinds]).astype(np.int64)
        tod = np.concatenate([k.tod for k in kinds]).astype(np.float64)
        order = np.argsort(index, kind="stable")
        at, tod = log.line[index[order]], tod[order]
    j = np.searchsorted(at, np.arange(first_line, first_line + n_lines), side="right") - 1
    return np.where(j >= 0, tod[np.maximum(j, 0)] if tod.size else np.nan, np.nan)


def nmea_datagrams(stream: ByteStream, name: str, piece_bytes: int) -> Iterator[Datagrams]:
    """The lines of the log ``stream`` as :class:`~registration.live.replay.stream.Datagrams`, about
    ``piece_bytes`` octets of lines at a time."""
    carry, first_line, anchored = b"", 1, False
    ledger = BoundedLedger(LEDGER_COLUMNS, 1, [name])
    while True:
        new = stream.read(piece_bytes)
        final = len(new) < piece_bytes
        data = carry + new
        cut = len(data) if final else data.rfind(b"\n") + 1
        if cut == 0 and len(data) <= MAX_LINE:
            carry = data
            continue
        cut = cut or len(data)
        data, carry = data[:cut], data[cut:]
        lines = _split(data)
        log = read_lines([line.decode("latin-1") for line in lines], name, ledger, first_line)
        times = line_times(log, first_line, len(lines), False)
        if np.isfinite(times).any():
            anchored = True
        elif not anchored:
            times = line_times(log, first_line, len(lines), True)
        first_line += len(lines)
        text = [line.rstrip(b"\r") for line in lines]
        keep = np.flatnonzero([bool(line.strip()) for line in text])
        if keep.size:
            sizes = np.fromiter((len(text[k]) + 2 for k in keep), dtype=np.int64, count=keep.size)
            end = np.cumsum(sizes)
            buf = b"\r\n".join(text[k] for k in keep) + b"\r\n"
            yield Datagrams(buf, end - sizes, end, times[keep], True, stream.position)
        if final:
            return
