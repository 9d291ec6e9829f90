"""Simulated scenarios for online registration: the two-ship set-up of Wang et al. 2011, section 4.

:func:`paper_scenario` rebuilds the paper's ships, errors and noise. The paper's target came
from a simulator (STAGE) that is not available; the trajectory here is our own, documented in the
docstring, and is not tuned to reproduce any printed number.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field

import numpy as np

from registration import _codegen
from registration._generated import api as generated
from registration.core.angles import wrap_angle
from registration.core.motion import ShipMotion
from registration.online.contract import (
    N_ROW,
    N_STATE,
    ROW_COLUMNS,
    SENSOR_COLUMNS,
    SENSOR_ROW,
    SENSORS,
    STATE_NAMES,
)

__all__ = ["ShipMotion", "Scenario", "ScenarioRuns", "paper_scenario", "paper_scenarios", "PAPER_TABLE1"]

#: Table 1 of Wang et al. 2011 (metres): X_A - X_B per ECEF axis before and after registration.
PAPER_TABLE1 = {
    "before": {
        "max": [1515.85, 519.10, 463.77],
        "mean": [1303.56, 454.90, 338.27],
        "std": [185.47, 41.66, 68.14],
    },
    "after": {"max": [82.04, 47.31, 109.05], "mean": [17.15, -0.32, 18.10], "std": [35.22, 23.84, 56.50]},
}


@dataclass
class Scenario:
    """A simulated run: the data contract (measured values) plus the ground truth."""

    data: dict  # time, a_lat, ..., b_elevation (SI units, radians)
    truth_state: np.ndarray  # (12,) true registration errors in STATE_NAMES order
    truth: dict = field(default_factory=dict)  # true ship/target tracks (ECEF, geodetic, attitude)
    sigma0: np.ndarray = field(default_factory=lambda: np.zeros(6))  # noise sigmas used
    description: dict = field(default_factory=dict)


def _dead_reckon(lat0, lon0, alt, course, speed, dt, substeps=10):
    """Integrate a track over the ellipsoid. course (K,) rad clockwise from north, speed (K,) m/s.

    Returns lat, lon (K,) at the sample instants; latitude and longitude rates use the WGS-84
    radii of curvature (generated function ``radii_of_curvature``). The steps are sequential
    (each uses the radii at its start), so :func:`paper_scenarios` runs this once per scenario
    configuration and caches the tracks.
    """
    radii = _codegen.get("radii_of_curvature").bind()
    k = len(course)
    lat, lon = np.empty(k), np.empty(k)
    la, lo = float(lat0), float(lon0)
    h = dt / substeps
    for i in range(k):
        lat[i], lon[i] = la, lo
        M, N = radii(la)[0]  # constant to ~1e-7 over one step (< 200 m of latitude)
        dla = speed[i] * np.cos(course[i]) * h / (M + alt[i])  # the same in every substep
        east, radius = speed[i] * np.sin(course[i]) * h, N + alt[i]
        for _ in range(substeps):
            la += dla
            lo += east / (radius * np.cos(la))
    return lat, lon


def _target_course(t: np.ndarray) -> np.ndarray:
    """Target course (rad): 240 deg for 60 s, right turn at 2 deg/s for 90 s (to 60 deg), straight
    for 60 s, left turn at 2 deg/s for 90 s (back to 240 deg)."""
    deg = np.where(
        t < 60,
        240.0,
        np.where(t < 150, 240.0 + 2.0 * (t - 60), np.where(t < 210, 420.0, 420.0 - 2.0 * (t - 210))),
    )
    return np.radians(np.mod(deg, 360.0))


#: The paper's ships: start (rad), course (rad, clockwise from north), speed (m/s), wave phase.
_PAPER_SHIPS = {
    "a": dict(lat0=np.radians(20.0), lon0=np.radians(115.0), course=np.radians(150.0), speed=12.0, phase=0.0),
    "b": dict(lat0=np.radians(20.0), lon0=np.radians(115.5), course=np.radians(330.0), speed=8.0, phase=2.1),
}


def _paper_target(t: np.ndarray, dt: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Target latitude, longitude (rad) and altitude (m): 45 km north of the ships' midpoint, 200 m/s."""
    n_steps = len(t)
    mid_lat, mid_lon = np.radians(20.0), np.radians(115.25)
    M, N = generated.radii_of_curvature(lat=mid_lat).radii[0]
    tgt_alt = np.linspace(2000.0, 4000.0, n_steps)
    tgt_lat, tgt_lon = _dead_reckon(
        mid_lat + 45_000.0 / (M + 2000.0), mid_lon, tgt_alt, _target_course(t), 200.0 * np.ones(n_steps), dt
    )
    return tgt_lat, tgt_lon, tgt_alt


