"""Checks of whole fleet files, in file units (degrees, metres, seconds): angles given in radians
in degree columns, angle sigmas that look like radians, and plots with values in a channel for
which the sensors file has no sigma column. Errors are ValueErrors naming the file, a row (from 0,
the first data row) and the column; the weaker findings come back as notes (text) for
:attr:`registration.io.fleet.reading.read.FleetTables.notes`. See docs/reference/fleet-files.md,
"What is rejected".

Refused (radians look like degrees of nearly nothing, so only a pattern that degrees would not
show is refused):

* ``bearing_deg``: at least :data:`MIN_UNIT_CHECK_VALUES` values, not all 0, all within +-2 pi;
* ``lat_deg`` with ``lon_deg``: all within +-pi/2 and +-2 pi (a fleet within 1.6 deg of 0 N 0 E);
* ``heading_deg`` of a moving platform: all within +-2 pi, and read as radians the headings follow
  the platform's course over ground (from ``lat_deg``/``lon_deg``) while read as degrees they do
  not (:func:`attitude_check`). A ship's bow points along its track, give or take leeway and
  current, so that holds for degrees only by a crab of tens of degrees. A ship on a steady
  course near north, a ship that does not move and a fixed site are not judged.

Noted only (plausible in degrees too): ``pitch_deg`` and ``roll_deg`` of a moving platform that
all stay within +-:data:`SMALL_ATTITUDE` (not all equal; a level site of zeros is not noted), and
``sigma_bearing_deg``/``sigma_elevation_deg`` below :data:`MIN_ANGLE_SIGMA_DEG` (precision
trackers reach that; a radar in radians lands there). If they are radians the run's consistency
check finds the misfit.
"""

from __future__ import annotations

import math

import numpy as np

from registration.core.angles import wrap_angle

__all__ = [
    "MIN_UNIT_CHECK_VALUES",
    "MIN_ANGLE_SIGMA_DEG",
    "SMALL_ATTITUDE",
    "radians_check",
    "attitude_check",
    "sigma_notes",
    "channel_columns_check",
    "missing_channel_notes",
]

#: Fewest values of a bearing column (or of lat/lon) for the radians-in-degrees check.
MIN_UNIT_CHECK_VALUES = 100
#: An angle sigma below this (deg) is noted: 0.02 rad is a 1.15 deg radar, 0.02 deg a precision tracker.
MIN_ANGLE_SIGMA_DEG = 0.02
#: Pitch and roll of a moving platform all within +- this (deg as labelled) are noted: radians?
SMALL_ATTITUDE = 0.2
#: The heading check: stretches of the track of at least SEGMENT_S s, MIN_SEGMENT_M m and MIN_SPEED m/s,
#: at least MIN_SEGMENTS of them; refused when the median difference between the course over ground
#: and the heading read as radians is at most RADIANS_MATCH_DEG and read as degrees at least DEGREES_MISS_DEG.
SEGMENT_S, MIN_SEGMENT_M, MIN_SPEED, MIN_SEGMENTS = 5.0, 20.0, 1.0, 5
RADIANS_MATCH_DEG, DEGREES_MISS_DEG = 15.0, 30.0
_EARTH_RADIUS = 6.371e6  # m, mean; enough for a course over ground
_CHANNEL_COLUMNS = (
    ("range_m", "sigma_range_m", "range"),
    ("bearing_deg", "sigma_bearing_deg", "bearing"),
    ("elevation_deg", "sigma_elevation_deg", "elevation"),
)


