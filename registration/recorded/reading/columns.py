"""The columns of the files ``registration register`` reads and writes, with their units.

Files carry their units in the column names (``a_lat_deg``, ``a_range_m``, ``time_s``); the
Python data contract (:data:`registration.online.contract.DATA_COLUMNS`) is in SI units and
radians. A :class:`Field` ties the two together. Forms read:

* a **synchronous table**: ``time_s`` and, for each prefix ``a_`` and ``b_``, the navigation,
  attitude and plot of that radar (:data:`SYNC_FIELDS`, :data:`SYNC_COLUMNS`);
* a **per-sensor plot file** (asynchronous form): ``time_s``, ``range_m``, ``bearing_deg``,
  ``elevation_deg`` (:data:`PLOT_FIELDS`) and optionally the ship's navigation
  (:data:`NAV_FIELDS`); the names may carry the radar's prefix (``a_range_m``);
* a **navigation file**: ``time_s`` and the prefixed navigation columns of one or both ships.

Outputs: :data:`ESTIMATE_COLUMNS`, :data:`POSITION_COLUMNS`, :data:`REJECTED_COLUMNS`,
:data:`UNPAIRED_COLUMNS`, :data:`PAIRED_COLUMNS`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.online.contract import DATA_COLUMNS, IS_ANGLE, SENSOR_COLUMNS, STATE_NAMES

__all__ = [
    "Field",
    "TIME_FIELD",
    "NAV_KINDS",
    "PLOT_KINDS",
    "sensor_fields",
    "SYNC_FIELDS",
    "SYNC_COLUMNS",
    "PLOT_FIELDS",
    "NAV_FIELDS",
    "ESTIMATE_COLUMNS",
    "POSITION_COLUMNS",
    "REJECTED_COLUMNS",
    "UNPAIRED_COLUMNS",
    "PAIRED_COLUMNS",
]

_UNIT = {
    "lat": "deg",
    "lon": "deg",
    "alt": "m",
    "heading": "deg",
    "pitch": "deg",
    "roll": "deg",
    "range": "m",
    "bearing": "deg",
    "elevation": "deg",
}
_MEANING = {
    "lat": "geodetic latitude of the radar antenna (WGS-84), north positive",
    "lon": "geodetic longitude of the radar antenna, east positive",
    "alt": "antenna height above the WGS-84 ellipsoid",
    "heading": "measured ship heading, clockwise from true north",
    "pitch": "measured ship pitch (bow up positive)",
    "roll": "measured ship roll (starboard down positive)",
    "range": "measured slant range to the target (> 0)",
    "bearing": "measured target bearing in the deck frame, clockwise from the bow",
    "elevation": "measured target elevation above the deck plane",
}
#: Column kinds of a ship's navigation and of a radar's plot.
NAV_KINDS = SENSOR_COLUMNS[:6]
PLOT_KINDS = SENSOR_COLUMNS[6:]


@dataclass(frozen=True)
class Field:
    """One file column: its name in the file, the contract column and the scale to SI."""

    file_name: str  # e.g. "a_lat_deg"
    kind: str  # "time" or one of SENSOR_COLUMNS
    prefix: str  # "a", "b" or "" (unprefixed)
    unit: str  # "s", "deg" or "m"

    @property
    def contract_name(self) -> str:
        return "time" if self.kind == "time" else f"{self.prefix}_{self.kind}"

    @property
    def scale(self) -> float:
        """Multiply a file value by this to get SI units / radians."""
        return np.pi / 180 if self.unit == "deg" else 1.0

    @property
    def meaning(self) -> str:
        return (
            "timestamp, seconds (any epoch; strictly increasing)"
            if self.kind == "time"
            else _MEANING[self.kind]
        )


TIME_FIELD = Field("time_s", "time", "", "s")


def sensor_fields(prefix: str, kinds=SENSOR_COLUMNS) -> tuple[Field, ...]:
    """Fields of one sensor; ``prefix`` '' gives the unprefixed names (``range_m``)."""
    lead = f"{prefix}_" if prefix else ""
    return tuple(Field(f"{lead}{k}_{_UNIT[k]}", k, prefix, _UNIT[k]) for k in kinds)


#: The synchronous table, in contract order (``time`` first).
SYNC_FIELDS = (TIME_FIELD,) + sensor_fields("a") + sensor_fields("b")
SYNC_COLUMNS = tuple(f.file_name for f in SYNC_FIELDS)
#: A per-sensor plot file: the required columns (unprefixed form).
PLOT_FIELDS = (TIME_FIELD,) + sensor_fields("", PLOT_KINDS)
#: The navigation columns of one ship (unprefixed form); prefixed in a navigation file.
NAV_FIELDS = sensor_fields("", NAV_KINDS)
assert tuple(f.contract_name for f in SYNC_FIELDS) == DATA_COLUMNS

#: estimates.csv|parquet: input row, time (s), each state and its 1 sigma (deg or m), the NIS.
ESTIMATE_COLUMNS = (
    ["row", "time_s"]
    + [
        c
        for i, n in enumerate(STATE_NAMES)
        for c in (f"{n}_{'deg' if IS_ANGLE[i] else 'm'}", f"{n}_sigma_{'deg' if IS_ANGLE[i] else 'm'}")
    ]
    + ["nis"]
)
#: positions.csv|parquet: corrected target ECEF from radar A and B, raw and corrected A - B (m).
POSITION_COLUMNS = [
    "row",
    "time_s",
    "a_ecef_x_m",
    "a_ecef_y_m",
    "a_ecef_z_m",
    "b_ecef_x_m",
    "b_ecef_y_m",
    "b_ecef_z_m",
    "diff_raw_x_m",
    "diff_raw_y_m",
    "diff_raw_z_m",
    "diff_x_m",
    "diff_y_m",
    "diff_z_m",
]
#: rejected.csv: one bad input row with its reason.
REJECTED_COLUMNS = ["file", "row", "column", "reason_code", "reason", "values"]
#: unpaired.csv: an instant of the asynchronous form that could not be paired, with its reason.
UNPAIRED_COLUMNS = ["time_s", "file", "row", "reason"]
#: paired.csv|parquet: the synchronous table made by pairing, plus the instant's row in the
#: reference plot file and 1 where the other radar's plot was interpolated.
PAIRED_COLUMNS = list(SYNC_COLUMNS) + ["pair_row", "pair_interpolated"]
