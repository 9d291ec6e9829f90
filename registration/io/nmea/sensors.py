"""The sensors table of an NMEA import: the fleet sensors file (docs/reference/fleet-files.md, "The files":
noise
sigmas, bias priors, lever arm, in degrees and metres) plus an optional ``talker`` column, the
two-character NMEA talker of the sensor's TTM sentences (``RA``). Read and checked with errors
that name the file, the row (from 0, the first data row, as the fleet files count them; and the
file's line), the column and its unit.
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from registration.io.files.unreadable import read_error
from registration.io.fleet.reading.cells import FILE_COLUMNS

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["read_sensors", "check_sensors", "platform_sensors", "talker_map", "TALKER_COLUMN"]

#: The column naming a sensor's TTM talker.
TALKER_COLUMN = "talker"
_TALKER = re.compile(r"^[A-Z0-9]{2}$")
_SPEC = {column: (unit, required, limits) for column, _, unit, required, limits in FILE_COLUMNS["sensors"]}
_POSITIVE = {"sigma_range_m", "sigma_bearing_deg", "sigma_elevation_deg"}


def _where(source: str, row: int, column: str) -> str:
    return f"{source}: row {row} (line {row + 2}), column {column!r}"


def _cell_number(source: str, row: int, column: str, value, unit: str, limits) -> float:
    """A number cell in file units; NaN for an empty optional cell. ValueError naming the cell."""
    empty_text = isinstance(value, str) and not value.strip()
    if value is None or (isinstance(value, float) and math.isnan(value)) or empty_text:
        return math.nan
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{_where(source, row, column)}: {value!r} is not a number ({unit})") from None
    if math.isnan(v):
        return v
    lo, hi = limits if limits is not None else (-math.inf, math.inf)
    strict = column in _POSITIVE
    if (v <= lo if strict else v < lo) or v > hi or (math.isinf(v) and not column.startswith("prior_")):
        span = f"{'(' if strict else '['}{lo:g}, {hi:g}]"
        raise ValueError(f"{_where(source, row, column)}: {v:g} {unit} is outside {span} {unit}")
    return v


def _ids(frame, source: str, column: str) -> list[str]:
    out = []
    for row, v in enumerate(frame[column].tolist()):
        text = "" if v is None or (isinstance(v, float) and math.isnan(v)) else str(v).strip()
        if not text:
            raise ValueError(f"{_where(source, row, column)}: empty; every row needs a {column} id")
        out.append(text)
    return out


def check_sensors(frame: pd.DataFrame, source: str = "sensors") -> pd.DataFrame:
    """The sensors table ``frame`` (a DataFrame in file columns) checked, as a new DataFrame with ids
    as text, numbers as floats and ``talker`` (if given) as upper-case text ('' for none).
    ``source`` names the table in the errors (a file name). ValueError naming the row, column and
    unit for: a missing or unknown column, an empty id, a duplicated sensor, a cell that is not a
    number or out of range, a talker that is not two letters or digits, a talker given twice on
    one platform. The result's ``attrs["source"]`` keeps ``source`` for later errors."""
    import pandas as pd

    frame = frame.rename(columns=lambda c: str(c).strip())
    known = set(_SPEC) | {TALKER_COLUMN}
    missing = [c for c in ("sensor", "platform") if c not in frame.columns]
    if missing:
        raise ValueError(f"{source}: missing column(s) {missing} (columns found: {list(frame.columns)})")
    unknown = [c for c in frame.columns if c not in known]
    if unknown:
        raise ValueError(
            f"{source}: unknown column(s) {unknown}; the sensors table has columns "
            f"{[c for c, *_ in FILE_COLUMNS['sensors']]} and {TALKER_COLUMN!r}"
        )
    if len(frame) == 0:
        raise ValueError(f"{source}: no rows; give at least one sensor")
    out: dict[str, list] = {
        "sensor": _ids(frame, source, "sensor"),
        "platform": _ids(frame, source, "platform"),
    }
    seen: dict[str, int] = {}
    for row, s in enumerate(out["sensor"]):
        if s in seen:
            raise ValueError(
                f"{_where(source, row, 'sensor')}: sensor {s!r} is given twice (first at row {seen[s]})"
            )
        seen[s] = row
    for column in frame.columns:
        if column in _SPEC and _SPEC[column][0] != "id":
            unit, _, limits = _SPEC[column]
            out[column] = [
                _cell_number(source, row, column, v, unit, limits)
                for row, v in enumerate(frame[column].tolist())
            ]
    if TALKER_COLUMN in frame.columns:
        out[TALKER_COLUMN] = _talkers(frame[TALKER_COLUMN].tolist(), out["platform"], source)
    columns = [c for c in frame.columns if c in out]
    checked = pd.DataFrame(
        {
            c: np.asarray(out[c], dtype=object if c in ("sensor", "platform", TALKER_COLUMN) else float)
            for c in columns
        }
    )
    checked.attrs["source"] = source
    return checked


