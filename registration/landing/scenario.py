"""The simulated carrier approach: ship motion, sensor models, glide path, deck layout and the
noise-free truth seen by each sensor. Every default is an assumption stated in docs/background/landing.md
and can be changed through the dataclasses (or the CLI). SI units and radians."""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from registration._generated import api as generated
from registration.landing.geometry import LandingGeometry, deck_to_touchdown_rotation
from registration.landing.pipeline import LandingConfig

__all__ = [
    "ShipMotion",
    "RadarModel",
    "CameraModel",
    "Approach",
    "LandingScenario",
    "default_geometry",
    "default_scenario",
    "with_overrides",
]


@dataclass(frozen=True)
class ShipMotion:
    """Ship speed (m/s) and sinusoidal attitude about the mean heading (rad, s)."""

    speed_mps: float = 15.0
    yaw_amplitude_rad: float = float(np.radians(0.5))
    yaw_period_s: float = 15.0
    yaw_phase_rad: float = 0.0
    pitch_amplitude_rad: float = float(np.radians(1.0))
    pitch_period_s: float = 8.0
    pitch_phase_rad: float = 0.0
    roll_amplitude_rad: float = float(np.radians(2.0))
    roll_period_s: float = 12.0
    roll_phase_rad: float = 0.0

    def __post_init__(self) -> None:
        for name in ("yaw_period_s", "pitch_period_s", "roll_period_s"):
            if not getattr(self, name) > 0:
                raise ValueError(f"{name}: expected a period > 0 s, got {getattr(self, name)!r}")
        for name in ("yaw_amplitude_rad", "pitch_amplitude_rad", "roll_amplitude_rad"):
            v = getattr(self, name)
            if not 0 <= v < np.pi / 4:
                raise ValueError(
                    f"{name}: expected 0 <= amplitude < pi/4 rad, got {v!r} (degrees passed as radians?)"
                )
        if not self.speed_mps >= 0:
            raise ValueError(f"speed_mps: expected >= 0 m/s, got {self.speed_mps!r}")

    def attitude(self, t) -> np.ndarray:
        """[yaw deviation, pitch, roll] (N, 3) in rad at times t (s)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        cols = []
        for a, T, ph in (
            (self.yaw_amplitude_rad, self.yaw_period_s, self.yaw_phase_rad),
            (self.pitch_amplitude_rad, self.pitch_period_s, self.pitch_phase_rad),
            (self.roll_amplitude_rad, self.roll_period_s, self.roll_phase_rad),
        ):
            cols.append(a * np.sin(2 * np.pi * t / T + ph))
        return np.stack(cols, axis=1)


@dataclass(frozen=True)
class RadarModel:
    """Landing-guidance radar: rate (Hz), clock offset (s; its clock reads true + offset), noise."""

    rate_hz: float = 20.0
    clock_offset_s: float = 0.0
    first_sample_s: float = 0.0
    sigma_range_m: float = 3.0
    sigma_azimuth_rad: float = 1.0e-3
    sigma_elevation_rad: float = 1.0e-3

    @property
    def sigma(self) -> np.ndarray:
        """[m, rad, rad] noise standard deviations."""
        return np.array([self.sigma_range_m, self.sigma_azimuth_rad, self.sigma_elevation_rad])


@dataclass(frozen=True)
class CameraModel:
    """Centreline camera: rate (Hz), clock offset (s; its clock reads true + offset), angle noise (rad)."""

    rate_hz: float = 25.0
    clock_offset_s: float = 0.004
    first_sample_s: float = 0.0
    sigma_azimuth_rad: float = 0.3e-3
    sigma_elevation_rad: float = 0.3e-3

    @property
    def sigma(self) -> np.ndarray:
        """[rad, rad] noise standard deviations."""
        return np.array([self.sigma_azimuth_rad, self.sigma_elevation_rad])


@dataclass(frozen=True)
class Approach:
    """Straight glide path in the mtd frame along the angled-deck centreline.

    ``start_range_m`` and ``end_range_m`` are distances to the touchdown point along the path (m);
    ``ground_speed_mps`` is the aircraft's speed over the sea (m/s); ``lateral_offset_m`` and
    ``height_offset_m`` shift the whole path sideways (mtd y) and up (mtd z), 0 by default.
    """

    glide_slope_rad: float = float(np.radians(3.5))
    ground_speed_mps: float = 70.0
    start_range_m: float = 4000.0
    end_range_m: float = 0.0
    lateral_offset_m: float = 0.0
    height_offset_m: float = 0.0

    def __post_init__(self) -> None:
        if not 0 <= self.glide_slope_rad < np.radians(30):
            raise ValueError(f"glide_slope_rad: expected [0, 0.52) rad, got {self.glide_slope_rad!r}")
        if not self.start_range_m > self.end_range_m >= 0:
            raise ValueError(
                f"start_range_m > end_range_m >= 0 (m) required, got {self.start_range_m!r}, "
                f"{self.end_range_m!r}"
            )
        if not self.ground_speed_mps > 0:
            raise ValueError(f"ground_speed_mps: expected > 0 m/s, got {self.ground_speed_mps!r}")


def default_geometry(
    angled_deck_rad: float = float(np.radians(9.0)), camera_ahead_m: float = 25.0
) -> LandingGeometry:
    """The default deck layout (deck frame, m from the motion centre): touchdown point
    (-8, -105, 20), radar (38, -40, 35), camera ``camera_ahead_m`` forward of the touchdown point
    on the angled-deck centreline."""
    l_td = np.array([-8.0, -105.0, 20.0])
    R_td_deck0 = deck_to_touchdown_rotation(np.zeros(3), LandingGeometry(angled_deck_rad, l_td, l_td, l_td))[
        0
    ]
    forward_deck = R_td_deck0.T @ np.array([-1.0, 0.0, 0.0])  # -x_td: forward along the angled deck
    return LandingGeometry(
        angled_deck_rad=angled_deck_rad,
        l_touchdown_deck_m=l_td,
        l_radar_deck_m=np.array([38.0, -40.0, 35.0]),
        l_camera_deck_m=l_td + camera_ahead_m * forward_deck,
    )


@dataclass(frozen=True)
class LandingScenario:
    """Everything the simulation needs; change any field with ``dataclasses.replace``."""

    ship: ShipMotion = field(default_factory=ShipMotion)
    geometry: LandingGeometry = field(default_factory=default_geometry)
    radar: RadarModel = field(default_factory=RadarModel)
    camera: CameraModel = field(default_factory=CameraModel)
    approach: Approach = field(default_factory=Approach)

    @property
    def glide_direction_mtd(self) -> np.ndarray:
        """Unit vector from the touchdown point up the glide path (aft and up), mtd axes."""
        g = self.approach.glide_slope_rad
        return np.array([np.cos(g), 0.0, np.sin(g)])

    @property
    def closure_speed_mps(self) -> float:
        """Aircraft speed relative to the ship's mean motion along the path, m/s.

        Solves ``|v_ship + c d| = ground speed`` for c > 0 with d the unit vector towards touchdown.
        """
        R_td_deck0 = deck_to_touchdown_rotation(np.zeros(3), self.geometry)[0]
        v_ship_mtd = R_td_deck0 @ np.array([0.0, self.ship.speed_mps, 0.0])  # level = deck at zero attitude
        d = -self.glide_direction_mtd
        dv = float(d @ v_ship_mtd)
        disc = dv**2 - self.ship.speed_mps**2 + self.approach.ground_speed_mps**2
        c = -dv + np.sqrt(disc) if disc >= 0 else -1.0
        if not c > 0:
            raise ValueError(
                f"ground_speed_mps = {self.approach.ground_speed_mps} m/s cannot close on a ship at "
                f"{self.ship.speed_mps} m/s along this path"
            )
        return float(c)

    @property
    def duration_s(self) -> float:
        """Time from the start to the end of the approach, s."""
        return (self.approach.start_range_m - self.approach.end_range_m) / self.closure_speed_mps

    def attitude(self, t) -> np.ndarray:
        """Ship attitude [yaw, pitch, roll] (N, 3), rad, at true times t (s)."""
        return self.ship.attitude(t)

    def truth_mtd(self, t) -> np.ndarray:
        """Aircraft position (N, 3), m, in the mean touchdown frame at true times t (s)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        s = self.approach.start_range_m - self.closure_speed_mps * t
        p = s[:, None] * self.glide_direction_mtd[None, :]
        p[:, 1] += self.approach.lateral_offset_m
        p[:, 2] += self.approach.height_offset_m
        return p

    def _deck(self, t: np.ndarray) -> dict[str, np.ndarray | float]:
        """The inputs every generated deck transform takes at true times t (s): attitude, angled deck."""
        return {"attitude": self.attitude(t), "angled_deck": self.geometry.angled_deck_rad}

    def truth_td(self, t) -> np.ndarray:
        """Aircraft position (N, 3), m, in the touchdown frame (which moves with the deck)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        l_td_deck = self.geometry.l_touchdown_deck_m
        return generated.landing_mtd2td(p_mtd=self.truth_mtd(t), **self._deck(t), l_td_deck=l_td_deck).p_td

    def truth_radar(self, t) -> np.ndarray:
        """Noise-free radar polar [r, a, b] (N, 3) at true times t (s)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        d_radar_deck = self.geometry.d_radar_deck_m
        return generated.landing_td2radar(
            p_td=self.truth_td(t), **self._deck(t), d_radar_deck=d_radar_deck
        ).polar_rdr

    def truth_camera(self, t) -> np.ndarray:
        """Noise-free camera angles [a, b] (N, 2) at true times t (s)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        d_camera_deck = self.geometry.d_camera_deck_m
        return generated.landing_td2camera(
            p_td=self.truth_td(t), **self._deck(t), d_camera_deck=d_camera_deck
        ).angles_cam

    def truth_ctd(self, t) -> np.ndarray:
        """True polar [r, a, b] (N, 3) about the camera in td axes at true times t (s)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        d_camera_deck = self.geometry.d_camera_deck_m
        return generated.landing_td2ctd(
            p_td=self.truth_td(t), **self._deck(t), d_camera_deck=d_camera_deck
        ).polar_ctd

    def config(self, **overrides) -> LandingConfig:
        """A processing configuration that knows this scenario's clock offsets (calibrated clocks)."""
        base: dict[str, Any] = dict(
            radar_clock_offset_s=self.radar.clock_offset_s, camera_clock_offset_s=self.camera.clock_offset_s
        )
        base.update(overrides)
        return LandingConfig(**base)


def default_scenario() -> LandingScenario:
    """The default approach (every field at its default; see docs/background/landing.md, Assumptions)."""
    return LandingScenario()


def with_overrides(scenario: LandingScenario, **sections) -> LandingScenario:
    """``with_overrides(sc, ship={"roll_amplitude_rad": 0.05})``: replace fields section by section."""
    out = scenario
    for name, fields in sections.items():
        if fields:
            out = replace(out, **{name: replace(getattr(out, name), **fields)})
    return out
