"""Sentences for the tests, built by the independent encoders only: pynmea2 for NMEA 0183 (fields
and checksum), pyais for AIS (``encode_dict``) and its tag blocks. The helpers only format numbers
into fields; pynmea2 and pyais write the sentences."""

from __future__ import annotations

import datetime as dt

import numpy as np
import pynmea2
from pyais import TagBlock, encode_dict

__all__ = [
    "hhmmss",
    "ddmm",
    "gga",
    "rmc",
    "gns",
    "zda",
    "hdt",
    "ths",
    "pashr",
    "ttm",
    "ais",
    "tag",
    "checksummed",
]


def hhmmss(t: float, decimals: int = 2) -> str:
    """UTC time of day ``hhmmss.ss`` of ``t`` s (any day)."""
    q = 10**decimals
    n = int(round((t % 86400.0) * q)) % (86400 * q)
    h, rest = divmod(n, 3600 * q)
    m, s = divmod(rest, 60 * q)
    return f"{h:02d}{m:02d}{s // q:02d}." + f"{s % q:0{decimals}d}"


def ddmm(angle_rad: float, lon: bool) -> tuple[str, str]:
    """``[d]ddmm.mmmmmm`` and hemisphere letter of an angle (rad)."""
    deg = abs(float(np.degrees(angle_rad)))
    d = int(deg)
    m = (deg - d) * 60.0
    if round(m, 6) >= 60.0:
        d, m = d + 1, 0.0
    text = f"{d:03d}" if lon else f"{d:02d}"
    hemi = ("E" if angle_rad >= 0 else "W") if lon else ("N" if angle_rad >= 0 else "S")
    return text + f"{m:09.6f}", hemi


def gga(
    t: float,
    lat: float,
    lon: float,
    alt_msl: float = 30.0,
    geoid: str = "42.00",
    quality: str = "2",
    talker: str = "GP",
) -> str:
    la, ns = ddmm(lat, False)
    lo, ew = ddmm(lon, True)
    return str(
        pynmea2.GGA(
            talker,
            "GGA",
            (hhmmss(t), la, ns, lo, ew, quality, "12", "0.8", f"{alt_msl:.2f}", "M", geoid, "M", "", ""),
        )
    )


def rmc(
    t: float, lat: float, lon: float, day: dt.date, status: str = "A", sog: str = "15.6", cog: str = "40.0"
) -> str:
    la, ns = ddmm(lat, False)
    lo, ew = ddmm(lon, True)
    return str(
        pynmea2.RMC(
            "GP", "RMC", (hhmmss(t), status, la, ns, lo, ew, sog, cog, day.strftime("%d%m%y"), "", "", "D")
        )
    )


def gns(
    t: float, lat: float, lon: float, mode: str = "AA", alt_msl: float = 30.0, geoid: str = "42.00"
) -> str:
    la, ns = ddmm(lat, False)
    lo, ew = ddmm(lon, True)
    return str(
        pynmea2.GNS(
            "GN", "GNS", (hhmmss(t), la, ns, lo, ew, mode, "14", "0.8", f"{alt_msl:.2f}", geoid, "", "")
        )
    )


def zda(t: float, day: dt.date) -> str:
    return str(
        pynmea2.ZDA(
            "GP", "ZDA", (hhmmss(t), f"{day.day:02d}", f"{day.month:02d}", f"{day.year:04d}", "00", "00")
        )
    )


def hdt(heading_deg: float) -> str:
    return str(pynmea2.HDT("HE", "HDT", (f"{heading_deg % 360.0:.2f}", "T")))


def ths(heading_deg: float, mode: str = "A") -> str:
    """THS (pynmea2 has no class for it: the generic talker sentence writes it)."""
    return str(pynmea2.TalkerSentence("HE", "THS", (f"{heading_deg % 360.0:.2f}", mode)))


def pashr(t: float, heading_deg: float, roll_deg: float, pitch_deg: float, flag: str = "T") -> str:
    fields = [
        "R",
        hhmmss(t, 3),
        f"{heading_deg % 360.0:.3f}",
        flag,
        f"{roll_deg:+.3f}",
        f"{pitch_deg:+.3f}",
        "+0.00",
        "0.020",
        "0.020",
        "0.050",
        "2",
        "1",
    ]
    return str(pynmea2.ash.ASHRATT("ASH", fields))


def ttm(
    number: int,
    distance: str,
    bearing_deg: float,
    reference: str = "R",
    unit: str = "N",
    status: str = "T",
    t: float | None = None,
    talker: str = "RA",
) -> str:
    """TTM; ``t`` None: the sentence of NMEA 2.x, without the time and acquisition fields."""
    fields = [
        f"{number:02d}",
        distance,
        f"{bearing_deg % 360.0:.4f}",
        reference,
        "10.0",
        "0.0",
        "T",
        "0.5",
        "10.0",
        unit,
        "",
        status,
        "",
    ]
    if t is not None:
        fields += [hhmmss(t), "A"]
    return str(pynmea2.TTM(talker, "TTM", tuple(fields)))


def tag(unix: float) -> str:
    """An NMEA 4.10 tag block with the reception time ``c:`` (whole unix seconds), backslashes included."""
    return "\\" + TagBlock.create_str(receiver_timestamp=int(np.floor(unix))) + "\\"


def ais(data: dict, own: bool = False, seq_id=None) -> list[str]:
    """The AIS sentences of a message (pyais ``encode_dict``; ``data`` with ``msg_type``)."""
    return encode_dict(data, sentence_type="VDO" if own else "VDM", seq_id=seq_id)


def checksummed(body: str, start: str = "$") -> str:
    """A sentence of any content with its correct checksum (pynmea2's checksum function)."""
    return f"{start}{body}*{pynmea2.NMEASentence.checksum(body):02X}"
