"""One file decoded: its data blocks found (:mod:`registration.io.asterix.capture.blocks`), the records
of CAT048, CAT034, CAT021, CAT001 and CAT002 walked (:mod:`registration.io.asterix.decode.walker`) in
the editions chosen and their fields read (``decode048``, ``decode034``, ``decode021``,
``decode001``, ``decode002``). Blocks of other categories and records that cannot be walked are set
aside with their file offsets.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterable, Mapping

import numpy as np

from registration.io.asterix.capture.blocks import Blocks, find_blocks
from registration.io.asterix.capture.capture import Capture, read_capture
from registration.io.asterix.decode.decode001 import WANTED as WANTED001
from registration.io.asterix.decode.decode001 import decode001
from registration.io.asterix.decode.decode002 import WANTED as WANTED002
from registration.io.asterix.decode.decode002 import decode002
from registration.io.asterix.decode.decode21 import decode021
from registration.io.asterix.decode.decode21 import wanted as wanted021
from registration.io.asterix.decode.decode34 import WANTED as WANTED034
from registration.io.asterix.decode.decode34 import decode034
from registration.io.asterix.decode.decode48 import WANTED as WANTED048
from registration.io.asterix.decode.decode48 import decode048
from registration.io.asterix.decode.digest import record_digests
from registration.io.asterix.decode.scalar import explain_record
from registration.io.asterix.decode.uap import DEFAULT_EDITIONS, check_editions, uap_for
from registration.io.asterix.decode.walker import Records, walk_records
from registration.io.asterix.errors import LEDGER_COLUMNS, AsterixImportError
from registration.io.files.ledger import RejectedLedger
from registration.io.files.limits import Limits

__all__ = [
    "CategoryRecords",
    "DecodedFile",
    "decode_capture",
    "decode_file",
    "CATEGORIES",
    "CHUNK_BYTES",
    "MIN_KNOWN_SHARE",
]

#: The categories decoded, in the order walked.
CATEGORIES = (48, 34, 21, 1, 2)

#: Data blocks are walked in chunks of about this many octets (progress and memory).
CHUNK_BYTES = 8 << 20


@dataclass
class CategoryRecords:
    """The records of one category in one file, (R,) each: ``fields`` (raw fields of the
    category's decoder), ``offset`` (of the record's FSPEC in the file), ``packet`` (number from 1,
    0 for a raw file), ``capture_time`` (UTC s since 1970, NaN for a raw file), ``digest`` (a
    64-bit hash of the record's octets, within one process: duplicates are found by it) and ``port``
    (UDP destination port, 0 for a raw file)."""

    fields: dict
    offset: np.ndarray
    packet: np.ndarray
    capture_time: np.ndarray
    digest: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    port: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))

    def subset(self, keep: np.ndarray) -> "CategoryRecords":
        """The records where ``keep`` (R,) bool is True."""
        return CategoryRecords(
            {k: v[keep] for k, v in self.fields.items()},
            self.offset[keep],
            self.packet[keep],
            self.capture_time[keep],
            self.digest[keep] if self.digest.size else self.digest,
            self.port[keep] if self.port.size else self.port,
        )

    @property
    def size(self) -> int:
        return int(self.offset.size)


@dataclass
class DecodedFile:
    """A file decoded: the capture read (``capture``), per category (:data:`CATEGORIES`) its records, the
    data blocks per category seen (all categories, decoded or not)."""

    capture: Capture
    records: dict
    blocks_by_category: dict = field(default_factory=dict)


def _decode(cat: int, edition: str, buf: np.ndarray, rec: Records) -> dict:
    if cat == 48:
        return decode048(buf, rec)
    if cat == 34:
        return decode034(buf, rec)
    if cat == 1:
        return decode001(buf, rec)
    if cat == 2:
        return decode002(buf, rec)
    return decode021(buf, rec, edition)


def _wanted(cat: int, edition: str) -> tuple:
    return {48: WANTED048, 34: WANTED034, 1: WANTED001, 2: WANTED002}.get(cat) or wanted021(edition)


def _chunks(sizes: np.ndarray) -> list[slice]:
    """Consecutive slices of blocks of about :data:`CHUNK_BYTES` octets each."""
    edges = np.searchsorted(np.cumsum(sizes), np.arange(CHUNK_BYTES, sizes.sum() + CHUNK_BYTES, CHUNK_BYTES))
    bounds = np.unique(np.concatenate([[0], np.minimum(edges + 1, sizes.size)]))
    return [slice(int(a), int(b)) for a, b in zip(bounds[:-1], bounds[1:])]


def _cut(rec: Records, offset: int) -> Records:
    """The records of ``rec`` that start before file ``offset`` (and the bad records before it)."""
    keep = int(np.searchsorted(rec.start, offset))
    bad = rec.bad_start < offset
    return Records(
        rec.start[:keep],
        rec.end[:keep],
        rec.block[:keep],
        {k: v[:keep] for k, v in rec.items.items()},
        rec.bad_start[bad],
        rec.bad_block[bad],
        rec.variant[:keep],
    )


def _over_limit(cap: Capture, blocks: Blocks, walked: dict, offset: int, limit: int, rejections) -> None:
    """Set aside, one row per category, what of the file lies from ``offset`` on (the first record
    beyond the limit of ``limit`` records): a category's first record cut there, or its first data
    block after it."""
    beyond = blocks.start >= offset
    for cat in CATEGORIES:
        cut = walked[cat][1].start if cat in walked else np.zeros(0, dtype=np.int64)
        cut = cut[cut >= offset]
        later = np.flatnonzero(beyond & (blocks.category == cat))
        if not (cut.size or later.size):
            continue
        rejections.add(
            cap.path,
            "over_limit",
            f"CAT{cat:03d}: the limit of {limit} records per input (max_records, --max-records) is "
            "reached; the records from here on in the file are not decoded",
            offset=int(cut[0]) if cut.size else int(blocks.start[later[0]]),
            packet=0,
            category=cat,
        )
    cap.notes.append(
        f"{cap.path}: the limit of {limit} records (max_records, --max-records) is reached at byte "
        f"{offset}; the rest of the file, of every category, is not decoded"
    )


def _set_aside_bad(
    cap: Capture, blocks: Blocks, idx: np.ndarray, rec: Records, cat: int, edition: str, uap, rejections
):
    """One rejected row per record of ``rec`` that failed to walk (blocks ``idx``)."""
    mv = memoryview(cap.buf)  # type: ignore[arg-type]  # a uint8 array is a buffer
    for start, b in zip(rec.bad_start.tolist(), rec.bad_block.tolist()):
        code, reason = explain_record(mv, start, int(blocks.end[idx[b]]), uap)
        rest = int(blocks.end[idx[b]]) - start
        seg = int(blocks.segment[idx[b]])
        rejections.add(
            cap.path,
            code,
            f"CAT{cat:03d} record (edition {edition}): {reason}; the rest of the data block "
            f"({rest} bytes) is skipped",
            offset=start,
            packet=int(cap.segments.packet[seg]),
            category=cat,
        )


def _walk_file(
    cap: Capture, blocks: Blocks, editions: Mapping[int, str], rejections, progress: Any, limit: int
) -> tuple[dict, int]:
    """The records of each of :data:`CATEGORIES` (category -> :class:`CategoryRecords`) and the
    CAT021 records that failed to walk. The blocks are walked in file order, in chunks of about
    :data:`CHUNK_BYTES`; the first ``limit`` records of the file, all categories together, are
    decoded, the rest set aside (:func:`_over_limit`): an import cut by the limit covers the
    same span of the recording in every category."""
    known = np.flatnonzero(np.isin(blocks.category, CATEGORIES))
    uaps = {cat: uap_for(cat, editions[cat]) for cat in CATEGORIES}
    parts: dict = {cat: [] for cat in CATEGORIES}
    left, failed21 = limit, 0
    for chunk in _chunks(blocks.end[known] - blocks.start[known]):
        here = known[chunk]
        walked = {}
        for cat in CATEGORIES:
            idx = here[blocks.category[here] == cat]
            if idx.size:
                wanted = _wanted(cat, editions[cat])
                walked[cat] = (
                    idx,
                    walk_records(cap.buf, blocks.start[idx], blocks.end[idx], uaps[cat], wanted),
                )
        n = sum(rec.start.size for _, rec in walked.values())
        over = n > left
        if over:
            offset = int(np.sort(np.concatenate([rec.start for _, rec in walked.values()]))[left])
            _over_limit(cap, blocks, walked, offset, limit, rejections)
            walked = {cat: (idx, _cut(rec, offset)) for cat, (idx, rec) in walked.items()}
        for cat, (idx, rec) in walked.items():
            left -= rec.start.size
            failed21 += rec.bad_start.size if cat == 21 else 0
            _set_aside_bad(cap, blocks, idx, rec, cat, editions[cat], uaps[cat], rejections)
            seg = blocks.segment[idx[rec.block]]
            port = cap.segments.port[seg] if cap.segments.port.size else np.zeros(seg.size, dtype=np.int64)
            digest = record_digests(cap.buf, rec.start, rec.end)
            decoded = _decode(cat, editions[cat], cap.buf, rec)
            parts[cat].append(
                (decoded, rec.start, cap.segments.packet[seg], cap.segments.time[seg], digest, port)
            )
        if progress is not None:
            progress.update(int((blocks.end[here] - blocks.start[here]).sum()))
        if over:
            break
    return {cat: _joined(p) for cat, p in parts.items()}, failed21


def _joined(parts: list) -> CategoryRecords:
    """The :class:`CategoryRecords` of one category's chunks (none: an empty one)."""
    fields = {k: np.concatenate([p[0][k] for p in parts]) for k in parts[0][0]} if parts else {}
    kinds = (np.int64, np.int64, np.float64, np.int64, np.int64)
    columns = [
        np.concatenate([p[i] for p in parts]).astype(t) if parts else np.zeros(0, dtype=t)
        for i, t in enumerate(kinds, start=1)
    ]
    return CategoryRecords(fields, *columns)


def _edition_hint(cap: Capture, blocks: Blocks, sel: np.ndarray, edition: str, failed: int) -> None:
    """A note when the CAT021 blocks walk better in the other family of editions (0.2x or 2.x)."""
    other = "0.26" if not edition.startswith("0.") else DEFAULT_EDITIONS[21]
    rec = walk_records(cap.buf, blocks.start[sel], blocks.end[sel], uap_for(21, other), _wanted(21, other))
    if rec.bad_start.size < failed:
        cap.notes.append(
            f"{cap.path}: {failed} CAT021 records failed to walk in edition {edition}, "
            f"{rec.bad_start.size} would in edition {other}: the feed may be of edition {other} "
            f"(--cat021-edition {other}, editions={{21: {other!r}}})"
        )


#: A raw file is refused when less than this share of its octets walk as data blocks of known
#: categories (random octets walk as blocks too, of random categories: about 14 % known).
MIN_KNOWN_SHARE = 0.5


def _check_asterix(cap: Capture, blocks: Blocks) -> None:
    """Raise :class:`AsterixImportError` for a capture without one ASTERIX datagram, or a raw file
    whose octets mostly do not walk as data blocks of known categories."""
    what = f"{cap.path}: not an ASTERIX recording"
    if cap.kind != "raw" and blocks.asterix_segments == 0:
        n = cap.counts.get("udp_datagrams", cap.segments.start.size)
        raise AsterixImportError(
            f"{what} (a {cap.kind} capture of {n} UDP datagrams"
            + (" on the ports chosen" if cap.counts.get("skipped_packets", {}).get("other_port") else "")
            + ", none of them ASTERIX data blocks)"
        )
    share = blocks.known_share(cap.size)
    if cap.kind == "raw" and share < MIN_KNOWN_SHARE:
        cats = np.unique(blocks.category).size
        raise AsterixImportError(
            f"{what} (only {100 * share:.0f} % of its {cap.size} bytes walk as data blocks of known "
            f"categories; {blocks.start.size} blocks of {cats} different categories)"
        )


def decode_file(
    path: str | Path,
    editions: Mapping[int, str] | None = None,
    rejections: RejectedLedger | None = None,
    ports: Iterable[int] | None = None,
    progress: Any = None,
    limits: Limits | None = None,
    framing: str = "auto",
) -> DecodedFile:
    """Decode the CAT048, CAT034, CAT021, CAT001 and CAT002 records of one file (raw, pcap or
    pcapng, gzip or not).

    ``editions``: category -> edition (default :data:`~registration.io.asterix.decode.uap.DEFAULT_EDITIONS`);
    ``rejections``: where what is set aside goes (a new one if None); ``ports``: UDP destination
    ports to keep from a capture (None: all); ``progress``: an object whose ``update(octets)`` is
    called with the octets of the blocks walked (a tqdm bar, say) and, if it has one,
    ``file_size(octets)`` with the file's (decompressed) size once read. Raises
    :class:`~registration.io.asterix.errors.AsterixImportError` for a file that is neither ASTERIX
    nor a capture; anything bad inside is set aside. ``limits``: the bounds on the decompressed
    size and the records of the file (:class:`~registration.io.files.limits.Limits`). ``framing``:
    'auto' (told by content), 'netto' (raw data blocks) or a recorder framing (gps, ioss, ...).
    """
    limits = Limits() if limits is None else limits
    rejections = RejectedLedger(LEDGER_COLUMNS) if rejections is None else rejections
    cap = read_capture(path, rejections, ports, limits.max_bytes, framing)
    if progress is not None and hasattr(progress, "file_size"):
        progress.file_size(cap.size)
    return decode_capture(cap, editions, rejections, progress, limits)


def decode_capture(
    cap: Capture,
    editions: Mapping[int, str] | None,
    rejections: RejectedLedger,
    progress: Any = None,
    limits: Limits | None = None,
    *,
    refuse_non_asterix: bool = True,
) -> DecodedFile:
    """:func:`decode_file` of a capture already read (a file's, or datagrams received:
    :func:`~registration.io.asterix.capture.capture.capture_from_datagrams`).
    ``refuse_non_asterix`` False: a capture without ASTERIX is not an error (a live stream's
    datagrams that are not ASTERIX are set aside one by one instead)."""
    limits = Limits() if limits is None else limits
    editions = check_editions(editions)
    blocks = find_blocks(cap, rejections)
    if refuse_non_asterix:
        _check_asterix(cap, blocks)
    cats, counts = np.unique(blocks.category, return_counts=True)
    records, failed21 = _walk_file(cap, blocks, editions, rejections, progress, limits.max_records)
    if failed21:
        sel = np.flatnonzero(blocks.category == 21)
        _edition_hint(cap, blocks, sel, editions[21], failed21)
    other = np.flatnonzero(~np.isin(blocks.category, CATEGORIES))
    if other.size:
        rejections.add(
            cap.path,
            "unknown_category",
            np.array(
                [
                    f"data block of category {c} ({e - s} bytes), not decoded"
                    for c, s, e in zip(blocks.category[other], blocks.start[other], blocks.end[other])
                ],
                dtype=object,
            ),
            offset=blocks.start[other],
            packet=cap.segments.packet[blocks.segment[other]],
            category=blocks.category[other],
        )
        if progress is not None:
            progress.update(int((blocks.end[other] - blocks.start[other]).sum()))
    return DecodedFile(cap, records, {int(c): int(n) for c, n in zip(cats, counts)})
