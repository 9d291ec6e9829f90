"""Stone Soup's world and body frames in this package's terms (no Stone Soup import needed).

**World.** Stone Soup works in one Cartesian frame. Here it is a local ENU frame about an
``origin`` (lat, lon rad; alt m): world x east, y north, z up along the geodetic normal at the
origin, in metres. ``p_ecef = geodetic2ecef(origin) + R_ecef_enu(origin) @ p_world``, both from
:mod:`registration.core.frames`; the mapping is exact (a rigid transform, no flat-earth
approximation), but away from the origin the world's axes are not the local east/north/up: a
platform 40 km away sees them tilted by 0.36 deg. Attitudes are therefore carried through ECEF.

**Body.** A Stone Soup sensor's body frame is x forward, y port, z up, so
``u_body = DECK2BODY @ u_deck = (u_bow, -u_starboard, u_up)``. Its orientation is the vector
``(roll, pitch, yaw)`` (rad) with ``R_world_body = Rz(yaw) Ry(-pitch) Rx(roll)`` (Stone Soup's
``build_rotation_matrix`` is its transpose). For a platform at the origin this is the package's
attitude with ``yaw = pi/2 - heading``, ``pitch = +pitch``, ``roll = +roll``; so
``R_world_deck = deck2enu_rotation(pi/2 - yaw, pitch, roll)`` and the rotations are built with the
package's own generated function, not written again.

**Sensor pose.** The sensor sits at ``p_nav + R_ecef_enu(nav) R_enu_deck lever_deck`` (the lever
arm in the deck frame at the navigation point, as in ``fleet_residual``).
"""

from __future__ import annotations

import numpy as np

from registration.core.angles import wrap_angle
from registration.core.frames import (
    deck2enu_rotation,
    ecef2geodetic,
    enu2deck_attitude,
    enu2ecef_rotation,
    geodetic2ecef,
)
from registration.core.validation import as_float_array

__all__ = ["DECK2BODY", "LocalFrame", "orientation_rotation"]

#: ``u_body = DECK2BODY @ u_deck``: deck (starboard, bow, up) -> Stone Soup body (forward, port, up).
DECK2BODY = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])


def _rows(name: str, value, width: int) -> np.ndarray:
    arr = as_float_array(name, value)
    if arr.ndim == 1 and arr.shape[0] == width:
        arr = arr[None, :]
    if arr.ndim != 2 or arr.shape[1] != width:
        raise ValueError(f"{name}: expected shape (N, {width}) or ({width},), got {arr.shape}")
    return arr


def orientation_rotation(orientation) -> np.ndarray:
    """R_world_deck (N, 3, 3) of Stone Soup orientations (N, 3) = (roll, pitch, yaw) rad.

    ``R_world_body = R_world_deck @ DECK2BODY.T`` is Stone Soup's sensor-to-world rotation.
    """
    o = _rows("orientation", orientation, 3)
    return deck2enu_rotation(wrap_angle(np.pi / 2 - o[:, 2]), o[:, 1], o[:, 0])


