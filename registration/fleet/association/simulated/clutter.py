"""Simulated plots without target ids, for the association (:func:`association_scenario`), and
the scores of an association against the truth (:func:`association_scores`).

The fleet is :mod:`registration.fleet.simulation.scenario`'s (three ships, one shore site) with its radars
(3-D and 2-D; the passive sensor is left out) and ``n_targets`` targets on straight lines and
circles, optionally in crossing pairs (two straight tracks through the same point at the same
time and height). A target more than :data:`MAX_ELEVATION_RAD` above a radar is not seen; each
other real plot is missed with probability ``p_missed``; each scan of each
sensor gets a Poisson number of clutter plots (mean ``clutter_per_scan``) uniform in range
(:data:`CLUTTER_RANGE_M`), bearing (all round) and elevation (:data:`CLUTTER_ELEVATION_RAD`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fleet.simulation.scenario import (
    SENSORS,
    SHIPS,
    SITE,
    FleetConfig,
    FleetScenario,
    fleet_scenario,
)
from registration.fleet.simulation.tracks import Circle, Line

__all__ = [
    "CLUTTER_RANGE_M",
    "CLUTTER_ELEVATION_RAD",
    "MAX_ELEVATION_RAD",
    "RADARS",
    "AssociationScenario",
    "association_targets",
    "association_scenario",
    "association_scores",
]

#: Range (m) and elevation (rad) windows of the uniform clutter.
CLUTTER_RANGE_M = (2.0e3, 100.0e3)
CLUTTER_ELEVATION_RAD = (0.0, 0.3)
#: Plots above this elevation (rad) are not made: the blind cone of a radar overhead.
MAX_ELEVATION_RAD = float(np.radians(70.0))
#: The scenario's radars (the default fleet's sensors that measure range).
RADARS = {k: v for k, v in SENSORS.items() if np.isfinite(v[1][0])}


@dataclass
class AssociationScenario:
    """``plots``: the plots table without ``target`` (real plots and clutter, in time order);
    ``true_target`` (rows,): each row's true target id, '' for clutter; ``scenario``: the fleet
    scenario whose real plots (with their ids, after the misses) are ``labelled_plots``."""

    plots: dict
    true_target: np.ndarray
    labelled_plots: dict
    scenario: FleetScenario


def association_targets(n_targets: int, rng, *, crossing: bool, duration_s: float) -> dict:
    """``n_targets`` target tracks in a 90 km square about the centre: crossing pairs first (two
    lines through one point at mid-time, same height) when ``crossing``, then lines and circles."""
    out: dict[str, Line | Circle] = {}
    n_pairs = n_targets // 2 if crossing else 0
    for k in range(n_pairs):
        point = rng.uniform(-30e3, 30e3, 2)
        z = rng.uniform(500.0, 6000.0)
        course = rng.uniform(0, 2 * np.pi)
        for j, turn in enumerate((0.0, rng.uniform(np.radians(20), np.radians(90)))):
            c, v = course + turn, rng.uniform(120.0, 250.0)
            start = point - 0.5 * duration_s * v * np.array([np.sin(c), np.cos(c)])
            out[f"T{2 * k + j + 1}"] = Line(start[0], start[1], c, v, z)
    for k in range(2 * n_pairs, n_targets):
        east, north = rng.uniform(-35e3, 35e3, 2)
        z, v = rng.uniform(300.0, 9000.0), rng.uniform(60.0, 250.0)
        if k % 2:
            out[f"T{k + 1}"] = Circle(east, north, rng.uniform(3e3, 15e3), v, z, rng.uniform(0, 2 * np.pi))
        else:
            out[f"T{k + 1}"] = Line(east, north, rng.uniform(0, 2 * np.pi), v, z)
    return out


def _clutter(scenario: FleetScenario, rng, per_scan: float) -> dict:
    sensors = scenario.sensors
    parts = []
    for s, sid in enumerate(sensors["sensor"]):
        times = np.unique(scenario.plots["time"][scenario.plots["sensor"] == sid])
        n = rng.poisson(per_scan, times.size)
        t = np.repeat(times, n)
        m = t.size
        cols = {
            "range": rng.uniform(*CLUTTER_RANGE_M, m),
            "bearing": rng.uniform(-np.pi, np.pi, m),
            "elevation": rng.uniform(*CLUTTER_ELEVATION_RAD, m),
        }
        for c in cols:
            if not np.isfinite(sensors[f"sigma_{c}"][s]):
                cols[c] = np.full(m, np.nan)
        parts.append({"time": t, "sensor": np.full(m, sid), **cols})
    return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}


def association_scenario(
    n_targets: int = 5,
    *,
    crossing: bool = False,
    angle_bias: float = np.radians(2.0),
    p_missed: float = 0.1,
    clutter_per_scan: float = 1.0,
    duration_s: float = 300.0,
    seed: int = 0,
    sensors: dict | None = None,
    **fleet,
) -> AssociationScenario:
    """The plots of ``n_targets`` targets with misses and clutter (module docstring); ``angle_bias``
    (rad) is the size of every angle bias (bearing and elevation), random signs; ``fleet``: other
    :func:`~registration.fleet.simulation.scenario.fleet_scenario` arguments (range_bias, heading_error,
    ...)."""
    if n_targets < 1 or not 0 <= p_missed < 1 or clutter_per_scan < 0:
        raise ValueError(
            f"n_targets >= 1, p_missed in [0, 1), clutter_per_scan >= 0; got {n_targets}, {p_missed}, "
            f"{clutter_per_scan}"
        )
    rng = np.random.default_rng(seed)
    targets = association_targets(n_targets, rng, crossing=crossing, duration_s=duration_s)
    config = FleetConfig(SHIPS, SITE, RADARS if sensors is None else sensors, targets, None)
    sc = fleet_scenario(seed, duration_s=duration_s, angle_bias=angle_bias, config=config, **fleet)
    kept = rng.random(sc.plots["time"].size) >= p_missed
    kept &= ~(np.abs(sc.plots["elevation"]) > MAX_ELEVATION_RAD)  # overhead: outside a radar's coverage
    sc.plots = {k: v[kept] for k, v in sc.plots.items()}
    clutter = _clutter(sc, rng, clutter_per_scan)
    real = {k: v for k, v in sc.plots.items() if k != "target"}
    plots = {k: np.concatenate([real[k], clutter[k]]) for k in real}
    truth = np.concatenate([sc.plots["target"].astype(str), np.full(clutter["time"].size, "")])
    order = np.argsort(plots["time"], kind="stable")
    return AssociationScenario({k: v[order] for k, v in plots.items()}, truth[order], sc.plots, sc)


def association_scores(labels: np.ndarray, true_target: np.ndarray) -> dict:
    """Scores of ``labels`` (rows,) against ``true_target`` (rows,; '' = clutter).

    Each label stands for the true target most of its plots belong to (majority). ``error_rate``:
    share of the real plots given a label that stands for another target; ``unassociated_rate``:
    share of the real plots left unassociated; ``clutter_associated``: share of the clutter plots
    given a label; ``labels_per_target``: labels per true target seen in the labels (1 = no splits).
    """
    labels, true_target = np.asarray(labels, dtype=str), np.asarray(true_target, dtype=str)
    real, given = true_target != "", labels != ""
    both = real & given
    stands_for = {}
    for lab in np.unique(labels[both]):
        ids, counts = np.unique(true_target[both & (labels == lab)], return_counts=True)
        stands_for[str(lab)] = str(ids[np.argmax(counts)])
    wrong = np.array(
        [stands_for.get(lab, "") != t for lab, t in zip(labels[both], true_target[both])], dtype=bool
    )
    n_real, n_clutter = int(real.sum()), int((~real).sum())
    targets = set(stands_for.values())
    return {
        "error_rate": float(wrong.sum()) / max(n_real, 1),
        "unassociated_rate": float((real & ~given).sum()) / max(n_real, 1),
        "clutter_associated": float((~real & given).sum()) / max(n_clutter, 1),
        "labels_per_target": len(stands_for) / max(len(targets), 1),
    }