def _ship_truth(prefix, ship, t, dt, p_target_ecef, *, ship_motion, antenna_height, t_variant) -> dict:
    """One ship's true track (rad, m), attitude (rad) and the true plot of the target (m, rad)."""
    n_steps = len(t)
    ones = np.ones(n_steps)
    alt = antenna_height * ones
    lat, lon = _dead_reckon(ship["lat0"], ship["lon0"], alt, ship["course"] * ones, ship["speed"] * ones, dt)
    heading = ship["course"] * ones
    if ship_motion is None:
        pitch, roll = np.zeros(n_steps), np.zeros(n_steps)
    else:
        pitch, roll = ship_motion.angles(t, ship["phase"])
    plot = generated.ecef2plot(
        t_variant=t_variant,
        p_ecef=p_target_ecef,
        lat=lat,
        lon=lon,
        alt=alt,
        heading=heading,
        pitch=pitch,
        roll=roll,
    ).plot
    return {
        f"{prefix}_lat": lat,
        f"{prefix}_lon": lon,
        f"{prefix}_alt": alt,
        f"{prefix}_heading": heading,
        f"{prefix}_pitch": pitch,
        f"{prefix}_roll": roll,
        f"{prefix}_plot": plot,
        f"{prefix}_p_ecef": generated.geodetic2ecef(lat=lat, lon=lon, alt=alt).p_ecef,
    }


@functools.lru_cache(maxsize=8, typed=True)
def _geometry(n_steps: int, dt: float, ship_motion, antenna_height: float, t_variant: str) -> dict:
    """Everything that does not depend on the errors and the noise: time (s), the target's and the
    ships' true tracks, attitudes and plots. Cached per configuration (read-only arrays)."""
    t = np.arange(n_steps) * dt
    tgt_lat, tgt_lon, tgt_alt = _paper_target(t, dt)
    p_target_ecef = generated.geodetic2ecef(lat=tgt_lat, lon=tgt_lon, alt=tgt_alt).p_ecef
    geo = {
        "time": t,
        "p_target_ecef": p_target_ecef,
        "target_lat": tgt_lat,
        "target_lon": tgt_lon,
        "target_alt": tgt_alt,
    }
    for prefix, ship in _PAPER_SHIPS.items():
        geo.update(
            _ship_truth(
                prefix,
                ship,
                t,
                dt,
                p_target_ecef,
                ship_motion=ship_motion,
                antenna_height=antenna_height,
                t_variant=t_variant,
            )
        )
    for a in geo.values():
        a.flags.writeable = False
    return geo


