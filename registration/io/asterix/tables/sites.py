"""SITES.csv: which radar each SAC/SIC is, where it stands and how noisy it is.

One row per sensor, columns (units in the names, degrees and metres as in the fleet files):

| column | meaning | accepted |
|---|---|---|
| ``sensor`` | the sensor's id in the fleet tables (also its platform's) | text, unique, not empty |
| ``sac``, ``sic`` | its ASTERIX data source's System Area and Identification Codes | 0-255, the pair unique |
| ``lat_deg``, ``lon_deg`` | WGS-84 latitude, longitude of the antenna | [-90, 90], [-360, 360] deg |
| ``alt_m`` | antenna height above the WGS-84 ellipsoid (not above mean sea level) | [-12000, 1e6] m |
| ``sigma_range_m``, ``sigma_bearing_deg`` | plot noise, one sigma | > 0 m; (0, 20] deg |

Optional (empty cell: no prior; ``inf``: no prior; 0: held fixed), passed on to the fleet
sensors file: ``prior_range_bias_m``, ``prior_bearing_bias_deg``, ``prior_range_gain`` (at most
0.1), ``prior_time_bias_s``, ``prior_position_m``, ``prior_eccentricity_deg`` (the azimuth
eccentricity's two terms); to the platforms file: ``prior_heading_deg``, ``prior_pitch_deg``,
``prior_roll_deg`` (default 0: a surveyed site's attitude is held fixed).

Optional ``psr_channel``: ``own`` makes the radar's primary-only plots (CAT048 I048/020 TYP 1,
CAT001 I001/020 SSR/PSR 1) a sensor of their own, ``<sensor>.psr``, a channel of the radar
(``channel_of`` in the sensors file: own range and bearing biases and range gain; the radar's
position, clock and eccentricity); empty: one sensor for all plots. Any other value is an error
naming the row and the column.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from registration.io.files.unreadable import read_error
from registration.io.fleet.schema import HELD, held

if TYPE_CHECKING:
    import pandas as pd

__all__ = [
    "SITE_COLUMNS",
    "SENSOR_PRIORS",
    "PLATFORM_PRIORS",
    "PSR_CHANNEL_VALUES",
    "PSR_SUFFIX",
    "channel_sensors",
    "read_sites",
    "check_sites",
]

#: Column -> (unit, low, high, low excluded, required).
SITE_COLUMNS = {
    "sensor": ("id", None, None, False, True),
    "sac": ("integer", 0, 255, False, True),
    "sic": ("integer", 0, 255, False, True),
    "lat_deg": ("deg", -90.0, 90.0, False, True),
    "lon_deg": ("deg", -360.0, 360.0, False, True),
    "alt_m": ("m", -12000.0, 1e6, False, True),
    "sigma_range_m": ("m", 0.0, 1e6, True, True),
    "sigma_bearing_deg": ("deg", 0.0, 20.0, True, True),
    "prior_range_bias_m": ("m", 0.0, math.inf, False, False),
    "prior_bearing_bias_deg": ("deg", 0.0, math.inf, False, False),
    "prior_range_gain": ("dimensionless", 0.0, 0.1, False, False),
    "prior_time_bias_s": ("s", 0.0, math.inf, False, False),
    "prior_position_m": ("m", 0.0, math.inf, False, False),
    "prior_eccentricity_deg": ("deg", 0.0, math.inf, False, False),
    "psr_channel": ("text", None, None, False, False),
    "prior_heading_deg": ("deg", 0.0, math.inf, False, False),
    "prior_pitch_deg": ("deg", 0.0, math.inf, False, False),
    "prior_roll_deg": ("deg", 0.0, math.inf, False, False),
}
#: Prior columns passed on to the fleet sensors file.
SENSOR_PRIORS = (
    "prior_range_bias_m",
    "prior_bearing_bias_deg",
    "prior_range_gain",
    "prior_time_bias_s",
    "prior_position_m",
    "prior_eccentricity_deg",
)
#: The values of ``psr_channel`` (besides empty: none) and the suffix of a channel's sensor id.
PSR_CHANNEL_VALUES = ("own",)
PSR_SUFFIX = ".psr"
#: Prior columns of the fleet platforms file (0 when SITES does not give them).
PLATFORM_PRIORS = ("prior_heading_deg", "prior_pitch_deg", "prior_roll_deg")


def read_sites(path: str | Path) -> pd.DataFrame:
    """Read and check SITES.csv (see the module docstring) into a DataFrame: ``sensor`` text,
    ``sac``, ``sic`` integers, the other columns floats (NaN: empty optional cell). ValueError
    naming the file, the row (from 0, the first data row), the column and its unit."""
    path = Path(path)
    try:
        with open(path, newline="", encoding="utf-8-sig") as f:
            lines = [row for row in csv.reader(f)]
    except (OSError, UnicodeDecodeError, csv.Error) as exc:
        raise read_error(path, exc, "cannot read it as CSV") from exc
    lines = [row for row in lines if any(cell.strip() for cell in row)]
    if not lines:
        raise ValueError(
            f"{path}: an empty file; expected a header and one row per sensor "
            f"({', '.join(c for c, v in SITE_COLUMNS.items() if v[4])})"
        )
    header = [c.strip() for c in lines[0]]
    for r, row in enumerate(lines[1:]):
        if len(row) != len(header):
            raise ValueError(
                f"{path}: row {r}: {len(row)} fields, the header {len(header)} "
                f"({'cut short' if len(row) < len(header) else 'an extra field'}?)"
            )
    rows = [[c.strip() for c in row] for row in lines[1:]]
    return _checked(header, [[row[k] for row in rows] for k in range(len(header))], len(rows), str(path))


def _number(source: str, r: int, column: str, cell: object) -> float:
    unit, low, high, strict, required = SITE_COLUMNS[column]
    assert low is not None and high is not None  # a number column has limits
    text = "" if cell is None or (isinstance(cell, float) and math.isnan(cell)) else str(cell).strip()
    where = f"{source}: row {r}, column {column!r}"
    if text == "":
        if required:
            raise ValueError(f"{where}: empty; a number ({unit}) is required")
        return math.nan
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"{where}: {text!r} is not a number ({unit})") from None
    if unit == "integer":
        if not value.is_integer() or not low <= value <= high:
            raise ValueError(f"{where}: {text!r} is not an integer in [0, 255]")
        return value
    if math.isnan(value) or (math.isinf(value) and high != math.inf):
        raise ValueError(f"{where}: {text!r} is not a finite number ({unit})")
    if value < low or value > high or (strict and value == low):
        span = f"{'(' if strict else '['}{low:g}, {high:g}]"
        raise ValueError(f"{where}: {value:g} {unit} is outside {span} {unit}")
    if held(column) and value != 0 and math.isfinite(value) and not HELD[0] <= abs(value) <= HELD[1]:
        raise ValueError(
            f"{where}: {value:g} {unit} cannot be held in the solve: a sigma or prior lies in "
            f"[{HELD[0]:g}, {HELD[1]:g}] {unit} (a prior may also be 0: held fixed, or empty or inf: none)"
        )
    return value


def check_sites(frame: pd.DataFrame, source: str = "sites") -> pd.DataFrame:
    """Check a SITES table (a DataFrame with the columns of the module docstring, cells as text or
    numbers) and return it typed: ``sensor`` str, ``sac``, ``sic`` int, the others float. ValueError
    naming ``source``, the row (from 0), the column and its unit."""
    columns = [str(c).strip() for c in frame.columns]
    return _checked(columns, [frame.iloc[:, k].tolist() for k in range(len(columns))], len(frame), source)


def _checked(columns: list[str], cells_by_column: list[list], n_rows: int, source: str) -> pd.DataFrame:
    """:func:`check_sites` of the cells of each column (text or numbers), in the columns' order."""
    import pandas as pd

    repeated = sorted({c for c in columns if columns.count(c) > 1})
    if repeated:
        raise ValueError(f"{source}: column(s) {repeated} appear more than once in the header")
    unknown = [c for c in columns if c not in SITE_COLUMNS]
    if unknown:
        raise ValueError(f"{source}: unknown column(s) {unknown}; the columns are {list(SITE_COLUMNS)}")
    missing = [c for c, v in SITE_COLUMNS.items() if v[4] and c not in columns]
    if missing:
        raise ValueError(
            f"{source}: missing column(s) {missing} (required: "
            f"{[c for c, v in SITE_COLUMNS.items() if v[4]]})"
        )
    if n_rows == 0:
        raise ValueError(f"{source}: no data rows (the file holds only a header)")
    out: dict[str, list] = {}
    for column, cells in zip(columns, cells_by_column):
        if column == "sensor":
            names = [
                "" if c is None or (isinstance(c, float) and math.isnan(c)) else str(c).strip() for c in cells
            ]
            for r, name in enumerate(names):
                if not name:
                    raise ValueError(
                        f"{source}: row {r}, column 'sensor': empty; every site needs a sensor id"
                    )
            out[column] = names
        elif column == "psr_channel":
            out[column] = [_psr_channel(source, r, c) for r, c in enumerate(cells)]
        else:
            out[column] = [_number(source, r, column, c) for r, c in enumerate(cells)]
    _unique(source, out["sensor"], "sensor", "sensor")
    _unique(source, [f"{int(a)}/{int(b)}" for a, b in zip(out["sac"], out["sic"])], "sic", "SAC/SIC")
    for r, (name, channel) in enumerate(zip(out["sensor"], out.get("psr_channel", [""] * n_rows))):
        if channel and name + PSR_SUFFIX in out["sensor"]:
            raise ValueError(
                f"{source}: row {r}, column 'psr_channel': the PSR channel's id {name + PSR_SUFFIX!r} is "
                "also a sensor of SITES; rename that sensor"
            )
    typed = pd.DataFrame(
        {c: np.asarray(v, dtype=np.int64 if c in ("sac", "sic") else None) for c, v in out.items()}
    )
    typed["sensor"] = typed["sensor"].astype(str)
    return typed


