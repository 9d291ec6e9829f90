"""Radar/camera fusion for carrier landing: time and space alignment, error transfer into the
touchdown frame, and weighted angle fusion; ``scenario`` simulates approaches for Monte Carlo."""

from registration.landing.model import (
    FUSION_METHODS, CameraTransfer, LandingConfig, LandingGeometry, LandingResult, PositionEstimate, RadarTransfer, combine,
    deck_to_touchdown_rotation, process, radar_only, radar_to_touchdown, transfer_camera, transfer_radar, variance_ratios,
)

__all__ = ["FUSION_METHODS", "CameraTransfer", "LandingConfig", "LandingGeometry", "LandingResult", "PositionEstimate",
           "RadarTransfer", "combine", "deck_to_touchdown_rotation", "process", "radar_only", "radar_to_touchdown",
           "transfer_camera", "transfer_radar", "variance_ratios"]
