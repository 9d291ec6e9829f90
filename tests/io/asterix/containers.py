"""pcap and pcapng containers written with struct (for the test fixtures): UDP datagrams in
Ethernet/IPv4 frames, with capture times, plus a few packets that are not UDP (ARP, TCP) that the
reader must skip and count."""

from __future__ import annotations

import datetime as dt
import struct

__all__ = ["udp_frame", "arp_frame", "tcp_frame", "pcap_bytes", "pcapng_bytes", "two_lans", "ASTERIX_PORT"]

ASTERIX_PORT = 8600
_MACS = bytes.fromhex("01005e000001") + bytes.fromhex("020000000001")


def _checksum(header: bytes) -> int:
    total = sum(struct.unpack(f"!{len(header) // 2}H", header))
    while total >> 16:
        total = (total & 0xFFFF) + (total >> 16)
    return ~total & 0xFFFF


def _ipv4(payload: bytes, proto: int, ident: int) -> bytes:
    head = struct.pack(
        "!BBHHHBBH4s4s",
        0x45,
        0,
        20 + len(payload),
        ident & 0xFFFF,
        0x4000,
        64,
        proto,
        0,
        bytes([10, 0, 0, 1]),
        bytes([239, 1, 1, 1]),
    )
    return head[:10] + struct.pack("!H", _checksum(head)) + head[12:] + payload


def udp_frame(payload: bytes, dport: int = ASTERIX_PORT, ident: int = 0, vlan: int | None = None) -> bytes:
    """An Ethernet frame (optionally 802.1Q tagged) holding an IPv4 UDP datagram."""
    udp = struct.pack("!HHHH", 40000, dport, 8 + len(payload), 0) + payload
    tag = b"" if vlan is None else struct.pack("!HH", 0x8100, vlan)
    return _MACS + tag + b"\x08\x00" + _ipv4(udp, 17, ident)


def arp_frame() -> bytes:
    return _MACS + b"\x08\x06" + bytes(28)


def tcp_frame(ident: int = 0) -> bytes:
    return _MACS + b"\x08\x00" + _ipv4(struct.pack("!HHIIHHHH", 1234, 80, 0, 0, 0x5002, 1024, 0, 0), 6, ident)


def pcap_bytes(
    frames: list[bytes], times: list[float], nanosecond: bool = False, big_endian: bool = False
) -> bytes:
    """A pcap file of Ethernet ``frames`` captured at ``times`` (UTC s since 1970)."""
    e = ">" if big_endian else "<"
    magic = 0xA1B23C4D if nanosecond else 0xA1B2C3D4
    out = [struct.pack(e + "IHHiIII", magic, 2, 4, 0, 0, 65535, 1)]
    scale = 10**9 if nanosecond else 10**6
    for frame, t in zip(frames, times):
        ticks = round(t * scale)
        out.append(struct.pack(e + "IIII", ticks // scale, ticks % scale, len(frame), len(frame)) + frame)
    return b"".join(out)


def _block(btype: int, body: bytes) -> bytes:
    body += bytes(-len(body) % 4)
    length = 12 + len(body)
    return struct.pack("<II", btype, length) + body + struct.pack("<I", length)


def pcapng_bytes(frames: list[bytes], times: list[float], nanosecond: bool = True) -> bytes:
    """A pcapng file (one section, one Ethernet interface with if_tsresol 9 or 6) of ``frames``
    captured at ``times`` in Enhanced Packet Blocks, with a Simple Packet Block of an ARP frame
    after the first packet."""
    shb = _block(0x0A0D0D0A, struct.pack("<IHHq", 0x1A2B3C4D, 1, 0, -1))
    resol = 9 if nanosecond else 6
    options = struct.pack("<HHB", 9, 1, resol) + bytes(3) + struct.pack("<HH", 0, 0)
    idb = _block(1, struct.pack("<HHI", 1, 0, 65535) + options)
    out = [shb, idb]
    for k, (frame, t) in enumerate(zip(frames, times)):
        ticks = round(t * 10**resol)
        out.append(
            _block(
                6, struct.pack("<IIIII", 0, ticks >> 32, ticks & 0xFFFFFFFF, len(frame), len(frame)) + frame
            )
        )
        if k == 0:
            arp = arp_frame()
            out.append(_block(3, struct.pack("<I", len(arp)) + arp))
    return b"".join(out)


def two_lans(recording) -> bytes:
    """A pcap of every datagram of ``recording`` (:class:`~tests.io.asterix.encode.Recording`) twice,
    on UDP ports 8600 (LAN A) and 8601 (LAN B, 0.4 ms later), as a dual feed records it."""
    midnight = dt.datetime.combine(recording.date, dt.time(), dt.timezone.utc).timestamp()
    frames, times = [], []
    for k, group in enumerate(recording.datagrams):
        payload = b"".join(recording.blocks[i] for i in group)
        t = midnight + max(recording.times[i] for i in group) + 0.01
        for port, lag in ((8600, 0.0), (8601, 0.0004)):
            frames.append(udp_frame(payload, dport=port, ident=k))
            times.append(t + lag)
    return pcap_bytes(frames, times)