def _psr_channel(source: str, r: int, cell: object) -> str:
    """A ``psr_channel`` cell: '' (none) or one of PSR_CHANNEL_VALUES; ValueError naming the row."""
    text = "" if cell is None or (isinstance(cell, float) and math.isnan(cell)) else str(cell).strip()
    if text and text not in PSR_CHANNEL_VALUES:
        raise ValueError(
            f"{source}: row {r}, column 'psr_channel': {text!r} is not a PSR channel; expected "
            f"{' or '.join(repr(v) for v in PSR_CHANNEL_VALUES)} (the radar's primary-only plots as a "
            "sensor of their own) or empty (none)"
        )
    return text


def _unique(source: str, values: list, column: str, what: str) -> None:
    seen: dict = {}
    for r, v in enumerate(values):
        if v in seen:
            raise ValueError(
                f"{source}: row {r}, column {column!r}: {what} {v} is also in row {seen[v]}; "
                "each must be unique"
            )
        seen[v] = r


def channel_sensors(sites: pd.DataFrame, sensor: np.ndarray, primary: np.ndarray) -> np.ndarray:
    """The plots' sensor ids (S,) with the primary-only plots (``primary`` (S,) bool) of the radars
    whose ``psr_channel`` is ``own`` moved to their channel ``<sensor>.psr``."""
    sensor = np.asarray(sensor).astype(str)
    if "psr_channel" not in sites or sensor.size == 0:
        return sensor
    own = sites["sensor"].astype(str).to_numpy()[sites["psr_channel"].astype(str).to_numpy() == "own"]
    psr = np.asarray(primary, dtype=bool) & np.isin(sensor, own)
    return np.where(psr, np.char.add(sensor, PSR_SUFFIX), sensor)
