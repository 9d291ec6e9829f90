"""Shared core: frames and geodesy, angles, input validation, time alignment, observability, ship motion,
small batched linear algebra and plotting set-up. Every capability builds on these modules;
nothing here imports a capability."""

from registration.core.alignment import AlignedSamples, align
from registration.core.angles import wrap_angle
from registration.core.frames import (
    deck2enu,
    deck2enu_jacobians,
    deck2enu_rotation,
    enu2ecef_rotation,
    geodetic2ecef,
    plot2ecef,
)
from registration.core.motion import ShipMotion
from registration.core.observability import ObservabilityReport, observability_report

__all__ = [
    "AlignedSamples",
    "ObservabilityReport",
    "ShipMotion",
    "align",
    "deck2enu",
    "deck2enu_jacobians",
    "deck2enu_rotation",
    "enu2ecef_rotation",
    "geodetic2ecef",
    "observability_report",
    "plot2ecef",
    "wrap_angle",
]
