"""The framing every ASTERIX encoder shares: the field specification (FSPEC) of a record from the
field reference numbers present, fixed-length items from integers, and a data block (CAT, LEN,
records) of at most 65 535 octets (EUROCONTROL ASTERIX Part 1, "Data Block and Record Structure").
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

__all__ = ["MAX_BLOCK_OCTETS", "fspec", "signed_item", "unsigned_item", "data_blocks"]

#: A data block's length field is 16 bits: the whole block, header included.
MAX_BLOCK_OCTETS = 65535


def fspec(frns: Iterable[int]) -> bytes:
    """The FSPEC of a record holding the items of field reference numbers ``frns`` (1-based):
    seven item bits per octet, the eighth (FX) set when another octet follows."""
    present = sorted(set(frns))
    if not present or present[0] < 1:
        raise ValueError(f"field reference numbers start at 1, got {present}")
    n = (present[-1] + 6) // 7
    octets = bytearray(n)
    for frn in present:
        octets[(frn - 1) // 7] |= 0x80 >> ((frn - 1) % 7)
    for i in range(n - 1):
        octets[i] |= 0x01
    return bytes(octets)


def unsigned_item(value: int, bits: int, name: str) -> int:
    """``value`` checked to fit ``bits`` unsigned bits (ValueError naming the item otherwise)."""
    if not 0 <= value < 1 << bits:
        raise ValueError(f"{name}: {value} does not fit {bits} unsigned bits")
    return value


def signed_item(value: int, bits: int, name: str) -> int:
    """``value`` in two's complement on ``bits`` bits (ValueError naming the item if it does not fit)."""
    if not -(1 << (bits - 1)) <= value < 1 << (bits - 1):
        raise ValueError(f"{name}: {value} does not fit {bits} signed bits")
    return value & ((1 << bits) - 1)


def data_blocks(category: int, records: Sequence[bytes]) -> bytes:
    """``records`` (each FSPEC and items) packed into data blocks of ``category``, as many records
    per block as fit in :data:`MAX_BLOCK_OCTETS`; empty for no records."""
    out, block = bytearray(), bytearray()
    for record in records:
        if 3 + len(record) > MAX_BLOCK_OCTETS:
            raise ValueError(f"a record of {len(record)} octets does not fit a data block")
        if 3 + len(block) + len(record) > MAX_BLOCK_OCTETS:
            out += bytes([category]) + (3 + len(block)).to_bytes(2, "big") + block
            block = bytearray()
        block += record
    if block:
        out += bytes([category]) + (3 + len(block)).to_bytes(2, "big") + block
    return bytes(out)
