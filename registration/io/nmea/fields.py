"""Fields of many sentences of one type at once: split, checked for count, converted column by column
with pandas (the fast path that replaces one pynmea2 object per line; tests/io/nmea/test_fastpath.py
checks it against pynmea2).

Conventions: times of day in seconds since midnight UTC, angles in radians, distances in metres.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.io.files.ledger import RejectedLedger
from registration.io.nmea.lines import SentenceLog

__all__ = ["Columns", "columns", "numbers", "time_of_day", "latitude", "longitude", "text"]


@dataclass
class Columns:
    """Sentences of one type: ``index`` (K,) into the :class:`SentenceLog`, ``talker`` (K,),
    ``cols`` the fields by position (element 0 the address, then field 1, 2, ...), each a tuple of
    K strings ('' where a sentence stops short of an optional field)."""

    log: SentenceLog
    index: np.ndarray
    talker: np.ndarray
    cols: list

    def __len__(self) -> int:
        return int(self.index.size)

    def take(self, keep: np.ndarray) -> "Columns":
        """The sentences where ``keep`` (K,) bool is true."""
        keep = np.asarray(keep, bool)
        return Columns(
            self.log,
            self.index[keep],
            self.talker[keep],
            [tuple(np.asarray(c, dtype=object)[keep]) for c in self.cols],
        )

    def reject(self, bad: np.ndarray, rejections: RejectedLedger, code: str, reason) -> "Columns":
        """Set aside the sentences where ``bad`` (K,) is true (``reason``: a text or (K,) texts) and
        return the rest."""
        bad = np.asarray(bad, bool)
        if bad.any():
            i = self.index[bad]
            r = reason if isinstance(reason, str) else np.asarray(reason, dtype=object)[bad]
            rejections.add(self.log.file[i], code, r, line=self.log.line[i])
            return self.take(~bad)
        return self


def columns(
    log: SentenceLog, index: np.ndarray, n_required: int, width: int, rejections: RejectedLedger, name: str
) -> Columns:
    """The sentences ``index`` split into ``width`` columns (the address and ``width - 1`` fields);
    those with fewer than ``n_required`` fields (address not counted) are set aside as
    ``too_few_fields``; missing optional fields read as ''."""
    rows = log.fields(index)
    n = np.fromiter(map(len, rows), dtype=np.int64, count=len(rows)) - 1
    short = n < n_required
    if short.any():
        i = index[short]
        reasons = [
            f"{name} has {k} fields, at least {n_required} expected (a truncated sentence?)" for k in n[short]
        ]
        rejections.add(log.file[i], "too_few_fields", reasons, line=log.line[i])
        rows = [r for r, s in zip(rows, short) if not s]
        index = index[~short]
    pad = [""] * width
    rows = [r if len(r) >= width else r + pad[: width - len(r)] for r in rows]
    cols = list(zip(*rows))[:width] if rows else [()] * width
    return Columns(log, index, log.talker[index], cols)


def numbers(col) -> np.ndarray:
    """(K,) float64 of a column of texts; NaN where empty or not a finite number."""
    import pandas as pd

    if len(col) == 0:
        return np.zeros(0)
    v = pd.to_numeric(pd.Series(col, dtype=object), errors="coerce").to_numpy(dtype=np.float64)
    return np.where(np.isfinite(v), v, np.nan)


def text(col) -> np.ndarray:
    """(K,) object array of a column's texts, stripped and upper case."""
    return np.array([c.strip().upper() for c in col], dtype=object)


def time_of_day(col) -> np.ndarray:
    """Seconds since midnight UTC (K,) of ``hhmmss[.sss]`` fields; NaN where empty or not a time of
    day (hours 0-23, minutes 0-59, seconds below 61 for a leap second). The seconds are the nearest
    double to the decimal text (``120001.01`` gives 43201.01, not 43201.0100000000052)."""
    out = np.full(len(col), np.nan)
    for k, c in enumerate(col):
        head, _, frac = c.strip().partition(".")
        if len(head) != 6 or not head.isdigit() or not (frac.isdigit() or frac == ""):
            continue
        h, m, s = int(head[:2]), int(head[2:4]), int(head[4:])
        if h < 24 and m < 60 and s < 61:
            out[k] = float(f"{h * 3600 + m * 60 + s}.{frac or 0}")
    return out


def _angle(col, hemi, positive: str, negative: str, limit_deg: float) -> np.ndarray:
    """Radians of ``[d]ddmm.mmmm`` fields with their hemisphere letters; NaN where not valid."""
    v = numbers(col)
    d = np.floor(v / 100.0)
    minutes = v - 100.0 * d
    deg = d + minutes / 60.0
    h = text(hemi)
    sign = np.where(h == positive, 1.0, np.where(h == negative, -1.0, np.nan))
    ok = (v >= 0) & (minutes < 60.0) & (deg <= limit_deg)
    return np.where(ok, np.radians(sign * deg), np.nan)


def latitude(col, hemi) -> np.ndarray:
    """Latitude (K,) in radians of ``ddmm.mmmm`` and ``N``/``S``; NaN where not valid."""
    return _angle(col, hemi, "N", "S", 90.0)


def longitude(col, hemi) -> np.ndarray:
    """Longitude (K,) in radians of ``dddmm.mmmm`` and ``E``/``W``; NaN where not valid."""
    return _angle(col, hemi, "E", "W", 180.0)
