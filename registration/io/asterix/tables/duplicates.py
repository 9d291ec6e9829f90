"""Duplicated records and time going back, across the files of one import.

A record is a **duplicate** when a record of the same category with the same octets (so the same
SAC/SIC and time of day) came earlier in the stream on the same day of the time axis: a feed
recorded twice (the A and B LANs of a radar network: two UDP ports or two source addresses in one
capture, or two files) or a recording whose tail replays its beginning. Duplicates are set aside
(reason ``duplicate``) before any other rule, so that every report counts once in the solve, and
counted per data source, per file and per UDP destination port (captures) in the summary.
``keep_duplicates`` turns this off.

**Time going back**: in stream order, a record of a data source (category, SAC/SIC) whose time
lies more than :data:`BACK_STEP_S` before the latest time of that source so far (a replayed tail,
a recorder restart); counted per source with the largest step, and noted in the summary.
"""

from __future__ import annotations

from collections import Counter

import numpy as np

from registration.io.asterix.decode.reader import CategoryRecords
from registration.io.asterix.tables.timeofday import DAY_S

__all__ = ["BACK_STEP_S", "StreamChecks"]

#: A time more than this (s) before the latest of its source counts as time going back (CAT021
#: reports and sector messages may arrive a little out of order).
BACK_STEP_S = 10.0
_NO_DAY = np.int64(0x5BD1E995)


def _has_source(fields: dict) -> np.ndarray:
    """(R,) bool: the record gives its data source (I0xx/010)."""
    return fields.get("has_010", np.ones(fields["sac"].size, dtype=bool))


class StreamChecks:
    """The duplicates and backward time steps of one import, file after file (stream order)."""

    def __init__(self, keep_duplicates: bool = False, horizon_s: float | None = None) -> None:
        """``horizon_s``: remember records for this long (s of the time axis) only, so that a
        stream that never ends holds bounded memory (a live service); None: the whole import."""
        self.keep = keep_duplicates
        self.horizon_s = horizon_s
        self.seen: dict[int, np.ndarray] = {}
        self.seen_time: dict[int, np.ndarray] = {}
        self.by_source: Counter = Counter()
        self.by_file: Counter = Counter()
        self.by_port: Counter = Counter()
        self.latest: dict[tuple, float] = {}
        self.back: dict[tuple, list] = {}

    def duplicates(self, path: str, cat: int, rec: CategoryRecords, times: np.ndarray) -> np.ndarray:
        """(R,) bool: the records of ``rec`` (category ``cat``, in stream order; ``times`` on the
        time axis) that repeat an earlier one; counted. All False with ``keep_duplicates``."""
        if self.keep or rec.size == 0 or rec.digest.size != rec.size:
            return np.zeros(rec.size, dtype=bool)
        day = np.where(np.isfinite(times), np.floor(np.nan_to_num(times) / DAY_S), 0).astype(np.int64)
        key = rec.digest ^ (
            np.where(np.isfinite(times), day, _NO_DAY) * np.int64(0x9E3779B97F4A7C15 - (1 << 64))
        )
        _, first = np.unique(key, return_index=True)
        dup = np.ones(rec.size, dtype=bool)
        dup[first] = False
        earlier = self.seen.get(cat, np.zeros(0, dtype=np.int64))
        dup |= np.isin(key, earlier)
        if self.horizon_s is None:
            self.seen[cat] = np.union1d(earlier, key)
        else:
            self._remember(cat, key[~dup], times[~dup])
        if dup.any():
            f = rec.fields
            src = np.where(_has_source(f)[dup], f["sac"][dup] * 256 + f["sic"][dup], -1)
            for p, n in zip(*[a.tolist() for a in np.unique(src, return_counts=True)]):
                self.by_source[(cat, p >> 8, p & 0xFF) if p >= 0 else (cat, None, None)] += n
            self.by_file[path] += int(dup.sum())
            if rec.port.size == rec.size:
                for port, n in zip(*[a.tolist() for a in np.unique(rec.port[dup], return_counts=True)]):
                    self.by_port[port] += n
        return dup

    def _remember(self, cat: int, key: np.ndarray, times: np.ndarray) -> None:
        """Keep the keys of the last ``horizon_s`` seconds (a record without time: the latest)."""
        keys = np.concatenate([self.seen.get(cat, np.zeros(0, dtype=np.int64)), key])
        previous = self.seen_time.get(cat, np.zeros(0))
        latest = float(np.nanmax(np.concatenate([previous, times]), initial=-np.inf))
        t = np.concatenate([previous, np.where(np.isfinite(times), times, latest)])
        keep = t >= latest - float(self.horizon_s or 0.0)
        self.seen[cat], self.seen_time[cat] = keys[keep], t[keep]

    def time_steps(self, path: str, cat: int, rec: CategoryRecords, times: np.ndarray) -> None:
        """Count the records whose time lies more than :data:`BACK_STEP_S` before the latest of
        their source so far (stream order)."""
        f = rec.fields
        ok = np.isfinite(times) & _has_source(f) if rec.size else np.zeros(0, dtype=bool)
        src = f["sac"][ok] * 256 + f["sic"][ok] if rec.size else np.zeros(0, dtype=np.int64)
        t, offsets = times[ok], rec.offset[ok]
        for p in np.unique(src).tolist():
            mine = src == p
            key = (cat, p >> 8, p & 0xFF)
            ts = t[mine]
            before = np.maximum.accumulate(np.concatenate([[self.latest.get(key, -np.inf)], ts]))[:-1]
            step = before - ts
            back = np.flatnonzero(step > BACK_STEP_S)
            if back.size:
                entry = self.back.setdefault(key, [0, 0.0, path, int(offsets[mine][back[0]])])
                entry[0] += int(back.size)
                entry[1] = max(entry[1], float(step[back].max()))
            self.latest[key] = float(max(self.latest.get(key, -np.inf), ts.max()))

    def summary(self) -> dict:
        """``duplicates`` (records, by source, by file, kept or not) when there were any or they
        were kept, and ``time_going_back`` when time went back (an import of a clean recording
        gives neither)."""
        out = {
            "duplicates": {
                "records": int(sum(self.by_source.values())),
                "set_aside": not self.keep,
                "by_source": [
                    {"category": f"{c:03d}", "sac": s, "sic": i, "records": n}
                    for (c, s, i), n in sorted(self.by_source.items(), key=lambda kv: (-kv[1], str(kv[0])))
                ],
                "by_file": [{"file": p, "records": n} for p, n in self.by_file.items()],
                "by_port": [{"port": p, "records": n} for p, n in sorted(self.by_port.items()) if p],
            },
            "time_going_back": [
                {
                    "category": f"{c:03d}",
                    "sac": s,
                    "sic": i,
                    "records": e[0],
                    "largest_step_s": round(e[1], 3),
                    "first_file": e[2],
                    "first_offset": e[3],
                }
                for (c, s, i), e in sorted(self.back.items())
            ],
        }
        if not self.by_source and not self.keep:
            del out["duplicates"]
        if not self.back:
            del out["time_going_back"]
        return out
