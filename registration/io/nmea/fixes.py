"""Position fixes (GGA, GNS, RMC) and dates (ZDA, RMC) of a :class:`SentenceLog`.

Heights: GGA and GNS give the antenna's altitude above mean sea level and the geoid separation
(the height of mean sea level above the WGS-84 ellipsoid); the ellipsoid height is their sum. A
fix without a geoid separation keeps NaN there (the navigation then uses 0 and notes it). RMC has
no height (NaN). Invalid fixes (GGA quality 0, RMC status V, GNS mode all N) are set aside as
``invalid_fix``.
"""

from __future__ import annotations

import datetime as dt
from dataclasses import dataclass

import numpy as np

from registration.io.files.ledger import RejectedLedger
from registration.io.nmea.fields import Columns, columns, latitude, longitude, numbers, text, time_of_day
from registration.io.nmea.lines import SentenceLog

__all__ = ["Fixes", "Dates", "read_fixes", "EPOCH_ORDINAL", "ALTITUDE_SPAN_M", "MAX_GEOID_M"]

#: Altitudes above mean sea level (m) taken as fixes (the fleet navigation's span).
ALTITUDE_SPAN_M = (-1.2e4, 1e6)
#: Largest geoid separation (m): the geoid lies within -107 m and +86 m of the WGS-84 ellipsoid.
MAX_GEOID_M = 200.0
#: Proleptic Gregorian ordinal of 1970-01-01 (day numbers here count from it).
EPOCH_ORDINAL = dt.date(1970, 1, 1).toordinal()


@dataclass
class Fixes:
    """Valid position fixes of one sentence type: ``index`` (K,) into the log, ``talker`` (K,),
    ``tod`` (K,) s since midnight UTC, ``lat``, ``lon`` (K,) rad, ``alt_msl`` (K,) m above mean sea
    level (NaN for RMC), ``geoid`` (K,) m, the geoid separation (NaN if not given)."""

    kind: str
    index: np.ndarray
    talker: np.ndarray
    tod: np.ndarray
    lat: np.ndarray
    lon: np.ndarray
    alt_msl: np.ndarray
    geoid: np.ndarray

    def take(self, keep: np.ndarray) -> "Fixes":
        return Fixes(
            self.kind,
            *(
                a[keep]
                for a in (self.index, self.talker, self.tod, self.lat, self.lon, self.alt_msl, self.geoid)
            ),
        )


@dataclass
class Dates:
    """Dated sentences (ZDA, valid RMC): ``index`` (K,), ``tod`` (K,) s, ``day`` (K,) days since
    1970-01-01 (UTC)."""

    index: np.ndarray
    tod: np.ndarray
    day: np.ndarray


def _timed(c: Columns, col: int, rejections: RejectedLedger, name: str) -> tuple[Columns, np.ndarray]:
    tod = time_of_day(c.cols[col])
    bad = np.isnan(tod)
    reasons = [f"{name} UTC time {v!r} is not hhmmss[.ss]" for v in c.cols[col]]
    c = c.reject(bad, rejections, "bad_time", reasons)
    return c, tod[~bad]


def _position(c: Columns, tod: np.ndarray, lat_col: int, rejections: RejectedLedger, name: str):
    lat = latitude(c.cols[lat_col], c.cols[lat_col + 1])
    lon = longitude(c.cols[lat_col + 2], c.cols[lat_col + 3])
    bad = np.isnan(lat) | np.isnan(lon)
    c = c.reject(bad, rejections, "bad_field", f"{name} latitude or longitude empty or not valid")
    return c, tod[~bad], lat[~bad], lon[~bad]


