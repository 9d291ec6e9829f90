"""Recordings as datagrams to replay, a piece at a time: each piece a buffer with the offsets of its
datagrams and their recorded times (numpy arrays; no Python object per datagram).

* **pcap** and **pcapng** captures: each UDP datagram's payload as captured, timed by its capture
  time (UTC s since 1970); ``ports`` keeps only those UDP destination ports (the packets and
  datagrams are found by :mod:`registration.io.asterix.capture`; a pcapng piece starts with the
  section header and interface descriptions read so far).
* **raw ASTERIX** (data blocks end to end): one datagram per data block, timed by the time of day of
  the first record of the block (I048/140, I034/030, I021/071..077 in the default editions;
  :mod:`registration.io.asterix.decode`); a block without one gets NaN (the previous block's time).
* **NMEA 0183 logs**: :mod:`registration.live.replay.nmealog`.

:func:`recognise` tells them apart by content, as the importers do (gzip or not).
"""

from __future__ import annotations

import struct
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Iterator

import numpy as np

from registration.io.asterix.capture.blocks import Blocks, find_blocks
from registration.io.asterix.capture.capture import Capture, read_capture
from registration.io.asterix.capture.netstack import Segments, udp_segments
from registration.io.asterix.capture.pcap import PCAPNG_MAGIC, pcap_packets, pcapng_packets
from registration.io.asterix.decode.decode21 import decode021
from registration.io.asterix.decode.decode21 import wanted as wanted021
from registration.io.asterix.decode.decode34 import WANTED as WANTED034
from registration.io.asterix.decode.decode34 import decode034
from registration.io.asterix.decode.decode48 import TOD_LSB_S, decode048
from registration.io.asterix.decode.decode48 import WANTED as WANTED048
from registration.io.asterix.decode.reader import MIN_KNOWN_SHARE
from registration.io.asterix.decode.uap import DEFAULT_EDITIONS, uap_for
from registration.io.asterix.decode.walker import Records, walk_records
from registration.io.asterix.errors import LEDGER_COLUMNS, AsterixImportError
from registration.io.asterix.octets import PAD
from registration.io.files.limits import BoundedLedger
from registration.live.replay.nmealog import looks_like_nmea, nmea_datagrams
from registration.live.replay.stream import ByteStream, Datagrams

__all__ = ["Recording", "ReplayError", "recognise", "datagrams", "PIECE_BYTES", "NMEA_PIECE_BYTES", "KINDS"]

#: Decompressed octets of a capture or raw recording read at a time (the memory a replay holds is
#: a few times this, some 100 MB above the interpreter's).
PIECE_BYTES = 4 << 20
#: Octets of an NMEA log read at a time (its lines become Python strings: some 20 times this).
NMEA_PIECE_BYTES = 1 << 20
#: Octets read to recognise a file.
HEAD_BYTES = 1 << 20
#: The kinds of recording.
KINDS = ("pcap", "pcapng", "raw", "nmea")
#: The longest pcap packet record (octets): a longer captured length is a corrupt header.
_MAX_RECORD = 16 + (1 << 24)


class ReplayError(ValueError):
    """A recording or a target that cannot be replayed: one line naming the file or the option."""


@dataclass(frozen=True)
class Recording:
    """A file to replay and its ``kind`` (:data:`KINDS`)."""

    path: str
    kind: str


def _ledger() -> BoundedLedger:
    """Where the readers set aside what is bad (a replay sends what it finds; the rows are not kept)."""
    return BoundedLedger(LEDGER_COLUMNS, 1)


