"""ORADIS records inside the UDP datagrams of a capture (the Croatia Control ``asterix`` tool's
``-R``): each datagram holds records of a 16-bit length counting the whole record, a 32-bit time
(not read), and data blocks. Told by content: the datagrams are taken as ORADIS when the sampled
ones do not hold data blocks end to end but do hold ORADIS records end to end, whose blocks are
plausible ASTERIX (:func:`~registration.io.asterix.capture.detect.plausible`).
"""

from __future__ import annotations

import numpy as np

from registration.io.asterix.capture.detect import SAMPLE_RECORDS, chain_blocks, plausible
from registration.io.asterix.capture.netstack import Segments

__all__ = ["oradis_datagrams"]

#: Octets of an ORADIS record header (length, time).
_HEAD = 6


def _records(mv: memoryview, s: int, e: int) -> list | None:
    """(start, end) of the data blocks of each ORADIS record filling [s, e), or None."""
    out, p = [], s
    while p + _HEAD + 3 <= e:
        length = (mv[p] << 8) | mv[p + 1]
        if length < _HEAD + 3 or p + length > e:
            return None
        out.append((p + _HEAD, p + length))
        p += length
    return out if p == e and out else None


def _split(mv: memoryview, seg: Segments, which: np.ndarray) -> tuple[Segments, int]:
    """The segments ``which`` split into their ORADIS records (a datagram that is not ORADIS kept
    whole), and how many of them were ORADIS."""
    rows: list = []
    found = 0
    for k in which.tolist():
        got = _records(mv, int(seg.start[k]), int(seg.end[k]))
        found += got is not None
        rows += [(a, b, k) for a, b in got] if got else [(int(seg.start[k]), int(seg.end[k]), k)]
    a = np.array(rows, dtype=np.int64).reshape(-1, 3)
    idx = a[:, 2]
    port = seg.port[idx] if seg.port.size else seg.port
    return Segments(a[:, 0], a[:, 1], seg.packet[idx], seg.time[idx], port), found


def oradis_datagrams(buf: np.ndarray, seg: Segments, framing: str) -> Segments | None:
    """``seg`` (UDP payloads) split into ORADIS records when ``framing`` is 'oradis', or 'auto' and
    the datagrams look like ORADIS rather than data blocks; else None."""
    if framing not in ("auto", "oradis") or not seg.start.size:
        return None
    mv = memoryview(buf)  # type: ignore[arg-type]  # a uint8 array is a buffer
    if framing == "auto":
        sample = np.arange(min(seg.start.size, SAMPLE_RECORDS))
        ps, pe = chain_blocks(buf, seg.start[sample], seg.end[sample])
        span = int((seg.end[sample] - seg.start[sample]).sum())
        if ps.size and plausible(buf, ps, pe, buf[ps].astype(np.int64), span).ok:
            return None
        split, found = _split(mv, seg, sample)
        if found < 0.9 * sample.size:
            return None
        bs, be = chain_blocks(buf, split.start, split.end)
        span = int((split.end - split.start).sum())
        if not bs.size or not plausible(buf, bs, be, buf[bs].astype(np.int64), span).ok:
            return None
    return _split(mv, seg, np.arange(seg.start.size))[0]
