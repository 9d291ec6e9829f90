"""Long-form input tables of fleet registration: their columns, units and defaults, and the reading
of a pandas DataFrame or a mapping of column name -> array into checked numpy columns.

Every table is long form, one row per item; SI units and radians (docs/reference/conventions.md):

* ``platforms`` (optional): ``platform`` id; the prior standard deviations of its attitude errors
  ``prior_heading``, ``prior_pitch``, ``prior_roll`` (rad; missing or ``inf`` = no prior, 0 = the
  error is known to be zero and is held fixed).
* ``sensors``: ``sensor`` id, ``platform`` id; the noise standard deviation of each measured
  channel ``sigma_range`` (m), ``sigma_bearing``, ``sigma_elevation`` (rad), NaN or missing = the
  channel is not measured; the prior standard deviations of the biases ``prior_range`` (m),
  ``prior_bearing``, ``prior_elevation`` (rad; same meaning as the platform priors); the lever arm
  ``lever_x``, ``lever_y``, ``lever_z`` (m, deck frame: starboard, bow, up; default 0); optional
  extended errors, each switched on by its column: ``prior_range_gain`` (dimensionless),
  ``prior_time_bias`` (s), ``prior_position`` (m, one sigma for the east, north and up position
  errors), ``prior_eccentricity`` (rad, one sigma for both terms a, b of the azimuth eccentricity:
  the bearing error ``a sin q + b cos q`` at the measured bearing q). A missing column leaves the
  error out of the model; an empty cell (NaN) or ``inf`` estimates it without a prior, a number is
  its prior sigma, 0 holds it at zero (listed as fixed). Optional ``channel_of``: the id of the
  sensor this one is a channel of (a radar's primary-only plots beside its secondary ones; empty:
  none): the channel has its own biases and range gain and shares the other sensor's platform,
  lever arm, position error, time bias and eccentricity (one state for both).
* ``navigation``: ``platform``, ``time`` (s), ``lat``, ``lon`` (rad), ``alt`` (m), ``heading``,
  ``pitch``, ``roll`` (rad) as reported (true + attitude error). A platform with one row is a
  fixed site (its time is not used); otherwise the rows are interpolated to the plot times.
* ``plots``: ``time`` (s), ``sensor``, ``target``, ``range`` (m), ``bearing``, ``elevation`` (rad);
  NaN (or a missing column) = not measured.
* ``references`` (optional): ``target``, ``time`` (s) and the known position either as ECEF
  ``x``, ``y``, ``z`` (m) or geodetic ``lat``, ``lon`` (rad), ``alt`` (m); ``sigma`` (m, standard
  deviation per axis of the known position, default :data:`DEFAULT_REFERENCE_SIGMA`); optional
  ``sigma_up`` (m, standard deviation along the local geodetic up at the position; missing or NaN:
  equal to ``sigma``, which then is the horizontal one, east and north; ``inf``: the reference gives
  no height, only the horizontal position); ``sigma`` ``inf`` with a finite ``sigma_up``: a height
  alone (a flight level turned into a height), the position giving only the local up.
* ``targets`` (optional): ``target`` id; ``surface_alt`` (m above the WGS-84 ellipsoid) and
  ``sigma_surface`` (m): the target moves on a surface of that height, such as a ship on the sea
  (empty: not a surface target); optional ``name`` (free text, for reports). Targets without plots
  are ignored.
"""

from __future__ import annotations

from typing import Mapping

import numpy as np

from registration.core.validation import as_float_array

__all__ = [
    "Table",
    "read_table",
    "CHANNELS",
    "CHANNEL_UNITS",
    "ATTITUDE_ERRORS",
    "EXTENDED_ERRORS",
    "EXTENDED_PRIOR_COLUMNS",
    "ECCENTRICITY_ERRORS",
    "ECCENTRICITY_PRIOR_COLUMN",
    "SHARED_EXTENDED",
    "NAV_COLUMNS",
    "DEFAULT_REFERENCE_SIGMA",
    "index_of",
]