def _measured_rows(geo: dict, errors: dict, sigmas: np.ndarray, noise: dict) -> np.ndarray:
    """Measured rows (R, K, 18) in contract order: navigation exact, attitude plus its errors,
    plots plus biases plus ``noise[prefix]`` (R, K, 3) standard normal draws scaled by ``sigmas``."""
    runs, k = next(iter(noise.values())).shape[:2]
    rows = np.empty((runs, k, N_ROW))
    for prefix in SENSORS:
        col = {c: SENSOR_ROW[prefix].start + j for j, c in enumerate(SENSOR_COLUMNS)}
        rows[:, :, col["lat"]] = geo[f"{prefix}_lat"]
        rows[:, :, col["lon"]] = geo[f"{prefix}_lon"]
        rows[:, :, col["alt"]] = geo[f"{prefix}_alt"]
        rows[:, :, col["heading"]] = wrap_angle(geo[f"{prefix}_heading"] + errors["heading"])
        rows[:, :, col["pitch"]] = geo[f"{prefix}_pitch"] + errors["pitch"]
        rows[:, :, col["roll"]] = geo[f"{prefix}_roll"] + errors["roll"]
        measured = (
            geo[f"{prefix}_plot"]
            + [errors["range"], errors["bearing"], errors["elevation"]]
            + noise[prefix] * sigmas
        )
        rows[:, :, col["range"]] = measured[..., 0]
        rows[:, :, col["bearing"]] = wrap_angle(measured[..., 1])
        rows[:, :, col["elevation"]] = measured[..., 2]
    return rows


@dataclass
class ScenarioRuns:
    """Runs of one scenario configuration that differ only in their noise (one seed per run).

    ``rows`` (R, K, 18): each run's measured rows in contract order (SI units, radians); ``time``
    (K,) s; ``truth`` the true tracks and plots, the same in every run; ``truth_state``, ``sigma0``
    and ``description`` as in :class:`Scenario` (the description without the seed).
    """

    seeds: tuple
    time: np.ndarray
    rows: np.ndarray
    truth_state: np.ndarray
    truth: dict
    sigma0: np.ndarray
    description: dict

    def scenario(self, i: int) -> Scenario:
        """Run ``i`` as a :class:`Scenario` (its own copies of every array)."""
        data = {"time": np.array(self.time)}
        data.update({c: self.rows[i, :, j].copy() for j, c in enumerate(ROW_COLUMNS)})
        return Scenario(
            data=data,
            truth_state=self.truth_state.copy(),
            truth={k: np.array(v) for k, v in self.truth.items()},
            sigma0=self.sigma0.copy(),
            description={"seed": self.seeds[i], **self.description},
        )


def _check_arguments(n_steps, dt, angles: dict) -> None:
    if n_steps < 2:
        raise ValueError("n_steps: need at least 2 measurement pairs")
    if not dt > 0:
        raise ValueError("dt: must be > 0 s")
    for name, v in angles.items():
        if abs(v) > np.radians(20):
            raise ValueError(f"{name}: {v} rad is implausibly large (pass radians, not degrees)")


