"""One time axis for the whole log: ``time_s``, seconds since midnight UTC of the first day of the log
(or of the ``date`` argument), in every table.

* **Times of day.** GGA, RMC, GNS, ZDA and ``$PASHR`` (the *anchors*) carry the UTC time of day of
  their data. Taken in log order, each is placed on the day that puts it nearest to the anchor
  before it (an unwrap with a period of one day): a time that drops from 23:59:59 to
  00:00:00 has crossed midnight. Another timed sentence (TTM) is placed on the day nearest to the
  anchor before it in the log.
* **The date** of the first anchor's day comes from the first ZDA or valid RMC (their dates, with
  their own times placed as above); without them from the ``date`` argument; without it from the
  reception times of the lines (tag block ``c:`` or a logger prefix, unix seconds). Without any,
  the date is unknown: the times still count from midnight of the log's first day, and the AIS
  positions (placed by unix reception times) are set aside.
* **Sentences without a time field** (HDT, THS) take the time of the anchor before them in the log
  (a burst of a receiver's sentences shares one epoch; at 1 Hz they are at most a second late).
"""

from __future__ import annotations

import datetime as dt
from dataclasses import dataclass, field

import numpy as np

from registration.io.nmea.fixes import EPOCH_ORDINAL, Dates

__all__ = ["Clock", "fit_clock", "unwrap_days", "DAY_S"]

DAY_S = 86400.0


@dataclass
class Clock:
    """``origin_day``: days since 1970-01-01 of ``time_s = 0`` (NaN: the date is unknown);
    ``day0``: the first anchor's day on the same scale (NaN: unknown); ``anchor_index`` (A,) and
    ``anchor_u`` (A,) s since midnight of ``day0``, the anchors in log order; ``date_source`` and
    ``notes`` for the summary."""

    origin_day: float
    day0: float
    anchor_index: np.ndarray
    anchor_u: np.ndarray
    date_source: str
    notes: list[str] = field(default_factory=list)

    def _shift(self) -> float:
        """Seconds to add to a time counted from midnight of ``day0`` to count from the origin."""
        if np.isnan(self.origin_day) or np.isnan(self.day0):
            return 0.0
        return (self.day0 - self.origin_day) * DAY_S

    def _previous(self, index: np.ndarray) -> np.ndarray:
        """Position in the anchors of the anchor before each sentence ``index`` (the first anchor
        for sentences before it); -1 without anchors."""
        if self.anchor_index.size == 0:
            return np.full(np.shape(index), -1)
        j = np.searchsorted(self.anchor_index, index, side="left") - 1
        return np.maximum(j, 0)

    def place(self, index: np.ndarray, tod: np.ndarray) -> np.ndarray:
        """``time_s`` (K,) of sentences ``index`` (K,) with times of day ``tod`` (K,) s: on the day
        nearest to the anchor before each."""
        index = np.asarray(index)
        tod = np.asarray(tod, dtype=np.float64)
        j = self._previous(index)
        if self.anchor_index.size == 0:
            u = unwrap_days(tod)
        else:
            ref = self.anchor_u[j]
            u = tod + DAY_S * np.round((ref - tod) / DAY_S)
        return u + self._shift()

    def previous_anchor_time(self, index: np.ndarray) -> np.ndarray:
        """``time_s`` (K,) of the anchor before each sentence ``index`` (NaN where none is before)."""
        index = np.asarray(index)
        if self.anchor_index.size == 0:
            return np.full(index.shape, np.nan)
        j = np.searchsorted(self.anchor_index, index, side="left") - 1
        out = self.anchor_u[np.maximum(j, 0)] + self._shift()
        return np.where(j >= 0, out, np.nan)

    def from_unix(self, unix: np.ndarray) -> np.ndarray:
        """``time_s`` (K,) of unix times (s); NaN when the date is unknown."""
        unix = np.asarray(unix, dtype=np.float64)
        if np.isnan(self.origin_day):
            return np.full(unix.shape, np.nan)
        return unix - self.origin_day * DAY_S

    @property
    def known(self) -> bool:
        """Whether the date is known (``time_s`` can be given as a UTC date and time)."""
        return not np.isnan(self.origin_day)

    def utc(self, time_s: float) -> str | None:
        """ISO 8601 UTC text of a ``time_s``; None when the date is unknown."""
        if not self.known or not np.isfinite(time_s):
            return None
        epoch = dt.datetime(1970, 1, 1, tzinfo=dt.timezone.utc)
        try:
            stamp = epoch + dt.timedelta(days=self.origin_day, seconds=float(time_s))
        except OverflowError:  # beyond the years 1-9999: no date to give
            return None
        return stamp.isoformat().replace("+00:00", "Z")

    def origin_date(self) -> str | None:
        """The origin's date (``YYYY-MM-DD``), None when unknown."""
        if not self.known:
            return None
        return dt.date.fromordinal(int(self.origin_day) + EPOCH_ORDINAL).isoformat()


