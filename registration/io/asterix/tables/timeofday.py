"""ASTERIX times of day (s since midnight UTC, 0 <= t < 86400) placed on a time axis: seconds
since midnight UTC of a reference day, across midnight and across files.

The reference day is the ``date`` the caller gives, else the UTC date of the first packet of the
first capture, else (raw recordings only) the day of the recording's first record. Records are
taken in stream order (the files in the order given, each in byte order): a time of day more than
12 h below the previous one is on the next day (the midnight rollover: ~86399.9 s, then ~0.1 s
adds 86400 s), more than 12 h above it on the day before (a late record just after midnight).
A capture's packet times place its first record on its day relative to the reference day, when
they agree with its time of day within an hour and lie within a day of it; otherwise a file
continues from where the previous one ended (the first file starts on the reference day).
"""

from __future__ import annotations

import datetime as dt

import numpy as np

__all__ = ["DAY_S", "midnight_utc", "capture_day", "Unwrapper", "recorder_times"]

DAY_S = 86400.0
_HALF_DAY_S = DAY_S / 2
#: Packet time and time of day must agree within this (s) for the packet date to place a record.
_CAPTURE_AGREEMENT_S = 3600.0


def midnight_utc(date: dt.date) -> float:
    """UTC seconds since 1970 of midnight at the start of ``date``."""
    return dt.datetime.combine(date, dt.time(), dt.timezone.utc).timestamp()


def capture_day(capture_time: float) -> dt.date:
    """The UTC date of a capture time (s since 1970)."""
    return dt.datetime.fromtimestamp(capture_time, dt.timezone.utc).date()


def recorder_times(recorder_tod_s: np.ndarray, times_s: np.ndarray) -> np.ndarray:
    """A recorder's time stamps that are times of day (s since midnight UTC, no date: the GPS and
    IOSS framings) placed on the time axis, each on the day that brings it nearest its record's
    time ``times_s`` (s since midnight of the reference day); NaN where either is NaN."""
    return recorder_tod_s + DAY_S * np.round((times_s - recorder_tod_s) / DAY_S)


class Unwrapper:
    """Time of day -> seconds since midnight of ``reference`` (a date, or None before it is known),
    file after file, carrying the day across files."""

    def __init__(self, reference: dt.date | None) -> None:
        self.reference = reference
        self.day: int | None = None
        self.last_tod: float | None = None
        self.placed_by_capture = 0

    def _start_day(self, tod: float, capture_time: float) -> int:
        """The day (relative to the reference) of a file's first record."""
        if self.reference is not None and np.isfinite(capture_time):
            since = capture_time - midnight_utc(self.reference)
            day = round((since - tod) / DAY_S)
            if abs(day) <= 1 and abs(since - tod - day * DAY_S) < _CAPTURE_AGREEMENT_S:
                self.placed_by_capture += 1
                return int(day)
        if self.day is None or self.last_tod is None:  # both set together, after a first file
            return 0
        return self.day + _step(tod - self.last_tod)

    def file_times(self, tod_s: np.ndarray, capture_time: np.ndarray) -> np.ndarray:
        """Seconds since midnight of the reference day of a file's records, given in stream order:
        ``tod_s`` (N,) times of day (NaN: none, left NaN), ``capture_time`` (N,) packet times (UTC s
        since 1970, NaN for a raw file)."""
        out = np.full(tod_s.shape, np.nan)
        valid = np.flatnonzero(np.isfinite(tod_s))
        if valid.size == 0:
            return out
        tod = tod_s[valid]
        first = self._start_day(float(tod[0]), float(capture_time[valid[0]]))
        steps = (np.diff(tod) < -_HALF_DAY_S).astype(np.int64) - (np.diff(tod) > _HALF_DAY_S)
        day = first + np.concatenate([[0], np.cumsum(steps)])
        out[valid] = tod + DAY_S * day
        self.day, self.last_tod = int(day[-1]), float(tod[-1])
        return out


def _step(diff: float) -> int:
    return int(diff < -_HALF_DAY_S) - int(diff > _HALF_DAY_S)
