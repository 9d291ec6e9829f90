"""The data blocks of a file: in each segment (a raw recording whole, one UDP payload, or one
record of a recorder framing) the data blocks end to end, each a category octet, a 16-bit length
counting the 3-octet header, and records.

A header whose length is below 3 or runs past its segment is set aside (``bad_block_length``,
``truncated_block``). In a UDP datagram the rest of the datagram goes with it. In a raw recording
the reader looks for the next offset where a data block of a category already seen (or a known
category) starts and is followed by another such block or by the end of the file; the bytes up to
it are set aside with the header's reason, which names the offset resumed at. If there is none,
the rest of the file is set aside: a recording cut off in its last block loses that block only.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Collection

import numpy as np

from registration.io.asterix.capture.model import ASTERIX_CATEGORIES, Capture
from registration.io.files.ledger import RejectedLedger

__all__ = ["Blocks", "find_blocks", "walk_raw"]

#: Octets searched at a time when resynchronising a raw recording.
_WINDOW = 1 << 20


@dataclass
class Blocks:
    """Per data block (N,), in file order: ``start`` (offset of its header), ``end`` (one past its
    last octet), ``category``, ``segment`` (index into the capture's segments)."""

    start: np.ndarray
    end: np.ndarray
    category: np.ndarray
    segment: np.ndarray
    asterix_segments: int = 0

    def known_share(self, size: int) -> float:
        """The share of ``size`` octets that lie in data blocks of known ASTERIX categories."""
        known = np.isin(self.category, list(ASTERIX_CATEGORIES))
        return float((self.end[known] - self.start[known]).sum()) / max(size, 1)


def _header(mv: memoryview, p: int) -> tuple[int, int]:
    return mv[p], (mv[p + 1] << 8) | mv[p + 2]


def _plausible(mv: memoryview, q: int, n: int, cats: Collection[int]) -> bool:
    """A block of a category in ``cats`` at q, inside the file, followed by the end or by another."""
    cat, length = _header(mv, q)
    if cat not in cats or length < 3 or q + length > n:
        return False
    r = q + length
    if r == n:
        return True
    if r + 3 > n:
        return False
    cat2, length2 = _header(mv, r)
    return cat2 in cats and length2 >= 3 and r + length2 <= n


def _resync(buf: np.ndarray, mv: memoryview, p: int, n: int, cats: Collection[int]) -> int | None:
    """The first offset after p where a plausible data block starts, or None."""
    lookup = np.zeros(256, dtype=bool)
    lookup[list(cats)] = True
    for lo in range(p + 1, n - 2, _WINDOW):
        hi = min(lo + _WINDOW, n - 2)
        for q in np.flatnonzero(lookup[buf[lo:hi]]) + lo:
            if _plausible(mv, int(q), n, cats):
                return int(q)
    return None


def _segment_blocks(
    mv: memoryview, buf: np.ndarray, s: int, e: int, where: str, seen: set, out: list, bad: list
) -> None:
    """Append (start, end, category) of the blocks in [s, e) to ``out``; problems to ``bad`` as
    (offset, code, reason). ``where``: 'file' (a raw recording: resynchronise after a bad header),
    'datagram' or 'record' (of a framing)."""
    raw = where == "file"
    p = s
    while p < e:
        if p + 3 > e:
            bad.append(
                (
                    p,
                    "truncated_block",
                    f"{e - p} bytes left at the end of the {where}, too few for a data block header",
                )
            )
            return
        cat, length = _header(mv, p)
        if 3 <= length <= e - p:
            out.append((p, p + length, cat))
            seen.add(cat)
            p += length
            continue
        code = "bad_block_length" if length < 3 else "truncated_block"
        what = (
            f"data block of category {cat} with length {length} (below the 3-byte header)"
            if length < 3
            else f"data block of category {cat} declares {length} bytes, {e - p} left in the {where}"
        )
        q = _resync(buf, mv, p, e, seen or ASTERIX_CATEGORIES) if raw else None
        if q is None:
            bad.append((p, code, f"{what}; the remaining {e - p} bytes are skipped"))
            return
        bad.append((p, code, f"{what}; {q - p} bytes skipped to the next valid data block at offset {q}"))
        p = q


def _datagram_blocks(buf: np.ndarray, start: np.ndarray, end: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The data blocks of many segments at once, each walked header by header in step (a datagram
    holds one or a few): (rows (B, 4): start, end, category, segment; in segment and file order),
    and per segment whether a header was bad (those segments' rows are left out: the caller walks
    them one by one for the reasons)."""
    n = start.size
    p, bad = start.astype(np.int64).copy(), np.zeros(n, dtype=bool)
    active = p < end
    parts = []
    while active.any():
        k = np.flatnonzero(active)
        q, e = p[k], end[k]
        short = q + 3 > e
        safe = np.where(short, 0, q)  # a short tail's header is not read
        cat = buf[safe].astype(np.int64)
        length = (buf[safe + 1].astype(np.int64) << 8) | buf[safe + 2]
        ok = ~short & (length >= 3) & (length <= e - q)
        bad[k[~ok]] = True
        parts.append(np.stack([q[ok], q[ok] + length[ok], cat[ok], k[ok]], axis=1))
        p[k[ok]] += length[ok]
        active[k[~ok]] = False
        active[k[ok]] = p[k[ok]] < e[ok]
    rows = np.concatenate(parts) if parts else np.zeros((0, 4), dtype=np.int64)
    rows = rows[~bad[rows[:, 3]]]
    return rows[np.lexsort((rows[:, 0], rows[:, 3]))], bad


def find_blocks(cap: Capture, rejections: RejectedLedger) -> Blocks:
    """The data blocks of ``cap``; bad headers are set aside in ``rejections``. ``asterix_segments``
    counts the segments that are data blocks of known categories end to end, without a bad header.
    Datagrams are walked all at once (:func:`_datagram_blocks`); a raw recording, a framing's
    records and any segment with a bad header one by one, so that the reasons name each."""
    mv = memoryview(cap.buf)  # type: ignore[arg-type]  # a uint8 array is a buffer
    seg = cap.segments
    where = {"raw": "file", "pcap": "datagram", "pcapng": "datagram", "udp": "datagram"}.get(
        cap.kind, "record"
    )
    if where == "datagram":
        fast, slow = _datagram_blocks(cap.buf, seg.start, seg.end)
    else:
        fast, slow = np.zeros((0, 4), dtype=np.int64), np.ones(seg.start.size, dtype=bool)
    rows: list = []
    seg_of: list = []
    seen: set[int] = set(np.unique(fast[:, 2]).tolist())
    good = 0
    for k in np.flatnonzero(slow).tolist():
        out: list = []
        bad: list = []
        _segment_blocks(mv, cap.buf, int(seg.start[k]), int(seg.end[k]), where, seen, out, bad)
        good += bool(out) and not bad and all(c in ASTERIX_CATEGORIES for _, _, c in out)
        rows += out
        seg_of += [k] * len(out)
        for offset, code, reason in bad:
            rejections.add(cap.path, code, reason, offset=offset, packet=int(seg.packet[k]), category=0)
    if fast.size:  # a datagram walked at once counts when it holds blocks of known categories only
        unknown = ~np.isin(fast[:, 2], list(ASTERIX_CATEGORIES))
        good += int(np.setdiff1d(np.unique(fast[:, 3]), fast[unknown, 3]).size)
    one_by_one = np.column_stack(
        [np.array(rows, dtype=np.int64).reshape(-1, 3), np.array(seg_of, dtype=np.int64)]
    )
    a = np.concatenate([fast, one_by_one])
    a = a[np.lexsort((a[:, 0], a[:, 3]))]
    return Blocks(a[:, 0], a[:, 1], a[:, 2], a[:, 3], good)


def walk_raw(buf: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(start, end, category) of the data blocks of the first ``n`` octets of ``buf`` read as a raw
    recording (resynchronising after a bad header, as :func:`find_blocks` does)."""
    mv = memoryview(buf)  # type: ignore[arg-type]  # a uint8 array is a buffer
    out: list = []
    _segment_blocks(mv, buf, 0, n, "file", set(), out, [])
    a = np.array(out, dtype=np.int64).reshape(-1, 3)
    return a[:, 0], a[:, 1], a[:, 2]
