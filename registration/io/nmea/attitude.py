"""Attitude sentences of a :class:`SentenceLog`: ``$PASHR`` (heading, roll, pitch, with its own UTC
time), HDT and THS (true heading, no time field).

``$PASHR`` is the attitude sentence of the RT300 family that Applanix POS MV, Trimble, NovAtel
SPAN, Hemisphere and OxTS receivers write (pynmea2 ``ASHRATT``): ``$PASHR,hhmmss.sss,HHH.HH,T,
RRR.RR,PPP.PP,heave,roll sigma,pitch sigma,heading sigma,aiding,IMU*hh``. Its signs: heading
clockwise from true north; roll positive with the starboard side down (the port side up); pitch
positive with the bow up. These are the package's signs (docs/reference/conventions.md), and with the
default Tait-Bryan angles (heading, then pitch, then roll) its rotation order too, so the angles
pass unchanged. A POS MV set to TSS angles gives roll as the athwartship axis's own tilt:
``sin(roll_tss) = sin(roll) cos(pitch)``; ``angles="tss"`` converts it (docs/howto/import-nmea.md). Ashtech's
other ``$PASHR`` messages (``$PASHR,POS``, ``$PASHR,HPR``: field 1 is a word, not a time) are not
used.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.io.files.ledger import RejectedLedger
from registration.io.nmea.fields import columns, numbers, text, time_of_day
from registration.io.nmea.lines import SentenceLog

__all__ = ["Attitude", "read_pashr", "read_headings", "PASHR_ANGLES", "pashr_subtypes"]

#: The angle conventions ``$PASHR`` roll may be given in.
PASHR_ANGLES = ("tait-bryan", "tss")


@dataclass
class Attitude:
    """Valid attitude samples of one sentence type: ``index`` (K,) into the log, ``talker`` (K,),
    ``tod`` (K,) s since midnight UTC (NaN: the sentence has no time field), ``heading`` (K,) rad
    clockwise from true north, ``pitch``, ``roll`` (K,) rad in the package's convention (NaN when
    the type has none)."""

    kind: str
    index: np.ndarray
    talker: np.ndarray
    tod: np.ndarray
    heading: np.ndarray
    pitch: np.ndarray
    roll: np.ndarray

    def take(self, keep: np.ndarray) -> "Attitude":
        return Attitude(
            self.kind,
            *(a[keep] for a in (self.index, self.talker, self.tod, self.heading, self.pitch, self.roll)),
        )

    def __len__(self) -> int:
        return int(self.index.size)


def pashr_subtypes(log: SentenceLog) -> tuple[np.ndarray, np.ndarray]:
    """(indices of the attitude ``$PASHR`` sentences, indices of Ashtech's other ``$PASHR``
    messages): an attitude sentence has a time of day (digits) in field 1."""
    index = log.where("PASHR")
    first = [log.sentence[i][7:].split(",", 1)[0] for i in index]
    att = np.array([f[:1].isdigit() for f in first], dtype=bool)
    return index[att], index[~att]


def read_pashr(log: SentenceLog, rejections: RejectedLedger, angles: str = "tait-bryan") -> Attitude:
    """The valid ``$PASHR`` attitude samples; ``angles``: ``"tait-bryan"`` (default) or ``"tss"``
    (roll converted by ``roll = asin(sin(roll_tss) / cos(pitch))``)."""
    if angles not in PASHR_ANGLES:
        raise ValueError(f"angles: expected one of {PASHR_ANGLES}, got {angles!r}")
    c = columns(log, pashr_subtypes(log)[0], 5, 6, rejections, "PASHR")
    tod = time_of_day(c.cols[1])
    bad = np.isnan(tod)
    c = c.reject(
        bad, rejections, "bad_time", [f"PASHR UTC time {v!r} is not hhmmss[.sss]" for v in c.cols[1]]
    )
    tod = tod[~bad]
    heading, roll, pitch = numbers(c.cols[2]), numbers(c.cols[4]), numbers(c.cols[5])
    flag = text(c.cols[3])
    bad = (
        np.isnan(heading)
        | np.isnan(roll)
        | np.isnan(pitch)
        | (heading < 0)
        | (heading > 360)
        | (np.abs(roll) > 90)
        | (np.abs(pitch) > 90)
    )
    reasons = np.where(
        bad,
        "PASHR heading, roll or pitch empty, not a number or out of range",
        "PASHR heading is not true (field 3 is not T)",
    )
    bad |= flag != "T"
    c = c.reject(bad, rejections, "bad_field", reasons)
    keep = ~bad
    heading, roll, pitch = np.radians(heading[keep]), np.radians(roll[keep]), np.radians(pitch[keep])
    if angles == "tss":
        roll = np.arcsin(np.clip(np.sin(roll) / np.cos(pitch), -1.0, 1.0))
    return Attitude("PASHR", c.index, c.talker, tod[keep], heading, pitch, roll)


def read_headings(log: SentenceLog, kind: str, rejections: RejectedLedger) -> Attitude:
    """The valid true headings of HDT (``heading,T``) or THS (``heading,mode``; mode V: invalid).
    Neither has a time field (``tod`` NaN) nor pitch and roll (NaN)."""
    c = columns(log, log.where(kind), 2, 3, rejections, kind)
    flag = text(c.cols[2])
    if kind == "THS":
        invalid = flag == "V"
        c = c.reject(invalid, rejections, "invalid_fix", "THS mode V (invalid heading)")
        flag = flag[~invalid]
    heading = numbers(c.cols[1])
    bad = np.isnan(heading) | (heading < 0) | (heading > 360)
    reasons = np.where(
        bad, f"{kind} heading empty, not a number or out of range", "HDT heading is not true (not T)"
    )
    if kind == "HDT":
        bad |= flag != "T"
    c = c.reject(bad, rejections, "bad_field", reasons)
    n = len(c)
    nan = np.full(n, np.nan)
    return Attitude(kind, c.index, c.talker, nan, np.radians(heading[~bad]), nan.copy(), nan.copy())
