"""Error transfer (Wang, Liu & Gao 2017, eqs. 8-11): radar polar measurements and camera angles,
with their covariances, moved into the camera-centred touchdown frame ``ctd``.

Radar ``[r m, a rad, b rad]`` in deck axes -> ``ctd`` polar with ``P_RL = (BMA) P_R (BMA)^T``;
camera ``[a, b]`` rad in deck-fixed landing-area axes -> ``ctd`` angles with ``J P_T J^T``.
Arrays are vectorised over a leading axis of N instants.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration._generated import api as generated
from registration.landing.checks import as_attitude, as_covariance, as_polar, common_count
from registration.landing.geometry import LandingGeometry

__all__ = [
    "RadarTransfer",
    "CameraTransfer",
    "propagate_covariance",
    "transfer_radar",
    "transfer_camera",
    "variance_ratios",
]


def propagate_covariance(J: np.ndarray, P: np.ndarray) -> np.ndarray:
    """``J P J^T`` for stacks (N, i, k) and (N, k, k): the covariance of ``J x`` (first order)."""
    return J @ P @ np.swapaxes(J, -1, -2)


@dataclass(frozen=True)
class RadarTransfer:
    """Radar measurement moved to the camera-centred polar frame (eqs. 7-11), N points.

    Attributes:
        polar_rdr: (N, 3) the radar measurement [r m, a rad, b rad], deck axes.
        polar_ctd: (N, 3) [r m, a rad, b rad] about the camera, td axes (the paper's r_RL, a_RL, b_RL).
        P_ctd: (N, 3, 3) its covariance ``BMA P_R (BMA)^T`` (m^2, m rad, rad^2).
        P_rdr: (N, 3, 3) the radar covariance that was transferred.
        A: (N, 3, 3) du_deck/dpolar_rdr at the radar (eq. 8).
        M: (N, 3, 3) R_td_deck.
        B: (N, 3, 3) dpolar_ctd/dv_ctd at the camera (eq. 9).
        BMA: (N, 3, 3) dpolar_ctd/dpolar_rdr (eq. 10).
        p_td: (N, 3) the radar point in the touchdown frame, m.
    """

    polar_rdr: np.ndarray
    polar_ctd: np.ndarray
    P_ctd: np.ndarray
    P_rdr: np.ndarray
    A: np.ndarray
    M: np.ndarray
    B: np.ndarray
    BMA: np.ndarray
    p_td: np.ndarray


def transfer_radar(polar_rdr, P_rdr, attitude, geometry: LandingGeometry) -> RadarTransfer:
    """Move radar polar measurements and their covariance into the camera's polar frame (eqs. 7-11).

    Args:
        polar_rdr: (N, 3) or (3,) [r m, a rad, b rad] in deck axes about the radar.
        P_rdr: (3, 3) or (N, 3, 3) covariance of ``polar_rdr`` (m^2, m rad, rad^2).
        attitude: (N, 3) or (3,) [yaw deviation, pitch, roll], rad, assumed exact (paper assumption 1).
        geometry: :class:`LandingGeometry`.
    """
    pol = as_polar("polar_rdr", polar_rdr, 3)
    att = as_attitude(attitude)
    n = common_count(polar_rdr=pol, attitude=att)
    P = as_covariance("P_rdr", P_rdr, n, 3)
    phic, d_r, d_c = geometry.angled_deck_rad, geometry.d_radar_deck_m, geometry.d_camera_deck_m
    td = generated.landing_radar2td(polar_rdr=pol, attitude=att, angled_deck=phic, d_radar_deck=d_r)
    B = generated.landing_td2ctd(p_td=td.p_td, attitude=att, angled_deck=phic, d_camera_deck=d_c).B
    ctd = generated.landing_radar2ctd(
        polar_rdr=pol, attitude=att, angled_deck=phic, d_radar_deck=d_r, d_camera_deck=d_c
    )
    return RadarTransfer(
        polar_rdr=pol,
        polar_ctd=ctd.polar_ctd,
        P_ctd=propagate_covariance(ctd.BMA, P),
        P_rdr=P,
        A=td.A,
        M=td.M,
        B=B,
        BMA=ctd.BMA,
        p_td=td.p_td,
    )


@dataclass(frozen=True)
class CameraTransfer:
    """Camera angles moved from the deck-fixed camera axes to the camera-centred td axes.

    Attributes:
        angles_ctd: (N, 2) [a, b] rad (the paper's a_TL, b_TL).
        P_ctd: (N, 2, 2) their covariance ``J P_cam J^T`` (rad^2).
        P_cam: (N, 2, 2) the camera covariance that was transferred.
        J: (N, 2, 2) dangles_ctd/dangles_cam.
    """

    angles_ctd: np.ndarray
    P_ctd: np.ndarray
    P_cam: np.ndarray
    J: np.ndarray


def transfer_camera(angles_cam, P_cam, attitude, geometry: LandingGeometry) -> CameraTransfer:
    """Rotate camera angles (rad; deck-fixed landing-area axes) into the ctd frame with their covariance.

    Args:
        angles_cam: (N, 2) or (2,) [a, b], rad.
        P_cam: (2, 2) or (N, 2, 2) covariance, rad^2.
        attitude: (N, 3) or (3,) [yaw deviation, pitch, roll], rad.
        geometry: :class:`LandingGeometry`.
    """
    ang = as_polar("angles_cam", angles_cam, 2)
    att = as_attitude(attitude)
    n = common_count(angles_cam=ang, attitude=att)
    P = as_covariance("P_cam", P_cam, n, 2)
    ctd = generated.landing_camera2ctd(angles_cam=ang, attitude=att, angled_deck=geometry.angled_deck_rad)
    return CameraTransfer(angles_ctd=ctd.angles_ctd, P_ctd=propagate_covariance(ctd.J, P), P_cam=P, J=ctd.J)


def variance_ratios(P_in: np.ndarray, P_out: np.ndarray) -> np.ndarray:
    """Variance amplification ratios (the paper's Figs. 2-3): diag(P_out) / diag(P_in), (N, k).

    For the radar, ``P_in`` is its own polar covariance and ``P_out`` the transferred one, so the
    ratios say how much each component's variance grows when seen from the camera in td axes
    (cross terms included: the radar's range error shows up in the camera-frame angles).
    """
    return np.diagonal(P_out, axis1=-2, axis2=-1) / np.diagonal(P_in, axis1=-2, axis2=-1)
