"""The fleet files' schemas, defined once: :data:`FLEET_FILES`, per table its columns in file units
(degrees, metres, seconds), the table column each becomes (:mod:`registration.fleet.data.tables`:
SI units, radians), whether a file must have it, the values accepted, and what it holds.

The reader checks cells against it (:data:`registration.io.fleet.reading.cells.FILE_COLUMNS` is its
columns without the texts); the ``fleet register`` options' help and the reference page
docs/reference/fleet-tables.md are written from it (:mod:`registration.io.fleet.schemadoc`):
``python -m registration.io.fleet > docs/reference/fleet-tables.md`` (a test fails when the
page differs).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

from registration.core.validation import TIME_LIMIT_S

__all__ = ["FLEET_FILES", "HELD", "INF_ALLOWED", "POSITIVE", "FileColumn", "held", "FileTable"]


class FileColumn(NamedTuple):
    """One column of a fleet file: its name in the ``file``, the table ``column`` it becomes, its
    file ``unit`` (``s``, ``m``, ``deg``, converted to radians, ``dimensionless``, or ``id``: text),
    whether the file must have it (``required``), the ``limits`` (low, high) accepted in file units
    (None: any) and what it holds (``text``)."""

    file: str
    column: str
    unit: str
    required: bool
    limits: tuple[float, float] | None
    text: str


@dataclass(frozen=True)
class FileTable:
    """One fleet file: its table ``name`` (the file is ``<name>.csv`` or ``.parquet``), whether a
    registration needs it (``required``), what its rows are and its rules (``text``: the
    ``fleet register --<name>`` help after the columns) and its ``columns``."""

    name: str
    required: bool
    text: str
    columns: tuple[FileColumn, ...]


_TIME = (-TIME_LIMIT_S, TIME_LIMIT_S)
_NO_PRIOR = "empty or inf: no prior; 0: known to be zero, held fixed"
_C = FileColumn

#: The fleet files (module docstring), in the order of ``read_fleet_tables``' arguments.
FLEET_FILES = {
    "plots": FileTable(
        "plots",
        True,
        "one row per plot; an empty cell of a channel: the sensor does not measure it; plots without "
        "a target id (no column, or empty cells) are associated to the targets with ids, the reference "
        "targets and each other, jointly with the registration; track: a sensor-local track id "
        "(associations.csv)",
        (
            _C("time_s", "time", "s", True, _TIME, "time of the plot"),
            _C("sensor", "sensor", "id", True, None, "the sensor that made the plot (listed in sensors)"),
            _C("target", "target", "id", False, None, "the target's id; empty: none, the plot is associated"),
            _C(
                "track",
                "track",
                "id",
                False,
                None,
                "a sensor-local track id (an ARPA target number); empty: none",
            ),
            _C(
                "kind",
                "kind",
                "id",
                False,
                None,
                "the plot's kind, e.g. mode_s, mode_a, primary (primary-only: PSR); empty: not known; "
                "the residual diagnostics compare the kinds (docs/background/diagnostics.md)",
            ),
            _C("range_m", "range", "m", False, (0.0, 1e8), "slant range, > 0; empty: not measured"),
            _C(
                "bearing_deg",
                "bearing",
                "deg",
                False,
                (-360.0, 360.0),
                "deck bearing, from the bow, starboard positive; empty: not measured",
            ),
            _C(
                "elevation_deg",
                "elevation",
                "deg",
                False,
                (-90.0, 90.0),
                "elevation above the deck plane; empty: not measured",
            ),
        ),
    ),
    "navigation": FileTable(
        "navigation",
        True,
        "one row per platform and time, as reported (one row for a fixed site)",
        (
            _C("time_s", "time", "s", True, _TIME, "time of the sample"),
            _C("platform", "platform", "id", True, None, "the platform's id"),
            _C("lat_deg", "lat", "deg", True, (-90.0, 90.0), "geodetic latitude (WGS-84)"),
            _C("lon_deg", "lon", "deg", True, (-360.0, 360.0), "longitude"),
            _C("alt_m", "alt", "m", True, (-1.2e4, 1e6), "height above the WGS-84 ellipsoid"),
            _C(
                "heading_deg",
                "heading",
                "deg",
                True,
                (-360.0, 360.0),
                "reported heading (true + attitude error)",
            ),
            _C("pitch_deg", "pitch", "deg", True, (-90.0, 90.0), "reported pitch"),
            _C("roll_deg", "roll", "deg", True, (-90.0, 90.0), "reported roll"),
        ),
    ),
    "sensors": FileTable(
        "sensors",
        True,
        f"one row per sensor; an empty sigma: the channel is not measured; bias priors ({_NO_PRIOR}); "
        "lever arm in the deck frame (starboard, bow, up; default 0); the extended errors "
        "(prior_range_gain, prior_time_bias_s, prior_position_m, prior_eccentricity_deg) are modelled "
        "only when their column is there",
        (
            _C("sensor", "sensor", "id", True, None, "the sensor's id"),
            _C("platform", "platform", "id", True, None, "the platform it is on (listed in navigation)"),
            _C(
                "sigma_range_m",
                "sigma_range",
                "m",
                False,
                (0.0, 1e6),
                "range noise sigma, > 0; empty: range not measured",
            ),
            _C(
                "sigma_bearing_deg",
                "sigma_bearing",
                "deg",
                False,
                (0.0, 20.0),
                "bearing noise sigma, > 0; empty: not measured",
            ),
            _C(
                "sigma_elevation_deg",
                "sigma_elevation",
                "deg",
                False,
                (0.0, 20.0),
                "elevation noise sigma, > 0; empty: not measured",
            ),
            _C(
                "prior_range_bias_m",
                "prior_range",
                "m",
                False,
                (0.0, math.inf),
                f"prior sigma of the range bias; {_NO_PRIOR}",
            ),
            _C(
                "prior_bearing_bias_deg",
                "prior_bearing",
                "deg",
                False,
                (0.0, math.inf),
                "prior sigma of the bearing bias (same meaning)",
            ),
            _C(
                "prior_elevation_bias_deg",
                "prior_elevation",
                "deg",
                False,
                (0.0, math.inf),
                "prior sigma of the elevation bias (same meaning)",
            ),
            _C(
                "lever_x_m",
                "lever_x",
                "m",
                False,
                (-1e4, 1e4),
                "lever arm to starboard from the navigation point; default 0",
            ),
            _C("lever_y_m", "lever_y", "m", False, (-1e4, 1e4), "lever arm to the bow; default 0"),
            _C("lever_z_m", "lever_z", "m", False, (-1e4, 1e4), "lever arm up; default 0"),
            _C(
                "prior_range_gain",
                "prior_range_gain",
                "dimensionless",
                False,
                (0.0, 0.1),
                "prior sigma of the range gain (1e-4 = 100 ppm); no column: not modelled",
            ),
            _C(
                "prior_time_bias_s",
                "prior_time_bias",
                "s",
                False,
                (0.0, math.inf),
                "prior sigma of the time bias; no column: not modelled",
            ),
            _C(
                "prior_position_m",
                "prior_position",
                "m",
                False,
                (0.0, math.inf),
                "prior sigma of the position error, east, north and up; no column: not modelled",
            ),
            _C(
                "prior_eccentricity_deg",
                "prior_eccentricity",
                "deg",
                False,
                (0.0, math.inf),
                "prior sigma of the azimuth eccentricity a, b (bearing error a sin q + b cos q at the "
                "measured bearing q), each; no column: not modelled",
            ),
            _C(
                "channel_of",
                "channel_of",
                "id",
                False,
                None,
                "the sensor this one is a channel of (a radar's primary-only plots): it shares that "
                "sensor's platform, lever arm, position error, time bias and eccentricity, and has its "
                "own biases and range gain; empty: none",
            ),
        ),
    ),
    "platforms": FileTable(
        "platforms",
        False,
        f"the prior sigmas of each platform's attitude errors ({_NO_PRIOR}); default: no priors",
        (
            _C("platform", "platform", "id", True, None, "the platform's id"),
            _C(
                "prior_heading_deg",
                "prior_heading",
                "deg",
                False,
                (0.0, math.inf),
                "prior sigma of the heading error",
            ),
            _C(
                "prior_pitch_deg",
                "prior_pitch",
                "deg",
                False,
                (0.0, math.inf),
                "prior sigma of the pitch error",
            ),
            _C(
                "prior_roll_deg", "prior_roll", "deg", False, (0.0, math.inf), "prior sigma of the roll error"
            ),
        ),
    ),
    "reference": FileTable(
        "reference",
        False,
        "known target positions, as lat_deg, lon_deg, alt_m or as ECEF x_m, y_m, z_m, with sigma_m (m "
        "per axis, default 1 m; horizontal with sigma_up_m) and sigma_up_m (m, vertical); a height alone "
        "(sigma_m inf), such as a flight level turned into a height; default: none",
        (
            _C("time_s", "time", "s", True, _TIME, "time of the known position"),
            _C("target", "target", "id", True, None, "the target's id"),
            _C("lat_deg", "lat", "deg", False, (-90.0, 90.0), "geodetic latitude (WGS-84)"),
            _C("lon_deg", "lon", "deg", False, (-360.0, 360.0), "longitude"),
            _C("alt_m", "alt", "m", False, (-1.2e4, 1e8), "height above the WGS-84 ellipsoid"),
            _C("x_m", "x", "m", False, (-1e8, 1e8), "ECEF x (instead of lat_deg, lon_deg, alt_m)"),
            _C("y_m", "y", "m", False, (-1e8, 1e8), "ECEF y"),
            _C("z_m", "z", "m", False, (-1e8, 1e8), "ECEF z"),
            _C(
                "sigma_m",
                "sigma",
                "m",
                False,
                (0.0, math.inf),
                "sigma per axis, > 0 (the horizontal one with sigma_up_m); inf: a height only (with a "
                "finite sigma_up_m; lat_deg, lon_deg give the local up); empty: 1 m",
            ),
            _C(
                "sigma_up_m",
                "sigma_up",
                "m",
                False,
                (0.0, math.inf),
                "sigma along the local up, > 0; inf: no height; empty: sigma_m",
            ),
            _C(
                "height_offset_prior_m",
                "height_offset_prior",
                "m",
                False,
                (0.0, math.inf),
                "on heights alone (flight levels turned into heights without a learned relation): they "
                "share one unknown offset, the state flight_levels:height_offset, estimated with this prior "
                "sigma (the same on every such row; inf: no prior); empty: the height has no such offset",
            ),
        ),
    ),
    "targets": FileTable(
        "targets",
        False,
        "targets that move on a surface of known height (surface_alt_m above WGS-84, with "
        "sigma_surface_m), such as ships on the sea; default: none",
        (
            _C("target", "target", "id", True, None, "the target's id"),
            _C("name", "name", "id", False, None, "a name, for reports"),
            _C(
                "surface_alt_m",
                "surface_alt",
                "m",
                False,
                (-1e4, 1e4),
                "height of its surface above the WGS-84 ellipsoid; empty: not on a surface",
            ),
            _C(
                "sigma_surface_m",
                "sigma_surface",
                "m",
                False,
                (0.0, 1e6),
                "sigma of its height about surface_alt_m, > 0",
            ),
        ),
    ),
}
#: Sigma columns whose value must be > 0 (a prior may be 0: fixed).
POSITIVE = frozenset(
    {
        "range_m",
        "sigma_range_m",
        "sigma_bearing_deg",
        "sigma_elevation_deg",
        "sigma_m",
        "sigma_up_m",
        "sigma_surface_m",
    }
)
#: Columns where inf is a meaning rather than an error (besides the priors' "no prior"): a reference
#: without a height, and one with a height only.
INF_ALLOWED = frozenset({"sigma_up_m", "sigma_m", "height_offset_prior_m"})
#: The smallest positive and the largest finite value of a sigma or a prior sigma (file units) that
#: float64 arithmetic holds through the solve, which squares and inverts them (1e-300 squared is 0,
#: 1e308 squared is inf); a prior of 0 (fixed) or inf (none) keeps its meaning.
HELD = (1e-15, 1e15)


def held(column: str) -> bool:
    """True for the sigma and prior columns, whose values must lie within :data:`HELD`."""
    return column.startswith(("sigma_", "prior_"))
