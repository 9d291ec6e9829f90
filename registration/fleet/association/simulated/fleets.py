"""Simulated fleets for the association's tests and benchmarks that :func:`association_scenario`
does not make: other ships and sites, a passive angle sensor, surface vessels reported by AIS, shore
2-D radars with ADS-B, several reference targets, sensor-local track numbers and clutter given as a
share of the real plots.

* :func:`rolling_fleet`: ships that roll 3-5 deg with 8-11 s periods, a shore site, any mix of
  sensors (by default the one of the issue that motivated the robust association: a 3-D radar on
  the first ship, a 3-D radar and a 1 Hz passive bearing/elevation sensor on the second, a 2-D
  radar on the third, a 3-D radar on the shore), aircraft at 3-10 km height, one circling.
* :func:`vessel_fleet`: one ship with one 2-D radar (an ARPA radar: range and bearing, track
  numbers) and surface vessels, most of them reporting AIS positions (references).
* :func:`atc_fleet`: shore 2-D radars (surveyed, attitude held at 0) with range bias, range gain,
  bearing bias and clock offset; aircraft with Mode S addresses (ids, and ADS-B references for
  most), Mode A-only aircraft (ids, no reference) and primary-only plots (no id).

Every plot comes from :func:`~registration.fleet.simulation.scenario.fleet_scenario` (the
generated measurement model); misses and clutter are drawn here. SI units and radians.
"""

from __future__ import annotations

import numpy as np

from registration.fleet.association.simulated.clutter import (
    CLUTTER_ELEVATION_RAD,
    CLUTTER_RANGE_M,
    AssociationScenario,
)
from registration.fleet.simulation.scenario import FleetConfig, fleet_scenario
from registration.fleet.simulation.tracks import Circle, Line, ShipTrack

__all__ = [
    "ISSUE_SENSORS",
    "rolling_ships",
    "aircraft",
    "rolling_fleet",
    "vessel_fleet",
    "atc_fleet",
    "reference_table",
    "drop_and_clutter",
    "registration_scores",
]

#: The issue's sensors: platform, sigmas (m, rad, rad; NaN = not measured), period (s), offset (s), lever (m).
ISSUE_SENSORS = {
    "A-3D": ("A", (25.0, np.radians(0.15), np.radians(0.2)), 2.0, 0.0, (0.0, 20.0, 25.0)),
    "B-3D": ("B", (30.0, np.radians(0.2), np.radians(0.25)), 2.5, 0.83, (0.0, 15.0, 20.0)),
    "B-ESM": ("B", (np.nan, np.radians(0.3), np.radians(0.3)), 1.0, 0.35, (2.0, 5.0, 30.0)),
    "C-2D": ("C", (40.0, np.radians(0.25), np.nan), 3.0, 1.37, (0.0, -30.0, 22.0)),
    "S-3D": ("S", (30.0, np.radians(0.1), np.radians(0.15)), 4.0, 2.09, (0.0, 0.0, 10.0)),
}


def rolling_ships(rng, names=("A", "B", "C"), area_m: float = 25e3) -> dict:
    """Ships at random places within ``area_m`` of the centre, 5-12 m/s, rolling 3-5 deg with
    8-11 s periods, pitching 1-2 deg with 6-9 s periods."""
    out: dict[str, ShipTrack] = {}
    for name in names:
        e, n = rng.uniform(-area_m, area_m, 2)
        out[name] = ShipTrack(
            e,
            n,
            rng.uniform(0, 2 * np.pi),
            rng.uniform(5.0, 12.0),
            rng.uniform(12.0, 20.0),
            np.radians(rng.uniform(1.0, 2.0)),
            rng.uniform(6.0, 9.0),
            np.radians(rng.uniform(3.0, 5.0)),
            rng.uniform(8.0, 11.0),
            rng.uniform(0, 2 * np.pi),
        )
    return out