def recognise(path: str | Path) -> Recording:
    """The :class:`Recording` of ``path``, by content: a pcap/pcapng capture or a raw ASTERIX
    recording as ``registration import asterix`` recognises them, else an NMEA 0183 log (text
    lines, most of its first ones sentences with a correct checksum). :class:`ReplayError` naming
    the file for anything else."""
    name = str(path)
    try:
        cap = read_capture(name, _ledger(), None, HEAD_BYTES)
    except AsterixImportError as exc:
        try:
            nmea = Path(name).is_file() and looks_like_nmea(name, HEAD_BYTES)
        except OSError:
            nmea = False
        if nmea:
            return Recording(name, "nmea")
        why = str(exc).removeprefix(f"{name}: ")
        if why.startswith("a text file"):
            why = "a text file whose lines are not NMEA sentences with correct checksums"
        raise ReplayError(
            f"{name}: neither a pcap/pcapng capture, a raw ASTERIX recording nor an NMEA 0183 log ({why})"
        ) from None
    if cap.kind == "raw":
        blocks = find_blocks(cap, _ledger())
        share = blocks.known_share(int(blocks.end.max()) if blocks.end.size else cap.size)
        if share < MIN_KNOWN_SHARE:
            raise ReplayError(
                f"{name}: neither a pcap/pcapng capture, a raw ASTERIX recording nor an NMEA 0183 log "
                f"(only {100 * share:.0f} % of its first {cap.size} bytes walk as ASTERIX data blocks of "
                "known categories)"
            )
    if cap.kind not in KINDS:
        raise ReplayError(
            f"{name}: a recording in the {cap.kind} framing; replay sends pcap/pcapng captures, raw "
            "ASTERIX and NMEA logs (import it with 'registration import asterix', which reads the framing)"
        )
    return Recording(name, cap.kind)


def datagrams(rec: Recording, ports: Iterable[int] | None = None) -> Iterator[Datagrams]:
    """The datagrams of ``rec``, piece after piece; ``ports``: UDP destination ports kept from a
    capture (None: all)."""
    ports = list(ports) if ports else None
    with ByteStream(rec.path) as stream:
        if rec.kind == "pcap":
            yield from _pcap(stream, rec.path, ports)
        elif rec.kind == "pcapng":
            yield from _pcapng(stream, rec.path, ports)
        elif rec.kind == "raw":
            yield from _raw(stream, rec.path)
        else:
            yield from nmea_datagrams(stream, rec.path, NMEA_PIECE_BYTES)


def _padded(data: bytes) -> np.ndarray:
    buf = np.zeros(len(data) + PAD, dtype=np.uint8)
    buf[: len(data)] = np.frombuffer(data, dtype=np.uint8)
    return buf


def _pcap(stream: ByteStream, name: str, ports: list | None) -> Iterator[Datagrams]:
    """The UDP datagrams of a pcap file, its packet records read a piece at a time: each piece is
    the file header, the octets left over from the piece before (a packet cut by the piece's end)
    and the next :data:`PIECE_BYTES`."""
    header = stream.read(24)
    carry = b""
    ledger = _ledger()
    while True:
        new = stream.read(PIECE_BYTES)
        final = len(new) < PIECE_BYTES
        data = header + carry + new
        packets = pcap_packets(data, name, ledger)
        used = int(packets.offset[-1] + packets.caplen[-1]) if packets.offset.size else 24
        carry = data[used:]
        if packets.offset.size:
            buf = _padded(data[:used])
            seg, _ = udp_segments(buf, packets, ports)
            yield Datagrams(buf, seg.start, seg.end, seg.time, False, stream.position)
        if final or (not packets.offset.size and len(carry) > _MAX_RECORD + PIECE_BYTES):
            return  # the end, or a corrupt record header: the rest of the capture is lost


def _framing(body: bytes, order: str) -> tuple[int, list[bytes], str]:
    """Where the complete pcapng blocks at the start of ``body`` end, the section headers and
    interface descriptions among them (from the last section header on), and the byte order."""
    p, heads = 0, []
    while p + 12 <= len(body):
        if body[p : p + 4] == PCAPNG_MAGIC:
            magic = body[p + 8 : p + 12]
            order = "<" if magic == b"\x4d\x3c\x2b\x1a" else ">" if magic == b"\x1a\x2b\x3c\x4d" else ""
            if not order:
                break
        btype, length = struct.unpack_from(order + "II", body, p)
        if length < 12 or length % 4 or p + length > len(body):
            break
        if btype == 0x0A0D0D0A:
            heads = [body[p : p + length]]
        elif btype == 1:
            heads.append(body[p : p + length])
        p += length
    return p, heads, order