def _gga_like(log: SentenceLog, kind: str, rejections: RejectedLedger) -> Fixes:
    """GGA (fields: time, lat, N/S, lon, E/W, quality, sats, hdop, alt, M, geoid sep, M, ...) or GNS
    (time, lat, N/S, lon, E/W, mode, sats, hdop, alt, geoid sep, ...)."""
    gga = kind == "GGA"
    c = columns(log, log.where(kind), 11 if gga else 10, 12, rejections, kind)
    c, tod = _timed(c, 1, rejections, kind)
    if gga:
        q = numbers(c.cols[6])
        invalid = ~(q > 0)
        reason = [f"GGA fix quality {v!r} (0: no fix)" for v in c.cols[6]]
    else:
        mode = text(c.cols[6])
        invalid = np.array([m == "" or set(m) <= {"N"} for m in mode], dtype=bool)
        reason = [f"GNS mode {v!r} (N: no fix)" for v in c.cols[6]]
    c = c.reject(invalid, rejections, "invalid_fix", reason)
    tod = tod[~invalid]
    c, tod, lat, lon = _position(c, tod, 2, rejections, kind)
    alt = numbers(c.cols[9])
    geoid = numbers(c.cols[11 if gga else 10])
    geoid = np.where(np.isnan(geoid) | (np.abs(geoid) <= MAX_GEOID_M), geoid, np.inf)  # NaN: not given
    bad = ~((alt >= ALTITUDE_SPAN_M[0]) & (alt <= ALTITUDE_SPAN_M[1])) | np.isinf(geoid)
    c = c.reject(
        bad,
        rejections,
        "bad_field",
        f"{kind} altitude empty, not a number or outside "
        f"[{ALTITUDE_SPAN_M[0]:g}, {ALTITUDE_SPAN_M[1]:g}] m, or geoid separation beyond {MAX_GEOID_M:g} m",
    )
    keep = ~bad
    return Fixes(kind, c.index, c.talker, tod[keep], lat[keep], lon[keep], alt[keep], geoid[keep])


def _days(day, month, year) -> np.ndarray:
    """Days since 1970-01-01 of day, month, year columns (numbers); NaN where not a date."""
    out = np.full(len(day), np.nan)
    for k, (d, m, y) in enumerate(zip(day, month, year)):
        try:
            out[k] = dt.date(int(y), int(m), int(d)).toordinal() - EPOCH_ORDINAL
        except (ValueError, OverflowError):
            pass
    return out


def _rmc(log: SentenceLog, rejections: RejectedLedger) -> tuple[Fixes, Dates]:
    """RMC (time, status, lat, N/S, lon, E/W, speed, course, ddmmyy, ...): fixes and dates."""
    c = columns(log, log.where("RMC"), 9, 10, rejections, "RMC")
    c, tod = _timed(c, 1, rejections, "RMC")
    status = text(c.cols[2])
    invalid = status != "A"
    c = c.reject(invalid, rejections, "invalid_fix", [f"RMC status {s!r} (V: void)" for s in status])
    tod = tod[~invalid]
    c, tod, lat, lon = _position(c, tod, 3, rejections, "RMC")
    ddmmyy = c.cols[9]
    v = numbers(ddmmyy)
    six = np.array([len(s.strip()) == 6 for s in ddmmyy], dtype=bool)
    yy = np.mod(v, 100.0)
    day = _days(
        np.floor(v / 10000.0), np.mod(np.floor(v / 100.0), 100.0), np.where(yy < 80, 2000.0 + yy, 1900.0 + yy)
    )
    day = np.where(six, day, np.nan)
    bad = np.isnan(day)
    c = c.reject(bad, rejections, "bad_field", [f"RMC date {s!r} is not ddmmyy" for s in ddmmyy])
    keep = ~bad
    n = int(keep.sum())
    fixes = Fixes(
        "RMC", c.index, c.talker, tod[keep], lat[keep], lon[keep], np.full(n, np.nan), np.full(n, np.nan)
    )
    return fixes, Dates(c.index, tod[keep], day[keep])


def _zda(log: SentenceLog, rejections: RejectedLedger) -> Dates:
    """ZDA (time, day, month, year, zone hours, zone minutes): dates."""
    c = columns(log, log.where("ZDA"), 4, 5, rejections, "ZDA")
    c, tod = _timed(c, 1, rejections, "ZDA")
    day = _days(numbers(c.cols[2]), numbers(c.cols[3]), numbers(c.cols[4]))
    bad = np.isnan(day)
    c = c.reject(bad, rejections, "bad_field", "ZDA day, month or year is not a date")
    return Dates(c.index, tod[~bad], day[~bad])


def read_fixes(log: SentenceLog, rejections: RejectedLedger) -> tuple[dict[str, Fixes], Dates]:
    """The valid fixes per type (``GGA``, ``GNS``, ``RMC``) and the dates of ZDA and valid RMC
    sentences (in log order)."""
    rmc, rmc_dates = _rmc(log, rejections)
    fixes = {"GGA": _gga_like(log, "GGA", rejections), "GNS": _gga_like(log, "GNS", rejections), "RMC": rmc}
    zda = _zda(log, rejections)
    index = np.concatenate([zda.index, rmc_dates.index])
    order = np.argsort(index, kind="stable")
    dates = Dates(
        index[order],
        np.concatenate([zda.tod, rmc_dates.tod])[order],
        np.concatenate([zda.day, rmc_dates.day])[order],
    )
    return fixes, dates