#: The measured channels, in plot order, and their units.
CHANNELS = ("range", "bearing", "elevation")
CHANNEL_UNITS = ("m", "rad", "rad")
#: A platform's attitude errors, in state order.
ATTITUDE_ERRORS = ("heading", "pitch", "roll")
#: The extended errors of a sensor, in state order (after its three biases), and the sensors-table
#: column of each one's prior (the three position errors share one).
EXTENDED_ERRORS = ("range_gain", "time_bias", "position_east", "position_north", "position_up")
EXTENDED_PRIOR_COLUMNS = (
    "prior_range_gain",
    "prior_time_bias",
    "prior_position",
    "prior_position",
    "prior_position",
)
#: The azimuth eccentricity of a sensor, in state order (after the extended errors): the terms a and b
#: of the bearing error a sin q + b cos q (rad); the sensors-table column of their prior.
ECCENTRICITY_ERRORS = ("eccentricity_sin", "eccentricity_cos")
ECCENTRICITY_PRIOR_COLUMN = "prior_eccentricity"
#: Which extended errors (EXTENDED_ERRORS order) a channel (``channel_of``) shares with its sensor:
#: all but the range gain.
SHARED_EXTENDED = (False, True, True, True, True)
#: Navigation columns, in the order the generated functions take them.
NAV_COLUMNS = ("lat", "lon", "alt", "heading", "pitch", "roll")
#: Standard deviation per axis (m) of a reference position when the table gives none.
DEFAULT_REFERENCE_SIGMA = 1.0


class Table:
    """One input table as numpy columns, with errors that name the table, column and row."""

    def __init__(self, name: str, columns: dict[str, np.ndarray], n_rows: int):
        self.name = name
        self.columns = columns
        self.n_rows = n_rows

    def has(self, column: str) -> bool:
        return column in self.columns

    def ids(self, column: str) -> np.ndarray:
        """An id column as strings (ids may be given as numbers or strings)."""
        return np.asarray(self.require(column)).astype(str)

    def floats(self, column: str, default: float | None = None) -> np.ndarray:
        """A numeric column as float64; ``default`` fills a missing column (None: it is required)."""
        if column not in self.columns:
            if default is None:
                return self.require(column)  # raises: the column is missing
            return np.full(self.n_rows, float(default))
        values = self.columns[column]
        if (
            values.dtype == bool
            or values.dtype.kind in "OUS"
            and any(isinstance(v, (str, bool)) for v in values)
        ):
            raise ValueError(f"{self.name}: column {column!r} must hold numbers, got {values.dtype} values")
        return as_float_array(f"{self.name}.{column}", values).reshape(self.n_rows)

    def require(self, column: str) -> np.ndarray:
        """The raw column; ValueError naming the table and its columns when it is missing."""
        if column not in self.columns:
            raise ValueError(f"{self.name}: missing column {column!r} (columns: {sorted(self.columns)})")
        return self.columns[column]

    def error(self, row: int, message: str) -> ValueError:
        """The error for one bad row: ``<table> row R: message``."""
        return ValueError(f"{self.name} row {row}: {message}")


def read_table(name: str, table, required: tuple[str, ...] = ()) -> Table:
    """A pandas DataFrame or a mapping of column name -> 1-D array (equal lengths) as a :class:`Table`."""
    if table is None:
        raise ValueError(f"{name}: a table is required")
    if hasattr(table, "to_dict") and hasattr(table, "columns") and not isinstance(table, Mapping):
        table = {str(c): table[c].to_numpy() for c in table.columns}
    if not isinstance(table, Mapping):
        raise ValueError(
            f"{name}: expected a pandas DataFrame or a mapping of column -> array, got {type(table).__name__}"
        )
    columns, n = {}, None
    for key, values in table.items():
        arr = np.asarray(values)
        if arr.ndim == 0:
            raise ValueError(f"{name}: column {key!r} is a scalar; give one value per row")
        if arr.ndim != 1:
            raise ValueError(f"{name}: column {key!r} must be 1-D, got shape {arr.shape}")
        if n is None:
            n = arr.shape[0]
        elif arr.shape[0] != n:
            raise ValueError(f"{name}: column {key!r} has {arr.shape[0]} rows, other columns have {n}")
        columns[str(key)] = arr
    out = Table(name, columns, n or 0)
    for column in required:
        out.require(column)
    return out


def index_of(values: np.ndarray, ids) -> np.ndarray:
    """Index of each of ``values`` (strings) in ``ids``; -1 where absent (vectorised)."""
    unique, inverse = np.unique(values, return_inverse=True)
    lookup = {v: i for i, v in enumerate(ids)}
    return np.array([lookup.get(u, -1) for u in unique], dtype=np.int64)[inverse].reshape(values.shape)