def aircraft(
    n: int,
    rng,
    *,
    duration_s: float,
    height_m=(3e3, 10e3),
    circling: int = 1,
    area_m: float = 35e3,
    prefix: str = "T",
) -> dict:
    """``n`` aircraft at ``height_m`` (m), the first ``circling`` on circles of 4-12 km radius, the
    others on straight lines through a point within ``area_m`` of the centre at mid-time, 100-250 m/s."""
    out: dict[str, Line | Circle] = {}
    for k in range(n):
        e, no = rng.uniform(-area_m, area_m, 2)
        z, v = rng.uniform(*height_m), rng.uniform(100.0, 250.0)
        if k < circling:
            out[f"{prefix}{k + 1}"] = Circle(e, no, rng.uniform(4e3, 12e3), v, z, rng.uniform(0, 2 * np.pi))
        else:
            c = rng.uniform(0, 2 * np.pi)
            out[f"{prefix}{k + 1}"] = Line(
                e - 0.5 * duration_s * v * np.sin(c), no - 0.5 * duration_s * v * np.cos(c), c, v, z
            )
    return out


def drop_and_clutter(
    sc, rng, *, p_detect: float = 0.9, clutter_share: float = 0.0, max_elevation: float = np.radians(70.0)
) -> AssociationScenario:
    """The scenario's plots with misses (each kept with probability ``p_detect``; none above
    ``max_elevation``) and uniform clutter, ``clutter_share`` of each sensor's real plots, at its
    scan times, uniform in range (:data:`CLUTTER_RANGE_M`), bearing and elevation
    (:data:`CLUTTER_ELEVATION_RAD`), in the channels it measures."""
    kept = (rng.random(sc.plots["time"].size) < p_detect) & ~(np.abs(sc.plots["elevation"]) > max_elevation)
    sc.plots = {k: v[kept] for k, v in sc.plots.items()}
    parts = []
    for s, sid in enumerate(sc.sensors["sensor"]):
        times = np.unique(sc.plots["time"][sc.plots["sensor"] == sid])
        m = (
            rng.poisson(clutter_share * np.count_nonzero(sc.plots["sensor"] == sid))
            if clutter_share > 0
            else 0
        )
        cols = {
            "time": rng.choice(times, m) if times.size else np.zeros(0),
            "sensor": np.full(m, sid),
            "range": rng.uniform(*CLUTTER_RANGE_M, m),
            "bearing": rng.uniform(-np.pi, np.pi, m),
            "elevation": rng.uniform(*CLUTTER_ELEVATION_RAD, m),
        }
        for c in ("range", "bearing", "elevation"):
            if not np.isfinite(sc.sensors[f"sigma_{c}"][s]):
                cols[c] = np.full(m, np.nan)
        parts.append(cols)
    clutter = {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}
    real = {k: v for k, v in sc.plots.items() if k != "target"}
    plots = {k: np.concatenate([real[k], clutter[k]]) for k in real}
    truth = np.concatenate([sc.plots["target"].astype(str), np.full(clutter["time"].size, "")])
    order = np.argsort(plots["time"], kind="stable")
    return AssociationScenario({k: v[order] for k, v in plots.items()}, truth[order], sc.plots, sc)


def reference_table(
    sc, targets, rng, *, period_s: float, sigma_m: float, duration_s: float, jitter: bool = True
) -> dict | None:
    """Reference positions (ECEF, m) of ``targets`` every ``period_s`` s (with random phase and,
    with ``jitter``, +-20 % jitter), with noise ``sigma_m`` per axis; None for no targets."""
    parts = []
    for tid in targets:
        t = np.arange(rng.uniform(0, period_s), duration_s, period_s)
        if jitter:
            t = np.clip(t + rng.uniform(-0.2, 0.2, t.size) * period_s, 0.0, duration_s)
        p = sc.target_ecef(tid, t) + sigma_m * rng.normal(size=(t.size, 3))
        parts.append(
            {
                "target": np.full(t.size, tid),
                "time": t,
                "x": p[:, 0],
                "y": p[:, 1],
                "z": p[:, 2],
                "sigma": np.full(t.size, sigma_m),
            }
        )
    if not parts:
        return None
    return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}