def radians_check(path, columns: dict) -> None:
    """Radians in degree columns: every bearing within +-2 pi, or every lat within +-pi/2 and lon
    within +-2 pi, over at least MIN_UNIT_CHECK_VALUES values (degrees span far more). ``columns``:
    file column -> values in file units, NaN where not given or bad."""
    checks = [("bearing_deg",), ("lat_deg", "lon_deg")]
    for names in checks:
        if not all(n in columns for n in names):
            continue
        vals = [columns[n][np.isfinite(columns[n])] for n in names]
        if min(v.size for v in vals) < MIN_UNIT_CHECK_VALUES or not any(np.any(v != 0) for v in vals):
            continue
        bounds = (2 * math.pi,) if len(names) == 1 else (math.pi / 2, 2 * math.pi)
        if all(np.max(np.abs(v)) <= b for v, b in zip(vals, bounds)):
            col = columns[names[0]]
            r = int(np.nanargmax(np.abs(col)))
            raise ValueError(
                f"{path}: row {r}, column {names[0]!r}: all {vals[0].size} values of "
                f"{' and '.join(repr(n) for n in names)} lie within +-{np.max(np.abs(vals[0])):.3g} "
                f"(the largest here, {col[r]:.4g}): radians? These columns are in degrees"
            )


def _stretches(t: np.ndarray, lat_deg: np.ndarray, lon_deg: np.ndarray):
    """The moving stretches of one platform's track: (first rows (K,), last rows (K,), course over
    ground (K,) rad clockwise from north, speed (K,) m/s), from rows at least SEGMENT_S s apart."""
    order = np.argsort(t, kind="stable")
    t, lat, lon = t[order], np.radians(lat_deg[order]), np.radians(lon_deg[order])
    _, pick = np.unique(np.floor((t - t[0]) / SEGMENT_S), return_index=True)
    a, b = pick[:-1], pick[1:]
    north = (lat[b] - lat[a]) * _EARTH_RADIUS
    east = wrap_angle(lon[b] - lon[a]) * _EARTH_RADIUS * np.cos(0.5 * (lat[a] + lat[b]))
    dist, dt = np.hypot(north, east), t[b] - t[a]
    moving = (dist >= MIN_SEGMENT_M) & (dist >= MIN_SPEED * dt)
    return order[a[moving]], order[b[moving]], np.arctan2(east, north)[moving], (dist / dt)[moving]


def _miss(course: np.ndarray, first: np.ndarray, last: np.ndarray) -> float:
    """Median |course - heading| (deg) over stretches, the heading (rad) of a stretch the mean of its ends."""
    heading = np.arctan2(np.sin(first) + np.sin(last), np.cos(first) + np.cos(last))
    return float(np.degrees(np.median(np.abs(wrap_angle(course - heading)))))


def attitude_check(path, columns: dict, platform: np.ndarray) -> list[str]:
    """Radians in the attitude columns of a navigation file (module docstring): a ValueError for
    headings, notes for pitch and roll. ``columns``: file column -> values in file units (NaN where
    bad); ``platform`` (N,) ids."""
    notes = []
    for pid in dict.fromkeys(platform.tolist()):
        rows = np.flatnonzero(platform == pid)
        rows = rows[
            np.all(
                [
                    np.isfinite(columns[c][rows])
                    for c in ("time_s", "lat_deg", "lon_deg", "heading_deg", "pitch_deg", "roll_deg")
                ],
                axis=0,
            )
        ]
        if rows.size < 2:
            continue
        a, b, course, speed = _stretches(*(columns[c][rows] for c in ("time_s", "lat_deg", "lon_deg")))
        if course.size < MIN_SEGMENTS:
            continue
        h = columns["heading_deg"][rows]
        peak = float(np.max(np.abs(h)))
        if peak <= 2 * math.pi:
            as_radians, as_degrees = (
                _miss(course, h[a], h[b]),
                _miss(course, np.radians(h[a]), np.radians(h[b])),
            )
            if as_radians <= RADIANS_MATCH_DEG and as_degrees >= DEGREES_MISS_DEG:
                r = int(rows[np.argmax(np.abs(h))])
                raise ValueError(
                    f"{path}: row {r}, column 'heading_deg': the {rows.size} headings of platform "
                    f"{str(pid)!r} lie within +-{peak:.3g} and follow its course only read as radians "
                    f"(median miss {as_radians:.1f} deg, as degrees {as_degrees:.1f} deg): radians? "
                    "heading_deg, pitch_deg and roll_deg are in degrees"
                )
        pr = np.concatenate([columns["pitch_deg"][rows], columns["roll_deg"][rows]])
        if np.max(np.abs(pr)) <= SMALL_ATTITUDE and np.ptp(pr) > 0:
            notes.append(
                f"{path}: pitch_deg and roll_deg of platform {str(pid)!r} all lie within "
                f"+-{np.max(np.abs(pr)):.2g} while it moves at {np.median(speed):.1f} m/s: radians? "
                "(a ship at sea pitches and rolls by degrees; if these are degrees, ignore this note)"
            )
    return notes


