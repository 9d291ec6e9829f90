"""TTM (tracked target message) -> plots of range and deck bearing.

``$RATTM,nn,distance,bearing,T|R,speed,course,T|R,CPA,TCPA,K|N|S,name,status,reference,hhmmss.ss,A|M*hh``

* ``range_m``: the distance in its unit: N nautical miles (1852 m), K kilometres (1000 m), S
  statute miles (1609.344 m).
* ``bearing_deg``: the deck bearing (from the bow, starboard positive, (-180, 180]). A relative
  bearing (R, clockwise from the bow) is one already. A true bearing (T, clockwise from true
  north) is made relative by subtracting the heading the navigation reports at the TTM's time
  (interpolated, across north by the shortest way): ``q = wrap(b_true - heading(t))``. The radar
  made it true with its own heading at its own time, so this undoes it exactly when the radar used
  the heading this log reports; with another gyro, the difference of the two gyros becomes part
  of the bearing bias that registration estimates.
* ``time_s``: the TTM's own UTC time field (the radar's clock: its offset is the sensor's time
  bias). A TTM without that field (NMEA before 3.0) is set aside (``no_time``): its time is never
  guessed.
* ``track``: the target number, a sensor-local id (``"07"`` -> ``"7"``).
* Status L (lost) is set aside, Q (in acquisition) too unless ``keep_acquiring``.
* ``sensor``: the sensor whose ``talker`` is the TTM's talker; without a talker column, the
  platform's only sensor.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from registration.core.angles import wrap_angle
from registration.io.files.ledger import RejectedLedger
from registration.io.nmea.clock import Clock
from registration.io.nmea.fields import Columns, columns, numbers, text, time_of_day
from registration.io.nmea.lines import SentenceLog
from registration.io.nmea.navigation import Navigation

if TYPE_CHECKING:
    import pandas as pd

__all__ = [
    "Plots",
    "read_ttm",
    "value_problems",
    "DISTANCE_UNITS_M",
    "MAX_RANGE_M",
    "TTM_FIELDS",
    "TTM_MIN_FIELDS",
]

#: Largest TTM range (m) taken as a measurement (a radar's horizon is far below it).
MAX_RANGE_M = 1e6
#: TTM distance unit letter -> metres.
DISTANCE_UNITS_M = {"N": 1852.0, "K": 1000.0, "S": 1609.344}


@dataclass
class Plots:
    """TTM plots (K,): ``time`` s, ``sensor``, ``track`` (ids), ``range`` m, ``bearing`` rad (deck,
    (-pi, pi]); ``reference`` (K,) the TTM's bearing reference (T or R); ``unit`` (K,) its distance
    unit letter; ``status`` (K,) T or Q; ``index`` (K,) the TTM's position in the
    :class:`~registration.io.nmea.lines.SentenceLog`."""

    time: np.ndarray
    sensor: np.ndarray
    track: np.ndarray
    range: np.ndarray
    bearing: np.ndarray
    reference: np.ndarray
    unit: np.ndarray
    status: np.ndarray
    index: np.ndarray | None = None

    def frame(self) -> pd.DataFrame:
        """The plots file table: ``time_s``, ``sensor``, ``track``, ``range_m``, ``bearing_deg``."""
        import pandas as pd

        return pd.DataFrame(
            {
                "time_s": self.time,
                "sensor": self.sensor,
                "track": self.track,
                "range_m": self.range,
                "bearing_deg": np.degrees(self.bearing),
            }
        )


def _track_ids(col) -> np.ndarray:
    """Target numbers as ids: digits without leading zeros, other text stripped."""
    out = []
    for c in col:
        c = c.strip()
        out.append(str(int(c)) if c.isdigit() else c)
    return np.array(out, dtype=object)


def _sensors(c: Columns, talkers: dict[str, str], only: str | None, rejections: RejectedLedger):
    """The sensor of each TTM by its talker (or the platform's only sensor); others set aside."""
    talker = c.talker.astype(str)
    sensor = np.array([talkers.get(t, only) for t in talker], dtype=object)
    bad = np.array([s is None for s in sensor], dtype=bool)
    known = sorted(talkers) if talkers else []
    c = c.reject(
        bad,
        rejections,
        "ttm_no_sensor",
        [
            f"TTM talker {t!r} names no sensor of the platform (talkers in the sensors table: {known})"
            for t in talker
        ],
    )
    return c, sensor[~bad]


def _status(c: Columns, sensor: np.ndarray, keep_acquiring: bool, rejections: RejectedLedger):
    status = text(c.cols[12])
    tests = (
        ("ttm_lost", lambda s: s == "L"),
        ("ttm_acquiring", lambda s: (s == "Q") & (not keep_acquiring)),
        ("ttm_status", lambda s: ~np.isin(s, ["T", "Q", "L"])),
    )
    for code, test in tests:
        bad = test(status)
        c = c.reject(bad, rejections, code, [f"TTM target status {s!r}" for s in status])
        status, sensor = status[~bad], sensor[~bad]
    return c, sensor, status


#: Position of each TTM field the importer reads (position 0 is the address, ``RATTM``).
TTM_FIELDS = {"number": 1, "distance": 2, "bearing": 3, "reference": 4, "unit": 10, "status": 12, "time": 14}
#: Fields a TTM must have, the address not counted (the rest, up to the time, may be missing).
TTM_MIN_FIELDS = 12


def value_problems(number, distance: np.ndarray, bearing: np.ndarray, unit, reference) -> np.ndarray:
    """(K,) the reason, naming the field, why each TTM's values cannot be read ('' where they can):
    ``number`` the target number texts, ``distance`` and ``bearing`` (deg) the numbers
    (:func:`~registration.io.nmea.fields.numbers`), ``unit`` and ``reference`` the letters
    (:func:`~registration.io.nmea.fields.text`). The first check failed gives the reason."""
    factor = np.array([DISTANCE_UNITS_M.get(u, np.nan) for u in unit])
    with np.errstate(over="ignore", invalid="ignore"):
        too_far = distance * np.nan_to_num(factor, nan=1.0) > MAX_RANGE_M
    far = f"TTM distance empty, not a number, not positive or beyond {MAX_RANGE_M:g} m"
    checks = (
        (~(distance > 0) | too_far, far),
        (np.isnan(factor), "TTM distance unit is not K, N or S"),
        (~((bearing >= 0) & (bearing <= 360)), "TTM bearing empty, not a number or outside [0, 360] deg"),
        (~np.isin(reference, ["T", "R"]), "TTM bearing reference is not T (true) or R (relative)"),
        (np.array([not v.strip() for v in number], dtype=bool), "TTM target number is empty"),
    )
    reasons = np.full(len(unit), "", dtype=object)
    for b, why in checks[::-1]:  # the first check's reason wins
        reasons[b] = why
    return reasons


def _values(c: Columns, rejections: RejectedLedger):
    """(the TTMs with valid values, their kept mask, range m, bearing rad as given, unit, reference)."""
    f = TTM_FIELDS
    distance, bearing = numbers(c.cols[f["distance"]]), numbers(c.cols[f["bearing"]])
    unit, ref = text(c.cols[f["unit"]]), text(c.cols[f["reference"]])
    reasons = value_problems(c.cols[f["number"]], distance, bearing, unit, ref)
    bad = reasons != ""
    keep = ~bad
    c = c.reject(bad, rejections, "bad_field", reasons)
    factor = np.array([DISTANCE_UNITS_M.get(u, np.nan) for u in unit[keep]])
    return c, keep, distance[keep] * factor, np.radians(bearing[keep]), unit[keep], ref[keep]


def read_ttm(
    log: SentenceLog,
    clock: Clock,
    nav: Navigation,
    talkers: dict[str, str],
    only: str | None,
    keep_acquiring: bool,
    rejections: RejectedLedger,
) -> Plots:
    """The plots of the log's TTM sentences (see the module's text). ``talkers``: talker -> sensor;
    ``only``: the sensor of TTMs whose talker is not in ``talkers`` (the platform's only sensor),
    None to set those aside."""
    c = columns(log, log.where("TTM"), TTM_MIN_FIELDS, 16, rejections, "TTM")
    c, sensor = _sensors(c, talkers, only, rejections)
    c, sensor, status = _status(c, sensor, keep_acquiring, rejections)
    no_time = np.array([v.strip() == "" for v in c.cols[14]], dtype=bool)
    c = c.reject(
        no_time, rejections, "no_time", "TTM without a UTC time field (field 14): its time is not guessed"
    )
    sensor, status = sensor[~no_time], status[~no_time]
    tod = time_of_day(c.cols[14])
    bad = np.isnan(tod)
    c = c.reject(bad, rejections, "bad_time", [f"TTM UTC time {v!r} is not hhmmss[.ss]" for v in c.cols[14]])
    tod, sensor, status = tod[~bad], sensor[~bad], status[~bad]
    c, keep, rng, q, unit, ref = _values(c, rejections)
    tod, sensor, status = tod[keep], sensor[keep], status[keep]
    time = clock.place(c.index, tod)
    true = ref == "T"
    heading = nav.heading_at(time[true])
    q[true] = q[true] - heading  # true -> deck bearing
    no_heading = np.zeros(len(c), bool)
    no_heading[true] = np.isnan(heading)
    c = c.reject(
        no_heading,
        rejections,
        "ttm_no_heading",
        "true TTM bearing at a time without heading samples around it to make it relative",
    )
    keep = ~no_heading
    time, sensor, status, rng, q, unit, ref = (a[keep] for a in (time, sensor, status, rng, q, unit, ref))
    track = _track_ids(c.cols[1])
    dup = _duplicates(time, sensor, track)
    c = c.reject(
        dup, rejections, "duplicate_time", "a second TTM of the same sensor and track at the same time"
    )
    keep = ~dup
    return Plots(
        time[keep],
        sensor[keep],
        track[keep],
        rng[keep],
        wrap_angle(q[keep]),
        ref[keep],
        unit[keep],
        status[keep],
        c.index,
    )


def _duplicates(time: np.ndarray, sensor: np.ndarray, track: np.ndarray) -> np.ndarray:
    """(K,) bool: a row whose (sensor, track, time) an earlier row has."""
    import pandas as pd

    return pd.DataFrame({"t": time, "s": sensor, "k": track}).duplicated().to_numpy()