def rolling_fleet(
    seed: int,
    *,
    duration_s: float = 600.0,
    n_aircraft: int = 6,
    sensors: dict | None = None,
    clutter_share: float = 0.0,
    p_detect: float = 0.9,
    angle_bias: float = np.radians(2.0),
    range_bias: float = 250.0,
    site=(-20e3, 30e3, 60.0),
    **fleet,
) -> AssociationScenario:
    """Three rolling ships and a shore site ``site`` (east, north, height m), the ``sensors`` (default
    :data:`ISSUE_SENSORS`), ``n_aircraft`` aircraft (one circling), misses and clutter
    (:func:`drop_and_clutter`); ``fleet``: other :func:`fleet_scenario` arguments."""
    rng = np.random.default_rng(seed)
    sensors = ISSUE_SENSORS if sensors is None else sensors
    ships = rolling_ships(rng, tuple(sorted({v[0] for v in sensors.values()} - {"S"})))
    config = FleetConfig(ships, {"S": site}, sensors, aircraft(n_aircraft, rng, duration_s=duration_s), None)
    sc = fleet_scenario(
        seed, duration_s=duration_s, angle_bias=angle_bias, range_bias=range_bias, config=config, **fleet
    )
    return drop_and_clutter(sc, rng, p_detect=p_detect, clutter_share=clutter_share)


def vessel_fleet(
    seed: int,
    *,
    duration_s: float = 600.0,
    n_vessels: int = 14,
    n_ais: int = 11,
    bearing_bias: float = np.radians(3.0),
    range_bias: float = 40.0,
    time_bias: float = 0.8,
    ais_period_s: float = 6.0,
    ais_sigma_m: float = 10.0,
    p_detect: float = 0.95,
) -> tuple:
    """One ship with one 2-D ARPA radar (range 15 m, bearing 0.4 deg, 2.5 s scans) and ``n_vessels``
    surface vessels (1-12 m/s, 2-14 km away), the first ``n_ais`` reporting AIS positions every
    ``ais_period_s`` s (references, ``ais_sigma_m``). The radar's bearing bias, range bias and
    clock offset (estimated: the sensors table has a ``prior_time_bias`` column) are the given
    sizes with random signs. Returns (scenario with a ``track`` column per radar target, the
    references)."""
    rng = np.random.default_rng(seed)
    ship = ShipTrack(
        0.0,
        0.0,
        rng.uniform(0, 2 * np.pi),
        rng.uniform(3.0, 8.0),
        20.0,
        np.radians(1.0),
        7.0,
        np.radians(rng.uniform(2.0, 4.0)),
        rng.uniform(8.0, 11.0),
        rng.uniform(0, 2 * np.pi),
    )
    vessels = {}
    for k in range(n_vessels):
        r, b = rng.uniform(2e3, 14e3), rng.uniform(0, 2 * np.pi)
        c, v = rng.uniform(0, 2 * np.pi), rng.uniform(1.0, 12.0)
        e, n = r * np.sin(b), r * np.cos(b)
        vessels[f"V{k + 1}"] = Line(
            e - 0.5 * duration_s * v * np.sin(c), n - 0.5 * duration_s * v * np.cos(c), c, v, 0.0
        )
    sensors = {"ARPA": ("A", (15.0, np.radians(0.4), np.nan), 2.5, 0.0, (0.0, 10.0, 25.0))}
    config = FleetConfig({"A": ship}, {}, sensors, vessels, None)
    sc = fleet_scenario(
        seed,
        duration_s=duration_s,
        angle_bias=bearing_bias,
        range_bias=range_bias,
        heading_error=np.radians(0.3),
        level_error=np.radians(0.1),
        config=config,
        time_bias=time_bias,
    )
    sim = drop_and_clutter(sc, rng, p_detect=p_detect)
    numbers = {tid: str(k + 1) for k, tid in enumerate(rng.permutation(list(vessels)))}
    sim.plots["track"] = np.array([numbers.get(t, "") for t in sim.true_target], dtype=object).astype(str)
    refs = reference_table(
        sc, list(vessels)[:n_ais], rng, period_s=ais_period_s, sigma_m=ais_sigma_m, duration_s=duration_s
    )
    return sim, refs


