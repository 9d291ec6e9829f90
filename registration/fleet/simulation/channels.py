"""A small air-traffic-control scenario with the errors real radars have and the three-error model
lacks (:func:`atc_channel_scenario`): an azimuth eccentricity on one radar, and on another a PSR
channel, its primary-only plots with biases of their own.

Three surveyed radar sites (level, north-aligned, attitude held fixed) see five aircraft, one of
which reports its position (the reference target). The plots come from :func:`fleet_scenario`
(through the generated ``fleet_residual``, biases and noise included) and are then perturbed here,
in NumPy, by the errors under test, written from their definitions and not through the generated
eccentric model:

* **eccentricity** of radar ``R1``: its reported bearing ``q`` satisfies ``q = q0 + a sin q + b cos q``
  with ``q0`` the bearing without it (true + bias + noise): the error is a function of the bearing
  the radar reports. Solved by fixed-point iteration (|a|, |b| << 1: a contraction; 8 steps leave
  less than 1e-15 rad);
* **PSR channel** of radar ``R2``: each of its plots is primary-only with probability
  ``psr_fraction``; those become sensor ``R2.psr`` (``channel_of`` ``R2``) with the range, bearing
  and elevation biases of ``R2`` plus offsets of their own, so the channel's true biases are the
  sums.

The sensors table has the column ``prior_eccentricity`` (inf, no prior, for R1; 0, held fixed, for
the others) and ``channel_of`` ('' except for ``R2.psr``).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from registration.core.angles import wrap_angle
from registration.fleet.simulation.scenario import FleetConfig, FleetScenario, fleet_scenario
from registration.fleet.simulation.tracks import Circle, Line

__all__ = ["ATC_FLEET", "atc_channel_scenario"]

#: Three radar sites (east, north of the centre m, height m) and their 3-D radars (range, bearing,
#: elevation sigma; period s; time offset s; lever arm m), five aircraft (T1 the reference target).
ATC_FLEET = FleetConfig(
    ships={},
    sites={"R1": (-25e3, 5e3, 60.0), "R2": (28e3, 12e3, 45.0), "R3": (2e3, -30e3, 80.0)},
    sensors={
        "R1": ("R1", (40.0, np.radians(0.08), np.radians(0.25)), 4.0, 0.0, (0.0, 0.0, 10.0)),
        "R2": ("R2", (50.0, np.radians(0.1), np.radians(0.3)), 4.5, 0.7, (0.0, 0.0, 12.0)),
        "R3": ("R3", (45.0, np.radians(0.09), np.radians(0.3)), 5.0, 1.9, (0.0, 0.0, 8.0)),
    },
    targets={
        "T1": Circle(0.0, 5e3, 18e3, 160.0, 7000.0, 0.2),
        "T2": Line(-50e3, -20e3, np.radians(70.0), 230.0, 9000.0),
        "T3": Circle(-25e3, 5e3, 12e3, 120.0, 4000.0, 1.3),
        "T4": Line(40e3, -40e3, np.radians(320.0), 200.0, 6000.0),
        "T5": Circle(20e3, -10e3, 9e3, 100.0, 3000.0, 2.6),
    },
    reference_target="T1",
)


def _eccentric(q0: np.ndarray, a: float, b: float) -> np.ndarray:
    """The bearing q (rad) with q = q0 + a sin q + b cos q (fixed-point iteration), wrapped."""
    q = q0.copy()
    for _ in range(8):
        q = q0 + a * np.sin(q) + b * np.cos(q)
    return wrap_angle(q)


def atc_channel_scenario(
    seed: int,
    *,
    duration_s: float = 300.0,
    eccentricity: float = np.radians(0.2),
    psr_range: float = 120.0,
    psr_angle: float = np.radians(0.15),
    psr_fraction: float = 0.5,
    config: FleetConfig = ATC_FLEET,
) -> FleetScenario:
    """The scenario of the module docstring: the eccentricity terms of ``R1`` are +-``eccentricity``
    (rad) each, the PSR channel's offsets from ``R2``'s biases +-``psr_range`` (m) and
    +-``psr_angle`` (rad, bearing and elevation), every sign drawn at random from ``seed``; biases
    as :func:`fleet_scenario`'s defaults. ``truth_state`` names every state of the layout."""
    base = fleet_scenario(seed, duration_s=duration_s, config=config)
    rng = np.random.default_rng([seed, 48])
    plots = {k: np.array(v, copy=True) for k, v in base.plots.items()}
    truth = dict(base.truth_state)
    a, b = eccentricity * rng.choice([-1.0, 1.0], 2)
    truth.update({"R1:eccentricity_sin": a, "R1:eccentricity_cos": b})
    r1 = plots["sensor"] == "R1"
    plots["bearing"][r1] = _eccentric(plots["bearing"][r1], a, b)
    offset = np.array([psr_range, psr_angle, psr_angle]) * rng.choice([-1.0, 1.0], 3)
    psr = (plots["sensor"] == "R2") & (rng.uniform(size=plots["sensor"].size) < psr_fraction)
    plots["sensor"] = np.where(psr, "R2.psr", plots["sensor"].astype(object)).astype(str)
    for k, channel in enumerate(("range", "bearing", "elevation")):
        plots[channel][psr] += offset[k]
        truth[f"R2.psr:{channel}_bias"] = truth[f"R2:{channel}_bias"] + offset[k]
    plots["bearing"][psr] = wrap_angle(plots["bearing"][psr])
    sensors = {k: np.asarray(v) for k, v in base.sensors.items()}
    r2 = int(np.flatnonzero(sensors["sensor"] == "R2")[0])
    sensors = {k: np.append(v, v[r2]) for k, v in sensors.items()}
    sensors["sensor"] = np.append(sensors["sensor"][:-1].astype(object), "R2.psr").astype(str)
    sensors["channel_of"] = np.where(sensors["sensor"] == "R2.psr", "R2", "")
    sensors["prior_eccentricity"] = np.where(sensors["sensor"] == "R1", np.inf, 0.0)
    for sid in sensors["sensor"]:
        if sid != "R1":
            truth.update({f"{sid}:eccentricity_sin": 0.0, f"{sid}:eccentricity_cos": 0.0})
    description = dict(base.description, eccentricity=eccentricity, psr_range=psr_range, psr_angle=psr_angle)
    return replace(base, plots=plots, sensors=sensors, truth_state=truth, description=description)
