"""The sensors and platforms tables checked and converted (see :mod:`registration.fleet.data.tables`
for their columns and units): each sensor's platform, measured channels, noise, bias priors, lever
arm and extended-error priors (:class:`SensorSpecs`), and each platform's attitude-error priors.
Every error names the table, the row and the sensor or platform id."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.core.validation import check_range
from registration.fleet.data.tables import (
    ATTITUDE_ERRORS,
    CHANNELS,
    ECCENTRICITY_PRIOR_COLUMN,
    EXTENDED_PRIOR_COLUMNS,
    Table,
    read_table,
)

__all__ = ["MAX_ANGLE_SIGMA", "MAX_GAIN_PRIOR", "SensorSpecs", "read_platforms", "read_sensors"]

#: A noise sigma above this (rad) for an angle channel is taken for degrees.
MAX_ANGLE_SIGMA = 0.35
#: The largest accepted prior sigma of a range gain (dimensionless: 0.1 = 10 %).
MAX_GAIN_PRIOR = 0.1


def _sigma_column(table: Table, column: str, rows_ids, *, allow_missing: bool, what: str) -> np.ndarray:
    """A non-negative sigma column; NaN means 'missing' when allowed, else 'no prior' (inf).
    Errors name the row and the object."""
    values = table.floats(column, default=np.nan if allow_missing else np.inf)
    if not allow_missing:
        values = np.where(np.isnan(values), np.inf, values)
    for row in range(table.n_rows):
        v = values[row]
        if np.isnan(v):
            continue
        if v < 0:
            raise table.error(
                row, f"{column} of {what} {str(rows_ids[row])!r} is {v}; expected a standard deviation >= 0"
            )
    return values


def read_platforms(platforms, sensor_platforms: np.ndarray) -> tuple[tuple[str, ...], np.ndarray]:
    """Platform ids (table order, else order of first use by a sensor) and their attitude-error
    priors (P, 3) rad (inf = none, 0 = fixed)."""
    if platforms is None:
        used = tuple(str(p) for p in dict.fromkeys(sensor_platforms))
        return used, np.full((len(used), 3), np.inf)
    table = read_table("platforms", platforms, ("platform",))
    ids = table.ids("platform")
    dupes = sorted({p for p in ids if list(ids).count(p) > 1})
    if dupes:
        raise ValueError(f"platforms: duplicate platform ids {dupes}")
    priors = np.stack(
        [
            _sigma_column(table, f"prior_{a}", ids, allow_missing=False, what="platform")
            for a in ATTITUDE_ERRORS
        ],
        axis=1,
    )
    return tuple(str(p) for p in ids), priors


@dataclass(frozen=True)
class SensorSpecs:
    """Sensors in table order: platform index (S,), measured channels (S, 3) bool, noise sigma
    (S, 3) m/rad (NaN where not measured), bias priors (S, 3), lever arm (S, 3) m (deck frame),
    priors of the extended errors (S, 5) in EXTENDED_ERRORS order (NaN = not modelled);
    ``sigma_columns``: per channel, whether the table has its sigma column at all;
    ``eccentricity_prior`` (S,) rad, the prior of both eccentricity terms (NaN = not modelled);
    ``channel_of`` (S,) the index of the sensor each one is a channel of (-1: none)."""

    ids: tuple[str, ...]
    platform: np.ndarray
    channels: np.ndarray
    sigma: np.ndarray
    prior: np.ndarray
    lever: np.ndarray
    extended_prior: np.ndarray
    sigma_columns: tuple[bool, ...] = (True, True, True)
    eccentricity_prior: np.ndarray | None = None
    channel_of: np.ndarray | None = None


def read_sensors(table: Table, platform_ids) -> SensorSpecs:
    ids = table.ids("sensor")
    dupes = sorted({s for s in ids if list(ids).count(s) > 1})
    if dupes:
        raise ValueError(f"sensors: duplicate sensor ids {dupes}")
    plat = table.ids("platform")
    index = {p: i for i, p in enumerate(platform_ids)}
    for row, p in enumerate(plat):
        if p not in index:
            raise table.error(
                row,
                f"sensor {str(ids[row])!r} is on unknown platform {str(p)!r} "
                f"(platforms: {list(platform_ids)})",
            )
    sigma = np.stack(
        [_sigma_column(table, f"sigma_{c}", ids, allow_missing=True, what="sensor") for c in CHANNELS], axis=1
    )
    for row in range(table.n_rows):
        if np.any(sigma[row] == 0):
            k = int(np.flatnonzero(sigma[row] == 0)[0])
            raise table.error(
                row,
                f"sigma_{CHANNELS[k]} of sensor {str(ids[row])!r} is 0; a measured channel needs a noise "
                "standard deviation > 0 (NaN = channel not measured)",
            )
        if np.all(np.isnan(sigma[row])):
            raise table.error(
                row,
                f"sensor {str(ids[row])!r} measures no channel: give sigma_range, sigma_bearing "
                "and/or sigma_elevation",
            )
        if np.nanmax(sigma[row, 1:], initial=0.0) > MAX_ANGLE_SIGMA:
            raise table.error(
                row, f"angle sigma of sensor {str(ids[row])!r} above 20 deg; pass radians, not degrees"
            )
    prior = np.stack(
        [_sigma_column(table, f"prior_{c}", ids, allow_missing=False, what="sensor") for c in CHANNELS],
        axis=1,
    )
    lever = np.stack([table.floats(f"lever_{a}", default=0.0) for a in "xyz"], axis=1)
    check_range("sensors.lever", lever, -1.0e4, 1.0e4, "m (deck frame)")
    return SensorSpecs(
        tuple(str(s) for s in ids),
        np.array([index[p] for p in plat], dtype=np.int64),
        ~np.isnan(sigma),
        sigma,
        prior,
        lever,
        _extended_priors(table, ids),
        tuple(table.has(f"sigma_{c}") for c in CHANNELS),
        _eccentricity_priors(table, ids),
        _channel_of(table, ids, plat, lever),
    )


def _eccentricity_priors(table: Table, ids) -> np.ndarray:
    """(S,) prior sigma (rad) of each sensor's eccentricity terms: NaN without the column (not
    modelled), inf for an empty cell or inf (no prior); a negative one names the row."""
    if not table.has(ECCENTRICITY_PRIOR_COLUMN):
        return np.full(table.n_rows, np.nan)
    values = _sigma_column(table, ECCENTRICITY_PRIOR_COLUMN, ids, allow_missing=False, what="sensor")
    big = np.flatnonzero(np.isfinite(values) & (values > MAX_ANGLE_SIGMA))
    if big.size:
        row = int(big[0])
        raise table.error(
            row,
            f"{ECCENTRICITY_PRIOR_COLUMN} of sensor {str(ids[row])!r} is {values[row]}; expected a sigma "
            f"of at most {MAX_ANGLE_SIGMA} rad (20 deg)",
        )
    return values


def _channel_of(table: Table, ids, platform, lever: np.ndarray) -> np.ndarray:
    """(S,) index of the sensor each one is a channel of (``channel_of``; -1: none). A channel must
    name another sensor of the table that is not itself a channel, on the same platform with the
    same lever arm (one antenna); errors name the row."""
    out = np.full(table.n_rows, -1, dtype=np.int64)
    if not table.has("channel_of"):
        return out
    raw = table.require("channel_of")
    index = {str(s): i for i, s in enumerate(ids)}
    for row, value in enumerate(raw):
        name = "" if value is None or (isinstance(value, float) and np.isnan(value)) else str(value).strip()
        if name in ("", "nan"):
            continue
        sid = str(ids[row])
        if name not in index or name == sid:
            raise table.error(
                row,
                f"channel_of of sensor {sid!r} is {name!r}; expected the id of another sensor "
                f"(sensors: {list(map(str, ids))})",
            )
        out[row] = index[name]
    for row in np.flatnonzero(out >= 0).tolist():
        parent, sid = int(out[row]), str(ids[row])
        if out[parent] >= 0:
            raise table.error(
                row,
                f"channel_of of sensor {sid!r} names {str(ids[parent])!r}, itself a channel of "
                f"{str(ids[out[parent]])!r}; name the sensor itself",
            )
    for row in np.flatnonzero(out >= 0).tolist():
        parent, sid = int(out[row]), str(ids[row])
        if str(platform[row]) != str(platform[parent]) or not np.array_equal(lever[row], lever[parent]):
            raise table.error(
                row,
                f"sensor {sid!r} is a channel of {str(ids[parent])!r} but its platform or lever arm "
                "differs; a channel shares its sensor's antenna: give the same platform and lever",
            )
    return out


def _extended_priors(table: Table, ids) -> np.ndarray:
    """(S, 5) priors of the extended errors: NaN where the column is missing (not modelled), inf
    for an empty cell or inf (no prior); a negative sigma, or a gain sigma above MAX_GAIN_PRIOR, is
    an error naming the row and column."""
    out = np.full((table.n_rows, len(EXTENDED_PRIOR_COLUMNS)), np.nan)
    for k, column in enumerate(EXTENDED_PRIOR_COLUMNS):
        if table.has(column):
            out[:, k] = _sigma_column(table, column, ids, allow_missing=False, what="sensor")
    if table.has("prior_range_gain"):
        big = np.flatnonzero(np.isfinite(out[:, 0]) & (out[:, 0] > MAX_GAIN_PRIOR))
        if big.size:
            row = int(big[0])
            raise table.error(
                row,
                f"prior_range_gain of sensor {str(ids[row])!r} is {out[row, 0]}; expected a "
                f"dimensionless sigma <= {MAX_GAIN_PRIOR} (1e-4 = 100 ppm; not percent or ppm)",
            )
    return out