def paper_scenarios(
    seeds,
    *,
    n_steps: int = 300,
    dt: float = 1.0,
    angle_sigma: float = np.radians(0.5),
    range_sigma: float = 50.0,
    range_bias: float = 1000.0,
    angle_bias: float = np.radians(0.5),
    heading_error: float = np.radians(0.1),
    level_error: float = np.radians(0.03),
    ship_motion: ShipMotion | None = None,
    antenna_height: float = 20.0,
    t_variant: str = "standard",
) -> ScenarioRuns:
    """:func:`paper_scenario` for every seed of ``seeds`` at once, as :class:`ScenarioRuns`.

    Run ``i`` holds bit for bit the rows of ``paper_scenario(seeds[i], ...)``. The tracks and the
    true plots are computed once per configuration (and cached); per seed only the noise is drawn.
    """
    _check_arguments(
        n_steps,
        dt,
        {
            "angle_sigma": angle_sigma,
            "angle_bias": angle_bias,
            "heading_error": heading_error,
            "level_error": level_error,
        },
    )
    seeds = tuple(seeds)
    try:
        geo = _geometry(n_steps, dt, ship_motion, antenna_height, t_variant)
    except TypeError:  # an unhashable ship motion: not cached
        geo = _geometry.__wrapped__(n_steps, dt, ship_motion, antenna_height, t_variant)
    errors = {
        "heading": heading_error,
        "pitch": level_error,
        "roll": level_error,
        "range": range_bias,
        "bearing": angle_bias,
        "elevation": angle_bias,
    }
    truth_state = np.array(
        [errors[k] for k in ("heading", "pitch", "roll", "range", "bearing", "elevation")] * 2
    )
    assert truth_state.shape == (N_STATE,)
    sigmas = np.array([range_sigma, angle_sigma, angle_sigma])
    noise = {p: np.empty((len(seeds), n_steps, 3)) for p in SENSORS}
    for r, seed in enumerate(seeds):
        rng = np.random.default_rng(seed)
        for p in SENSORS:  # ship A's draws, then ship B's
            noise[p][r] = rng.normal(size=(n_steps, 3))
    truth = {k: geo[k] for k in ("p_target_ecef", "target_lat", "target_lon", "target_alt")}
    for p in SENSORS:
        truth.update({f"{p}_{k}": geo[f"{p}_{k}"] for k in ("heading", "pitch", "roll", "plot", "p_ecef")})
    description = {
        "n_steps": n_steps,
        "dt_s": dt,
        "angle_sigma_rad": angle_sigma,
        "range_sigma_m": range_sigma,
        "ship_motion": None if ship_motion is None else ship_motion.__dict__,
        "t_variant": t_variant,
        "truth": dict(zip(STATE_NAMES, truth_state.tolist())),
    }
    return ScenarioRuns(
        seeds=seeds,
        time=geo["time"],
        rows=_measured_rows(geo, errors, sigmas, noise),
        truth_state=truth_state,
        truth=truth,
        sigma0=np.tile(sigmas, 2),
        description=description,
    )


def paper_scenario(seed: int = 0, **kwargs) -> Scenario:
    """The paper's scenario (Wang et al. 2011, section 4), with our own documented target trajectory.

    Ships (true values; navigation is exact, as the paper assumes high-precision GPS):

    * A starts at (20 N, 115 E), course 150 deg, 12 m/s; B at (20 N, 115.5 E), course 330 deg,
      8 m/s; both sail straight; radar antenna ``antenna_height`` m above the ellipsoid. The
      heading equals the course. Without ``ship_motion`` pitch = roll = 0 (the paper); with it,
      each ship pitches and rolls sinusoidally (B with a different phase).
    * Attitude errors (both ships): heading ``heading_error`` (paper 0.1 deg), pitch and roll
      ``level_error`` (paper 0.03 deg). Radar biases (both): range ``range_bias`` (1 km), bearing
      and elevation ``angle_bias`` (0.5 deg). Noise: range ``range_sigma`` (50 m), bearing and
      elevation ``angle_sigma`` (0.5 deg), white Gaussian.

    Target (our design; the paper used the STAGE simulator): starts 45 km north of the point
    midway between the ships' starting positions at 2000 m, flies at 200 m/s, climbing linearly
    to 4000 m over the run, course 240 deg for 60 s, a 2 deg/s right turn for 90 s to course
    60 deg, straight for 60 s, then a 2 deg/s left turn back to 240 deg (turn radius 5.7 km). It
    stays 40-75 km from both ships, at 1.5-5 deg elevation, inside both radars' coverage.

    ``n_steps`` synchronous measurement pairs at ``dt`` s (paper: 300 at 1 s). Keyword arguments
    (defaults in :func:`paper_scenarios`): ``n_steps``, ``dt``, ``angle_sigma``, ``range_sigma``,
    ``range_bias``, ``angle_bias``, ``heading_error``, ``level_error``, ``ship_motion``,
    ``antenna_height``, ``t_variant``. Returns a :class:`Scenario` whose ``data`` follows the
    registration data contract (SI units, radians): ``time`` and, per prefix ``a_``/``b_``: lat,
    lon, alt, heading, pitch, roll (measured, i.e. with attitude errors), range, bearing,
    elevation (measured: true + bias + noise).
    """
    return paper_scenarios((seed,), **kwargs).scenario(0)
