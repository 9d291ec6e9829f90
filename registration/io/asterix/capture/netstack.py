"""The UDP datagrams of captured packets, found over all packets at once (numpy): link layer
(Ethernet with up to two VLAN tags, Linux cooked SLL and SLL2, BSD loopback, raw IP), IPv4 or
IPv6, UDP. The payload of each datagram is one segment of the file, read as ASTERIX data blocks
by :mod:`registration.io.asterix.capture.blocks`.

Skipped and counted, never set aside record by record: packets that are not IP, IP packets that
are not UDP (IPv6 with extension headers included), IPv4 fragments (reassembly is not done),
datagrams to other ports when ports are given, packets of an unsupported link type, and packets
cut short before their UDP header. A datagram cut short by the capture's snap length keeps the
octets captured; its last data block is then set aside as truncated.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable

import numpy as np

from registration.io.asterix.capture.pcap import Packets
from registration.io.asterix.octets import u8, u16, u32

__all__ = ["LINKTYPES", "Segments", "udp_segments"]

#: LINKTYPE_ numbers read -> name.
LINKTYPES = {
    0: "BSD loopback",
    1: "Ethernet",
    12: "raw IP",
    14: "raw IP",
    101: "raw IP",
    108: "OpenBSD loopback",
    113: "Linux cooked (SLL)",
    228: "raw IPv4",
    229: "raw IPv6",
    276: "Linux cooked (SLL2)",
}


@dataclass
class Segments:
    """Per segment (N,): ``start``, ``end`` (octets of the file), ``packet`` (number from 1; 0 for a
    raw recording), ``time`` (capture time, UTC s since 1970; NaN when none) and ``port`` (UDP
    destination port; 0 for a raw recording, or empty: none known)."""

    start: np.ndarray
    end: np.ndarray
    packet: np.ndarray
    time: np.ndarray
    port: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))


def _network(buf: np.ndarray, p: Packets) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per packet: offset of the IP header, its version (4, 6; 0: not IP) and whether the link type
    is supported."""
    off, lt = p.offset, p.linktype
    l3 = np.full(off.size, -1, dtype=np.int64)
    ethertype = np.zeros(off.size, dtype=np.int64)
    eth = lt == 1
    ethertype[eth], l3[eth] = u16(buf, off[eth] + 12), off[eth] + 14
    for _ in range(2):  # 802.1Q / 802.1ad tags
        tag = eth & np.isin(ethertype, (0x8100, 0x88A8, 0x9100))
        ethertype[tag], l3[tag] = u16(buf, l3[tag] + 2), l3[tag] + 4
    sll, sll2 = lt == 113, lt == 276
    ethertype[sll], l3[sll] = u16(buf, off[sll] + 14), off[sll] + 16
    ethertype[sll2], l3[sll2] = u16(buf, off[sll2]), off[sll2] + 20
    version = np.where(ethertype == 0x0800, 4, np.where(ethertype == 0x86DD, 6, 0))
    loop = np.isin(lt, (0, 108))
    family = u32(buf, off[loop])
    family = np.maximum(family, ((family & 0xFF) << 24) | ((family & 0xFF00) << 8))  # either byte order
    l3[loop] = off[loop] + 4
    version[loop] = np.where(family == 2 << 24, 4, np.where(np.isin(family >> 24, (24, 28, 30)), 6, 0))
    raw = np.isin(lt, (12, 14, 101, 228, 229))
    l3[raw] = off[raw]
    version[raw] = u8(buf, off[raw]) >> 4
    supported = np.isin(lt, list(LINKTYPES))
    version[~supported] = 0
    return l3, version, supported


def udp_segments(
    buf: np.ndarray, packets: Packets, ports: Iterable[int] | None = None
) -> tuple[Segments, dict]:
    """The UDP payloads of ``packets`` (to a destination port in ``ports``, if given) as segments,
    and the counts of packets: read, UDP datagrams kept, and those skipped by kind."""
    l3, version, supported = _network(buf, packets)
    end = packets.offset + packets.caplen
    v4, v6 = (version == 4) & (l3 + 20 <= end), (version == 6) & (l3 + 40 <= end)
    ihl = (u8(buf, l3) & 0x0F) * 4
    proto = np.where(v4, u8(buf, l3 + 9), np.where(v6, u8(buf, l3 + 6), -1))
    fragment = v4 & ((u16(buf, l3 + 6) & 0x3FFF) != 0)  # more-fragments flag or an offset
    udp = np.where(v4, l3 + ihl, l3 + 40)
    is_udp = (v4 | v6) & (proto == 17) & ~fragment & (ihl >= 20)
    whole = is_udp & (udp + 8 <= end)
    length = u16(buf, udp + 4)
    port = u16(buf, udp + 2)
    wanted = whole & (length >= 8) & (np.isin(port, list(ports)) if ports else True)
    start = udp + 8
    stop = np.minimum(udp + length, end)
    keep = wanted & (stop >= start)
    segments = Segments(
        start[keep], stop[keep], packets.number[keep], packets.time[keep], port[keep].astype(np.int64)
    )
    counts = {
        "packets": int(packets.number.size),
        "udp_datagrams": int(keep.sum()),
        "skipped_packets": {
            "unsupported_link_type": int((~supported).sum()),
            "not_ip": int((supported & ~(v4 | v6)).sum()),
            "not_udp": int(((v4 | v6) & ~fragment & (proto != 17)).sum()),
            "ip_fragment": int(fragment.sum()),
            "cut_before_udp_payload": int((is_udp & ~whole).sum() + (v4 & (proto == 17) & (ihl < 20)).sum()),
            "bad_udp_length": int((whole & (length < 8)).sum()),
            "other_port": int((whole & (length >= 8) & ~wanted).sum()),
        },
    }
    counts["non_udp_packets"] = int(counts["packets"] - keep.sum())
    return segments, counts
