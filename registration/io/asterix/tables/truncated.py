"""The full time of day of CAT001 reports, whose I001/141 is truncated: the time of day modulo
512 s, in 1/128 s.

A CAT001 report's full time is built on a **base**, a full time of day that came before it in the
stream (the files in the order given, each in byte order):

1. the time (I002/030) of the last CAT002 service message (north marker, sector crossing, ...)
   of the same radar (SAC/SIC) before it;
2. without one, the last full time of day of any record before it (CAT048 I048/140, CAT034
   I034/030, CAT021, CAT002 of any radar): counted in the summary, since another source's clock
   may differ from the radar's;
3. without any, the report has no full time and is set aside (``no_full_time``).

The full time is the base plus the difference of the truncated parts, taken between -256 s and
+256 s (modulo 512 s): right for a report stamped within 256 s of its base, before or after it
(a radar sends a north marker every scan, 4 to 12 s; a report stamped just before the marker that
precedes it in the stream is placed before the marker, not 512 s later). A radar silent in
CAT002 for more than 256 s, or a base from a clock that differs by more than that, gives a time
off by a multiple of 512 s. The result is taken modulo 24 h, so a base just before midnight and a
report just after it give a time of day just after midnight (placed on the next day by
:mod:`registration.io.asterix.tables.timeofday`). The bases carry across the files of one import.
"""

from __future__ import annotations

from collections import Counter

import numpy as np

from registration.io.asterix.decode.decode001 import TRUNCATED_TOD_WRAP

__all__ = ["DAY_RAW", "BASE_NONE", "BASE_CAT002", "BASE_OTHER", "TruncatedClock"]

#: 24 h in 1/128 s.
DAY_RAW = 86400 * 128
#: ``time_base`` of a CAT001 record: no base, a CAT002 of its radar, another record.
BASE_NONE, BASE_CAT002, BASE_OTHER = 0, 1, 2
_SHIFT = np.int64(1) << np.int64(40)  # offsets are below 2^40 (the inputs are bounded well below)
_MIX = np.int64(0x2545F4914F6CDD1D)  # odd: spreads the full time over the record's digest


def _full_times(records: dict) -> tuple[np.ndarray, np.ndarray]:
    """(offsets, times of day in 1/128 s) of the records of ``records`` with a full, valid time of
    day, in stream order."""
    offsets, tods = [], []
    for cat, rec in records.items():
        if cat == 1 or rec.size == 0:
            continue
        f = rec.fields
        given = (f["time_item"] != "") if cat == 21 else f["has_140" if cat == 48 else "has_030"]
        ok = given & (f["tod"] < DAY_RAW)
        offsets.append(rec.offset[ok])
        tods.append(f["tod"][ok])
    if not offsets:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    offset, tod = np.concatenate(offsets), np.concatenate(tods)
    order = np.argsort(offset, kind="stable")
    return offset[order], tod[order].astype(np.int64)


def _last_before(keys: np.ndarray, query: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(index of the last key below each query, 0 where none; found) in ``keys`` sorted ascending."""
    idx = np.searchsorted(keys, query, side="left") - 1
    return np.maximum(idx, 0), idx >= 0


class TruncatedClock:
    """The bases of the CAT001 times, file after file (stream order), and the counts of the
    summary."""

    def __init__(self) -> None:
        self.by_source: dict[int, int] = {}  # SAC*256+SIC -> last CAT002 time of day (1/128 s)
        self.last_any: int | None = None
        self.counts: Counter = Counter()

    def place(self, records: dict) -> None:
        """Add to the CAT001 fields of one file's ``records`` (category -> CategoryRecords) ``tod``
        (full time of day, 1/128 s, 0 where none) and ``time_base`` (:data:`BASE_NONE`,
        :data:`BASE_CAT002`, :data:`BASE_OTHER`), and mix the full time into the records' digests
        (two plots of the same octets 512 s apart, a fixed clutter point say, are no duplicates);
        update the bases from the file's records."""
        rec1, rec2 = records.get(1), records.get(2)
        any_offset, any_tod = _full_times(records)
        if rec2 is not None and rec2.size:
            f = rec2.fields
            ok = f["has_010"] & f["has_030"] & (f["tod"] < DAY_RAW)
            src2, off2, tod2 = f["sac"][ok] * 256 + f["sic"][ok], rec2.offset[ok], f["tod"][ok]
        else:
            src2 = off2 = tod2 = np.zeros(0, dtype=np.int64)
        if rec1 is not None and rec1.size:
            self._place(rec1.fields, rec1.offset, (src2, off2, tod2), (any_offset, any_tod))
            if rec1.digest.size == rec1.size:  # the duplicates: same octets and same full time
                rec1.digest = rec1.digest ^ (rec1.fields["tod"].astype(np.int64) * _MIX)
        for s, t in zip(*(a.tolist() for a in self._last_per_source(src2, off2, tod2))):
            self.by_source[s] = t
        if any_tod.size:
            self.last_any = int(any_tod[-1])

    @staticmethod
    def _last_per_source(src: np.ndarray, offset: np.ndarray, tod: np.ndarray) -> tuple:
        order = np.lexsort((offset, src))
        src, tod = src[order], tod[order]
        last = np.concatenate([src[1:] != src[:-1], [True]]) if src.size else np.zeros(0, dtype=bool)
        return src[last], tod[last]

    def _place(self, f: dict, offset: np.ndarray, cat002: tuple, anything: tuple) -> None:
        src2, off2, tod2 = cat002
        carried = np.array(sorted(self.by_source), dtype=np.int64)
        keys = np.concatenate([carried * _SHIFT, src2 * _SHIFT + off2 + 1])
        before = np.array([self.by_source[s] for s in carried.tolist()], dtype=np.int64)
        values = np.concatenate([before, tod2])
        order = np.argsort(keys, kind="stable")
        keys, values = keys[order], values[order]
        src1 = f["sac"] * 256 + f["sic"]
        query = src1 * _SHIFT + offset + 1
        idx, found = _last_before(keys, query)
        same = found & f["has_010"]
        if keys.size:
            same &= keys[idx] // _SHIFT == src1  # the last key below is of the plot's own radar
        a_off, a_tod = anything
        if self.last_any is not None:
            a_off = np.concatenate([[-1], a_off])
            a_tod = np.concatenate([[self.last_any], a_tod])
        other, other_found = _last_before(a_off, offset)
        base = np.where(same, values[idx] if values.size else 0, a_tod[other] if a_tod.size else 0)
        kind = np.where(same, BASE_CAT002, np.where(other_found, BASE_OTHER, BASE_NONE))
        kind = np.where(f["has_141"], kind, BASE_NONE)
        half = TRUNCATED_TOD_WRAP // 2
        step = np.mod(f["ttod"] - base + half, TRUNCATED_TOD_WRAP) - half
        f["tod"] = np.where(kind > 0, np.mod(base + step, DAY_RAW), 0)
        f["time_base"] = kind
        plots = f["typ"] == 0
        for name, code in (("cat002", BASE_CAT002), ("other_category", BASE_OTHER), ("none", BASE_NONE)):
            self.counts[name] += int(((kind == code) & plots & f["has_141"]).sum())

    def summary(self) -> dict:
        """How the CAT001 plots with I001/141 got their full time: ``from_cat002`` (of their radar),
        ``from_other_category`` (no CAT002 of their radar before them: the last full time of any
        record), ``without_full_time`` (set aside)."""
        return {
            "from_cat002": self.counts["cat002"],
            "from_other_category": self.counts["other_category"],
            "without_full_time": self.counts["none"],
            "window_s": [-256.0, 256.0],
        }
