"""Stone Soup interoperation: detections <-> plot and navigation tables, and a feeder that
corrects detections with a registration result. See docs/howto/stonesoup.md.

Needs the optional dependency Stone Soup: ``pip install stonesoup``;
without it, importing this module raises ImportError saying so.

Conventions (verified numerically by tests/interop/): Stone Soup's world is a local ENU frame
(x east, y north, z up) about a chosen origin (:class:`LocalFrame`); its body frame is x forward,
y port, z up; ``yaw = pi/2 - heading``, ``pitch = +pitch``, ``roll = +roll``; Stone Soup's bearing
is minus the deck bearing; measurement vectors are (elevation, bearing, range) or (bearing, range).
"""

from __future__ import annotations

# first, so that without Stone Soup the error says how to install it (not which module failed)
from registration.interop.requires import INSTALL_HINT, STONESOUP_VERSION  # isort: split

from registration.interop.convert import (
    EPOCH,
    MODEL_CHANNELS,
    POSITION_MAPPING,
    measured_plot,
    measurement_model,
    mounted_radar,
    tables_to_detections,
)
from registration.interop.detections import detections_to_tables
from registration.interop.feeder import RegisteredDetectionFeeder, RegistrationCorrector
from registration.interop.world import DECK2BODY, LocalFrame, orientation_rotation

__all__ = [
    "DECK2BODY",
    "EPOCH",
    "INSTALL_HINT",
    "MODEL_CHANNELS",
    "POSITION_MAPPING",
    "STONESOUP_VERSION",
    "LocalFrame",
    "RegisteredDetectionFeeder",
    "RegistrationCorrector",
    "detections_to_tables",
    "measured_plot",
    "measurement_model",
    "mounted_radar",
    "orientation_rotation",
    "tables_to_detections",
]
