"""Checks and conversion of the platforms, sensors, plots and references tables (see
:mod:`registration.fleet.data.tables` for their columns and units). Every error names the table, the
row and the object (platform, sensor or target id)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, NamedTuple

import numpy as np

from registration.core.frames import geodetic2ecef
from registration.core.validation import check_range, degree_hint
from registration.fleet.data.tables import (
    ATTITUDE_ERRORS,
    CHANNELS,
    DEFAULT_REFERENCE_SIGMA,
    EXTENDED_PRIOR_COLUMNS,
    Table,
    read_table,
)

__all__ = [
    "index_of",
    "SensorSpecs",
    "PlotColumns",
    "References",
    "RowProblem",
    "plot_problems",
    "read_platforms",
    "read_sensors",
    "read_plots",
    "read_references",
    "read_surface",
    "SurfaceTargets",
]

#: The accepted window of each measured channel (low, high, unit).
CHANNEL_LIMITS = {
    "range": (0.0, 1.0e8, "m (slant range, > 0)"),
    "bearing": (-2 * np.pi, 2 * np.pi, "rad"),
    "elevation": (-np.pi / 2, np.pi / 2, "rad"),
}
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
        ids = tuple(str(p) for p in dict.fromkeys(sensor_platforms))
        return ids, np.full((len(ids), 3), np.inf)
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


def index_of(values: np.ndarray, ids) -> np.ndarray:
    """Index of each of ``values`` (strings) in ``ids``; -1 where absent (vectorised)."""
    unique, inverse = np.unique(values, return_inverse=True)
    lookup = {v: i for i, v in enumerate(ids)}
    return np.array([lookup.get(u, -1) for u in unique], dtype=np.int64)[inverse].reshape(values.shape)


@dataclass(frozen=True)
class SensorSpecs:
    """Sensors in table order: platform index (S,), measured channels (S, 3) bool, noise sigma
    (S, 3) m/rad (NaN where not measured), bias priors (S, 3), lever arm (S, 3) m (deck frame),
    priors of the extended errors (S, 5) in EXTENDED_ERRORS order (NaN = not modelled);
    ``sigma_columns``: per channel, whether the table has its sigma column at all."""

    ids: tuple[str, ...]
    platform: np.ndarray
    channels: np.ndarray
    sigma: np.ndarray
    prior: np.ndarray
    lever: np.ndarray
    extended_prior: np.ndarray
    sigma_columns: tuple[bool, ...] = (True, True, True)


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
                f"sensor {str(ids[row])!r} is on unknown platform {str(p)!r} (platforms: {list(platform_ids)})",
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
    )


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


@dataclass(frozen=True)
class PlotColumns:
    """Plots in table order: time (N,) s, sensor index (N,), target id (N,), measured values (N, 3)
    (m, rad, rad; 0 where not measured), mask (N, 3) True where measured."""

    time: np.ndarray
    sensor: np.ndarray
    target: np.ndarray
    meas: np.ndarray
    mask: np.ndarray


class RowProblem(NamedTuple):
    """One kind of problem of a table's rows: reason ``code`` and ``column`` (a str, or per row an
    (N,) array of str), the rows it hits ``bad`` (N,) bool, and ``message(row)``, the reason of one
    row (without the table and row, which :meth:`Table.error` adds)."""

    code: str | np.ndarray
    column: str | np.ndarray
    bad: np.ndarray
    message: Callable[[int], str]

    def at(self, row: int) -> tuple[str, str]:
        """(code, column) of one row."""
        return tuple(v if isinstance(v, str) else str(v[row]) for v in (self.code, self.column))


def _channel_problem(values: np.ndarray, k: int, sensor_ids, sensor: np.ndarray) -> RowProblem:
    """Values of channel k outside its window (or infinite); codes as the recorded files' reasons."""
    name = CHANNELS[k]
    lo, hi, unit = CHANNEL_LIMITS[name]
    finite = np.isfinite(values)
    below = finite & ((values <= lo) if k == 0 else (values < lo))
    bad = np.isinf(values) | below | (finite & (values > hi))
    code = np.where(
        np.isinf(values), "non_finite", np.where(below & (k == 0), "non_positive_range", "out_of_range")
    )

    def message(row: int) -> str:
        hint = degree_hint(values[finite], max(abs(lo), abs(hi))) if k else ""
        return (
            f"{name} {values[row]} of sensor {str(sensor_ids[sensor[row]])!r} is outside "
            f"{'(' if k == 0 else '['}{lo:g}, {hi:g}] {unit}{hint}"
        )

    return RowProblem(code, name, bad, message)


