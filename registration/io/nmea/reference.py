"""AIS position reports -> reference positions of other vessels (``target`` = MMSI), with sigmas.

* **Messages**: 1, 2, 3 (class A), 18, 19 (class B) and 27 (long range) from ``!AIVDM``. Reports of
  ``!AIVDO`` (the own ship) are counted, never references; a ``!AIVDM`` of an MMSI seen in
  ``!AIVDO`` is set aside (``ais_own_ship``). Static messages 5, 19 and 24 give names.
* **Time**: the report's UTC second (0-59) within the minute of its reception time: the latest
  ``minute + second`` not more than :data:`CLOCK_TOLERANCE_S` after the reception time. A second
  of 60-63 means "not available", and message 27 has none: the reception time is used, with the
  latency's sigma (:class:`AisSigmas`).
* **Sigma** (m, per axis): ``sqrt(position^2 + (speed * time)^2)`` with the position sigma from
  the position-accuracy flag (1: better than 10 m, 0: worse), message 27's positions in 1/10 minute
  adding their quantisation (185.2 m / sqrt(12) in latitude), and the time sigma that of a time
  given to the whole second (1 s / sqrt(12)) or, without a second, the latency.
* **Height**: AIS has none, so a reference gives only the horizontal position (``sigma_up`` inf;
  ``alt`` is mean sea level, for display). The vessels are surface targets instead
  (:meth:`References.targets_frame`): they move on mean sea level, whose ellipsoid height is the
  own ship's geoid separation (GGA), with the sigma :attr:`AisSigmas.height_m` (10 m: the unknown
  height above the sea of the point the radar sees). A surface is one constraint per trajectory
  coefficient, not a measured value per report.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import TYPE_CHECKING

import numpy as np

from registration.io.files.ledger import RejectedLedger
from registration.io.nmea.ais import AisMessage
from registration.io.nmea.clock import Clock
from registration.io.nmea.lines import SentenceLog

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["AisSigmas", "References", "read_references", "CLOCK_TOLERANCE_S", "KNOT_MPS", "POSITION_TYPES"]

#: A report's ``minute + second`` may lie this far (s) after its reception time (receiver clock error).
CLOCK_TOLERANCE_S = 5.0
#: One knot in m/s.
KNOT_MPS = 1852.0 / 3600.0
#: AIS message types that report a position.
POSITION_TYPES = (1, 2, 3, 18, 19, 27)
_CLASS = {1: "A", 2: "A", 3: "A", 5: "A", 18: "B", 19: "B", 24: "B", 27: "long range"}


@dataclass(frozen=True)
class AisSigmas:
    """The sigma model of AIS reference positions (docs/howto/import-nmea.md, "AIS reference positions").

    ``high_accuracy_m`` (5 m): position sigma per axis with the accuracy flag 1 (better than 10 m,
    taken as 2 sigma); ``low_accuracy_m`` (10 m): flag 0 (worse than 10 m: an unaugmented GNSS);
    ``msg27_quantisation_m`` (53.5 m): message 27's 1/10 minute positions, 185.2 m / sqrt(12);
    ``time_resolution_s`` (1 s): the UTC second of the report, a uniform error of sigma
    ``time_resolution_s / sqrt(12)``; ``latency_s`` (2 s): the time sigma when the report has no
    second and its reception time stands for it; ``unknown_speed_mps`` (15 m/s, 29 knots): the
    speed used when the report has none; ``height_m`` (10 m): the sigma of an AIS vessel's height
    about mean sea level, the surface it moves on: the point the radar sees (the echo centre of the hull and
    superstructure) and the GNSS antenna lie metres to tens of metres above the sea, and the tide
    and the geoid's change from the own ship's position add a metre or two.
    """

    high_accuracy_m: float = 5.0
    low_accuracy_m: float = 10.0
    msg27_quantisation_m: float = 185.2 / math.sqrt(12.0)
    time_resolution_s: float = 1.0
    latency_s: float = 2.0
    unknown_speed_mps: float = 15.0
    height_m: float = 10.0

    def __post_init__(self) -> None:
        for f in fields(self):
            v = getattr(self, f.name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v >= 0):
                raise ValueError(f"AisSigmas.{f.name}: expected a finite number >= 0, got {v!r}")
        if not self.height_m > 0:
            raise ValueError(f"AisSigmas.height_m: expected a vertical sigma > 0 m, got {self.height_m!r}")


@dataclass
class References:
    """AIS reference positions (K,): ``time`` s, ``target`` (MMSI text), ``lat``, ``lon`` rad, ``alt``
    m (mean sea level), ``sigma`` m per horizontal axis (east, north), ``sigma_up`` m along the local up
    (inf: AIS gives no height); ``vessels``: MMSI -> what the log says of it (name, call sign, class,
    positions); ``own``: the own ship's MMSIs and its ``!AIVDO`` messages per type; ``sea_level``: the
    ellipsoid height (m) of mean sea level; ``surface_sigma``: the sigma (m) of a vessel's height
    about it; ``index`` (K,) the position in the :class:`~registration.io.nmea.lines.SentenceLog`
    of each report's first sentence."""

    time: np.ndarray
    target: np.ndarray
    lat: np.ndarray
    lon: np.ndarray
    alt: np.ndarray
    sigma: np.ndarray
    sigma_up: np.ndarray
    vessels: dict
    own: dict
    sea_level: float = 0.0
    surface_sigma: float = 10.0
    index: np.ndarray | None = None

    def frame(self) -> pd.DataFrame:
        """The reference file table: ``time_s``, ``target``, ``lat_deg``, ``lon_deg``, ``alt_m``, ``sigma_m``,
        ``sigma_up_m``."""
        import pandas as pd

        return pd.DataFrame(
            {
                "time_s": self.time,
                "target": self.target,
                "lat_deg": np.degrees(self.lat),
                "lon_deg": np.degrees(self.lon),
                "alt_m": self.alt,
                "sigma_m": self.sigma,
                "sigma_up_m": self.sigma_up,
            }
        )

    def targets_frame(self) -> pd.DataFrame:
        """The targets file table of the vessels with reference positions: ``target`` (MMSI), ``name``
        (from messages 5, 19, 24; empty if none), ``surface_alt_m`` (mean sea level above the
        ellipsoid), ``sigma_surface_m``."""
        import pandas as pd

        mmsi = [m for m, v in self.vessels.items() if v["positions"] > 0]
        return pd.DataFrame(
            {
                "target": mmsi,
                "name": [self.vessels[m]["name"] or "" for m in mmsi],
                "surface_alt_m": np.full(len(mmsi), float(self.sea_level)),
                "sigma_surface_m": np.full(len(mmsi), float(self.surface_sigma)),
            }
        )


