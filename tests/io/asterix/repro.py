"""The reproduction files of issue 32 for the readers, built here byte by byte with struct (an
encoder independent of the reader): pcapng files whose last Enhanced Packet Block is 12-20 bytes
long or whose packet time is out of range, and a gzip of empty CAT048 records. The fuzz tests use
them as corpus."""

from __future__ import annotations

import gzip
import struct

from tests.io.asterix.containers import udp_frame

__all__ = [
    "pcapng_block",
    "pcapng_head",
    "short_last_epb",
    "out_of_range_time",
    "empty_cat048_gzip",
    "source_only_cat048_gzip",
]


def pcapng_block(btype: int, body: bytes) -> bytes:
    """A pcapng block (little-endian): type, total length, body padded to 4 octets, total length."""
    body += bytes(-len(body) % 4)
    return struct.pack("<II", btype, len(body) + 12) + body + struct.pack("<I", len(body) + 12)


def pcapng_head() -> bytes:
    """A Section Header Block and one Ethernet Interface Description Block (microseconds)."""
    shb = pcapng_block(0x0A0D0D0A, struct.pack("<IHHq", 0x1A2B3C4D, 1, 0, -1))
    return shb + pcapng_block(1, struct.pack("<HHI", 1, 0, 65535))


def _epb(frame: bytes, hi: int, lo: int) -> bytes:
    return pcapng_block(6, struct.pack("<IIIII", 0, hi, lo, len(frame), len(frame)) + frame)


def short_last_epb(length: int, payload: bytes = bytes([48, 0, 3])) -> bytes:
    """One good packet, then an Enhanced Packet Block of ``length`` (12-20) octets ending the file."""
    ticks = 1_700_000_000 * 10**6
    short = struct.pack("<II", 6, length) + bytes(length - 12) + struct.pack("<I", length)
    return pcapng_head() + _epb(udp_frame(payload), ticks >> 32, ticks & 0xFFFFFFFF) + short


def out_of_range_time(payload: bytes = bytes([48, 0, 3])) -> bytes:
    """One packet whose 64-bit time stamp is 2^64 - 1 microseconds (the year 586524)."""
    return pcapng_head() + _epb(udp_frame(payload), 0xFFFFFFFF, 0xFFFFFFFF)


def empty_cat048_gzip(records: int = 2_000_000) -> bytes:
    """gzip of raw CAT048 data blocks of empty records (FSPEC 0x00): each block the largest that
    fits, 65532 records of one octet. 2 million records compress to about 2 KB."""
    per_block = 0xFFFF - 3
    block = bytes([48, 0xFF, 0xFF]) + bytes(per_block)
    count, rest = divmod(records, per_block)
    tail = bytes([48]) + (rest + 3).to_bytes(2, "big") + bytes(rest) if rest else b""
    return gzip.compress(block * count + tail, compresslevel=9)


def source_only_cat048_gzip(records: int = 500_000) -> bytes:
    """gzip of raw CAT048 blocks of records holding only I048/010 (FSPEC 0x80, SAC 10, SIC 1):
    each walks, and each is set aside (no time, no position). 500 000 compress to about 1.5 KB."""
    per_block = (0xFFFF - 3) // 3
    block = bytes([48]) + (per_block * 3 + 3).to_bytes(2, "big") + bytes([0x80, 10, 1]) * per_block
    count, rest = divmod(records, per_block)
    tail = bytes([48]) + (rest * 3 + 3).to_bytes(2, "big") + bytes([0x80, 10, 1]) * rest if rest else b""
    return gzip.compress(block * count + tail, compresslevel=9)
