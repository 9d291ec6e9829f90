"""A fleet registration problem: the checked description built from the long-form tables.

:func:`build_problem` (also :meth:`FleetProblem.from_tables`) reads the tables of
:mod:`registration.fleet.data.tables`, checks them (errors name the table, row and object),
interpolates each platform's navigation to the plot times, lays out the registration state
(:class:`~registration.fleet.data.layout.StateLayout`) and sets aside the targets that carry no
registration information: a target seen by one sensor only, and not a reference, fits that
sensor's plots exactly whatever the errors are.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from registration.fleet.data.known_targets import References, SurfaceTargets, read_references, read_surface
from registration.fleet.data.layout import StateLayout, make_layout
from registration.fleet.data.navigation import (
    navigation_at,
    navigation_rate_at,
    outside_navigation,
    platform_navigation,
    unused_platforms,
)
from registration.fleet.data.plot_rows import RowProblem, plot_problems, read_plots
from registration.fleet.data.sensor_specs import read_platforms, read_sensors
from registration.fleet.data.tables import index_of, read_table

__all__ = ["Exclusion", "FleetProblem", "build_problem", "plot_row_problems"]


@dataclass(frozen=True)
class Exclusion:
    """Plots set aside: which target, over which time span (s), how many plots, and why."""

    target: str
    reason: str
    n_plots: int
    t_start: float
    t_end: float

    def text(self) -> str:
        span = f"{self.n_plots} plots, {self.t_start:g} s to {self.t_end:g} s"
        return f"target {self.target} ({span}): {self.reason}"


@dataclass(frozen=True)
class FleetProblem:
    """Platforms, sensors, plots (with their platform's navigation) and references, checked.

    Per kept plot ``i`` (N in all): ``time[i]`` s, ``sensor[i]`` and ``platform[i]`` (indices
    into ``sensor_ids``/``platform_ids``), ``target[i]`` (index into ``target_ids``), ``meas[i]``
    (range m, bearing rad, elevation rad; 0 where not measured), ``mask[i]`` (True where measured),
    ``nav[i]`` (lat, lon rad, alt m, heading, pitch, roll rad as reported), and ``row[i]``, its row
    in the input plots table. Sensors: ``sensor_sigma`` (S, 3) noise sigma (NaN = not measured),
    ``sensor_lever`` (S, 3) m, deck frame. ``excluded``: targets set aside, with reasons.
    ``notes``: what was ignored without an error (the navigation of platforms that carry no
    sensor), one text each. ``surface``: the targets that move on a surface of known height, by id
    (None: none does; :meth:`surface_of_targets` gives them per target).
    """

    platform_ids: tuple[str, ...]
    sensor_ids: tuple[str, ...]
    target_ids: tuple[str, ...]
    sensor_platform: np.ndarray
    sensor_sigma: np.ndarray
    sensor_lever: np.ndarray
    layout: StateLayout
    time: np.ndarray
    sensor: np.ndarray
    target: np.ndarray
    meas: np.ndarray
    mask: np.ndarray
    nav: np.ndarray
    row: np.ndarray
    n_input_plots: int
    references: References
    ref_target: np.ndarray  # (R,) index into target_ids
    excluded: tuple[Exclusion, ...] = field(default_factory=tuple)
    tracks: dict | None = None  # per platform id: navigation (times, values), for plots seen at other times
    notes: tuple[
        str, ...
    ] = ()  # what was ignored without an error, e.g. navigation of platforms without sensors
    surface: SurfaceTargets | None = None  # targets on a surface of known height, by id

    def navigation_at(
        self, time: np.ndarray, plot: np.ndarray | None = None
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(nav (M, 6), its rate (M, 6), outside (M,) bool) of the platforms of plots ``plot`` (M,;
        default all) at times ``time`` (M,) s, for plots seen at times corrected by a time bias:
        the navigation on the C1 Hermite curve through its samples, its rate of change (rad/s, m/s)
        and whether a time lies outside the platform's navigation span (the nearest end is used
        there). See :class:`registration.fleet.data.navigation.SeenNavigation`."""
        plot = np.arange(self.n_plots) if plot is None else plot
        if self.tracks is None:
            raise ValueError("this problem was built without its navigation tracks")
        return navigation_rate_at(self.tracks, self.platform_ids, self.platform[plot], time)

    def seen(self, x: np.ndarray, plot: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(time (M,) s, nav (M, 6) rad/m, rate (M, 6) rad/s, m/s) of plots ``plot`` (M,) under the
        states ``x`` (n,; rad, m, 1, s): the time each plot's target and platform were seen (reported
        time minus its sensor's time bias), the platform's navigation then and its rate
        (:meth:`navigation_at`; outside the navigation's span, its nearest end). Without time
        biases: the reported time, the navigation at it and a rate of 0."""
        if not self.layout.time_biased:
            return self.time[plot], self.nav[plot], np.zeros((np.size(plot), 6))
        xs = np.append(np.asarray(x, dtype=np.float64), 0.0)
        t = self.time[plot] - xs[self.layout.sensor_states(self.sensor[plot], self.sensor_platform)[:, 7]]
        nav, rate, _ = self.navigation_at(t, plot)
        return t, nav, rate

    def surface_of_targets(self) -> tuple[np.ndarray, np.ndarray] | None:
        """(alt (T,) m above WGS-84, sigma (T,) m) of the surface each of ``target_ids`` moves on
        (NaN: not a surface target), or None when no target of the problem is on a surface."""
        if self.surface is None:
            return None
        alt, sigma = self.surface.of(self.target_ids)
        return (alt, sigma) if np.isfinite(alt).any() else None

    def targets_without_height(self) -> tuple[str, ...]:
        """The targets whose height nothing but slant ranges measures: no plot of theirs has an
        elevation, no reference position of theirs a height (``sigma_up`` inf) and they are not on a
        surface. Their height is then determined only weakly (to second order in the ranges), and it
        trades off against the range biases."""
        measured = np.zeros(len(self.target_ids), dtype=bool)
        measured[self.target[self.mask[:, 2]]] = True
        refs = self.references
        measured[self.ref_target[np.isfinite(refs.up_sigma)]] = True
        surface = self.surface_of_targets()
        if surface is not None:
            measured |= np.isfinite(surface[0])
        return tuple(t for t, m in zip(self.target_ids, measured) if not m)

    @property
    def n_plots(self) -> int:
        return int(self.time.shape[0])

    @property
    def platform(self) -> np.ndarray:
        return self.sensor_platform[self.sensor]

    @property
    def sigma(self) -> np.ndarray:
        """(N, 3) noise sigma of each plot's channels (NaN where not measured)."""
        return np.where(self.mask, self.sensor_sigma[self.sensor], np.nan)

    @classmethod
    def from_tables(
        cls, plots, sensors, navigation, platforms=None, references=None, targets=None
    ) -> "FleetProblem":
        """See :func:`build_problem`."""
        return build_problem(plots, sensors, navigation, platforms, references, targets)

    def drop_plots(self, drop: np.ndarray, exclusions) -> "FleetProblem":
        """The problem without the plots flagged in ``drop`` (N,), with ``exclusions`` recorded."""
        keep = ~np.asarray(drop, dtype=bool)
        per_plot = {
            k: getattr(self, k)[keep] for k in ("time", "sensor", "target", "meas", "mask", "nav", "row")
        }
        return replace(self, **per_plot, excluded=self.excluded + tuple(exclusions))

    def lines(self) -> list[str]:
        """A short human-readable summary."""
        out = [
            f"{len(self.platform_ids)} platforms, {len(self.sensor_ids)} sensors, "
            f"{len(self.target_ids)} targets, {self.n_plots} plots used of {self.n_input_plots}, "
            f"{len(self.references.time)} reference positions, "
            f"{self.layout.n} states ({self.layout.free.size} estimated)"
        ]
        out += [f"  excluded: {e.text()}" for e in self.excluded]
        out += [f"  note: {n}" for n in self.notes]
        return out


def _first_seen(ids: np.ndarray) -> tuple[str, ...]:
    """The distinct ids in order of first appearance."""
    unique, first = np.unique(ids, return_index=True)
    return tuple(str(u) for u in unique[np.argsort(first)])


def _seen_by_one_sensor(
    target: np.ndarray, sensor: np.ndarray
) -> tuple[tuple[str, ...], np.ndarray, np.ndarray]:
    """Targets in order of first appearance, each plot's index into them, and the targets (indices)
    seen by one sensor only."""
    targets = _first_seen(target)
    which = index_of(target, targets)
    # the distinct (target, sensor) pairs as one integer key each (np.unique on columns sorts
    # tuples: a tenth of a second on 180 000 plots)
    span = int(np.max(sensor, initial=0)) + 1
    pairs = np.unique(which.astype(np.int64) * span + np.asarray(sensor, dtype=np.int64))
    n_sensors = np.bincount(pairs // span, minlength=len(targets))
    return targets, which, np.flatnonzero(n_sensors == 1)


def _single_sensor_targets(plots, references) -> list[Exclusion]:
    """Targets seen by one sensor only and not references: no registration information."""
    out = []
    refs = set(references.target)
    targets, which, single = _seen_by_one_sensor(plots.target, plots.sensor)
    for k in single:
        tid = targets[k]
        if tid not in refs:
            sel = which == k
            t = plots.time[sel]
            out.append(
                Exclusion(
                    str(tid),
                    "seen by one sensor only and not a reference: its plots fit any "
                    "registration errors, so they carry no registration information",
                    int(sel.sum()),
                    float(t.min()),
                    float(t.max()),
                )
            )
    return out


def plot_row_problems(plots, sensors, navigation, platforms=None, reference_targets=()) -> list[RowProblem]:
    """The problems of the plots rows that :func:`build_problem` raises for, per row, in its order
    (:func:`~registration.fleet.data.plot_rows.plot_problems`, then ``outside_navigation``: a plot outside
    its platform's navigation time span, not counting the targets it sets aside as seen by one
    sensor, unless in ``reference_targets``). The other tables are checked as build_problem does
    (ValueError naming table, row and object)."""
    sensors_t = read_table("sensors", sensors, ("sensor", "platform"))
    platform_ids, _ = read_platforms(platforms, sensors_t.ids("platform"))
    specs = read_sensors(sensors_t, platform_ids)
    plots_t = read_table("plots", plots, ("time", "sensor"))
    problems = plot_problems(plots_t, specs)
    valid = ~np.any([p.bad for p in problems], axis=0)
    tracks = platform_navigation(read_table("navigation", navigation, ("platform",)), platform_ids)
    time = plots_t.floats("time")
    # without target ids (plots to be associated) no target is set aside as seen by one sensor
    target = plots_t.ids("target") if plots_t.has("target") else np.full(plots_t.n_rows, "")
    sensor = np.where(valid, index_of(plots_t.ids("sensor"), specs.ids), 0)
    targets, which, single = _seen_by_one_sensor(target[valid], sensor[valid])
    set_aside = [
        targets[k] for k in single if targets[k] not in set(np.asarray(reference_targets).astype(str))
    ]
    platform = specs.platform[sensor]
    outside = valid & ~np.isin(target, set_aside) & outside_navigation(tracks, platform_ids, platform, time)

    def message(row: int) -> str:
        pid = platform_ids[platform[row]]
        t = tracks[pid][0]
        return (
            f"plot of sensor {specs.ids[sensor[row]]!r} at {time[row]:g} s lies outside the navigation of "
            f"platform {str(pid)!r} ({t[0]:g} s to {t[-1]:g} s)"
        )

    return problems + [RowProblem("outside_navigation", "time", outside, message)]


def build_problem(plots, sensors, navigation, platforms=None, references=None, targets=None) -> FleetProblem:
    """Check the long-form tables (see :mod:`registration.fleet.data.tables`) and build the problem.
    ``targets``: the optional targets table (the surface targets move on, docs/background/fleet-model.md).

    ValueError names the table, row and object for: a missing column, an unknown sensor,
    platform or reference target, a sensor with no measured channel, a negative or zero noise
    sigma, a negative prior, a value out of range (with a hint when degrees seem to have been
    given for radians), a plot outside its platform's navigation time span, an empty plots table,
    plots with values in a channel whose sigma column the sensors table lacks. The navigation of
    platforms that carry no sensor is ignored, and named in ``problem.notes``.
    """
    sensors_t = read_table("sensors", sensors, ("sensor", "platform"))
    platform_ids, platform_priors = read_platforms(platforms, sensors_t.ids("platform"))
    specs = read_sensors(sensors_t, platform_ids)
    plots_t = read_table("plots", plots, ("time", "sensor", "target"))
    if plots_t.n_rows == 0:
        raise ValueError("plots: the table has no rows, so there is nothing to register")
    cols = read_plots(plots_t, specs)
    refs = read_references(references, list(dict.fromkeys(cols.target)))
    excluded = _single_sensor_targets(cols, refs)
    keep = np.flatnonzero(~np.isin(cols.target, [e.target for e in excluded]))
    target_ids = _first_seen(cols.target[keep])
    sensor = cols.sensor[keep]
    time = cols.time[keep]
    nav_t = read_table("navigation", navigation, ("platform",))
    tracks = platform_navigation(nav_t, platform_ids)

    def describe(i: int) -> str:
        return f"plots row {int(keep[i])} (sensor {str(specs.ids[sensor[i]])!r}, time {time[i]:g} s)"

    nav = navigation_at(tracks, platform_ids, specs.platform[sensor], time, describe)
    layout = make_layout(
        platform_ids,
        platform_priors,
        specs.ids,
        specs.channels,
        specs.prior,
        specs.extended_prior,
        specs.eccentricity_prior,
        specs.channel_of,
        refs.offset_prior,
    )
    ref_keep = np.isin(refs.target, target_ids)
    refs = refs.subset(ref_keep)
    return FleetProblem(
        platform_ids=tuple(platform_ids),
        sensor_ids=specs.ids,
        target_ids=target_ids,
        sensor_platform=specs.platform,
        sensor_sigma=specs.sigma,
        sensor_lever=specs.lever,
        layout=layout,
        time=time,
        sensor=sensor,
        target=index_of(cols.target[keep], target_ids),
        meas=cols.meas[keep],
        mask=cols.mask[keep],
        nav=nav,
        row=keep,
        n_input_plots=int(cols.time.shape[0]),
        references=refs,
        ref_target=index_of(refs.target, target_ids),
        excluded=tuple(excluded),
        tracks=tracks,
        notes=tuple(unused_platforms(nav_t, platform_ids)),
        surface=read_surface(targets),
    )
