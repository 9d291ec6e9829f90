"""What a simulated sensor can see: the limits of its coverage, so that a scenario of any length
produces only plots a real sensor would report.

A real sensor reports nothing beyond its instrumented range, nothing below its radio horizon, and
nothing above the top of its beam: a rotating radar has a cone of silence overhead (its beam
reaches some 40-70 deg by design; 70 deg here for every radar), and a passive sensor's field of
view stops short of the zenith too (85 deg here). A target that passes overhead is
therefore not plotted while it is inside the cone, rather than reported at an elevation of 90 deg
or more. The limits are per sensor kind (:data:`DEFAULT_COVERAGE`, by which channels the sensor
measures), and each plot is judged at its true geometry (before biases and noise):

- slant range at most ``max_range`` (m), when the sensor measures range;
- elevation in the sensor's deck frame at most ``max_elevation`` (rad);
- the target above the radio horizon of a 4/3 earth: slant range at most
  ``sqrt(2 k a h_s) + sqrt(2 k a h_t)`` with ``k = 4/3``, ``a`` the WGS-84 semi-major axis and
  ``h_s``, ``h_t`` the heights (m) of sensor and target above the ellipsoid (at least 1 m).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration import _codegen

__all__ = ["Coverage", "DEFAULT_COVERAGE", "coverage_for", "horizon_range", "visible"]

#: Effective earth radius factor for radio propagation in a standard atmosphere.
REFRACTION_K = 4.0 / 3.0


@dataclass(frozen=True)
class Coverage:
    """A sensor's coverage: ``max_range`` (m, slant; inf: no limit) and ``max_elevation`` (rad,
    in the deck frame)."""

    max_range: float
    max_elevation: float


#: Coverage by sensor kind: a 3-D radar (range, bearing, elevation), a 2-D radar (range, bearing),
#: a passive angle sensor (bearing, elevation), a bearing-only sensor and a range-only sensor.
DEFAULT_COVERAGE = {
    "3d": Coverage(250e3, np.radians(70.0)),
    "2d": Coverage(400e3, np.radians(70.0)),
    "passive": Coverage(np.inf, np.radians(85.0)),
    "bearing": Coverage(np.inf, np.radians(70.0)),
    "range": Coverage(400e3, np.radians(70.0)),
}


def coverage_for(sigma) -> Coverage:
    """The default coverage of a sensor from its noise
    sigmas (range, bearing, elevation; NaN: not measured)."""
    has = np.isfinite(np.asarray(sigma, dtype=float))
    kinds: dict[tuple[bool, ...], str] = {
        (True, True, True): "3d",
        (True, True, False): "2d",
        (False, True, True): "passive",
        (False, True, False): "bearing",
        (True, False, False): "range",
    }
    return DEFAULT_COVERAGE[kinds.get(tuple(bool(h) for h in has), "3d")]


def horizon_range(h_sensor: np.ndarray, h_target: np.ndarray) -> np.ndarray:
    """Radio horizon range (m) between a sensor and a target at heights ``h_sensor``, ``h_target``
    (m above the ellipsoid, clipped at 1 m), over a 4/3 earth."""
    a = _codegen.wgs84()["wgs84_a_m"]
    ka = 2.0 * REFRACTION_K * a
    return np.sqrt(ka * np.maximum(h_sensor, 1.0)) + np.sqrt(ka * np.maximum(h_target, 1.0))


def visible(
    coverage: Coverage,
    range_true: np.ndarray,
    elevation_true: np.ndarray,
    h_sensor: np.ndarray,
    h_target: np.ndarray,
) -> np.ndarray:
    """Boolean mask of the plots the sensor reports: true slant range (m) and deck elevation (rad)
    within its coverage and the target above the radio horizon."""
    return (
        (range_true <= coverage.max_range)
        & (elevation_true <= coverage.max_elevation)
        & (range_true <= horizon_range(h_sensor, h_target))
    )
