"""Deck geometry and space alignment: the deck-to-touchdown rotation and the radar point in the
touchdown frame (Wang, Liu & Gao 2017, eqs. 7-8).

Frames (full definitions with sign conventions in ``derive/landing.py`` and ``docs/background/landing.md``):

- ``deck``: ship-fixed; origin at the ship's motion centre; x starboard, y bow, z deck normal.
- ``level``: origin at the motion centre, x starboard / y bow along the *mean* heading, z up;
  ``R_level_deck = Rz(yaw) Rx(pitch) Ry(roll)``; attitude = [yaw deviation, pitch, roll] (rad),
  positive yaw turns the bow to starboard, positive pitch lifts the bow, positive roll puts the
  starboard side down.
- ``td``: origin at the ideal touchdown point (deck-fixed, so it moves with the ship's motion);
  level axes: x horizontal aft along the angled-deck centreline (towards the approaching
  aircraft), z up, y = z x x. ``M = R_td_deck = T_A(phi_c) T_L R_level_deck`` (eqs. 7-8).
- ``rdr``: radar polar ``[r, a, b]`` (m, rad, rad) about the radar in deck axes; a counter-clockwise
  from starboard towards the bow, b above the deck plane (dead astern: a = -pi/2).
- ``cam``: camera angles ``[a, b]`` (rad) about the camera, deck-fixed axes equal to the td axes
  at zero attitude (x aft along the angled-deck centreline, z deck normal).
- ``ctd``: camera-centred td axes. Fusion works in its polar coordinates ``[r, a, b]``.

Transforms and Jacobians come from the generated ``landing_*`` functions. Arrays are vectorised
over a leading axis of N instants; SI units and radians.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration._generated import api as generated
from registration.core.validation import as_float_array, check_range
from registration.landing.checks import as_attitude, as_lever_arm, as_polar, common_count

__all__ = ["LandingGeometry", "deck_to_touchdown_rotation", "radar_to_touchdown"]


@dataclass(frozen=True)
class LandingGeometry:
    """Known deck geometry (the paper's assumptions 2 and 3).

    Attributes:
        angled_deck_rad: angle between the angled-deck centreline and the ship's centreline,
            rad, positive when the landing area's forward end points to port (US carriers ~0.16).
        l_touchdown_deck_m: ideal touchdown point, deck frame, m from the motion centre.
        l_radar_deck_m: radar phase centre, deck frame, m from the motion centre.
        l_camera_deck_m: camera optical centre, deck frame, m from the motion centre.
    """

    angled_deck_rad: float
    l_touchdown_deck_m: np.ndarray
    l_radar_deck_m: np.ndarray
    l_camera_deck_m: np.ndarray

    def __post_init__(self) -> None:
        a = as_float_array("angled_deck_rad", self.angled_deck_rad)
        check_range("angled_deck_rad", a, -np.pi / 4, np.pi / 4, "rad (angled-deck angle)", angle=True)
        object.__setattr__(self, "angled_deck_rad", float(a))
        for name in ("l_touchdown_deck_m", "l_radar_deck_m", "l_camera_deck_m"):
            object.__setattr__(self, name, as_lever_arm(name, getattr(self, name)))

    @property
    def d_radar_deck_m(self) -> np.ndarray:
        """Radar minus touchdown point, deck axes (m)."""
        return self.l_radar_deck_m - self.l_touchdown_deck_m

    @property
    def d_camera_deck_m(self) -> np.ndarray:
        """Camera minus touchdown point, deck axes (m)."""
        return self.l_camera_deck_m - self.l_touchdown_deck_m


def deck_to_touchdown_rotation(attitude, geometry: LandingGeometry) -> np.ndarray:
    """M = R_td_deck (N, 3, 3) = T_A(phi_c) T_L R_level_deck(yaw, pitch, roll) (eq. 8); attitude in rad."""
    att = as_attitude(attitude)
    return generated.landing_deck2td_rotation(attitude=att, angled_deck=geometry.angled_deck_rad).R_td_deck


def radar_to_touchdown(polar_rdr, attitude, geometry: LandingGeometry) -> tuple[np.ndarray, np.ndarray]:
    """Eq. (7): radar polar ``[r m, a rad, b rad]`` (deck axes) -> target ``p_td`` (N, 3) m in the
    touchdown frame, and ``J = dp_td/dpolar_rdr = M A`` (N, 3, 3)."""
    pol = as_polar("polar_rdr", polar_rdr, 3)
    att = as_attitude(attitude)
    common_count(polar_rdr=pol, attitude=att)
    td = generated.landing_radar2td(
        polar_rdr=pol,
        attitude=att,
        angled_deck=geometry.angled_deck_rad,
        d_radar_deck=geometry.d_radar_deck_m,
    )
    return td.p_td, td.J
