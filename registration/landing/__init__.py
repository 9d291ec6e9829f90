"""Radar/camera fusion for carrier landing, after Wang, Liu & Gao, "A self-calibration method based
on fusion of landing guidance radar and centerline camera", Ship Science and Technology 39(3),
140-144 (2017): time alignment, space alignment into the touchdown frame, error transfer and
weighted angle fusion; plus a simulated approach and its Monte Carlo evaluation.

Modules: ``geometry`` (deck layout, frame rotations), ``transfer`` (eqs. 8-11), ``fusion``
(eq. 12 and the joint update), ``pipeline`` (``process``), ``scenario`` (the simulated approach),
``simulation`` (noisy tracks), ``montecarlo`` (statistics by range bin), ``plots`` (the figures;
imported on its own, it needs matplotlib).
"""

from registration.landing.fusion import FUSION_METHODS, PositionEstimate, combine, radar_only
from registration.landing.geometry import LandingGeometry, deck_to_touchdown_rotation, radar_to_touchdown
from registration.landing.montecarlo import MonteCarloResult, default_bin_edges, monte_carlo, regroup
from registration.landing.pipeline import LandingConfig, LandingResult, fusion_instants, process
from registration.landing.scenario import (
    Approach,
    CameraModel,
    LandingScenario,
    RadarModel,
    ShipMotion,
    default_geometry,
    default_scenario,
    with_overrides,
)
from registration.landing.simulation import LandingSimulation, run_once, simulate
from registration.landing.transfer import (
    CameraTransfer,
    RadarTransfer,
    transfer_camera,
    transfer_radar,
    variance_ratios,
)

__all__ = [
    # fusion pipeline
    "FUSION_METHODS",
    "CameraTransfer",
    "LandingConfig",
    "LandingGeometry",
    "LandingResult",
    "PositionEstimate",
    "RadarTransfer",
    "combine",
    "deck_to_touchdown_rotation",
    "fusion_instants",
    "process",
    "radar_only",
    "radar_to_touchdown",
    "transfer_camera",
    "transfer_radar",
    "variance_ratios",
    # simulated approach and Monte Carlo
    "Approach",
    "CameraModel",
    "LandingScenario",
    "LandingSimulation",
    "MonteCarloResult",
    "RadarModel",
    "ShipMotion",
    "default_bin_edges",
    "default_geometry",
    "default_scenario",
    "monte_carlo",
    "regroup",
    "run_once",
    "simulate",
    "with_overrides",
]
