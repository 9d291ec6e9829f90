"""One input file read and recognised by its content, not its name: gzip (1f 8b, decompressed
first, a truncated or corrupt stream keeping what came out), pcap, pcapng, or a raw ASTERIX
recording (data blocks end to end: category, 16-bit length counting the 3-octet header, records).

A file that is no capture is unwrapped by :mod:`registration.io.asterix.capture.unwrap`: a
recorder framing (GPS, IOSS/FINAL, RFF, ORADIS, HDLC) or raw ASTERIX, told by content. A file that
is none of these raises :class:`~registration.io.asterix.errors.AsterixImportError` naming the
file; a cut-off tail or corrupt stretches later in the file are set aside by
:mod:`registration.io.asterix.capture.blocks`, not refused.
"""

from __future__ import annotations

import zlib
from pathlib import Path
from typing import Iterable, Sequence

import numpy as np

from registration.io.asterix.capture.model import ASTERIX_CATEGORIES, Capture
from registration.io.asterix.capture.netstack import Segments, udp_segments
from registration.io.asterix.capture.oradis import oradis_datagrams
from registration.io.asterix.capture.pcap import (
    PCAP_MAGICS,
    PCAPNG_MAGIC,
    Packets,
    pcap_packets,
    pcapng_packets,
)
from registration.io.asterix.capture.unwrap import unwrap
from registration.io.asterix.errors import AsterixImportError
from registration.io.asterix.octets import PAD
from registration.io.files.ledger import RejectedLedger
from registration.io.files.limits import DEFAULT_MAX_BYTES
from registration.io.files.unreadable import read_error

__all__ = ["Capture", "capture_from_datagrams", "read_capture", "ASTERIX_CATEGORIES"]


def _gunzip(raw: bytes, path: str, notes: list, max_bytes: int, over: list) -> bytes:
    """All members of a gzip stream decompressed, fed 1 MiB at a time so that a truncated or corrupt
    stream keeps what came out before the fault; at most ``max_bytes`` octets come out (``over``
    gets a word when there were more)."""
    out, pos, step, size = [], 0, 1 << 20, 0
    while raw[pos : pos + 2] == b"\x1f\x8b":
        d = zlib.decompressobj(wbits=31)
        try:
            while not d.eof and pos < len(raw):
                chunk = d.decompress(raw[pos : pos + step], max_bytes + 1 - size)
                out.append(chunk)
                size += len(chunk)
                if size > max_bytes:
                    out[-1] = chunk[: len(chunk) - (size - max_bytes)]
                    over.append("decompressed, the file exceeds")
                    return b"".join(out)
                pos = min(pos + step, len(raw))
        except zlib.error as exc:
            notes.append(
                f"{path}: the gzip stream is corrupt after {sum(map(len, out))} decompressed bytes ({exc}); "
                "the rest of the file is lost"
            )
            break
        if not d.eof:
            out.append(d.flush())
            notes.append(
                f"{path}: the gzip stream is truncated after {sum(map(len, out))} decompressed bytes; "
                "what came before is imported"
            )
            break
        pos -= len(d.unused_data)
    data = b"".join(out)
    if not data:
        raise AsterixImportError(f"{path}: a gzip file that decompresses to nothing (corrupt or empty)")
    return data


#: Packet times (UTC s since 1970) outside [0, this) are no dates (the year 10000 and later).
_LAST_TIME_S = 253402300800.0


def _drop_bad_times(packets: Packets, path: str, notes: list) -> None:
    """Packet times that are no date (before 1970 or after the year 9999) become NaN, with a note
    naming the first such packet: its records are then placed by their time of day alone."""
    bad = np.flatnonzero(~((packets.time >= 0) & (packets.time < _LAST_TIME_S)) & ~np.isnan(packets.time))
    if bad.size:
        k = int(bad[0])
        notes.append(
            f"{path}: {bad.size} packet time(s) outside the years 1970-9999 ignored, the first in packet "
            f"{int(packets.number[k])} at offset {int(packets.offset[k])} ({packets.time[k]:.6g} s)"
        )
        packets.time[bad] = np.nan


