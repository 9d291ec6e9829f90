"""Noisy radar and camera tracks of a :class:`~registration.landing.scenario.LandingScenario`
(white Gaussian noise, each sensor on its own clock), and their processing."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.landing.pipeline import LandingConfig, LandingResult, process
from registration.landing.scenario import LandingScenario

__all__ = ["LandingSimulation", "simulate", "run_once"]


@dataclass(frozen=True)
class LandingSimulation:
    """Noisy sensor tracks of R runs sharing one pair of clocks.

    ``t_radar``/``t_camera`` are the timestamps as each sensor's clock reads them (s);
    ``true_t_radar``/``true_t_camera`` the true sampling instants; ``polar_rdr`` (R, n, 3)
    [r m, a rad, b rad] and ``angles_cam`` (R, m, 2) [a, b] rad.
    """

    scenario: LandingScenario
    t_radar: np.ndarray
    true_t_radar: np.ndarray
    polar_rdr: np.ndarray
    t_camera: np.ndarray
    true_t_camera: np.ndarray
    angles_cam: np.ndarray


def _sample_times(rate_hz: float, first_s: float, duration_s: float) -> np.ndarray:
    if not rate_hz > 0:
        raise ValueError(f"rate_hz: expected > 0 Hz, got {rate_hz!r}")
    n = int(np.floor((duration_s - first_s) * rate_hz + 1e-9)) + 1
    if n < 2:
        raise ValueError(f"the approach ({duration_s:.3g} s) holds fewer than 2 samples at {rate_hz} Hz")
    return first_s + np.arange(n) / rate_hz


def simulate(
    scenario: LandingScenario, runs: int = 1, rng: np.random.Generator | int | None = 0
) -> LandingSimulation:
    """Simulate ``runs`` independent noise realisations of the scenario's approach."""
    if not (isinstance(runs, (int, np.integer)) and runs >= 1):
        raise ValueError(f"runs: expected an integer >= 1, got {runs!r}")
    rng = np.random.default_rng(rng)
    T = scenario.duration_s
    tr = _sample_times(scenario.radar.rate_hz, scenario.radar.first_sample_s, T)
    tc = _sample_times(scenario.camera.rate_hz, scenario.camera.first_sample_s, T)
    pr = scenario.truth_radar(tr)
    pc = scenario.truth_camera(tc)
    polar = pr[None] + rng.standard_normal((runs, *pr.shape)) * scenario.radar.sigma
    angles = pc[None] + rng.standard_normal((runs, *pc.shape)) * scenario.camera.sigma
    return LandingSimulation(
        scenario=scenario,
        t_radar=tr + scenario.radar.clock_offset_s,
        true_t_radar=tr,
        polar_rdr=polar,
        t_camera=tc + scenario.camera.clock_offset_s,
        true_t_camera=tc,
        angles_cam=angles,
    )


def run_once(sim: LandingSimulation, config: LandingConfig) -> LandingResult:
    """Process one simulation (all its runs) with ``config``."""
    sc = sim.scenario
    return process(
        sim.t_radar,
        sim.polar_rdr,
        sc.radar.sigma,
        sim.t_camera,
        sim.angles_cam,
        sc.camera.sigma,
        sc.attitude,
        sc.geometry,
        config,
    )