def _article(word: str) -> str:
    return ("an " if word[:1] in "aeiou" else "a ") + word


def _missing_sigma_columns(sensors: SensorSpecs, names: np.ndarray, mask: np.ndarray) -> None:
    """A ValueError, the sensors table's, for a channel with plot values whose sigma column the
    sensors table lacks altogether (no sensor measures it): not the plots' fault row by row."""
    for k, c in enumerate(CHANNELS):
        if not sensors.sigma_columns[k] and mask[:, k].any():
            row = int(np.argmax(mask[:, k]))
            which = [str(s) for s in np.unique(names[mask[:, k]])]
            raise ValueError(
                f"sensors: no sigma_{c} column, but the plots have {c} values for sensor(s) {which} "
                f"({int(mask[:, k].sum())} plots; the first, plots row {row}): give the sensors' "
                f"sigma_{c}, or leave the plots' {c} empty (NaN)"
            )


def plot_problems(table: Table, sensors: SensorSpecs) -> list[RowProblem]:
    """The problems of the plots rows, in the order :func:`read_plots` checks them: time not
    finite, unknown sensor, a channel outside its window, a value in a channel the sensor does not
    measure, no measured channel. A row may be hit by several; its first one is its reason.
    ValueError (the sensors table's) when the plots have values of a channel whose sigma column
    the sensors table lacks."""
    time = table.floats("time")
    names = table.ids("sensor")
    sensor = index_of(names, sensors.ids)
    known = sensor >= 0
    meas = np.stack([table.floats(c, default=np.nan) for c in CHANNELS], axis=1)
    mask = np.isfinite(meas)
    _missing_sigma_columns(sensors, names, mask & known[:, None])
    extra = mask & ~sensors.channels[np.where(known, sensor, 0)] & known[:, None]
    first_extra = np.array(CHANNELS)[np.argmax(extra, axis=1)]

    def unmeasured(row: int) -> str:
        c = first_extra[row]
        return (
            f"sensor {str(names[row])!r} has {_article(c)} value but does not measure {c} (its sigma_{c} in the "
            f"sensors table is empty): give it there, or leave the plots' {c} of this sensor empty"
        )

    return [
        RowProblem(
            "non_finite",
            "time",
            ~np.isfinite(time),
            lambda r: f"time {time[r]} is not a finite number of seconds",
        ),
        RowProblem(
            "unknown_sensor",
            "sensor",
            ~known,
            lambda r: f"unknown sensor {str(names[r])!r} (sensors: {list(sensors.ids)})",
        ),
        *(_channel_problem(meas[:, k], k, sensors.ids, sensor) for k in range(3)),
        RowProblem("unmeasured_channel", first_extra, extra.any(axis=1), unmeasured),
        RowProblem(
            "no_channel",
            "range",
            ~mask.any(axis=1),
            lambda r: f"plot of sensor {str(names[r])!r} has no measured channel",
        ),
    ]


def read_plots(table: Table, sensors: SensorSpecs) -> PlotColumns:
    """The checked plots; ValueError naming the row and sensor for the first of :func:`plot_problems`."""
    for problem in plot_problems(table, sensors):
        if problem.bad.any():
            row = int(np.flatnonzero(problem.bad)[0])
            raise table.error(row, problem.message(row))
    meas = np.stack([table.floats(c, default=np.nan) for c in CHANNELS], axis=1)
    mask = np.isfinite(meas)
    return PlotColumns(
        table.floats("time"),
        index_of(table.ids("sensor"), sensors.ids),
        table.ids("target"),
        np.where(mask, meas, 0.0),
        mask,
    )


@dataclass(frozen=True)
class References:
    """Known target positions: target id (R,), time (R,) s, p_ecef (R, 3) m, sigma (R,) m and
    sigma_up (R,) m. ``sigma`` is the standard deviation of each ECEF axis when ``sigma_up`` equals
    it (the default: None gives a copy of ``sigma``); otherwise ``sigma`` is the horizontal one
    (east and north) and ``sigma_up`` the one along the local geodetic up at the position."""

    target: np.ndarray
    time: np.ndarray
    p_ecef: np.ndarray
    sigma: np.ndarray
    sigma_up: np.ndarray | None = None

    def __post_init__(self) -> None:
        if self.sigma_up is None:
            object.__setattr__(self, "sigma_up", np.array(self.sigma, dtype=np.float64, copy=True))

    @staticmethod
    def empty() -> "References":
        return References(np.array([], dtype=object), np.zeros(0), np.zeros((0, 3)), np.zeros(0), np.zeros(0))

    def subset(self, which: np.ndarray) -> "References":
        """The references selected by ``which``: an (R,) bool mask or an array of indices (in the
        order given), every field taken alike."""
        return References(
            self.target[which], self.time[which], self.p_ecef[which], self.sigma[which], self.sigma_up[which]
        )


