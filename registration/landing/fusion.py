"""Fusion of the transferred radar point with the transferred camera angles in the camera-centred
touchdown frame: inverse-variance weighting of the angles (Wang, Liu & Gao 2017, eq. 12) or a joint
linear minimum-variance update, and the position rebuilt in the touchdown frame."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration._generated import api as generated
from registration.core.angles import wrap_angle
from registration.landing.checks import as_attitude
from registration.landing.geometry import LandingGeometry, radar_to_touchdown
from registration.landing.transfer import CameraTransfer, RadarTransfer, propagate_covariance

__all__ = ["FUSION_METHODS", "PositionEstimate", "radar_only", "combine"]

#: ways to combine the camera-centred radar polar point with the camera angles
#: ``radar``: radar only; ``camera``: camera angles with the radar range; ``paper``: eq. (12),
#: range from the radar, each angle inverse-variance weighted with its own variance;
#: ``information``: the joint linear minimum-variance update of [r, a, b] with both camera angles
#: (uses the radar's range-angle correlations, so it can also improve the range).
FUSION_METHODS = ("radar", "camera", "paper", "information")


@dataclass(frozen=True)
class PositionEstimate:
    """One method's estimate at N instants.

    Attributes:
        method: one of :data:`FUSION_METHODS`.
        polar_ctd: (N, 3) [r m, a rad, b rad] about the camera in td axes.
        P_polar: (N, 3, 3) covariance of ``polar_ctd``.
        p_td: (N, 3) position in the touchdown frame, m.
        P_td: (N, 3, 3) its covariance, m^2 (first order).
        weights: (N, 2) weight of the camera in the fused azimuth and elevation (0 radar only,
            1 camera only); NaN for ``information``, whose gain is a matrix.
    """

    method: str
    polar_ctd: np.ndarray
    P_polar: np.ndarray
    p_td: np.ndarray
    P_td: np.ndarray
    weights: np.ndarray


def radar_only(radar: RadarTransfer, attitude, geometry: LandingGeometry) -> PositionEstimate:
    """The radar's own estimate: ``p_td`` by eq. (7), covariance ``J P_R J^T`` with ``J = M A``."""
    p_td, J = radar_to_touchdown(radar.polar_rdr, attitude, geometry)
    n = p_td.shape[0]
    return PositionEstimate(
        method="radar",
        polar_ctd=radar.polar_ctd,
        P_polar=radar.P_ctd,
        p_td=p_td,
        P_td=propagate_covariance(J, radar.P_rdr),
        weights=np.zeros((n, 2)),
    )


def _joint_update(
    x_r: np.ndarray, P_r: np.ndarray, innov: np.ndarray, P_c: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Linear minimum-variance update of [r, a, b] (N, 3) by the camera's angle pair; returns the
    polar point, its covariance (Joseph form: symmetric, PSD) and NaN weights."""
    H = np.zeros((2, 3))
    H[0, 1] = H[1, 2] = 1.0
    S = H @ P_r @ H.T + P_c
    K = P_r @ H.T @ np.linalg.inv(S)  # (N, 3, 2)
    x = x_r + np.einsum("nij,nj->ni", K, innov)
    I_KH = np.eye(3) - K @ H
    P = propagate_covariance(I_KH, P_r) + propagate_covariance(K, P_c)
    return x, P, np.full((x_r.shape[0], 2), np.nan)


def _weighted_angles(
    method: str, x_r: np.ndarray, P_r: np.ndarray, innov: np.ndarray, P_c: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Radar range with each angle a weighted mean of radar and camera: camera weight 0
    (``radar``), 1 (``camera``) or ``s2_RL / (s2_TL + s2_RL)`` (``paper``, eq. 12); returns the
    polar point, the exact covariance of that linear combination and the weights (N, 2)."""
    n = x_r.shape[0]
    if method == "radar":
        w = np.zeros((n, 2))
    elif method == "camera":
        w = np.ones((n, 2))
    else:
        s2_r = np.diagonal(P_r, axis1=1, axis2=2)[:, 1:]
        s2_c = np.diagonal(P_c, axis1=1, axis2=2)
        w = s2_r / (s2_r + s2_c)
    x = x_r.copy()
    x[:, 1:] = x_r[:, 1:] + w * innov
    G_r = np.zeros((n, 3, 3))
    G_r[:, 0, 0] = 1.0
    G_r[:, 1, 1] = 1.0 - w[:, 0]
    G_r[:, 2, 2] = 1.0 - w[:, 1]
    G_c = np.zeros((n, 3, 2))
    G_c[:, 1, 0] = w[:, 0]
    G_c[:, 2, 1] = w[:, 1]
    return x, propagate_covariance(G_r, P_r) + propagate_covariance(G_c, P_c), w


def combine(
    radar: RadarTransfer, camera: CameraTransfer, attitude, geometry: LandingGeometry, method: str = "paper"
) -> PositionEstimate:
    """Combine the transferred radar point with the transferred camera angles (eq. 12).

    Both inputs must describe the same N instants (already time-aligned). The sensors' errors are
    taken as independent. ``method`` (see :data:`FUSION_METHODS`):

    - ``radar``: ``[r, a, b]`` of the radar as seen from the camera.
    - ``camera``: radar range with the camera's angles.
    - ``paper``: eq. (12): ``r = r_RL``; ``a = s2 (a_TL / s2_TL + a_RL / s2_RL)`` with
      ``s2 = s2_TL s2_RL / (s2_TL + s2_RL)``, and likewise b, using each angle's own variance
      (diagonal entries of the transferred covariances).
    - ``information``: linear minimum-variance update of the radar's full ``[r, a, b]`` with the
      camera's angle pair (Kalman form), using all covariance entries.

    The fused covariance is exact for the linear combination: ``G_R P_RL G_R^T + G_T P_TL G_T^T``.
    The position ``p_td`` is rebuilt from the fused polar point about the camera, with
    ``P_td = J P J^T``, ``J = dp_td/dpolar``.
    """
    if method not in FUSION_METHODS:
        raise ValueError(f"method: expected one of {FUSION_METHODS}, got {method!r}")
    x_r, P_r = radar.polar_ctd, radar.P_ctd
    z_c, P_c = camera.angles_ctd, camera.P_ctd
    n = x_r.shape[0]
    if z_c.shape[0] != n:
        raise ValueError(
            f"camera: has {z_c.shape[0]} instants but radar has {n}; align them to the same instants first"
        )
    att = as_attitude(attitude)
    innov = wrap_angle(z_c - x_r[:, 1:])  # camera minus radar angles, (N, 2)
    if method == "information":
        x, P, w = _joint_update(x_r, P_r, innov, P_c)
    else:
        x, P, w = _weighted_angles(method, x_r, P_r, innov, P_c)
    x[:, 1] = wrap_angle(x[:, 1])
    td = generated.landing_ctd2td(
        polar_ctd=x,
        attitude=att,
        angled_deck=geometry.angled_deck_rad,
        d_camera_deck=geometry.d_camera_deck_m,
    )
    return PositionEstimate(
        method=method, polar_ctd=x, P_polar=P, p_td=td.p_td, P_td=propagate_covariance(td.J, P), weights=w
    )
