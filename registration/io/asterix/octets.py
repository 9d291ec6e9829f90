"""Big-endian unsigned and two's-complement fields read at many byte offsets at once.

``buf`` is a uint8 array padded with zero octets past the data, so that reads a few octets past a
data block (of records found bad afterwards) stay inside it.
"""

from __future__ import annotations

import numpy as np

__all__ = ["u8", "u16", "u24", "u32", "signed", "PAD"]

#: Zero octets appended to every buffer: more than one record's items can run past its block.
PAD = 1 << 16


def u8(buf: np.ndarray, at: np.ndarray) -> np.ndarray:
    """Octet at ``at`` (int64)."""
    return buf[at].astype(np.int64)


def u16(buf: np.ndarray, at: np.ndarray) -> np.ndarray:
    """Unsigned 16-bit big-endian field starting at ``at`` (int64)."""
    return (buf[at].astype(np.int64) << 8) | buf[at + 1]


def u24(buf: np.ndarray, at: np.ndarray) -> np.ndarray:
    """Unsigned 24-bit big-endian field starting at ``at`` (int64)."""
    return (buf[at].astype(np.int64) << 16) | (buf[at + 1].astype(np.int64) << 8) | buf[at + 2]


def u32(buf: np.ndarray, at: np.ndarray) -> np.ndarray:
    """Unsigned 32-bit big-endian field starting at ``at`` (int64)."""
    return (u16(buf, at) << 16) | u16(buf, at + 2)


def signed(value: np.ndarray, bits: int) -> np.ndarray:
    """Two's complement of a ``bits``-bit unsigned field."""
    value = np.asarray(value, dtype=np.int64)
    return np.where(value >= (1 << (bits - 1)), value - (1 << bits), value)