def _vessel(vessels: dict, mmsi: str) -> dict:
    return vessels.setdefault(
        mmsi, {"mmsi": mmsi, "name": None, "callsign": None, "class": None, "positions": 0, "messages": {}}
    )


def _static(v: dict, data) -> None:
    """Names and class from messages 5, 19, 24 (and the class of any message)."""
    t = int(data.msg_type)
    v["messages"][str(t)] = v["messages"].get(str(t), 0) + 1
    v["class"] = v["class"] or _CLASS.get(t)
    name = getattr(data, "shipname", None)
    if name and str(name).strip(" @"):
        v["name"] = str(name).strip(" @")
    call = getattr(data, "callsign", None)
    if call and str(call).strip(" @"):
        v["callsign"] = str(call).strip(" @")


def _sigma(data, s: AisSigmas, timed: bool) -> float:
    t = int(data.msg_type)
    pos = s.high_accuracy_m if bool(getattr(data, "accuracy", False)) else s.low_accuracy_m
    if t == 27:
        pos = math.hypot(pos, s.msg27_quantisation_m)
    speed = getattr(data, "speed", None)
    unavailable = 63.0 if t == 27 else 102.3
    v = s.unknown_speed_mps if speed is None or float(speed) >= unavailable else float(speed) * KNOT_MPS
    dt = s.time_resolution_s / math.sqrt(12.0) if timed else s.latency_s
    return math.hypot(pos, v * dt)


def _second(data) -> float:
    """The report's UTC second (NaN for message 27, which has none, or when missing)."""
    second = getattr(data, "second", None)
    return float(second) if second is not None and int(data.msg_type) != 27 else np.nan


