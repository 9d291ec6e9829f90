"""The platform's navigation table: one row per attitude sample, with the position interpolated to it.

* **Position**: the first of GGA, GNS, RMC with valid fixes, from its most frequent talker (one
  antenna); the ellipsoid height is the altitude above mean sea level plus the geoid separation
  (0 where a fix lacks it, noted). RMC alone has no height: 0 m, noted.
* **Attitude**: ``$PASHR`` (heading, pitch, roll, its own UTC time) if the log has it, else HDT,
  else THS (heading only: pitch and roll 0, a level ship, noted; their time is that of the
  navigation sentence before them, see :mod:`registration.io.nmea.clock`).
* **Rows** at the attitude times (10 Hz for a motion sensor), the positions (1 Hz or so)
  interpolated linearly to them (longitude unwrapped). An attitude sample without a fix within
  :data:`MAX_POSITION_GAP_S` on both sides is set aside (``outside_positions``): navigation is
  never extrapolated. A second sample at the same time is set aside (``duplicate_time``).

Heading at any time, for true TTM bearings: :meth:`Navigation.heading_at`, interpolated over all
valid attitude samples with the wrap at north, NaN across gaps above :data:`MAX_HEADING_GAP_S`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from registration.core.angles import wrap_angle
from registration.io.files.ledger import RejectedLedger
from registration.io.nmea.attitude import Attitude
from registration.io.nmea.clock import Clock
from registration.io.nmea.errors import NmeaImportError
from registration.io.nmea.fixes import Fixes
from registration.io.nmea.lines import SentenceLog

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["Navigation", "build_navigation", "MAX_POSITION_GAP_S", "MAX_HEADING_GAP_S", "interpolate_angle"]

#: Largest gap (s) between two position fixes that an attitude sample is interpolated across.
MAX_POSITION_GAP_S = 10.0
#: Largest gap (s) between two heading samples that a TTM bearing's heading is interpolated across.
MAX_HEADING_GAP_S = 5.0


@dataclass
class Navigation:
    """Rows (K,): ``time`` s, ``lat``, ``lon`` rad, ``alt`` m above the ellipsoid, ``heading``,
    ``pitch``, ``roll`` rad (as reported). ``sources``: the sentence type and talker of the
    positions and the attitude; ``sea_level``: the ellipsoid height of mean sea level (m, the
    median geoid separation of the fixes; 0 if none gave one); ``heading_time`` (H,),
    ``heading_unwrapped`` (H,): all valid heading samples, for :meth:`heading_at`."""

    time: np.ndarray
    lat: np.ndarray
    lon: np.ndarray
    alt: np.ndarray
    heading: np.ndarray
    pitch: np.ndarray
    roll: np.ndarray
    sources: dict
    sea_level: float
    heading_time: np.ndarray
    heading_unwrapped: np.ndarray
    notes: list[str] = field(default_factory=list)

    def heading_at(self, t: np.ndarray) -> np.ndarray:
        """Heading (K,) rad in (-pi, pi] at times ``t`` (K,) s; NaN outside the samples' span or
        across a gap above :data:`MAX_HEADING_GAP_S`."""
        return interpolate_angle(self.heading_time, self.heading_unwrapped, t, MAX_HEADING_GAP_S)

    def frame(self, platform: str) -> pd.DataFrame:
        """The navigation file table: ``time_s``, ``platform``, ``lat_deg``, ``lon_deg``, ``alt_m``,
        ``heading_deg`` [0, 360), ``pitch_deg``, ``roll_deg``."""
        import pandas as pd

        return pd.DataFrame(
            {
                "time_s": self.time,
                "platform": np.full(self.time.size, str(platform), dtype=object),
                "lat_deg": np.degrees(self.lat),
                "lon_deg": np.degrees(wrap_angle(self.lon)),
                "alt_m": self.alt,
                "heading_deg": np.mod(np.degrees(self.heading), 360.0),
                "pitch_deg": np.degrees(self.pitch),
                "roll_deg": np.degrees(self.roll),
            }
        )


def interpolate_angle(
    t_samples: np.ndarray, unwrapped: np.ndarray, t: np.ndarray, max_gap: float
) -> np.ndarray:
    """Linear interpolation of an unwrapped angle series (rad) at ``t``, wrapped to (-pi, pi]; NaN
    outside the span or where the bracketing samples are more than ``max_gap`` s apart."""
    t = np.asarray(t, dtype=np.float64)
    if t_samples.size == 0:
        return np.full(t.shape, np.nan)
    out = wrap_angle(np.interp(t, t_samples, unwrapped))
    return np.where(_bracketed(t_samples, t, max_gap), out, np.nan)


def _bracketed(t_samples: np.ndarray, t: np.ndarray, max_gap: float) -> np.ndarray:
    """(K,) bool: ``t`` lies within the samples' span with its two neighbours at most ``max_gap`` apart."""
    j = np.clip(np.searchsorted(t_samples, t, side="right"), 1, max(t_samples.size - 1, 1))
    inside = (t >= t_samples[0]) & (t <= t_samples[-1])
    if t_samples.size == 1:
        return inside
    return inside & (t_samples[j] - t_samples[j - 1] <= max_gap)


