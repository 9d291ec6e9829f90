"""Tracks of the simulated fleet: ships (geodetic, with wave motion) and targets (ENU about a
centre point, placed in ECEF through the generated ``geodetic2ecef`` and
``enu2ecef_rotation_standard``)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration._generated import api as generated
from registration.core.angles import wrap_angle
from registration.core.motion import ShipMotion

__all__ = ["ShipTrack", "Circle", "Line", "enu2ecef_points", "random_targets"]


def enu2ecef_points(centre, p_enu: np.ndarray) -> np.ndarray:
    """(N, 3) ECEF (m) of points given in the ENU frame at ``centre`` = (lat, lon rad, alt m)."""
    lat, lon, alt = centre
    origin = generated.geodetic2ecef(lat=lat, lon=lon, alt=alt).p_ecef[0]
    R_ecef_enu = generated.enu2ecef_rotation_standard(lat=lat, lon=lon).R_ecef_enu[0]
    return origin + np.atleast_2d(p_enu) @ R_ecef_enu.T


@dataclass(frozen=True)
class ShipTrack:
    """A ship sailing a straight course with sinusoidal pitch and roll.

    Start ``east0``, ``north0`` (m from the centre), ``course`` (rad clockwise from north; the
    heading equals it), ``speed`` (m/s), navigation point ``height`` (m above the ellipsoid),
    pitch and roll amplitudes (rad) and periods (s), wave ``phase`` (rad). The true track is
    defined in geodetic coordinates: the east/north offsets are divided by the radii of curvature
    at the centre (any track is a valid truth; the plots are computed from this one).
    """

    east0: float
    north0: float
    course: float
    speed: float
    height: float
    pitch_amplitude: float
    pitch_period: float
    roll_amplitude: float
    roll_period: float
    phase: float

    @staticmethod
    def geodetic(centre, east: np.ndarray, north: np.ndarray, height: float):
        """(lat, lon) rad of points offset east/north (m) from ``centre`` at ``height`` m."""
        M, N = generated.radii_of_curvature(lat=centre[0]).radii[0]
        lat = centre[0] + north / (M + height)
        lon = centre[1] + east / ((N + height) * np.cos(centre[0]))
        return lat, lon

    def navigation(self, centre, t: np.ndarray, motion: bool = True) -> np.ndarray:
        """(N, 6) true lat, lon (rad), alt (m), heading, pitch, roll (rad) at times t (s)."""
        east = self.east0 + self.speed * t * np.sin(self.course)
        north = self.north0 + self.speed * t * np.cos(self.course)
        lat, lon = self.geodetic(centre, east, north, self.height)
        scale = 1.0 if motion else 0.0
        waves = ShipMotion(self.pitch_amplitude, self.pitch_period, self.roll_amplitude, self.roll_period)
        pitch, roll = (scale * a for a in waves.angles(t, self.phase))
        heading = np.full(t.shape, float(wrap_angle(self.course)))
        return np.stack([lat, lon, np.full(t.shape, self.height), heading, pitch, roll], axis=1)


@dataclass(frozen=True)
class Circle:
    """A target circling counter-clockwise: centre east/north (m), radius (m), speed (m/s),
    altitude z (m, ENU up), start angle (rad from east)."""

    east: float
    north: float
    radius: float
    speed: float
    z: float
    phase: float

    def enu(self, t: np.ndarray) -> np.ndarray:
        a = self.phase + self.speed / self.radius * t
        return np.stack(
            [
                self.east + self.radius * np.cos(a),
                self.north + self.radius * np.sin(a),
                np.full(np.shape(t), self.z),
            ],
            axis=-1,
        )


@dataclass(frozen=True)
class Line:
    """A target on a straight course: start east/north (m), course (rad from north), speed
    (m/s), altitude z (m, ENU up)."""

    east: float
    north: float
    course: float
    speed: float
    z: float

    def enu(self, t: np.ndarray) -> np.ndarray:
        return np.stack(
            [
                self.east + self.speed * t * np.sin(self.course),
                self.north + self.speed * t * np.cos(self.course),
                np.full(np.shape(t), self.z),
            ],
            axis=-1,
        )


def random_targets(n: int, seed: int = 0, *, half_width: float = 40e3) -> dict:
    """``n`` targets ``T1`` ... ``Tn`` circling inside the square of ``half_width`` m about the centre,
    so that they stay in the sensors' coverage for any duration: centres uniform in the square,
    radii 3-20 km, speeds 100-250 m/s, altitudes 1-10 km (ENU up), start angles uniform."""
    if not (isinstance(n, (int, np.integer)) and n >= 1):
        raise ValueError(f"n: expected a number of targets >= 1, got {n!r}")
    rng = np.random.default_rng(seed)
    east, north = rng.uniform(-half_width, half_width, (2, n))
    radius, speed = rng.uniform(3e3, 20e3, n), rng.uniform(100.0, 250.0, n)
    z, phase = rng.uniform(1e3, 10e3, n), rng.uniform(0.0, 2.0 * np.pi, n)
    return {
        f"T{k + 1}": Circle(
            float(east[k]), float(north[k]), float(radius[k]), float(speed[k]), float(z[k]), float(phase[k])
        )
        for k in range(n)
    }