def _pcapng(stream: ByteStream, name: str, ports: list | None) -> Iterator[Datagrams]:
    """The UDP datagrams of a pcapng file, its blocks read a piece at a time: each piece is the
    section header and interface descriptions read so far (the packets' link types and time
    resolutions), then the complete blocks of the octets left over and the next
    :data:`PIECE_BYTES`."""
    prefix, carry, order = b"", b"", "<"
    ledger = _ledger()
    while True:
        new = stream.read(PIECE_BYTES)
        final = len(new) < PIECE_BYTES
        body = carry + new
        cut, heads, order = _framing(body, order)
        data = prefix + body[:cut]
        if cut:
            packets = pcapng_packets(data, name, ledger)
            buf = _padded(data)
            seg, _ = udp_segments(buf, packets, ports)
            if seg.start.size:
                yield Datagrams(buf, seg.start, seg.end, seg.time, False, stream.position)
        has_section = bool(heads) and heads[0][:4] == PCAPNG_MAGIC
        prefix = b"".join(heads) if has_section else prefix + b"".join(heads)
        carry = body[cut:]
        if final or (not cut and len(carry) > _MAX_RECORD + PIECE_BYTES):
            return  # the end, or a corrupt block header: the rest of the capture is lost


def _first_records(rec: Records) -> tuple[np.ndarray, Records]:
    """(block index, the record) of the first record walked in each block."""
    blocks, first = np.unique(rec.block, return_index=True)
    empty = np.zeros(0, dtype=np.int64)
    items = {k: v[first] for k, v in rec.items.items()}
    return blocks, Records(rec.start[first], rec.end[first], rec.block[first], items, empty, empty)


def block_times(buf: np.ndarray, blocks: Blocks) -> np.ndarray:
    """Time of day (s since midnight UTC; NaN: none) of each data block: that of its first record,
    for CAT048 (I048/140), CAT034 (I034/030) and CAT021 (I021/071, else /073, else /077) in the
    default editions (:data:`~registration.io.asterix.decode.uap.DEFAULT_EDITIONS`)."""
    tod = np.full(blocks.start.size, np.nan)
    for cat in (48, 34, 21):
        sel = np.flatnonzero(blocks.category == cat)
        if not sel.size:
            continue
        edition = DEFAULT_EDITIONS[cat]
        wanted = {48: WANTED048, 34: WANTED034}.get(cat) or wanted021(edition)
        walked = walk_records(buf, blocks.start[sel], blocks.end[sel], uap_for(cat, edition), wanted)
        if not walked.start.size:
            continue
        which, first = _first_records(walked)
        if cat == 48:
            fields = decode048(buf, first)
            has = fields["has_140"]
        elif cat == 34:
            fields = decode034(buf, first)
            has = fields["has_030"]
        else:
            fields = decode021(buf, first, edition)
            has = fields["time_item"] != ""
        tod[sel[which[has]]] = fields["tod"][has] * TOD_LSB_S
    return tod


def _raw(stream: ByteStream, name: str) -> Iterator[Datagrams]:
    """The data blocks of a raw recording, read a piece at a time: a block cut by the piece's end
    goes with the next piece (:func:`registration.io.asterix.capture.blocks.find_blocks` finds
    them, setting aside bad stretches as the importer does)."""
    carry = b""
    ledger = _ledger()
    while True:
        new = stream.read(PIECE_BYTES)
        final = len(new) < PIECE_BYTES
        data = carry + new
        if not data:
            return
        n = len(data)
        whole = Segments(np.array([0]), np.array([n]), np.array([0]), np.array([np.nan]))
        cap = Capture(name, _padded(data), n, "raw", stream.gzip, whole)
        blocks = find_blocks(cap, ledger)
        used = int(blocks.end.max()) if blocks.end.size else 0
        carry = data[used:] if not final and n - used <= PIECE_BYTES else b""
        if blocks.start.size:
            yield Datagrams(
                cap.buf, blocks.start, blocks.end, block_times(cap.buf, blocks), True, stream.position
            )
        if final:
            return