def read_references(references, target_ids) -> References:
    if references is None:
        return References.empty()
    table = read_table("references", references, ("target", "time"))
    target = table.ids("target")
    known = set(target_ids)
    for row, t in enumerate(target):
        if t not in known:
            raise table.error(
                row, f"reference target {str(t)!r} has no plots (targets: {sorted(str(k) for k in known)})"
            )
    time = table.floats("time")
    if table.has("x"):
        p = np.stack([table.floats(c) for c in "xyz"], axis=1)
        check_range("references.x/y/z", p, -1.0e8, 1.0e8, "m (ECEF)")
    elif table.has("lat"):
        p = geodetic2ecef(table.floats("lat"), table.floats("lon"), table.floats("alt"))
    else:
        raise ValueError(
            "references: give the known position as ECEF x, y, z (m) or as lat, lon (rad), alt (m)"
        )
    sigma = table.floats("sigma", default=DEFAULT_REFERENCE_SIGMA)
    bad = np.flatnonzero(~(np.isfinite(time) & (sigma > 0) & np.isfinite(sigma)))
    if bad.size:
        r = int(bad[0])
        raise table.error(
            r,
            f"reference of target {str(target[r])!r}: time {time[r]} s and sigma {sigma[r]} m must be "
            "finite and sigma > 0 (the accuracy of the known position)",
        )
    sigma_up = table.floats("sigma_up", default=np.nan)
    sigma_up = np.where(np.isnan(sigma_up), sigma, sigma_up)  # not given: the same as sigma
    bad = np.flatnonzero(~(sigma_up > 0))
    if bad.size:
        r = int(bad[0])
        raise table.error(
            r,
            f"reference of target {str(target[r])!r}: sigma_up {sigma_up[r]} m must be > 0 "
            "(the accuracy of the known position along the local up; NaN: the same as sigma; "
            "inf: no height known)",
        )
    return References(target, time, p.reshape(-1, 3), sigma, sigma_up)


@dataclass(frozen=True)
class SurfaceTargets:
    """Targets that move on a surface of known height, such as ships on the sea: ``target`` ids
    (K,), ``alt`` (K,) m above the WGS-84 ellipsoid and its standard deviation ``sigma`` (K,) m
    (what the targets table's ``surface_alt`` and ``sigma_surface`` give)."""

    target: np.ndarray
    alt: np.ndarray
    sigma: np.ndarray

    def of(self, target_ids) -> tuple[np.ndarray, np.ndarray]:
        """(alt, sigma), each (T,) m, of the targets ``target_ids``; NaN where not on a surface."""
        row = index_of(np.asarray(target_ids, dtype=str), list(self.target))
        listed = row >= 0
        at = np.where(listed, row, 0)  # read_surface makes none without a target
        return np.where(listed, self.alt[at], np.nan), np.where(listed, self.sigma[at], np.nan)


def read_surface(targets) -> SurfaceTargets | None:
    """The surface targets of the optional ``targets`` table (None: no table, or no row gives a
    ``surface_alt``). A target listed twice, a height further than 10 km from the ellipsoid, or a
    surface height without a finite ``sigma_surface`` > 0 is an error naming the row."""
    if targets is None:
        return None
    table = read_table("targets", targets, ("target",))
    ids = table.ids("target")
    alt = table.floats("surface_alt", default=np.nan)
    sigma = table.floats("sigma_surface", default=np.nan)
    seen: dict = {}
    for row, t in enumerate(ids):
        if t in seen:
            raise table.error(row, f"target {str(t)!r} is listed again (first in row {seen[t]})")
        seen[t] = row
        if np.isnan(alt[row]):
            continue
        if not (np.isfinite(alt[row]) and -1.0e4 <= alt[row] <= 1.0e4):
            raise table.error(
                row,
                f"target {str(t)!r}: surface_alt {alt[row]} m must lie within 10 km of the "
                "WGS-84 ellipsoid (the height of the surface the target moves on)",
            )
        if not (np.isfinite(sigma[row]) and sigma[row] > 0):
            raise table.error(
                row,
                f"target {str(t)!r}: sigma_surface {sigma[row]} m must be finite and > 0 "
                "(the standard deviation of the target's height about surface_alt)",
            )
    on = np.isfinite(alt)
    if not on.any():
        return None
    return SurfaceTargets(ids[on], alt[on], sigma[on])