def unwrap_days(tod: np.ndarray) -> np.ndarray:
    """Times of day (K,) s placed each on the day nearest to the one before: ``tod + DAY_S * k`` with
    whole days ``k`` (exact, unlike ``numpy.unwrap``'s float corrections)."""
    tod = np.asarray(tod, dtype=np.float64)
    if tod.size == 0:
        return tod
    k = np.concatenate([[0.0], np.cumsum(np.round(-np.diff(tod) / DAY_S))])
    return tod + DAY_S * k


def _day_of(date) -> float:
    if isinstance(date, str):
        try:
            date = dt.date.fromisoformat(date)
        except ValueError:
            raise ValueError(f"date: {date!r} is not a date (YYYY-MM-DD)") from None
    if isinstance(date, dt.datetime):
        date = date.date()
    if not isinstance(date, dt.date):
        raise ValueError(f"date: expected a datetime.date or 'YYYY-MM-DD', got {type(date).__name__}")
    return float(date.toordinal() - EPOCH_ORDINAL)


def _day0_from_received(clock: Clock, received: np.ndarray) -> float:
    """The first anchor's day from the lines' reception times (unix s): the median over anchors
    with one, else the first line with one against the anchor before it; NaN without any."""
    if clock.anchor_index.size == 0:
        return np.nan
    r = received[clock.anchor_index]
    ok = np.isfinite(r)
    if ok.any():
        return float(np.median(np.round((r[ok] - clock.anchor_u[ok]) / DAY_S)))
    lines = np.flatnonzero(np.isfinite(received))
    if lines.size == 0:
        return np.nan
    j = clock._previous(lines[:1])[0]
    return float(np.round((received[lines[0]] - clock.anchor_u[j]) / DAY_S))


def fit_clock(
    anchor_index: np.ndarray, anchor_tod: np.ndarray, dates: Dates, date, received: np.ndarray
) -> Clock:
    """The :class:`Clock` of a log: anchors ``anchor_index`` (A,) with times of day ``anchor_tod``
    (A,) s, the dated sentences ``dates``, the ``date`` argument (``datetime.date``,
    ``'YYYY-MM-DD'`` or None) and each sentence's reception time ``received`` (N,) unix s."""
    order = np.argsort(anchor_index, kind="stable")
    index, tod = np.asarray(anchor_index)[order], np.asarray(anchor_tod, dtype=np.float64)[order]
    u = unwrap_days(tod)
    clock = Clock(np.nan, np.nan, index, u, "none")
    given = None if date is None else _day_of(date)
    if dates.index.size:
        k = np.floor(clock.place(dates.index, dates.tod) / DAY_S)
        candidates = dates.day - k
        clock.day0 = float(candidates[0])
        clock.date_source = "ZDA/RMC"
        n_other = int((candidates != candidates[0]).sum())
        if n_other:
            clock.notes.append(
                f"{n_other} of {candidates.size} ZDA/RMC dates disagree with the first one "
                f"(by the log's times of day); the first is used"
            )
    elif given is not None:
        clock.day0, clock.date_source = given, "date argument"
    else:
        clock.day0 = _day0_from_received(clock, received)
        clock.date_source = "reception times" if np.isfinite(clock.day0) else "none"
    clock.origin_day = given if given is not None else clock.day0
    if given is not None and np.isfinite(clock.day0) and clock.day0 != given:
        clock.notes.append(
            f"the log's first day ({clock.date_source}) is {int(clock.day0 - given):+d} day(s) "
            f"from the date argument; time_s counts from midnight of the date argument"
        )
    if not clock.known:
        clock.notes.append(
            "the log gives no date (no ZDA, no valid RMC, no reception times) and no date argument "
            "was given: time_s counts from midnight of the log's first day; AIS positions are set aside"
        )
    return clock
