"""HDLC frames of ASTERIX data blocks (the Croatia Control ``asterix`` tool's ``-H``): per frame an
address octet 01, a control octet 03, data blocks end to end, and the 16-bit frame check sequence
(FCS-16 of ISO/IEC 13239 (the CRC of X.25 / PPP), least significant octet first) over address,
control and data blocks. Octets between frames (flags, noise) are skipped to the next 01 03 that
starts a frame whose blocks chain and whose FCS checks; the frames carry no time stamp.
"""

from __future__ import annotations

import binascii

import numpy as np

from registration.io.asterix.capture.framings import Framed

__all__ = ["walk_hdlc", "fcs16"]

#: Octets searched at a time for the next frame start.
_WINDOW = 1 << 20
#: The longest frame tried (octets): a frame holds at most a few data blocks.
_MAX_FRAME = 1 << 16
#: Each octet with its bits reversed (FCS-16 is the bit-reversed form of the CCITT CRC).
_REVERSED = bytes(int(f"{b:08b}"[::-1], 2) for b in range(256))


def fcs16(data: bytes) -> int:
    """The FCS-16 of ``data`` (ISO/IEC 13239: reflected polynomial 0x8408, initial value and final
    XOR 0xFFFF; 0x906E for b'123456789')."""
    crc = binascii.crc_hqx(data.translate(_REVERSED), 0xFFFF)
    return int(f"{crc:016b}"[::-1], 2) ^ 0xFFFF


def _frame_end(mv: memoryview, p: int, n: int) -> int | None:
    """One past the FCS of the frame starting at ``p`` (01 03 at p), or None when its blocks do not
    chain to an FCS that checks."""
    q = p + 2
    last = min(n, p + _MAX_FRAME)
    while q + 3 <= last:
        length = (mv[q + 1] << 8) | mv[q + 2]
        if length < 3 or q + length + 2 > last:
            return None
        q += length
        if fcs16(bytes(mv[p:q])) == mv[q] | (mv[q + 1] << 8):
            return q + 2
    return None


def _next_start(buf: np.ndarray, p: int, n: int) -> int | None:
    """The first offset >= p holding 01 03, or None."""
    for lo in range(p, n - 1, _WINDOW):
        hi = min(lo + _WINDOW, n - 1)
        hit = np.flatnonzero((buf[lo:hi] == 1) & (buf[lo + 1 : hi + 1] == 3))
        if hit.size:
            return lo + int(hit[0])
    return None


def walk_hdlc(mv: memoryview, n: int, limit: int | None = None) -> Framed:
    """The frames of an HDLC recording; skipped stretches are ``problems`` (the walk goes on). With a
    ``limit`` (detection) only the first MiB is searched."""
    n = n if limit is None else min(n, 1 << 20)
    buf = np.frombuffer(mv, dtype=np.uint8)
    rows: list = []
    problems: list = []
    p, q = 0, None
    while p < n - 1 and (limit is None or len(rows) < limit):
        q = _next_start(buf, p, n)
        while q is not None and _frame_end(mv, q, n) is None:
            q = _next_start(buf, q + 1, n)
        stop = n if q is None else q
        if stop > p and any(mv[i] != 0x7E for i in range(p, stop)):
            problems.append(
                (
                    p,
                    len(rows) + 1,
                    f"HDLC: {stop - p} bytes that are no frame (no 01 03 starting data blocks whose "
                    "FCS checks) skipped",
                )
            )
        if q is None:
            break
        end = _frame_end(mv, q, n)
        assert end is not None
        rows.append((q + 2, end - 2, q, np.nan))
        p = end
    cut = bool(problems) and problems[-1][0] > n - _MAX_FRAME and q is None
    return Framed.of(rows, "none", problems, cut)