def _one_talker(sample) -> tuple:
    """The samples of the most frequent talker (one device), and that talker."""
    talkers, counts = np.unique(sample.talker.astype(str), return_counts=True)
    best = talkers[np.argmax(counts)]
    return sample.take(sample.talker.astype(str) == best), str(best)


def _sorted_unique(log: SentenceLog, index: np.ndarray, t: np.ndarray, rejections: RejectedLedger, what: str):
    """Order of the samples by time, without the second and later samples of one time (set aside)."""
    order = np.argsort(t, kind="stable")
    ts = t[order]
    dup = np.zeros(ts.size, bool)
    dup[1:] = ts[1:] == ts[:-1]
    i = index[order[dup]]
    rejections.add(log.file[i], "duplicate_time", f"a second {what} at the same time", line=log.line[i])
    return order[~dup]


def _positions(
    log: SentenceLog, clock: Clock, fixes: dict[str, Fixes], rejections: RejectedLedger, notes: list
):
    kind = next((k for k in ("GGA", "GNS", "RMC") if fixes[k].index.size), None)
    if kind is None:
        raise NmeaImportError("no valid position in the log: no GGA, GNS or RMC sentence with a valid fix")
    f, talker = _one_talker(fixes[kind])
    t = clock.place(f.index, f.tod)
    keep = _sorted_unique(log, f.index, t, rejections, f"{kind} fix")
    f, t = f.take(keep), t[keep]
    geoid = np.concatenate([fixes["GGA"].geoid, fixes["GNS"].geoid])
    geoid = geoid[np.isfinite(geoid)]
    sea_level = float(np.median(geoid)) if geoid.size else 0.0
    if kind == "RMC":
        alt = np.zeros(t.size)
        notes.append("positions from RMC, which has no height: alt 0 m above the ellipsoid")
    else:
        missing = np.isnan(f.geoid)
        if missing.any():
            notes.append(
                f"{int(missing.sum())} {kind} fixes without geoid separation: their altitude above mean "
                "sea level is used as the ellipsoid height (an error of the geoid height, tens of metres)"
            )
        alt = f.alt_msl + np.where(missing, 0.0, f.geoid)
    if not geoid.size:
        notes.append("no geoid separation in the log: mean sea level taken as the ellipsoid (AIS alt_m 0)")
    return t, f.lat, np.unwrap(f.lon), alt, f"{kind} ({talker})" if talker else kind, sea_level


def _attitude(
    log: SentenceLog, clock: Clock, attitudes: dict[str, Attitude], rejections: RejectedLedger, notes: list
):
    kind = next((k for k in ("PASHR", "HDT", "THS") if len(attitudes[k])), None)
    if kind is None:
        raise NmeaImportError(
            "no valid heading in the log: no $PASHR, HDT or THS sentence with a valid heading"
        )
    a, talker = _one_talker(attitudes[kind])
    if kind == "PASHR":
        t = clock.place(a.index, a.tod)
    else:
        t = clock.previous_anchor_time(a.index)
        bad = np.isnan(t)
        i = a.index[bad]
        rejections.add(
            log.file[i],
            "no_time",
            f"{kind} has no time field and no timed sentence before it",
            line=log.line[i],
        )
        a, t = a.take(~bad), t[~bad]
        a.pitch[:] = 0.0
        a.roll[:] = 0.0
        notes.append(
            f"no $PASHR attitude: heading from {kind}, pitch and roll 0 (a level ship); {kind} sentences "
            "have no time field and take the time of the navigation sentence before them"
        )
    keep = _sorted_unique(log, a.index, t, rejections, f"{kind} attitude")
    return a.take(keep), t[keep], f"{kind} ({talker})" if talker else kind


def build_navigation(
    log: SentenceLog,
    clock: Clock,
    fixes: dict[str, Fixes],
    attitudes: dict[str, Attitude],
    rejections: RejectedLedger,
) -> Navigation:
    """The :class:`Navigation` of the log; :class:`NmeaImportError` without a valid position or
    heading, or when no attitude sample lies among the positions."""
    notes: list[str] = []
    tp, lat, lon, alt, position_source, sea_level = _positions(log, clock, fixes, rejections, notes)
    a, ta, attitude_source = _attitude(log, clock, attitudes, rejections, notes)
    heading_unwrapped = np.unwrap(a.heading)
    inside = _bracketed(tp, ta, MAX_POSITION_GAP_S)
    i = a.index[~inside]
    rejections.add(
        log.file[i],
        "outside_positions",
        f"this attitude sample lacks a position fix within {MAX_POSITION_GAP_S:g} s before it or within "
        f"{MAX_POSITION_GAP_S:g} s after it (both are needed to interpolate the position)",
        line=log.line[i],
    )
    if not inside.any():
        raise NmeaImportError(
            f"no attitude sample ({attitude_source}, {ta.size} valid) lies within the position fixes "
            f"({position_source}, {tp.size} valid) to interpolate them: "
            "the two do not overlap in time"
        )
    t = ta[inside]
    nav = Navigation(
        t,
        np.interp(t, tp, lat),
        np.interp(t, tp, lon),
        np.interp(t, tp, alt),
        a.heading[inside],
        a.pitch[inside],
        a.roll[inside],
        {"position": position_source, "attitude": attitude_source},
        sea_level,
        ta,
        heading_unwrapped,
        notes,
    )
    return nav