def _read(path: str, max_bytes: int, over: list) -> bytes:
    """The first ``max_bytes`` octets of the file (``over`` gets a word when there are more)."""
    try:
        with open(path, "rb") as f:
            raw = f.read(max_bytes + 1)
    except OSError as exc:
        raise read_error(path, exc, "cannot read the file", AsterixImportError) from exc
    if len(raw) > max_bytes:
        over.append("the file exceeds")
        raw = raw[:max_bytes]
    return raw


def read_capture(
    path: str | Path,
    rejections: RejectedLedger,
    ports: Iterable[int] | None = None,
    max_bytes: int = DEFAULT_MAX_BYTES,
    framing: str = "auto",
) -> Capture:
    """Read ``path`` (at most ``max_bytes`` octets, decompressed) and find its data blocks'
    segments; packets cut short are set aside in ``rejections``. ``ports``: UDP destination ports
    to keep (None: all). ``framing``: of a file that is no capture, 'auto' (told by content),
    'netto' (raw data blocks) or a recorder framing
    (:data:`~registration.io.asterix.capture.detect.FRAMING_NAMES`)."""
    name = str(path)
    notes: list = []
    over: list = []
    raw = _read(name, max_bytes, over)
    zipped = raw[:2] == b"\x1f\x8b"
    data = _gunzip(raw, name, notes, max_bytes, over) if zipped else raw
    del raw
    if over:
        text = f"{over[0]} the limit of {max_bytes} bytes (max_bytes, --max-bytes); the rest is not read"
        notes.append(f"{name}: {text}")
        rejections.add(name, "over_limit", text, offset=max_bytes, packet=0, category=0)
    if not data:
        raise AsterixImportError(
            f"{name}: an empty file, neither a pcap/pcapng capture nor an ASTERIX recording"
        )
    buf = np.zeros(len(data) + PAD, dtype=np.uint8)
    buf[: len(data)] = np.frombuffer(data, dtype=np.uint8)
    magic = bytes(data[:4])
    counts: dict = {}
    if magic in PCAP_MAGICS or magic == PCAPNG_MAGIC:
        kind = "pcap" if magic in PCAP_MAGICS else "pcapng"
        packets = (pcap_packets if kind == "pcap" else pcapng_packets)(data, name, rejections)
        _drop_bad_times(packets, name, notes)
        segments, counts = udp_segments(buf, packets, ports)
        if packets.number.size and np.isfinite(packets.time).any():
            counts["first_packet_time"] = float(np.nanmin(packets.time))
        split = oradis_datagrams(buf, segments, framing)
        framed = kind if split is None else "oradis"
        return Capture(
            name, buf, len(data), kind, zipped, segments if split is None else split, counts, notes, framed
        )
    del data
    unwrapped = unwrap(buf, buf.size - PAD, name, framing, rejections)
    notes += unwrapped.notes
    kind = "raw" if unwrapped.framing == "netto" else unwrapped.framing
    return Capture(
        name,
        buf,
        buf.size - PAD,
        kind,
        zipped,
        unwrapped.segments,
        unwrapped.counts,
        notes,
        unwrapped.framing,
        unwrapped.clock,
    )


def capture_from_datagrams(payloads: Sequence[bytes], ports: Sequence[int], name: str) -> Capture:
    """Datagrams received (UDP payloads, in arrival order, with their destination ``ports``) as a
    capture of kind ``udp``: one segment per datagram, numbered from 1 as ``packet`` (their order
    in this batch), without capture time (NaN: the time of day alone places the records). ``name``
    stands for the file in what is set aside (``udp://host:port``)."""
    sizes = np.fromiter((len(p) for p in payloads), dtype=np.int64, count=len(payloads))
    end = np.cumsum(sizes)
    start = end - sizes
    buf = np.zeros(int(end[-1]) + PAD if sizes.size else PAD, dtype=np.uint8)
    if sizes.size:
        buf[: end[-1]] = np.frombuffer(b"".join(payloads), dtype=np.uint8)
    segments = Segments(
        start,
        end,
        np.arange(1, sizes.size + 1, dtype=np.int64),
        np.full(sizes.size, np.nan),
        np.asarray(ports, dtype=np.int64),
    )
    return Capture(name, buf, int(end[-1]) if sizes.size else 0, "udp", False, segments, {}, [], "udp")
