"""A simulated fleet for tests, examples and benchmarks (:func:`fleet_scenario`).

Three ships that pitch and roll, one shore site, six sensors of four kinds (3-D radars, a 2-D
radar on a ship and one on the shore, a passive angle sensor), five targets of which one
reports its own position (a reference target). Every sensor samples at its own rate and time
offset, so no two sensors share an instant. The geometry goes through the generated functions
(``geodetic2ecef``, ``enu2ecef_rotation_standard``, ``radii_of_curvature``, ``fleet_residual``);
the layout itself (tracks, rates, noise) is ours, documented in :data:`SHIPS`, :data:`SENSORS`,
:data:`TARGETS`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration._generated import api as generated
from registration.core.angles import wrap_angle
from registration.core.frames import ecef2geodetic
from registration.fleet.data.problem import FleetProblem, build_problem
from registration.fleet.data.tables import NAV_COLUMNS
from registration.fleet.simulation.coverage import coverage_for, visible
from registration.fleet.simulation.tracks import Circle, Line, ShipTrack, enu2ecef_points

__all__ = [
    "DEFAULT_FLEET",
    "FleetConfig",
    "FleetScenario",
    "fleet_scenario",
    "SHIPS",
    "SITE",
    "SENSORS",
    "TARGETS",
    "CENTRE",
]

#: Centre of the exercise area (lat, lon rad; alt m): the ENU origin of the targets' tracks.
CENTRE = (np.radians(36.0), np.radians(14.5), 0.0)
#: Ships: start east/north of CENTRE (m), course (rad from north), speed (m/s), antenna height
#: (m), pitch and roll amplitude (rad) and period (s), wave phase (rad).
SHIPS = {
    "A": ShipTrack(
        -20e3, -10e3, np.radians(60.0), 10.0, 15.0, np.radians(1.5), 8.0, np.radians(4.0), 11.0, 0.0
    ),
    "B": ShipTrack(
        15e3, -20e3, np.radians(330.0), 8.0, 12.0, np.radians(2.0), 7.0, np.radians(5.0), 12.0, 1.7
    ),
    "C": ShipTrack(0.0, 15e3, np.radians(200.0), 12.0, 18.0, np.radians(1.0), 9.0, np.radians(3.0), 9.5, 3.1),
}
#: The shore site: east/north of CENTRE (m), height (m); level and north-aligned by survey.
SITE = {"S": (-30e3, 25e3, 80.0)}
#: Sensors: platform, noise sigma (range m, bearing rad, elevation rad; NaN = not measured),
#: sample period (s), time offset (s), lever arm (m, deck frame). The periods are multiples of
#: 0.5 s and the offsets differ modulo 0.5 s, so no two sensors ever sample at the same instant.
SENSORS = {
    "A-3D": ("A", (25.0, np.radians(0.15), np.radians(0.2)), 2.0, 0.0, (0.0, 20.0, 25.0)),
    "A-ESM": ("A", (np.nan, np.radians(0.3), np.radians(0.3)), 1.0, 0.35, (2.0, 5.0, 30.0)),
    "B-3D": ("B", (30.0, np.radians(0.2), np.radians(0.25)), 2.5, 0.83, (0.0, 15.0, 20.0)),
    "C-3D": ("C", (20.0, np.radians(0.1), np.radians(0.15)), 1.5, 0.21, (0.0, 25.0, 30.0)),
    "C-2D": ("C", (40.0, np.radians(0.25), np.nan), 3.0, 1.37, (0.0, -30.0, 22.0)),
    "S-2D": ("S", (30.0, np.radians(0.1), np.nan), 4.0, 2.09, (0.0, 0.0, 10.0)),
}
#: Targets (ENU tracks about CENTRE). T1 reports its position (the reference target).
TARGETS = {
    "T1": Circle(5e3, 30e3, 10e3, 150.0, 5000.0, 0.3),
    "T2": Line(-40e3, 40e3, np.radians(120.0), 220.0, 8000.0),
    "T3": Circle(20e3, 0.0, 3e3, 40.0, 500.0, 2.0),
    "T4": Line(-10e3, 35e3, np.radians(90.0), 8.0, 5.0),
    "T5": Circle(-10e3, -35e3, 15e3, 180.0, 3000.0, 4.0),
}


@dataclass(frozen=True)
class FleetConfig:
    """What a simulated fleet holds: ships (:class:`ShipTrack`), shore sites (east, north, height),
    sensors (platform, sigmas, period, offset, lever arm), targets (tracks with ``enu(t)``) and the
    id of the target that reports its position (None: no reference target)."""

    ships: dict
    sites: dict
    sensors: dict
    targets: dict
    reference_target: str | None = None


#: The default fleet of the module docstring.
DEFAULT_FLEET = FleetConfig(SHIPS, SITE, SENSORS, TARGETS, "T1")


@dataclass
class FleetScenario:
    """The long-form input tables (dicts of numpy columns, SI units, radians) and the truth.

    ``truth_state``: state name -> true value (rad or m) in the names of
    :mod:`registration.fleet.data.layout`; :meth:`target_ecef`: true ECEF positions (m).
    """

    platforms: dict
    sensors: dict
    navigation: dict
    plots: dict
    references: dict | None
    truth_state: dict
    config: FleetConfig = DEFAULT_FLEET
    description: dict = field(default_factory=dict)

    def problem(self) -> FleetProblem:
        return build_problem(self.plots, self.sensors, self.navigation, self.platforms, self.references)

    def truth_vector(self, layout) -> np.ndarray:
        """The true states in the order of ``layout`` (a StateLayout)."""
        return np.array([self.truth_state[name] for name in layout.names])

    def target_ecef(self, target: str, t) -> np.ndarray:
        """(N, 3) true ECEF position (m) of ``target`` at times ``t`` (s)."""
        return enu2ecef_points(CENTRE, self.config.targets[str(target)].enu(np.asarray(t, dtype=np.float64)))

    def frames(self) -> dict:
        """The tables as pandas DataFrames."""
        import pandas as pd

        names = ("platforms", "sensors", "navigation", "plots", "references")
        return {n: None if getattr(self, n) is None else pd.DataFrame(getattr(self, n)) for n in names}


#: The extended errors the simulator can give every sensor, with the sensors-table prior column
#: that switches each on (the position errors share one).
EXTENDED_SIZES = {
    "range_gain": "prior_range_gain",
    "time_bias": "prior_time_bias",
    "position_error": "prior_position",
}


def _extended_truth(config: FleetConfig, rng, extended: dict) -> dict:
    """Per sensor: range gain (sensors with range), time bias and east/north/up position errors of
    the given sizes (None: not simulated) with random signs."""
    truth = {}
    for sid, (_, sigma, _, _, _) in config.sensors.items():
        if extended.get("range_gain") is not None and np.isfinite(sigma[0]):
            truth[f"{sid}:range_gain"] = extended["range_gain"] * rng.choice([-1.0, 1.0])
        if extended.get("time_bias") is not None:
            truth[f"{sid}:time_bias"] = extended["time_bias"] * rng.choice([-1.0, 1.0])
        if extended.get("position_error") is not None:
            for axis in ("east", "north", "up"):
                truth[f"{sid}:position_{axis}"] = extended["position_error"] * rng.choice([-1.0, 1.0])
    return truth


def _truth_errors(config: FleetConfig, rng, sizes: dict) -> dict:
    """Attitude errors of the ships (the sites' are zero) and biases: given sizes, random signs."""
    truth = {}
    for pid in (*config.ships, *config.sites):
        for what, key in (("heading", "heading_error"), ("pitch", "level_error"), ("roll", "level_error")):
            truth[f"{pid}:{what}_error"] = (
                0.0 if pid in config.sites else sizes[key] * rng.choice([-1.0, 1.0])
            )
    for sid, (_, sigma, _, _, _) in config.sensors.items():
        for k, ch in enumerate(("range", "bearing", "elevation")):
            if np.isfinite(sigma[k]):
                size = sizes["range_bias"] if k == 0 else sizes["angle_bias"]
                truth[f"{sid}:{ch}_bias"] = size * rng.choice([-1.0, 1.0])
    return truth


def _site_nav(config: FleetConfig, pid: str) -> np.ndarray:
    east, north, height = config.sites[pid]
    lat, lon = ShipTrack.geodetic(CENTRE, np.array([east]), np.array([north]), height)
    return np.array([lat[0], lon[0], height, 0.0, 0.0, 0.0])


def _navigation(
    config: FleetConfig, duration_s: float, truth: dict, ship_motion: bool, rate_hz: float
) -> dict:
    t = np.arange(0.0, duration_s + 0.5 / rate_hz, 1.0 / rate_hz)
    names = ("lat", "lon", "alt", "heading", "pitch", "roll")
    platform, times, rows = [], [], []
    for pid, ship in config.ships.items():
        nav = ship.navigation(CENTRE, t, ship_motion)
        nav[:, 3:] += [truth[f"{pid}:{a}_error"] for a in ("heading", "pitch", "roll")]
        nav[:, 3] = wrap_angle(nav[:, 3])
        platform += [pid] * t.size
        times.append(t)
        rows.append(nav)
    for pid in config.sites:
        platform.append(pid)
        times.append(np.zeros(1))
        rows.append(_site_nav(config, pid)[None, :])
    table = np.concatenate(rows)
    return {
        "platform": np.array(platform),
        "time": np.concatenate(times),
        **{c: table[:, j] for j, c in enumerate(names)},
    }


def _true_nav(config: FleetConfig, pid: str, t: np.ndarray, ship_motion: bool) -> np.ndarray:
    if pid in config.ships:
        return config.ships[pid].navigation(CENTRE, t, ship_motion)
    return np.tile(_site_nav(config, pid), (t.size, 1))


def _sensor_plots(
    config: FleetConfig, sid: str, duration_s: float, truth: dict, rng, noise_scale: float, ship_motion: bool
) -> dict:
    pid, sigma, period, offset, lever = config.sensors[sid]
    times = np.arange(offset, duration_s, period)
    sigma = np.asarray(sigma)
    bias = np.array([truth.get(f"{sid}:{c}_bias", 0.0) for c in ("range", "bearing", "elevation")])
    seen = times - truth.get(f"{sid}:time_bias", 0.0)  # reported time = true time + time bias
    nav = _true_nav(config, pid, seen, ship_motion)
    n_t = len(config.targets)
    p = np.concatenate([enu2ecef_points(CENTRE, track.enu(seen)) for track in config.targets.values()])
    nav = np.tile(nav, (n_t, 1))
    lever = np.asarray(lever, dtype=float)
    ports = dict(zip(NAV_COLUMNS, nav.T), bias=bias, lever_deck=lever, r=0.0, q=0.0, e=0.0)
    extended = [f"{sid}:{k}" for k in ("range_gain", "time_bias", "position_east")]
    if any(k in truth for k in extended):  # the sensor sits at stated position - position error
        pos_err = np.array([truth.get(f"{sid}:position_{a}", 0.0) for a in ("east", "north", "up")])
        z3, z6 = np.zeros(3), np.zeros(6)
        gain = truth.get(f"{sid}:range_gain", 0.0)
        plot = generated.fleet_residual_ext(
            p_ecef=p, v_ecef=z3, **ports, nav_rate=z6, att_err=z3, gain=gain, dt=0.0, pos_err=pos_err
        ).plot
    else:
        plot = generated.fleet_residual(p_ecef=p, **ports, att_err=np.zeros(3)).plot
    measured = plot + noise_scale * rng.normal(size=plot.shape) * np.nan_to_num(sigma)
    measured[:, ~np.isfinite(sigma)] = np.nan
    measured[:, 1] = wrap_angle(measured[:, 1])
    seen_plots = _in_coverage(sid, sigma, p, nav, lever)
    return {
        "time": np.tile(times, n_t)[seen_plots],
        "sensor": np.full(times.size * n_t, sid)[seen_plots],
        "target": np.repeat(np.array(list(config.targets)), times.size)[seen_plots],
        "range": measured[seen_plots, 0],
        "bearing": measured[seen_plots, 1],
        "elevation": measured[seen_plots, 2],
    }


def _in_coverage(
    sid: str, sigma: np.ndarray, p_ecef: np.ndarray, nav: np.ndarray, lever: np.ndarray
) -> np.ndarray:
    """Which plots the sensor reports (:mod:`registration.fleet.simulation.coverage`): judged at the
    true geometry, without biases (the true navigation ``nav``, target ECEF ``p_ecef``)."""
    ports = dict(zip(NAV_COLUMNS, nav.T), att_err=np.zeros(3), bias=np.zeros(3), lever_deck=lever)
    true_plot = generated.fleet_residual(p_ecef=p_ecef, **ports, r=0.0, q=0.0, e=0.0).plot
    h_target = ecef2geodetic(p_ecef)[2] if p_ecef.size else np.zeros(0)
    return visible(coverage_for(sigma), true_plot[:, 0], true_plot[:, 2], nav[:, 2] + lever[2], h_target)


def _tables(config: FleetConfig, noise_scale: float, extended: dict) -> tuple[dict, dict]:
    """The platforms table (ships without priors, sites fixed) and the sensors table (with an
    empty prior column, estimated without prior, for each simulated extended error)."""
    n_ships, n_sites = len(config.ships), len(config.sites)
    platforms = {"platform": np.array([*config.ships, *config.sites])}
    for a in ("heading", "pitch", "roll"):
        platforms[f"prior_{a}"] = np.array([np.inf] * n_ships + [0.0] * n_sites)
    spec = list(config.sensors.values())
    sensors = {"sensor": np.array(list(config.sensors)), "platform": np.array([v[0] for v in spec])}
    for k, c in enumerate(("range", "bearing", "elevation")):
        sensors[f"sigma_{c}"] = np.array([v[1][k] for v in spec], dtype=float) * noise_scale
    for k, a in enumerate("xyz"):
        sensors[f"lever_{a}"] = np.array([v[4][k] for v in spec], dtype=float)
    for key, column in EXTENDED_SIZES.items():
        if extended.get(key) is not None:
            sensors[column] = np.full(len(spec), np.inf)
    return platforms, sensors


def _references(config: FleetConfig, duration_s: float, sigma: float, rng) -> dict | None:
    tid = config.reference_target
    if tid is None:
        return None
    t = np.arange(0.5, duration_s, 1.0)
    p = enu2ecef_points(CENTRE, config.targets[tid].enu(t)) + sigma * rng.normal(size=(t.size, 3))
    return {
        "target": np.full(t.size, tid),
        "time": t,
        "x": p[:, 0],
        "y": p[:, 1],
        "z": p[:, 2],
        "sigma": np.full(t.size, sigma),
    }


def _check_sizes(duration_s: float, nav_rate_hz: float, **angles: float) -> None:
    """ValueError for an angle error over 20 deg (degrees passed as radians), a duration of 10 s or
    less or a navigation rate that is not positive."""
    for name, v in angles.items():
        if abs(v) > np.radians(20):
            raise ValueError(f"{name}: {v} rad is implausibly large (pass radians, not degrees)")
    if not duration_s > 10 or not nav_rate_hz > 0:
        raise ValueError(
            f"duration_s must exceed 10 s and nav_rate_hz be > 0, got {duration_s}, {nav_rate_hz}"
        )


def _check_extended(extended: dict[str, float | None]) -> None:
    """ValueError for an extended error size that is not finite, or a range gain over 0.1."""
    for name, v in extended.items():
        if v is not None and not np.isfinite(v):
            raise ValueError(f"{name}: expected a finite size or None, got {v}")
    range_gain = extended["range_gain"]
    if range_gain is not None and abs(range_gain) > 0.1:
        raise ValueError(f"range_gain: {range_gain} is implausibly large (dimensionless: 1e-3 = 1000 ppm)")


def fleet_scenario(
    seed: int = 0,
    *,
    duration_s: float = 300.0,
    angle_bias: float = np.radians(1.0),
    range_bias: float = 300.0,
    heading_error: float = np.radians(0.5),
    level_error: float = np.radians(0.2),
    noise_scale: float = 1.0,
    ship_motion: bool = True,
    reference_sigma: float = 3.0,
    nav_rate_hz: float = 10.0,
    config: FleetConfig = DEFAULT_FLEET,
    range_gain: float | None = None,
    time_bias: float | None = None,
    position_error: float | None = None,
) -> FleetScenario:
    """The fleet ``config`` (default: the module docstring's) over ``duration_s`` seconds.

    Errors: each ship's heading error is +-``heading_error`` and its pitch and roll errors
    +-``level_error`` (random signs); a site's attitude is surveyed (errors 0, held fixed by a
    prior sigma of 0). Each sensor's biases are +-``range_bias`` (m) and +-``angle_bias`` (rad)
    per measured channel. Noise: the sensors' sigmas times ``noise_scale`` (the sensors table
    states the scaled sigmas). The reference target reports its ECEF position once a second with
    noise ``reference_sigma`` (m). Navigation: ``nav_rate_hz`` for ships (reported = true +
    attitude error; the solver interpolates it linearly, an error of about 0.002 deg in roll at
    10 Hz), one row per site. No priors on the ships' errors and the biases (maximum likelihood).

    Extended errors (docs/background/fleet-model.md, "Sensor error model"), each None by default (not
    simulated and
    its column absent from the sensors table, so not modelled): ``range_gain`` (dimensionless,
    sensors with range), ``time_bias`` (s: the sensor reports time = true time + bias) and
    ``position_error`` (m per east, north and up axis: stated sensor position = true + error),
    each +-size with random signs per sensor and estimated without prior (empty prior column).
    A plot whose true time falls before the navigation starts is set aside by the solver.
    """
    _check_sizes(
        duration_s, nav_rate_hz, angle_bias=angle_bias, heading_error=heading_error, level_error=level_error
    )
    rng = np.random.default_rng(seed)
    sizes = {
        "angle_bias": angle_bias,
        "range_bias": range_bias,
        "heading_error": heading_error,
        "level_error": level_error,
    }
    truth = _truth_errors(config, rng, sizes)
    extended = {"range_gain": range_gain, "time_bias": time_bias, "position_error": position_error}
    _check_extended(extended)
    truth.update(_extended_truth(config, rng, extended))
    parts = [
        _sensor_plots(config, sid, duration_s, truth, rng, noise_scale, ship_motion) for sid in config.sensors
    ]
    plots = {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}
    platforms, sensors = _tables(config, noise_scale, extended)
    sizes.update({k: v for k, v in extended.items() if v is not None})
    description = {
        "seed": seed,
        "duration_s": duration_s,
        **{f"{k}": v for k, v in sizes.items()},
        "noise_scale": noise_scale,
        "ship_motion": ship_motion,
        "plots": int(plots["time"].size),
    }
    return FleetScenario(
        platforms,
        sensors,
        _navigation(config, duration_s, truth, ship_motion, nav_rate_hz),
        plots,
        _references(config, duration_s, reference_sigma, rng),
        truth,
        config,
        description,
    )
