"""The packets of a pcap or pcapng capture: where each packet's captured bytes lie in the file, how
many were captured, the capture time and the link type. The UDP datagrams in them are found by
:mod:`registration.io.asterix.capture.netstack`.

pcap (libpcap, tcpdump): a 24-octet file header (magic a1b2c3d4 for microsecond or a1b23c4d for
nanosecond time stamps, in either byte order; the link type), then per packet a 16-octet record
header (seconds, fraction, captured length, original length) and the captured bytes.

pcapng (the Wireshark default): blocks of (type, total length, body, total length). A Section
Header Block (type 0a0d0d0a) gives the byte order, Interface Description Blocks (type 1) the link
type and time resolution (option ``if_tsresol``, default microseconds) of each interface, and the
packets come in Enhanced (type 6), Simple (type 3, no time stamp) and obsolete Packet (type 2)
Blocks. Other blocks are skipped. A capture cut short inside a packet is set aside from there on
(reason ``truncated_packet``); the packets before it are kept.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass

import numpy as np

from registration.io.files.ledger import RejectedLedger

__all__ = ["PCAP_MAGICS", "PCAPNG_MAGIC", "Packets", "pcap_packets", "pcapng_packets"]

#: The first four octets of a pcap file -> (byte order, time stamp fraction unit in s).
PCAP_MAGICS = {
    b"\xd4\xc3\xb2\xa1": ("<", 1e-6),
    b"\xa1\xb2\xc3\xd4": (">", 1e-6),
    b"\x4d\x3c\xb2\xa1": ("<", 1e-9),
    b"\xa1\xb2\x3c\x4d": (">", 1e-9),
}
#: The block type of a pcapng Section Header Block (the first four octets of the file).
PCAPNG_MAGIC = b"\x0a\x0d\x0d\x0a"
#: A captured length above this (octets) means a corrupt record header, not a packet.
_MAX_PACKET = 1 << 24


@dataclass
class Packets:
    """Per packet (N,): ``offset`` of its first captured octet in the file, ``caplen`` octets
    captured, ``time`` (UTC, s since 1970; NaN when the format gives none), ``linktype`` (the
    LINKTYPE_ number of its interface), ``number`` (from 1, in file order)."""

    offset: np.ndarray
    caplen: np.ndarray
    time: np.ndarray
    linktype: np.ndarray
    number: np.ndarray

    @classmethod
    def from_lists(cls, rows: list) -> "Packets":
        a = np.array(rows, dtype=np.float64).reshape(-1, 5)
        return cls(
            a[:, 0].astype(np.int64),
            a[:, 1].astype(np.int64),
            a[:, 2],
            a[:, 3].astype(np.int64),
            a[:, 4].astype(np.int64),
        )


def pcap_packets(data: bytes, path: str, rejections: RejectedLedger) -> Packets:
    """The packets of a pcap file (``data``: its bytes, starting with one of :data:`PCAP_MAGICS`)."""
    order, unit = PCAP_MAGICS[bytes(data[:4])]
    n = len(data)
    rows: list[tuple] = []
    if n < 24:
        rejections.add(
            path,
            "truncated_packet",
            f"the pcap file header needs 24 bytes, the file has {n}",
            offset=0,
            packet=0,
            category=0,
        )
        return Packets.from_lists(rows)
    linktype = struct.unpack_from(order + "I", data, 20)[0] & 0xFFFF
    head = struct.Struct(order + "IIII")
    p, k = 24, 0
    while p < n:
        k += 1
        if p + 16 > n:
            rejections.add(
                path,
                "truncated_packet",
                f"packet {k}: the capture ends inside its 16-byte record header ({n - p} bytes left)",
                offset=p,
                packet=k,
                category=0,
            )
            break
        sec, frac, incl, _ = head.unpack_from(data, p)
        if incl > _MAX_PACKET or p + 16 + incl > n:
            rejections.add(
                path,
                "truncated_packet",
                f"packet {k}: captured length {incl} bytes runs past the end of the file "
                f"({n - p - 16} bytes left); the rest of the capture is lost",
                offset=p,
                packet=k,
                category=0,
            )
            break
        rows.append((p + 16, incl, sec + frac * unit, linktype, k))
        p += 16 + incl
    return Packets.from_lists(rows)


def _options(data: bytes, order: str, start: int, end: int) -> dict:
    """pcapng options (code -> first value's bytes) between ``start`` and ``end``."""
    out: dict[int, bytes] = {}
    while start + 4 <= end:
        code, length = struct.unpack_from(order + "HH", data, start)
        if code == 0:
            break
        out.setdefault(code, bytes(data[start + 4 : start + 4 + length]))
        start += 4 + length + (-length % 4)
    return out


def _resolution(opts: dict) -> float:
    """Seconds per time stamp unit from the ``if_tsresol`` option (code 9): 10^-n, or 2^-n when
    its top bit is set; microseconds by default."""
    raw = opts.get(9)
    if not raw:
        return 1e-6
    value = raw[0]
    return 2.0 ** -(value & 0x7F) if value & 0x80 else 10.0**-value


def _packet_block(data: bytes, order: str, btype: int, p: int, length: int, interfaces: list) -> tuple | None:
    """(data offset, captured length, time, interface) of a packet block, or None when malformed
    (shorter than its fixed fields, a captured length past the block, an undescribed interface)."""
    if length < (16 if btype == 3 else 32):
        return None
    if btype == 3:  # simple packet block: no interface id (the first), no time
        orig = struct.unpack_from(order + "I", data, p + 8)[0]
        return p + 12, min(orig, length - 16), np.nan, 0
    if btype == 6:
        iface, hi, lo, cap = struct.unpack_from(order + "IIII", data, p + 8)
    else:  # obsolete packet block: 16-bit interface id and drops count
        iface, _, hi, lo, cap = struct.unpack_from(order + "HHIII", data, p + 8)
    if cap > length - 32 or iface >= len(interfaces):
        return None
    return p + 28, cap, ((hi << 32) | lo) * interfaces[iface][1], iface


def pcapng_packets(data: bytes, path: str, rejections: RejectedLedger) -> Packets:
    """The packets of a pcapng file (``data``: its bytes, starting with :data:`PCAPNG_MAGIC`)."""
    n = len(data)
    rows: list[tuple] = []
    interfaces: list[tuple] = []
    order = "<"
    p, k = 0, 0
    while p < n:
        if p + 12 > n:
            rejections.add(
                path,
                "truncated_packet",
                f"the capture ends inside a block header ({n - p} bytes left)",
                offset=p,
                packet=k + 1,
                category=0,
            )
            break
        if bytes(data[p : p + 4]) == PCAPNG_MAGIC:
            magic = bytes(data[p + 8 : p + 12])
            order = "<" if magic == b"\x4d\x3c\x2b\x1a" else ">" if magic == b"\x1a\x2b\x3c\x4d" else ""
            if not order:
                rejections.add(
                    path,
                    "truncated_packet",
                    "a section header with a bad byte-order magic; the rest of the capture is skipped",
                    offset=p,
                    packet=k + 1,
                    category=0,
                )
                break
            interfaces = []
        btype, length = struct.unpack_from(order + "II", data, p)
        if length < 12 or length % 4 or p + length > n:
            rejections.add(
                path,
                "truncated_packet",
                f"block of type {btype} declares {length} bytes, {n - p} left in the file (not a multiple "
                "of 4, below 12 or past the end); the rest of the capture is lost",
                offset=p,
                packet=k + 1,
                category=0,
            )
            break
        if btype == 1 and length >= 20:
            linktype = struct.unpack_from(order + "H", data, p + 8)[0]
            interfaces.append((linktype, _resolution(_options(data, order, p + 16, p + length - 4))))
        elif btype in (2, 3, 6):
            k += 1
            got = _packet_block(data, order, btype, p, length, interfaces) if interfaces else None
            if got is None:
                rejections.add(
                    path,
                    "truncated_packet",
                    f"packet {k}: a packet block whose captured length exceeds the block or whose "
                    "interface was not described; the packet is skipped",
                    offset=p,
                    packet=k,
                    category=0,
                )
            else:
                rows.append((got[0], got[1], got[2], interfaces[got[3]][0], k))
        p += length
    return Packets.from_lists(rows)
