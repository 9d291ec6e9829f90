"""A 64-bit digest of each record's octets, computed for all records at once.

Duplicates (the same record received twice, on two feeds or in a replayed tail) are found by
their digests (:mod:`registration.io.asterix.tables.duplicates`). The digest reads a record as
little-endian 64-bit words (the last one zero-padded) and folds them, starting from the record's
length, through the SplitMix64 finaliser (Steele, Lea and Flood, "Fast splittable pseudorandom
number generators", OOPSLA 2014), one word column at a time over every record that long: no Python
loop over records. Equal octets give equal digests in every process (no random key); different
records collide with a probability of about 2**-64 per pair, which the tests check on real and
random records against byte equality.
"""

from __future__ import annotations

import numpy as np

__all__ = ["record_digests"]

_GOLDEN = np.uint64(0x9E3779B97F4A7C15)
_M1 = np.uint64(0xBF58476D1CE4E5B9)
_M2 = np.uint64(0x94D049BB133111EB)
_LANES = np.arange(8, dtype=np.int64)


def _mix(x: np.ndarray) -> np.ndarray:
    """SplitMix64's finaliser on (N,) uint64, wrapping modulo 2**64."""
    z = x + _GOLDEN
    z = (z ^ (z >> np.uint64(30))) * _M1
    z = (z ^ (z >> np.uint64(27))) * _M2
    return z ^ (z >> np.uint64(31))


def record_digests(buf: np.ndarray, start: np.ndarray, end: np.ndarray) -> np.ndarray:
    """(N,) int64 digests of the records ``buf[start[i]:end[i]]`` (``buf`` a uint8 array; offsets
    in octets, ``start <= end <= buf.size``)."""
    start = np.asarray(start, dtype=np.int64)
    end = np.asarray(end, dtype=np.int64)
    length = end - start
    h = _mix(length.astype(np.uint64))
    if start.size == 0 or buf.size == 0:
        return h.view(np.int64)
    words = (length + 7) // 8
    last = buf.size - 1
    # the records longest first: those with more than w words are a prefix, so each word column
    # costs the records that long only (one long record beside a million short ones stays cheap)
    order = np.argsort(-words, kind="stable")
    longer = np.searchsorted(-words[order], -np.arange(int(words.max())), side="left")
    for w in range(int(words.max())):
        live = order[: longer[w]]
        at = start[live, None] + 8 * w + _LANES
        octets = np.where(at < end[live, None], buf[np.minimum(at, last)], 0).astype(np.uint8)
        word = np.ascontiguousarray(octets).view("<u8").ravel()
        h[live] = _mix(h[live] ^ word)
    return h.view(np.int64)