def _position_time(clock: Clock, received: np.ndarray, second: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(time_s, timed) of reports received at unix ``received`` with UTC ``second`` (NaN: none)."""
    recv = clock.from_unix(received)
    timed = (second >= 0) & (second <= 59)
    t = np.floor(recv / 60.0) * 60.0 + np.where(timed, second, 0.0)
    t = np.where(t > recv + CLOCK_TOLERANCE_S, t - 60.0, t)
    return np.where(timed, t, recv), timed


def _reports(
    log: SentenceLog, messages: list[AisMessage], vessels: dict, own: dict, rejections: RejectedLedger
) -> list:
    """The position reports of other vessels as (message, mmsi, lat deg, lon deg); own ship's counted."""
    own_mmsi = {str(m.data.mmsi) for m in messages if m.own}
    own["mmsi"] = sorted(own_mmsi)
    out = []
    for m in messages:
        t = int(m.data.msg_type)
        if m.own:
            own["messages"][str(t)] = own["messages"].get(str(t), 0) + 1
            continue
        mmsi = str(m.data.mmsi)
        i = m.parts[0]
        if mmsi in own_mmsi:
            if t in POSITION_TYPES:
                rejections.add(
                    log.file[i], "ais_own_ship", f"MMSI {mmsi} is the own ship's (!AIVDO)", line=log.line[i]
                )
            continue
        _static(_vessel(vessels, mmsi), m.data)
        if t not in POSITION_TYPES:
            continue
        lat, lon = getattr(m.data, "lat", None), getattr(m.data, "lon", None)
        if lat is None or lon is None or not (abs(float(lat)) <= 90.0 and abs(float(lon)) <= 180.0):
            rejections.add(
                log.file[i],
                "ais_no_position",
                f"AIS message {t} of MMSI {mmsi}: position not available ({lat}, {lon})",
                line=log.line[i],
            )
            continue
        out.append((m, mmsi, float(lat), float(lon)))
    return out


def read_references(
    log: SentenceLog,
    messages: list[AisMessage],
    clock: Clock,
    sea_level: float,
    sigmas: AisSigmas,
    rejections: RejectedLedger,
) -> References:
    """The reference positions of the AIS messages (see the module's text); ``sea_level``: the
    ellipsoid height (m) of mean sea level."""
    vessels: dict = {}
    own: dict = {"mmsi": [], "messages": {}}
    reports = _reports(log, messages, vessels, own, rejections)
    first = np.array([m.parts[0] for m, *_ in reports], dtype=np.int64)
    received = np.array([m.received for m, *_ in reports], dtype=np.float64)
    second = np.array([_second(m.data) for m, *_ in reports], dtype=np.float64)
    time, timed = _position_time(clock, received, second)
    no_time = np.isnan(received)
    rejections.add(
        log.file[first[no_time]],
        "ais_no_time",
        "AIS position without a reception time (no tag block c: and no timestamp prefix)",
        line=log.line[first[no_time]],
    )
    no_date = np.isnan(time) & ~no_time
    rejections.add(
        log.file[first[no_date]],
        "no_date",
        "the log gives no date to place the AIS reception time",
        line=log.line[first[no_date]],
    )
    bad = no_time | no_date
    mmsi = np.array([r[1] for r in reports], dtype=object)
    lat = np.array([r[2] for r in reports], dtype=np.float64)
    lon = np.array([r[3] for r in reports], dtype=np.float64)
    sigma = np.array(
        [_sigma(m.data, sigmas, bool(k)) for (m, *_), k in zip(reports, timed)], dtype=np.float64
    )
    keep = np.flatnonzero(~bad)
    seen: set = set()
    repeated = []
    for k in keep:
        key = (mmsi[k], time[k], lat[k], lon[k])
        repeated.append(key in seen)
        seen.add(key)
    dup = np.array(repeated, dtype=bool)
    rejections.add(
        log.file[first[keep[dup]]],
        "ais_duplicate",
        "the same AIS report (MMSI, time, position) received again",
        line=log.line[first[keep[dup]]],
    )
    keep = keep[~dup]
    for k in keep:
        vessels[mmsi[k]]["positions"] += 1
    return References(
        time[keep],
        mmsi[keep],
        np.radians(lat[keep]),
        np.radians(lon[keep]),
        np.full(keep.size, float(sea_level)),
        sigma[keep],
        np.full(keep.size, np.inf),
        vessels,
        own,
        float(sea_level),
        float(sigmas.height_m),
        first[keep],
    )