def sigma_notes(path, columns: dict, sensor: np.ndarray) -> list[str]:
    """Notes for angle sigmas below MIN_ANGLE_SIGMA_DEG (deg), one per column, naming the sensors.
    ``columns``: file column -> values in file units; ``sensor`` (S,) ids."""
    notes = []
    for column in ("sigma_bearing_deg", "sigma_elevation_deg"):
        v = columns.get(column)
        if v is None:
            continue
        small = np.flatnonzero(np.isfinite(v) & (v < MIN_ANGLE_SIGMA_DEG))
        if len(small):
            listed = ", ".join(f"{str(sensor[r])!r} {v[r]:g} (row {r})" for r in small[:5])
            listed += f" and {len(small) - 5} more" if len(small) > 5 else ""
            notes.append(
                f"{path}: {column} below {MIN_ANGLE_SIGMA_DEG:g} deg for sensor(s) {listed}: radians? "
                f"({v[small[0]]:g} rad would be {math.degrees(v[small[0]]):.3g} deg; precision trackers "
                "reach such sigmas, radars rarely do: if they are degrees, ignore this note)"
            )
    return notes


def channel_columns_check(
    plots_path, plots: dict, plot_sensor: np.ndarray, sensors_path, sensor_columns
) -> None:
    """A ValueError, the sensors file's, for a channel with values in the plots file whose sigma
    column the sensors file lacks (without it no sensor measures that channel). ``plots``: file
    column -> values in file units (NaN where empty or bad); ``sensor_columns``: the sensors
    file's columns."""
    for column, sigma, name in _CHANNEL_COLUMNS:
        values = plots.get(column)
        if values is None or sigma in sensor_columns or not np.isfinite(values).any():
            continue
        given = np.isfinite(values)
        first = int(np.argmax(given))
        which = [str(s) for s in np.unique(plot_sensor[given])]
        raise ValueError(
            f"{sensors_path}: no column {sigma!r}, but {plots_path} has {name} values (column {column!r}) "
            f"for sensor(s) {which} ({int(given.sum())} rows, the first row {first}): give their {sigma}, "
            f"or leave the plots' {column} cells empty"
        )


def missing_channel_notes(
    plots_path, plot_columns, sensors_path, sigmas: dict, sensor: np.ndarray
) -> list[str]:
    """A note per measured column the plots file lacks while the sensors file gives its sigma for
    some sensors: their biases of that channel are then undetermined, for want of the column, not
    of the data. ``sigmas``: the sensors file's columns in file units (NaN where empty or bad);
    ``sensor`` (S,) ids."""
    notes = []
    for column, sigma, name in _CHANNEL_COLUMNS:
        values = sigmas.get(sigma)
        if column in plot_columns or values is None or not np.isfinite(values).any():
            continue
        which = [str(s) for s in sensor[np.isfinite(values)]]
        listed = ", ".join(which[:5]) + (f" and {len(which) - 5} more" if len(which) > 5 else "")
        notes.append(
            f"{plots_path}: no column {column!r}, while {sensors_path} gives {sigma} for {listed}: "
            f"their {name} biases stay undetermined (add the column, or leave {sigma} empty)"
        )
    return notes
