"""A file that is no pcap/pcapng capture unwrapped to its data blocks: its framing detected by content
(:mod:`registration.io.asterix.capture.detect`) or named (``framing``), each record of the framing a
segment of the file (views on the buffer, no copy), with the record's time stamp where the framing
has one. A file that walks as no framing and not as plausible raw ASTERIX ('netto') raises
:class:`~registration.io.asterix.errors.AsterixImportError` saying what was tried.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration.io.asterix.capture.blocks import walk_raw
from registration.io.asterix.capture.detect import (
    FRAMING_NAMES,
    FRAMINGS,
    RAW_MIN_KNOWN,
    SAMPLE_RECORDS,
    framed_verdict,
    plausible,
)
from registration.io.asterix.capture.framings import Framed
from registration.io.asterix.capture.model import ASTERIX_CATEGORIES
from registration.io.asterix.capture.netstack import Segments
from registration.io.asterix.errors import AsterixImportError
from registration.io.files.ledger import RejectedLedger

__all__ = ["Unwrapped", "unwrap", "check_framing"]

#: Octets of a raw file judged (its first MiB).
_RAW_SAMPLE = 1 << 20
#: Records a framing must show within its sample to be told by content.
_MIN_RECORDS = 3


@dataclass
class Unwrapped:
    """``framing`` ('netto' or a framing's name), ``segments`` (per record: its data blocks' octets,
    record number from 1 as ``packet``, time stamp), ``clock`` ('utc', 'time_of_day'; see
    :class:`~registration.io.asterix.capture.model.Capture`), ``notes``, ``counts``."""

    framing: str
    segments: Segments
    clock: str = "utc"
    notes: list = field(default_factory=list)
    counts: dict = field(default_factory=dict)


def check_framing(framing: str) -> str:
    """``framing`` if it is one of :data:`FRAMING_NAMES` ('final' is taken as 'ioss'), else ValueError."""
    framing = "ioss" if framing == "final" else framing
    if framing not in FRAMING_NAMES:
        raise ValueError(f"framing: {framing!r}; expected one of {', '.join(FRAMING_NAMES)}")
    return framing


def _looks_like_text(data: memoryview) -> bool:
    head = bytes(data[:512])
    return all(32 <= c < 127 or c in (9, 10, 13) for c in head)


def _raw_first_block(mv: memoryview, n: int) -> str:
    """Why ``mv`` cannot be raw ASTERIX by its first data block ('' when it can)."""
    if n < 3:
        return f"{n} bytes, too short for an ASTERIX data block or a capture"
    cat, length = mv[0], (mv[1] << 8) | mv[2]
    if cat not in ASTERIX_CATEGORIES:
        return f"the first byte, {cat}, is no ASTERIX category"
    if length < 3 or length > n:
        return f"the first data block, category {cat}, declares {length} bytes; the file has {n}"
    return ""


def _raw_verdict(buf: np.ndarray, mv: memoryview, n: int) -> str:
    """Why the file is not plausible raw ASTERIX ('' when it is)."""
    why = _raw_first_block(mv, n)
    if why:
        return why
    size = min(n, _RAW_SAMPLE)
    start, end, cats = walk_raw(buf, size)
    return plausible(buf, start, end, cats, size, f"its {n} bytes" if size == n else "", RAW_MIN_KNOWN).why


def _segments(framed: Framed) -> Segments:
    time = framed.time if framed.clock != "none" else np.full(framed.start.size, np.nan)
    number = np.arange(1, framed.start.size + 1, dtype=np.int64)
    return Segments(framed.start, framed.end, number, time, np.zeros(framed.start.size, dtype=np.int64))


def _unframed(name: str, framed: Framed, path: str, rejections: RejectedLedger) -> Unwrapped:
    """The whole file walked in ``name``: its records as segments, what did not walk set aside."""
    for offset, number, reason in framed.problems:
        rejections.add(
            path,
            "truncated_packet",
            f"{reason}; the rest of the file is lost" if name != "hdlc" else reason,
            offset=offset,
            packet=number,
            category=0,
        )
    out = Unwrapped(name, _segments(framed), "time_of_day" if framed.clock == "time_of_day" else "utc")
    out.notes += [f"{path}: {note}" for note in framed.notes]
    out.counts["framing_records"] = int(framed.start.size)
    finite = framed.time[np.isfinite(framed.time)]
    if framed.clock == "utc" and finite.size:
        out.counts["first_packet_time"] = float(finite.min())
    return out


def unwrap(buf: np.ndarray, n: int, path: str, framing: str, rejections: RejectedLedger) -> Unwrapped:
    """The segments of the ``n`` octets of ``buf`` (a file that is no capture) in ``framing`` ('auto':
    detected). Raises AsterixImportError naming ``path`` when nothing walks."""
    framing = check_framing(framing)
    mv = memoryview(buf)[:n]  # type: ignore[arg-type]  # a uint8 array is a buffer
    tried = []
    for name in FRAMINGS if framing == "auto" else [framing] if framing != "netto" else []:
        walk = FRAMINGS[name]
        if framing == "auto":
            sample = walk(mv, n, SAMPLE_RECORDS)
            verdict = framed_verdict(buf, n, sample)
            if verdict.ok and sample.start.size < min(_MIN_RECORDS, SAMPLE_RECORDS):
                verdict.ok, verdict.why = False, f"only {sample.start.size} record(s)"
            if not verdict.ok:
                tried.append(f"{name}: {verdict.why}")
                continue
        framed = walk(mv, n)
        if not framed.start.size:
            raise AsterixImportError(
                f"{path}: not an ASTERIX recording in the {name} framing asked for "
                f"({framed.problems[0][2] if framed.problems else 'no record'})"
            )
        return _unframed(name, framed, path, rejections)
    why = _raw_verdict(buf, mv, n)
    if not why or framing == "netto" and not _raw_first_block(mv, n):
        return Unwrapped("netto", Segments(np.array([0]), np.array([n]), np.array([0]), np.array([np.nan])))
    text = "a text file, " if _looks_like_text(mv) else ""
    framings = "; ".join(tried) if tried else f"the {framing} framing asked for"
    raise AsterixImportError(
        f"{path}: {text}not an ASTERIX recording ({why}; neither a pcap/pcapng capture nor an ASTERIX "
        f"recording in a recorder framing: {framings})"
    )
