"""The import's summary: a JSON-able dict of what the log held and what became of it (counts per
sentence type and talker, the sources used, the time span, the vessels seen with their names,
the lines set aside per reason, notes)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.io.files.ledger import RejectedLedger
from registration.io.nmea.clock import Clock
from registration.io.nmea.lines import SentenceLog
from registration.io.nmea.navigation import Navigation
from registration.io.nmea.reference import References
from registration.io.nmea.ttm import Plots

__all__ = ["ImportParts", "build_summary", "sentence_counts"]


@dataclass
class ImportParts:
    """What :func:`build_summary` reports on."""

    log: SentenceLog
    clock: Clock
    navigation: Navigation
    plots: Plots
    references: References
    rejections: RejectedLedger
    not_used: dict
    ais_messages: int


def sentence_counts(log: SentenceLog) -> dict:
    """Sentences with a correct checksum per type, then per talker (``-`` for proprietary ones)."""
    out: dict = {}
    if not len(log.sentence):
        return out
    pairs = np.char.add(np.char.add(log.kind.astype(str), "\t"), log.talker.astype(str))
    keys, counts = np.unique(pairs, return_counts=True)
    for key, n in zip(keys, counts):
        kind, talker = str(key).split("\t")
        out.setdefault(kind, {})[talker or "-"] = int(n)
    return dict(sorted(out.items()))


def _span(clock: Clock, t: np.ndarray) -> dict | None:
    if t.size == 0:
        return None
    lo, hi = float(np.min(t)), float(np.max(t))
    return {"start_s": lo, "end_s": hi, "start_utc": clock.utc(lo), "end_utc": clock.utc(hi)}


def _counts(values: np.ndarray) -> dict:
    keys, n = np.unique(np.asarray(values).astype(str), return_counts=True)
    return {str(k): int(v) for k, v in zip(keys, n)}


def _plots(p: Plots) -> dict:
    per_sensor = {}
    for s in sorted(set(p.sensor.astype(str))):
        mine = p.sensor.astype(str) == s
        per_sensor[s] = {"plots": int(mine.sum()), "tracks": int(np.unique(p.track[mine].astype(str)).size)}
    return {
        "rows": int(p.time.size),
        "per_sensor": per_sensor,
        "bearing_reference": _counts(p.reference),
        "distance_unit": _counts(p.unit),
        "status": _counts(p.status),
    }


def _vessels(r: References) -> list[dict]:
    out = []
    for mmsi in sorted(r.vessels):
        v = dict(r.vessels[mmsi])
        mine = r.time[r.target == mmsi]
        v["first_s"] = float(mine.min()) if mine.size else None
        v["last_s"] = float(mine.max()) if mine.size else None
        out.append(v)
    return out


def build_summary(parts: ImportParts) -> dict:
    """The summary dict (every value a JSON type)."""
    nav, clock, r = parts.navigation, parts.clock, parts.references
    times = [a for a in (nav.time, parts.plots.time, r.time) if a.size]
    return {
        "files": list(parts.log.files),
        "lines": int(parts.log.lines),
        "blank_lines": int(parts.log.blank_lines),
        "sentences": sentence_counts(parts.log),
        "not_used": dict(sorted(parts.not_used.items())),
        "date": {"origin": clock.origin_date(), "source": clock.date_source},
        "time_span": {
            "all": _span(clock, np.concatenate(times)) if times else None,
            "navigation": _span(clock, nav.time),
            "plots": _span(clock, parts.plots.time),
            "reference": _span(clock, r.time),
        },
        "navigation": {
            "rows": int(nav.time.size),
            "position": nav.sources["position"],
            "attitude": nav.sources["attitude"],
            "sea_level_m": float(nav.sea_level),
        },
        "plots": _plots(parts.plots),
        "ais": {
            "messages": int(parts.ais_messages),
            "reference_positions": int(r.time.size),
            "vessels": _vessels(r),
            "own_ship": {"mmsi": list(r.own["mmsi"]), "messages": dict(r.own["messages"])},
        },
        "rejected": {"lines": parts.rejections.count(), "by_reason": parts.rejections.by_code()},
        "notes": list(clock.notes) + list(nav.notes),
    }
