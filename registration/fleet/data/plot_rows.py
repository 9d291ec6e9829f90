"""The plots table checked row by row and converted (see :mod:`registration.fleet.data.tables` for
its columns and units): the problems of each row (:class:`RowProblem`: what is wrong, where, why),
and the checked plots as typed columns (:class:`PlotColumns`). Every error names the table, the
row and the sensor."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, NamedTuple

import numpy as np

from registration.core.validation import TIME_LIMIT_S, degree_hint
from registration.fleet.data.sensor_specs import SensorSpecs
from registration.fleet.data.tables import CHANNELS, Table, index_of

__all__ = ["CHANNEL_LIMITS", "PlotColumns", "RowProblem", "plot_problems", "read_plots"]

#: The accepted window of each measured channel (low, high, unit).
CHANNEL_LIMITS = {
    "range": (0.0, 1.0e8, "m (slant range, > 0)"),
    "bearing": (-2 * np.pi, 2 * np.pi, "rad"),
    "elevation": (-np.pi / 2, np.pi / 2, "rad"),
}


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
        code, column = (v if isinstance(v, str) else str(v[row]) for v in (self.code, self.column))
        return code, column


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
            f"sensor {str(names[row])!r} has {_article(c)} value but does not measure {c} "
            f"(its sigma_{c} in the sensors table is empty): give it there, or leave the plots' {c} of "
            "this sensor empty"
        )

    return [
        RowProblem(
            "non_finite",
            "time",
            ~(np.abs(time) <= TIME_LIMIT_S),
            lambda r: f"time {time[r]} is not a finite number of seconds within +-{TIME_LIMIT_S:g} s",
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
