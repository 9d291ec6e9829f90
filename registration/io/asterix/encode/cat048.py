"""CAT048 plots corrected by a registration's estimates, re-encoded in place: what a tracker that
knows nothing of registration reads to get registered plots (EUROCONTROL ASTERIX Category 048,
monoradar target reports).

:func:`correct_cat048` takes one datagram (one or more data blocks: CAT, LEN, records) and, in each
CAT048 record whose I048/010 SAC/SIC has a :class:`PlotCorrection`, rewrites exactly

- I048/040 RHO (slant range, LSB 1/256 NM, unsigned 16 bits) and THETA (azimuth, LSB 360/2^16 deg),
- I048/140 time of day (LSB 1/128 s, 24 bits),

each rounded to the nearest LSB. Every other octet of the datagram is left as it is, so lengths
never change. The model is this package's error convention (docs/reference/conventions.md), the
errors reported minus true: reported range = (1 + gain) x true slant range + range bias, reported
azimuth = true + azimuth bias, reported time = true + time bias. So

    rho = (rho_reported - range_bias) / (1 + gain)     clamped to [0, 65535/256 NM], counted
    theta = theta_reported - azimuth_bias              wrapped to [0, 360 deg)
    tod = tod_reported - time_bias                     wrapped modulo 86 400 s

A time of day of 24 h or more (invalid; the reader sets it aside as ``bad_time``) is left as it
is. Records are walked by the project's one-record walk
(:func:`~registration.io.asterix.decode.scalar.walk_one`) with the UAP of the edition chosen: a
record that cannot be walked leaves the rest of its block unchanged and is counted, and so is a
data block whose length field is below 3 (the rest of the datagram is then unchanged). A block
whose length runs past the datagram (a datagram cut short) is walked up to the datagram's end:
its whole records are corrected, the one cut (or, when the cut falls between records, the
missing rest) counts as one record that cannot be walked. docs/reference/corrected-plots.md says
the same for users.

Speed: a datagram of 10 typical plots takes about 100 us (benchmarks/bench_correct.py), nearly
all of it the walk; the arithmetic is per record in plain Python, 3 times faster than numpy on
so few records (numpy's fixed cost per call dominates below some 30 records).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from registration.io.asterix.decode.scalar import RecordProblem, walk_one
from registration.io.asterix.decode.uap import DEFAULT_EDITIONS, check_editions, uap_for

__all__ = ["PlotCorrection", "CorrectedDatagram", "correct_cat048", "NM_M", "RHO_MAX_RAW"]

#: One international nautical mile, m.
NM_M = 1852.0
#: The largest RHO of I048/040 (65535/256 NM), in LSBs.
RHO_MAX_RAW = 65535
_RHO_LSB_M = NM_M / 256.0
_THETA_LSB_RAD = 2.0 * math.pi / 65536.0
_TOD_LSB_S = 1.0 / 128.0
_DAY_RAW = 86400 * 128
#: The items rewritten (and I048/010, which says whose record it is).
_WANTED = ("010", "040", "140")


@dataclass(frozen=True, kw_only=True)
class PlotCorrection:
    """Estimated errors of one radar, this package's convention: reported minus true.
    ``range_bias_m`` (m), ``range_gain`` (1), ``azimuth_bias_rad`` (rad, clockwise positive, as the
    azimuth), ``time_bias_s`` (s). ValueError for a value that is not finite or a gain of -1 or
    less (a range could not be corrected)."""

    range_bias_m: float = 0.0
    range_gain: float = 0.0
    azimuth_bias_rad: float = 0.0
    time_bias_s: float = 0.0

    def __post_init__(self) -> None:
        for name in ("range_bias_m", "range_gain", "azimuth_bias_rad", "time_bias_s"):
            if not math.isfinite(getattr(self, name)):
                raise ValueError(f"PlotCorrection: {name} = {getattr(self, name)!r} is not a finite number")
        if self.range_gain <= -1.0:
            raise ValueError(
                f"PlotCorrection: range_gain = {self.range_gain!r} (dimensionless) must be above -1 "
                "(reported range = (1 + gain) x true range + bias)"
            )


@dataclass(frozen=True)
class CorrectedDatagram:
    """A datagram corrected: ``data`` (as long as the input), ``records`` (CAT048 records seen: walked
    or found bad), ``corrected`` (records whose SAC/SIC had a correction: their I048/040 and
    I048/140, where present, rewritten), ``clamped`` (of those, RHO clamped to its range),
    ``unwalkable`` (CAT048 records or blocks that could not be walked, left as they were)."""

    data: bytes
    records: int
    corrected: int
    clamped: int
    unwalkable: int


def _blocks(datagram: bytes) -> tuple[list[tuple[int, int, bool]], int]:
    """The CAT048 data blocks of a datagram, (start of the first record, end, cut short) each, and
    the CAT048 blocks that cannot be walked (length below 3: the walk of the datagram ends)."""
    out, bad, pos, n = [], 0, 0, len(datagram)
    while pos + 3 <= n:
        cat, length = datagram[pos], (datagram[pos + 1] << 8) | datagram[pos + 2]
        if length < 3:
            bad += cat == 48
            break
        if cat == 48:
            out.append((pos + 3, min(pos + length, n), pos + length > n))
        pos += length
    if 0 < n - pos < 3 and datagram[pos] == 48:  # a CAT048 header cut short
        bad += 1
    return out, bad


def _walk(datagram: bytes, blocks: list, uap) -> tuple[list[dict], int, int]:
    """(the offsets of the wanted items of each record walked, records walked, records bad)."""
    found, walked, bad = [], 0, 0
    for pos, end, cut in blocks:
        while pos < end:
            try:
                pos, offsets = walk_one(datagram, pos, end, uap, _WANTED)
            except RecordProblem:
                bad += 1
                break
            walked += 1
            found.append(offsets)
        else:
            bad += cut  # cut between two records: the rest of the block is missing
    return found, walked, bad


def _correct_record(out: bytearray, offsets: dict, c: PlotCorrection) -> bool:
    """The I048/040 and I048/140 of one record (at ``offsets``, where present) corrected in ``out``;
    True when its RHO was clamped."""
    clamped = False
    at = offsets.get("040")
    if at is not None:
        rho, theta = (out[at] << 8) | out[at + 1], (out[at + 2] << 8) | out[at + 3]
        rho_m = (rho * _RHO_LSB_M - c.range_bias_m) / (1.0 + c.range_gain)
        rho = round(rho_m / _RHO_LSB_M)
        clamped = not 0 <= rho <= RHO_MAX_RAW
        rho = min(max(rho, 0), RHO_MAX_RAW)
        theta = round(theta - c.azimuth_bias_rad / _THETA_LSB_RAD) % 65536
        out[at : at + 4] = (rho << 16 | theta).to_bytes(4, "big")
    at = offsets.get("140")
    if at is not None:
        tod = (out[at] << 16) | (out[at + 1] << 8) | out[at + 2]
        if tod < _DAY_RAW:  # one of 24 h or more is not a time of day: kept
            tod = round(tod - c.time_bias_s / _TOD_LSB_S) % _DAY_RAW
            out[at : at + 3] = tod.to_bytes(3, "big")
    return clamped


def correct_cat048(
    datagram: bytes,
    corrections: Mapping[tuple[int, int], PlotCorrection],
    edition: str = DEFAULT_EDITIONS[48],
) -> CorrectedDatagram:
    """``datagram`` with the CAT048 plots of the radars in ``corrections`` ((SAC, SIC) -> their
    estimated errors) corrected, in CAT048 ``edition`` (see the module's text). Never raises for
    bad octets: what cannot be walked is left as it is and counted."""
    uap = uap_for(48, check_editions({48: edition})[48])
    data = bytes(datagram)
    blocks, bad_blocks = _blocks(data)
    found, walked, bad = _walk(data, blocks, uap)
    out = bytearray(data)
    corrected = clamped = 0
    for offsets in found:
        at = offsets.get("010")
        c = None if at is None else corrections.get((data[at], data[at + 1]))
        if c is not None:
            corrected += 1
            clamped += _correct_record(out, offsets, c)
    return CorrectedDatagram(bytes(out), walked + bad, corrected, clamped, bad + bad_blocks)