def atc_fleet(
    seed: int,
    *,
    duration_s: float = 300.0,
    n_mode_s: int = 6,
    n_adsb: int = 5,
    n_mode_a: int = 2,
    n_primary: int = 2,
    primary_share: float = 0.25,
    p_detect: float = 0.95,
) -> tuple:
    """Three shore 2-D radars 40-80 km apart (range 40 m, bearing 0.08 deg, 4-5 s scans; attitude held
    at 0) with range biases (+-150 m), range gains (+-300 ppm), bearing biases (+-0.3 deg) and clock
    offsets (+-0.4 s), all estimated without prior; aircraft: ``n_mode_s`` with a Mode S address as
    id (the first ``n_adsb`` of them reporting ADS-B positions at 1 Hz, 30 m), ``n_mode_a`` with a
    Mode A code ``A<octal>`` as id and ``n_primary`` without any id. Of the Mode S and Mode A
    aircraft's plots a share ``primary_share`` carries no id (the secondary reply missed). Returns
    (scenario whose plots' ``target`` column holds the ids given, '' where none; the references)."""
    rng = np.random.default_rng(seed)
    sites = {"R1": (-30e3, -20e3, 120.0), "R2": (35e3, -10e3, 90.0), "R3": (0.0, 40e3, 300.0)}
    sensors = {
        sid: (sid, (40.0, np.radians(0.08), np.nan), p, off, (0.0, 0.0, 15.0))
        for sid, p, off in (("R1", 4.0, 0.0), ("R2", 4.5, 1.13), ("R3", 5.0, 2.41))
    }
    n = n_mode_s + n_mode_a + n_primary
    planes = aircraft(
        n, rng, duration_s=duration_s, height_m=(2e3, 11e3), circling=1, area_m=40e3, prefix="P"
    )
    config = FleetConfig({}, sites, sensors, planes, None)
    sc = fleet_scenario(
        seed,
        duration_s=duration_s,
        angle_bias=np.radians(0.3),
        range_bias=150.0,
        config=config,
        range_gain=3e-4,
        time_bias=0.4,
    )
    names = list(planes)
    ids = {t: f"{int(rng.integers(0x400000, 0xC00000)):06X}" for t in names[:n_mode_s]}
    ids.update({t: f"A{int(rng.integers(0, 8**4)):04o}" for t in names[n_mode_s : n_mode_s + n_mode_a]})
    sim = drop_and_clutter(sc, rng, p_detect=p_detect)
    given = np.array([ids.get(t, "") for t in sim.true_target], dtype=object)
    given[rng.random(given.size) < primary_share] = ""
    sim.plots["target"] = given.astype(str)
    refs = reference_table(
        sc, names[:n_adsb], rng, period_s=1.0, sigma_m=30.0, duration_s=duration_s, jitter=False
    )
    if refs is not None:  # None without ADS-B targets
        refs["target"] = np.array([ids[t] for t in refs["target"]])
    sim.true_target = np.array([ids.get(t, t) for t in sim.true_target])
    return sim, refs


def registration_scores(result, base, truth: dict) -> dict:
    """How a registration ``result`` (BatchResult) compares with the truth and with ``base``, the
    registration of the same fleet with true target ids. ``vs_truth``: the largest |estimate - truth|
    / sigma over the identifiable states and the identifiable sums (``result.rows``); ``sigma_ratio``:
    the largest sigma(result) / sigma(base) over the free states with a finite sigma in both;
    ``chi2_mean`` and ``chi2_band``: the mean squared normalised residual per degree of freedom and
    its two-sided 99.9 % band for independent samples (``chi2_ok``: inside it); ``vs_ids``: the
    largest |estimate - base| / sigma(base) over those states."""
    rows = [r for r in result.rows(truth) if r["status"] in ("identifiable", "identifiable combination")]
    vs_truth = max(
        abs(r["estimate"] - r["truth"]) / r["sigma"]
        for r in rows
        if np.isfinite(r["sigma"]) and r["sigma"] > 0
    )
    free = base.layout.free
    ok = free[np.isfinite(base.sigma[free]) & np.isfinite(result.sigma[free]) & (base.sigma[free] > 0)]
    dof = result.chi_square.dof
    half = 3.29 * np.sqrt(2.0 / dof)
    mean = result.chi_square.mean
    return {
        "vs_truth": float(vs_truth),
        "sigma_ratio": float(np.max(result.sigma[ok] / base.sigma[ok])),
        "vs_ids": float(np.max(np.abs(result.estimate - base.estimate)[ok] / base.sigma[ok])),
        "chi2_mean": float(mean),
        "chi2_band": (1 - half, 1 + half),
        "chi2_ok": bool(abs(mean - 1) < half),
    }