def _talkers(values: list, platforms: list[str], source: str) -> list[str]:
    talkers: list[str] = []
    seen: dict = {}
    for row, v in enumerate(values):
        text = "" if v is None or (isinstance(v, float) and math.isnan(v)) else str(v).strip().upper()
        if text and not _TALKER.match(text):
            raise ValueError(
                f"{_where(source, row, TALKER_COLUMN)}: {v!r} is not an NMEA talker (two letters or "
                "digits, such as RA)"
            )
        key = (platforms[row], text)
        if text and key in seen:
            raise ValueError(
                f"{_where(source, row, TALKER_COLUMN)}: talker {text!r} is given twice on platform "
                f"{platforms[row]!r} (first at row {seen[key]}); one talker names one sensor"
            )
        seen[key] = row
        talkers.append(text)
    return talkers


def read_sensors(path: str | Path) -> pd.DataFrame:
    """Read and check a sensors file (CSV or Parquet; the fleet columns plus ``talker``): the
    checked DataFrame of :func:`check_sensors`, its errors naming the file."""
    import pandas as pd

    path = Path(path)
    if not path.is_file():
        raise ValueError(f"{path}: no such file")
    try:
        if path.suffix.lower() == ".parquet":
            frame = pd.read_parquet(path)
        else:
            frame = pd.read_csv(path, dtype=str, keep_default_na=False, skipinitialspace=True)
    except Exception as exc:  # pandas/pyarrow parse errors of many types
        raise read_error(path, exc, "cannot read it as a table") from exc
    return check_sensors(frame, str(path))


def platform_sensors(sensors: pd.DataFrame, platform: str, source: str = "sensors") -> pd.DataFrame:
    """The rows of ``platform`` of a checked sensors table; ValueError when it has none. A sensor that
    TTM sentences will feed (one with a talker, or the platform's only sensor) must have
    ``sigma_range_m`` and ``sigma_bearing_deg``: TTM gives both."""
    rows = sensors[sensors["platform"] == str(platform)].reset_index(drop=True)
    if len(rows) == 0:
        raise ValueError(
            f"{source}: no sensor on platform {str(platform)!r} "
            f"(platforms in the table: {sorted(set(sensors['platform']))})"
        )
    talkers, only = talker_map(rows)
    fed = set(talkers.values()) | ({only} if only else set())
    for s in sorted(fed):
        r = rows[rows["sensor"] == s].iloc[0]
        for column in ("sigma_range_m", "sigma_bearing_deg"):
            if column not in rows.columns or not np.isfinite(r[column]):
                raise ValueError(
                    f"{source}: sensor {s!r} receives TTM plots (range and bearing) but has no {column}; "
                    f"give its noise sigma"
                )
    return rows


def talker_map(rows: pd.DataFrame) -> tuple[dict[str, str], str | None]:
    """(talker -> sensor, the sensor of TTMs of other talkers) of one platform's checked rows: the
    sensor of other talkers is the platform's only sensor when it has one and no talker is given,
    else None (such TTMs are set aside)."""
    talkers = {}
    if TALKER_COLUMN in rows.columns:
        talkers = {t: s for t, s in zip(rows[TALKER_COLUMN], rows["sensor"]) if t}
    only = str(rows["sensor"].iloc[0]) if len(rows) == 1 and not talkers else None
    return talkers, only