class LocalFrame:
    """Stone Soup's world: the ENU frame at ``origin`` = (lat, lon rad, alt m); see the module docstring.

    Choose the origin near the middle of the exercise (:meth:`centred_on` takes the mean ECEF
    position of the navigation); any origin gives exact results, a central one keeps world z
    close to height.
    """

    def __init__(self, lat: float, lon: float, alt: float = 0.0):
        self.origin = (float(lat), float(lon), float(alt))
        self.origin_ecef = geodetic2ecef(lat, lon, alt)[0]
        self.R_ecef_world = enu2ecef_rotation(lat, lon)[0]

    def __repr__(self) -> str:
        lat, lon, alt = self.origin
        return f"LocalFrame(lat={lat!r}, lon={lon!r}, alt={alt!r})"

    @property
    def reference_point_deg(self) -> tuple[float, float, float]:
        """The origin as Stone Soup's geodetic feeders
        (``LLAtoENUConverter``) take it: (lon deg, lat deg, alt m)."""
        lat, lon, alt = self.origin
        return float(np.degrees(lon)), float(np.degrees(lat)), alt

    @classmethod
    def centred_on(cls, navigation) -> "LocalFrame":
        """The frame at the geodetic point (height 0) below the mean ECEF position of a navigation
        table's rows (columns ``lat``, ``lon`` rad, ``alt`` m)."""
        p = geodetic2ecef(navigation["lat"], navigation["lon"], navigation["alt"])
        lat, lon, _ = ecef2geodetic(p.mean(axis=0))
        return cls(lat[0], lon[0], 0.0)

    def world2ecef(self, p_world) -> np.ndarray:
        """ECEF (N, 3) m of world points (N, 3) or (3,) m."""
        return self.origin_ecef + _rows("p_world", p_world, 3) @ self.R_ecef_world.T

    def ecef2world(self, p_ecef) -> np.ndarray:
        """World (N, 3) m of ECEF points (N, 3) or (3,) m."""
        return (_rows("p_ecef", p_ecef, 3) - self.origin_ecef) @ self.R_ecef_world

    def geodetic2world(self, lat, lon, alt) -> np.ndarray:
        """World (N, 3) m of geodetic points (rad, rad, m)."""
        return self.ecef2world(geodetic2ecef(lat, lon, alt))

    def world2geodetic(self, p_world) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """lat, lon (rad), alt (m), each (N,), of world points (N, 3) m."""
        return ecef2geodetic(self.world2ecef(p_world))

    def _world_enu(self, lat, lon) -> np.ndarray:
        """R_world_enu (N, 3, 3): the local ENU axes at (lat, lon) in world axes."""
        return np.einsum("ji,njk->nik", self.R_ecef_world, enu2ecef_rotation(lat, lon))

    def orientation(self, lat, lon, heading, pitch, roll) -> np.ndarray:
        """Stone Soup orientations (N, 3) = (roll, pitch, yaw) rad of attitudes (rad, this package's
        convention, relative to the local ENU at (lat, lon) rad)."""
        R = self._world_enu(lat, lon) @ deck2enu_rotation(heading, pitch, roll)
        c = enu2deck_attitude(R)
        return np.stack([c[:, 2], c[:, 1], wrap_angle(np.pi / 2 - c[:, 0])], axis=1)

    def attitude(self, lat, lon, orientation) -> np.ndarray:
        """Attitudes (N, 3) = (heading, pitch, roll) rad at
        (lat, lon) rad of Stone Soup orientations (N, 3)."""
        R = np.swapaxes(self._world_enu(lat, lon), 1, 2) @ orientation_rotation(orientation)
        return enu2deck_attitude(R)

    def sensor_pose(self, navigation, lever_deck=(0.0, 0.0, 0.0)) -> tuple[np.ndarray, np.ndarray]:
        """A sensor's world position (N, 3) m and Stone Soup orientation (N, 3) rad from navigation
        rows (N, 6) = (lat, lon, alt, heading, pitch, roll) (rad, m) and its lever arm (deck, m)."""
        nav = _rows("navigation", navigation, 6)
        lever = _rows("lever_deck", lever_deck, 3)
        R_ecef_deck = enu2ecef_rotation(nav[:, 0], nav[:, 1]) @ deck2enu_rotation(
            nav[:, 3], nav[:, 4], nav[:, 5]
        )
        p_ecef = geodetic2ecef(nav[:, 0], nav[:, 1], nav[:, 2]) + np.einsum("nij,nj->ni", R_ecef_deck, lever)
        return self.ecef2world(p_ecef), self.orientation(
            nav[:, 0], nav[:, 1], nav[:, 3], nav[:, 4], nav[:, 5]
        )

    def navigation(self, p_world, orientation, lever_deck=(0.0, 0.0, 0.0)) -> np.ndarray:
        """The inverse of :meth:`sensor_pose`: navigation rows (N, 6) of sensors at world positions
        (N, 3) m with Stone Soup orientations (N, 3) rad and lever arms (deck, m).

        The attitude is relative to the ENU at the navigation point, which the lever arm moves: a
        fixed-point iteration (each step gains about 1e-7 per metre of lever arm) settles it.
        """
        p_sensor = self.world2ecef(p_world)
        o = _rows("orientation", orientation, 3)
        lever = np.broadcast_to(_rows("lever_deck", lever_deck, 3), p_sensor.shape)
        p_nav = p_sensor.copy()
        for _ in range(6):
            lat, lon, alt = ecef2geodetic(p_nav)
            att = self.attitude(lat, lon, o)
            R_ecef_deck = enu2ecef_rotation(lat, lon) @ deck2enu_rotation(att[:, 0], att[:, 1], att[:, 2])
            moved = p_sensor - np.einsum("nij,nj->ni", R_ecef_deck, lever)
            step = np.max(np.abs(moved - p_nav), initial=0.0)
            p_nav = moved
            if step < 1e-10:
                break
        lat, lon, alt = ecef2geodetic(p_nav)
        return np.column_stack([lat, lon, alt, self.attitude(lat, lon, o)])
