"""GENERATED FILE - DO NOT EDIT BY HAND.
Produced by `python -m derive` from the sympy derivations in derive/.
Edit derive/ and regenerate; `python -m derive --check` verifies freshness.

Typed wrappers of the generated functions: keyword-only inputs named, shaped and documented as
derive/ declares them, and a NamedTuple of the named outputs. Each calls
``registration._codegen.get(name)`` with the inputs in the function's order, so the results are
those of the generated function, bit for bit.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from registration._codegen import get

#: A float64 array: every output of a generated function.
Array = NDArray[np.float64]

__all__ = [
    "Array",
    "Ecef2plotOutputs",
    "ecef2plot",
    "Enu2ecefRotationOutputs",
    "enu2ecef_rotation",
    "InformationStepOutputs",
    "information_step",
    "KalmanStepFittedOutputs",
    "kalman_step_fitted",
    "KalmanStepPaperOutputs",
    "kalman_step_paper",
    "KalmanStepRelinearizedOutputs",
    "kalman_step_relinearized",
    "Plot2ecefOutputs",
    "plot2ecef",
    "PseudoMeasurementOutputs",
    "pseudo_measurement",
    "Cartesian2polar2Outputs",
    "cartesian2polar2",
    "Cartesian2polar3Outputs",
    "cartesian2polar3",
    "CvGateOutputs",
    "cv_gate",
    "CvPredictOutputs",
    "cv_predict",
    "CvStartOutputs",
    "cv_start",
    "CvUpdateOutputs",
    "cv_update",
    "Deck2enuOutputs",
    "deck2enu",
    "Deck2enuJacobiansOutputs",
    "deck2enu_jacobians",
    "Deck2enuRotationOutputs",
    "deck2enu_rotation",
    "Ecef2geodeticOutputs",
    "ecef2geodetic",
    "ecef2plot_paper",
    "ecef2plot_standard",
    "Enu2deckAttitudeOutputs",
    "enu2deck_attitude",
    "enu2ecef_rotation_paper",
    "enu2ecef_rotation_standard",
    "FleetPlot2ecefOutputs",
    "fleet_plot2ecef",
    "FleetPlot2ecefEccOutputs",
    "fleet_plot2ecef_ecc",
    "FleetPlot2ecefExtOutputs",
    "fleet_plot2ecef_ext",
    "FleetResidualOutputs",
    "fleet_residual",
    "FleetResidualEccOutputs",
    "fleet_residual_ecc",
    "FleetResidualExtOutputs",
    "fleet_residual_ext",
    "FleetRows1Outputs",
    "fleet_rows_1",
    "FleetRows4Outputs",
    "fleet_rows_4",
    "FleetRowsEcc31Outputs",
    "fleet_rows_ecc3_1",
    "FleetRowsEcc34Outputs",
    "fleet_rows_ecc3_4",
    "FleetRowsEcc1Outputs",
    "fleet_rows_ecc_1",
    "FleetRowsEcc4Outputs",
    "fleet_rows_ecc_4",
    "FleetRowsExt1Outputs",
    "fleet_rows_ext_1",
    "FleetRowsExt4Outputs",
    "fleet_rows_ext_4",
    "Geodetic2ecefOutputs",
    "geodetic2ecef",
    "information_step_paper",
    "information_step_standard",
    "kalman_step_fitted_paper",
    "KalmanStepFittedPaperCarlsonOutputs",
    "kalman_step_fitted_paper_carlson",
    "kalman_step_fitted_standard",
    "KalmanStepFittedStandardCarlsonOutputs",
    "kalman_step_fitted_standard_carlson",
    "kalman_step_paper_paper",
    "KalmanStepPaperPaperCarlsonOutputs",
    "kalman_step_paper_paper_carlson",
    "kalman_step_paper_standard",
    "KalmanStepPaperStandardCarlsonOutputs",
    "kalman_step_paper_standard_carlson",
    "kalman_step_relinearized_paper",
    "KalmanStepRelinearizedPaperCarlsonOutputs",
    "kalman_step_relinearized_paper_carlson",
    "kalman_step_relinearized_standard",
    "KalmanStepRelinearizedStandardCarlsonOutputs",
    "kalman_step_relinearized_standard_carlson",
    "LandingCamera2ctdOutputs",
    "landing_camera2ctd",
    "LandingCtd2tdOutputs",
    "landing_ctd2td",
    "LandingDeck2tdRotationOutputs",
    "landing_deck2td_rotation",
    "LandingMtd2tdOutputs",
    "landing_mtd2td",
    "LandingRadar2ctdOutputs",
    "landing_radar2ctd",
    "LandingRadar2tdOutputs",
    "landing_radar2td",
    "LandingTd2cameraOutputs",
    "landing_td2camera",
    "LandingTd2ctdOutputs",
    "landing_td2ctd",
    "LandingTd2radarOutputs",
    "landing_td2radar",
    "plot2ecef_paper",
    "plot2ecef_standard",
    "Polar2cartesian2Outputs",
    "polar2cartesian2",
    "Polar2cartesian3Outputs",
    "polar2cartesian3",
    "pseudo_measurement_paper",
    "pseudo_measurement_standard",
    "RadiiOfCurvatureOutputs",
    "radii_of_curvature",
    "SurfaceResidualOutputs",
    "surface_residual",
]


class Ecef2plotOutputs(NamedTuple):
    """The outputs of ``ecef2plot_{t_variant}``, by name."""

    plot: Array
    """(N, 3) [m, rad, rad]"""


def ecef2plot(
    *,
    t_variant: str,
    p_ecef: ArrayLike,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
) -> Ecef2plotOutputs:
    """The generated function ``ecef2plot_{t_variant}``, t_variant one of "standard", "paper". That of
    "standard": Inverse of eq. (3), T variant 'standard': target ECEF p (m) seen from a ship at (lat, lon
    rad; alt m) with attitude (heading, pitch, roll rad) -> plot [r m, q rad, e rad].

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        plot: (N, 3) [m, rad, rad]
    """
    outputs = get(f"ecef2plot_{t_variant}")(p_ecef, lat, lon, alt, heading, pitch, roll)
    return Ecef2plotOutputs(*outputs)


class Enu2ecefRotationOutputs(NamedTuple):
    """The outputs of ``enu2ecef_rotation_{t_variant}``, by name."""

    R_ecef_enu: Array
    """(N, 3, 3) [1]"""


def enu2ecef_rotation(*, t_variant: str, lat: ArrayLike, lon: ArrayLike) -> Enu2ecefRotationOutputs:
    """The generated function ``enu2ecef_rotation_{t_variant}``, t_variant one of "standard", "paper". That of
    "standard": R_ecef_enu at (lat, lon) in rad, 'standard' variant (docs/background/online.md).

    Inputs, each at this shape or with one more leading axis of N points:
        lat: () [rad]
        lon: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        R_ecef_enu: (N, 3, 3) [1]
    """
    outputs = get(f"enu2ecef_rotation_{t_variant}")(lat, lon)
    return Enu2ecefRotationOutputs(*outputs)


class InformationStepOutputs(NamedTuple):
    """The outputs of ``information_step_{t_variant}``, by name."""

    info_new: Array
    """(N, 12, 12) [1/rad^2, 1/m^2]"""


def information_step(
    *, t_variant: str, info: ArrayLike, x: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> InformationStepOutputs:
    """The generated function ``information_step_{t_variant}``, t_variant one of "standard", "paper". That of
    "standard": Fisher information accumulation, T variant 'standard': info_new = info + H^T R^-1 H, H and
    R at the row corrected by the fixed estimate x. Input info carried from output info_new.

    Inputs, each at this shape or with one more leading axis of N points:
        info: (12, 12) [1/rad^2, 1/m^2]
        x: (12,) [rad, m]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
    """
    outputs = get(f"information_step_{t_variant}")(info, x, row, sigma0)
    return InformationStepOutputs(*outputs)


class KalmanStepFittedOutputs(NamedTuple):
    """The outputs of ``kalman_step_fitted_{t_variant}``, by name."""

    x_new: Array
    """(N, 12) [rad, m]"""
    P_new: Array
    """(N, 12, 12) [rad^2, m^2]"""
    info_new: Array
    """(N, 12, 12) [1/rad^2, 1/m^2]"""
    nu: Array
    """(N, 3) [m]"""
    S: Array
    """(N, 3, 3) [m^2]"""
    nis: Array
    """(N,) [1]"""


def kalman_step_fitted(
    *,
    t_variant: str,
    x: ArrayLike,
    P: ArrayLike,
    info: ArrayLike,
    Q: ArrayLike,
    row: ArrayLike,
    sigma0: ArrayLike,
) -> KalmanStepFittedOutputs:
    """The generated function ``kalman_step_fitted_{t_variant}``, t_variant one of "standard", "paper". That
    of "standard": One registration Kalman step (eqs. 18-23), linearisation 'fitted', T variant 'standard'.
    Inputs x, P, info carried from outputs x_new, P_new, info_new of the previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get(f"kalman_step_fitted_{t_variant}")(x, P, info, Q, row, sigma0)
    return KalmanStepFittedOutputs(*outputs)


class KalmanStepPaperOutputs(NamedTuple):
    """The outputs of ``kalman_step_paper_{t_variant}``, by name."""

    x_new: Array
    """(N, 12) [rad, m]"""
    P_new: Array
    """(N, 12, 12) [rad^2, m^2]"""
    info_new: Array
    """(N, 12, 12) [1/rad^2, 1/m^2]"""
    nu: Array
    """(N, 3) [m]"""
    S: Array
    """(N, 3, 3) [m^2]"""
    nis: Array
    """(N,) [1]"""


def kalman_step_paper(
    *,
    t_variant: str,
    x: ArrayLike,
    P: ArrayLike,
    info: ArrayLike,
    Q: ArrayLike,
    row: ArrayLike,
    sigma0: ArrayLike,
) -> KalmanStepPaperOutputs:
    """The generated function ``kalman_step_paper_{t_variant}``, t_variant one of "standard", "paper". That of
    "standard": One registration Kalman step (eqs. 18-23), linearisation 'paper', T variant 'standard'.
    Inputs x, P, info carried from outputs x_new, P_new, info_new of the previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get(f"kalman_step_paper_{t_variant}")(x, P, info, Q, row, sigma0)
    return KalmanStepPaperOutputs(*outputs)


class KalmanStepRelinearizedOutputs(NamedTuple):
    """The outputs of ``kalman_step_relinearized_{t_variant}``, by name."""

    x_new: Array
    """(N, 12) [rad, m]"""
    P_new: Array
    """(N, 12, 12) [rad^2, m^2]"""
    info_new: Array
    """(N, 12, 12) [1/rad^2, 1/m^2]"""
    nu: Array
    """(N, 3) [m]"""
    S: Array
    """(N, 3, 3) [m^2]"""
    nis: Array
    """(N,) [1]"""


def kalman_step_relinearized(
    *,
    t_variant: str,
    x: ArrayLike,
    P: ArrayLike,
    info: ArrayLike,
    Q: ArrayLike,
    row: ArrayLike,
    sigma0: ArrayLike,
) -> KalmanStepRelinearizedOutputs:
    """The generated function ``kalman_step_relinearized_{t_variant}``, t_variant one of "standard", "paper".
    That of "standard": One registration Kalman step (eqs. 18-23), linearisation 'relinearized', T variant
    'standard'. Inputs x, P, info carried from outputs x_new, P_new, info_new of the previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get(f"kalman_step_relinearized_{t_variant}")(x, P, info, Q, row, sigma0)
    return KalmanStepRelinearizedOutputs(*outputs)


class Plot2ecefOutputs(NamedTuple):
    """The outputs of ``plot2ecef_{t_variant}``, by name."""

    p_ecef: Array
    """(N, 3) [m]"""


def plot2ecef(
    *,
    t_variant: str,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
) -> Plot2ecefOutputs:
    """The generated function ``plot2ecef_{t_variant}``, t_variant one of "standard", "paper". That of
    "standard": Eq. (3), T variant 'standard': a radar plot (r m, q rad, e rad) from a ship at (lat, lon
    rad; alt m) with attitude (heading, pitch, roll rad) -> target ECEF (m).

    Inputs, each at this shape or with one more leading axis of N points:
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        r: () [m]
        q: () [rad]
        e: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        p_ecef: (N, 3) [m]
    """
    outputs = get(f"plot2ecef_{t_variant}")(lat, lon, alt, heading, pitch, roll, r, q, e)
    return Plot2ecefOutputs(*outputs)


class PseudoMeasurementOutputs(NamedTuple):
    """The outputs of ``pseudo_measurement_{t_variant}``, by name."""

    Z: Array
    """(N, 3) [m]"""
    H: Array
    """(N, 3, 12) [m/rad, m/m]"""
    M: Array
    """(N, 3, 6) [m/m, m/rad]"""
    R: Array
    """(N, 3, 3) [m^2]"""
    p_a_ecef: Array
    """(N, 3) [m]"""
    p_b_ecef: Array
    """(N, 3) [m]"""


def pseudo_measurement(
    *,
    t_variant: str,
    nav_a: ArrayLike,
    att_a: ArrayLike,
    meas_a: ArrayLike,
    nav_b: ArrayLike,
    att_b: ArrayLike,
    meas_b: ArrayLike,
    sigma0: ArrayLike,
) -> PseudoMeasurementOutputs:
    """The generated function ``pseudo_measurement_{t_variant}``, t_variant one of "standard", "paper". That
    of "standard": Two-sensor pseudo-measurement (eqs. 7-19), T variant 'standard'. Inputs per sensor: nav
    [lat rad, lon rad, alt m], att [heading, pitch, roll rad], meas [r m, q rad, e rad]; sigma0 = [sr_A m,
    sq_A rad, se_A rad, sr_B, sq_B, se_B]. Outputs Z = X_A - X_B (m), H (3x12), M (3x6), R = M R0 M^T
    (m^2), and X_A, X_B (ECEF m).

    Inputs, each at this shape or with one more leading axis of N points:
        nav_a: (3,) [rad, rad, m]
        att_a: (3,) [rad]
        meas_a: (3,) [m, rad, rad]
        nav_b: (3,) [rad, rad, m]
        att_b: (3,) [rad]
        meas_b: (3,) [m, rad, rad]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        Z: (N, 3) [m]
        H: (N, 3, 12) [m/rad, m/m]
        M: (N, 3, 6) [m/m, m/rad]
        R: (N, 3, 3) [m^2]
        p_a_ecef: (N, 3) [m]
        p_b_ecef: (N, 3) [m]
    """
    outputs = get(f"pseudo_measurement_{t_variant}")(nav_a, att_a, meas_a, nav_b, att_b, meas_b, sigma0)
    return PseudoMeasurementOutputs(*outputs)


class Cartesian2polar2Outputs(NamedTuple):
    """The outputs of :func:`cartesian2polar2`, by name."""

    polar: Array
    """(N, 2) [m, rad]"""
    J: Array
    """(N, 2, 2) [1, rad/m]"""


def cartesian2polar2(*, p: ArrayLike) -> Cartesian2polar2Outputs:
    """2-D: Cartesian p [m] -> polar [r m, az rad in (-pi, pi]] and J = dpolar/dp.

    Inputs, each at this shape or with one more leading axis of N points:
        p: (2,) [m]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        polar: (N, 2) [m, rad]
        J: (N, 2, 2) [1, rad/m]
    """
    outputs = get("cartesian2polar2")(p)
    return Cartesian2polar2Outputs(*outputs)


class Cartesian2polar3Outputs(NamedTuple):
    """The outputs of :func:`cartesian2polar3`, by name."""

    polar: Array
    """(N, 3) [m, rad, rad]"""
    J: Array
    """(N, 3, 3) [1, rad/m]"""


def cartesian2polar3(*, p: ArrayLike) -> Cartesian2polar3Outputs:
    """3-D: Cartesian p [m] -> polar [r m, az rad, el rad] and J = dpolar/dp.

    Inputs, each at this shape or with one more leading axis of N points:
        p: (3,) [m]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        polar: (N, 3) [m, rad, rad]
        J: (N, 3, 3) [1, rad/m]
    """
    outputs = get("cartesian2polar3")(p)
    return Cartesian2polar3Outputs(*outputs)


class CvGateOutputs(NamedTuple):
    """The outputs of :func:`cv_gate`, by name."""

    d2: Array
    """(N,) [1]"""
    logdet: Array
    """(N,) [log m^6]"""


def cv_gate(*, x_pred: ArrayLike, P_pred: ArrayLike, z: ArrayLike, R: ArrayLike) -> CvGateOutputs:
    """A plot z (m, ECEF) of covariance R (m^2) against a constant-velocity prediction: squared Mahalanobis
    distance d2 of z - x-_p in S = P-_pp + R, and logdet = log det S (log m^6).

    Inputs, each at this shape or with one more leading axis of N points:
        x_pred: (6,) [m, m/s (ECEF position, velocity)]
        P_pred: (6, 6) [m^2, m^2/s, m^2/s^2]
        z: (3,) [m (ECEF)]
        R: (3, 3) [m^2]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        d2: (N,) [1]
        logdet: (N,) [log m^6]
    """
    outputs = get("cv_gate")(x_pred, P_pred, z, R)
    return CvGateOutputs(*outputs)


class CvPredictOutputs(NamedTuple):
    """The outputs of :func:`cv_predict`, by name."""

    x_pred: Array
    """(N, 6) [m, m/s (ECEF position, velocity)]"""
    P_pred: Array
    """(N, 6, 6) [m^2, m^2/s, m^2/s^2]"""


def cv_predict(*, x: ArrayLike, P: ArrayLike, dt: ArrayLike, accel_sigma: ArrayLike) -> CvPredictOutputs:
    """Constant-velocity prediction of state x (ECEF m, m/s) and covariance P by dt (s) with white
    acceleration noise of spectral density accel_sigma^2 (m^2/s^3): x- = F x, P- = F P F^T + Q.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (6,) [m, m/s (ECEF position, velocity)]
        P: (6, 6) [m^2, m^2/s, m^2/s^2]
        dt: () [s]
        accel_sigma: () [m/s^2/sqrt(Hz)]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_pred: (N, 6) [m, m/s (ECEF position, velocity)]
        P_pred: (N, 6, 6) [m^2, m^2/s, m^2/s^2]
    """
    outputs = get("cv_predict")(x, P, dt, accel_sigma)
    return CvPredictOutputs(*outputs)


class CvStartOutputs(NamedTuple):
    """The outputs of :func:`cv_start`, by name."""

    x: Array
    """(N, 6) [m, m/s (ECEF position, velocity)]"""
    P: Array
    """(N, 6, 6) [m^2, m^2/s, m^2/s^2]"""


def cv_start(*, z: ArrayLike, R: ArrayLike, max_speed: ArrayLike) -> CvStartOutputs:
    """Constant-velocity track opened at a plot z (m, ECEF) of covariance R (m^2): x = [z, 0], P = diag(R,
    max_speed^2 I) (max_speed m/s).

    Inputs, each at this shape or with one more leading axis of N points:
        z: (3,) [m (ECEF)]
        R: (3, 3) [m^2]
        max_speed: () [m/s]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x: (N, 6) [m, m/s (ECEF position, velocity)]
        P: (N, 6, 6) [m^2, m^2/s, m^2/s^2]
    """
    outputs = get("cv_start")(z, R, max_speed)
    return CvStartOutputs(*outputs)


class CvUpdateOutputs(NamedTuple):
    """The outputs of :func:`cv_update`, by name."""

    x: Array
    """(N, 6) [m, m/s (ECEF position, velocity)]"""
    P: Array
    """(N, 6, 6) [m^2, m^2/s, m^2/s^2]"""


def cv_update(*, x_pred: ArrayLike, P_pred: ArrayLike, z: ArrayLike, R: ArrayLike) -> CvUpdateOutputs:
    """Kalman update of a constant-velocity prediction (x-, P-) with a plot z (m, ECEF) of covariance R (m^2):
    K = P- H^T S^-1, x = x- + K (z - x-_p), P = sym(P- - K H P-).

    Inputs, each at this shape or with one more leading axis of N points:
        x_pred: (6,) [m, m/s (ECEF position, velocity)]
        P_pred: (6, 6) [m^2, m^2/s, m^2/s^2]
        z: (3,) [m (ECEF)]
        R: (3, 3) [m^2]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x: (N, 6) [m, m/s (ECEF position, velocity)]
        P: (N, 6, 6) [m^2, m^2/s, m^2/s^2]
    """
    outputs = get("cv_update")(x_pred, P_pred, z, R)
    return CvUpdateOutputs(*outputs)


class Deck2enuOutputs(NamedTuple):
    """The outputs of :func:`deck2enu`, by name."""

    u_enu: Array
    """(N, 3) [m]"""


def deck2enu(
    *, r: ArrayLike, q: ArrayLike, e: ArrayLike, heading: ArrayLike, pitch: ArrayLike, roll: ArrayLike
) -> Deck2enuOutputs:
    """Phi (eq. 2): radar measurement (r m, q rad, e rad) and attitude (rad) -> target ENU offset (m).

    Inputs, each at this shape or with one more leading axis of N points:
        r: () [m]
        q: () [rad]
        e: () [rad]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        u_enu: (N, 3) [m]
    """
    outputs = get("deck2enu")(r, q, e, heading, pitch, roll)
    return Deck2enuOutputs(*outputs)


class Deck2enuJacobiansOutputs(NamedTuple):
    """The outputs of :func:`deck2enu_jacobians`, by name."""

    u_enu: Array
    """(N, 3) [m]"""
    Psi: Array
    """(N, 3, 6) [m/rad, m/m]"""
    Gamma: Array
    """(N, 3, 3) [m/m, m/rad]"""


def deck2enu_jacobians(
    *, r: ArrayLike, q: ArrayLike, e: ArrayLike, heading: ArrayLike, pitch: ArrayLike, roll: ArrayLike
) -> Deck2enuJacobiansOutputs:
    """Psi = dPhi/d(C, phi, theta, r, q, e) (3x6, m/rad or m/m) and Gamma = dPhi/d(r, q, e) (3x3), eq. (11),
    by symbolic differentiation.

    Inputs, each at this shape or with one more leading axis of N points:
        r: () [m]
        q: () [rad]
        e: () [rad]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        u_enu: (N, 3) [m]
        Psi: (N, 3, 6) [m/rad, m/m]
        Gamma: (N, 3, 3) [m/m, m/rad]
    """
    outputs = get("deck2enu_jacobians")(r, q, e, heading, pitch, roll)
    return Deck2enuJacobiansOutputs(*outputs)


class Deck2enuRotationOutputs(NamedTuple):
    """The outputs of :func:`deck2enu_rotation`, by name."""

    R_enu_deck: Array
    """(N, 3, 3) [1]"""


def deck2enu_rotation(*, heading: ArrayLike, pitch: ArrayLike, roll: ArrayLike) -> Deck2enuRotationOutputs:
    """R_enu_deck from heading, pitch, roll (rad): Rz(C) Rx(phi) Ry(theta).

    Inputs, each at this shape or with one more leading axis of N points:
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        R_enu_deck: (N, 3, 3) [1]
    """
    outputs = get("deck2enu_rotation")(heading, pitch, roll)
    return Deck2enuRotationOutputs(*outputs)


class Ecef2geodeticOutputs(NamedTuple):
    """The outputs of :func:`ecef2geodetic`, by name."""

    geodetic: Array
    """(N, 3) [rad, rad, m]"""


def ecef2geodetic(*, p_ecef: ArrayLike) -> Ecef2geodeticOutputs:
    """Geodetic lat, lon (rad) and alt (m above WGS-84) of an ECEF point p_ecef (m): the inverse of eq. (1).

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        geodetic: (N, 3) [rad, rad, m]
    """
    outputs = get("ecef2geodetic")(p_ecef)
    return Ecef2geodeticOutputs(*outputs)


def ecef2plot_paper(
    *,
    p_ecef: ArrayLike,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
) -> Ecef2plotOutputs:
    """Inverse of eq. (3), T variant 'paper': target ECEF p (m) seen from a ship at (lat, lon rad; alt m) with
    attitude (heading, pitch, roll rad) -> plot [r m, q rad, e rad].

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        plot: (N, 3) [m, rad, rad]
    """
    outputs = get("ecef2plot_paper")(p_ecef, lat, lon, alt, heading, pitch, roll)
    return Ecef2plotOutputs(*outputs)


def ecef2plot_standard(
    *,
    p_ecef: ArrayLike,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
) -> Ecef2plotOutputs:
    """Inverse of eq. (3), T variant 'standard': target ECEF p (m) seen from a ship at (lat, lon rad; alt m)
    with attitude (heading, pitch, roll rad) -> plot [r m, q rad, e rad].

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        plot: (N, 3) [m, rad, rad]
    """
    outputs = get("ecef2plot_standard")(p_ecef, lat, lon, alt, heading, pitch, roll)
    return Ecef2plotOutputs(*outputs)


class Enu2deckAttitudeOutputs(NamedTuple):
    """The outputs of :func:`enu2deck_attitude`, by name."""

    attitude: Array
    """(N, 3) [rad]"""


def enu2deck_attitude(*, R_enu_deck: ArrayLike) -> Enu2deckAttitudeOutputs:
    """heading, pitch, roll (rad) of a rotation R_enu_deck = Rz(C) Rx(phi) Ry(theta): the inverse of
    deck2enu_rotation for pitch in [-pi/2, pi/2] (heading from the bow's horizontal components, pitch from
    the bow's up component, roll from the up row).

    Inputs, each at this shape or with one more leading axis of N points:
        R_enu_deck: (3, 3) [1]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        attitude: (N, 3) [rad]
    """
    outputs = get("enu2deck_attitude")(R_enu_deck)
    return Enu2deckAttitudeOutputs(*outputs)


def enu2ecef_rotation_paper(*, lat: ArrayLike, lon: ArrayLike) -> Enu2ecefRotationOutputs:
    """R_ecef_enu at (lat, lon) in rad, 'paper' variant (docs/background/online.md).

    Inputs, each at this shape or with one more leading axis of N points:
        lat: () [rad]
        lon: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        R_ecef_enu: (N, 3, 3) [1]
    """
    outputs = get("enu2ecef_rotation_paper")(lat, lon)
    return Enu2ecefRotationOutputs(*outputs)


def enu2ecef_rotation_standard(*, lat: ArrayLike, lon: ArrayLike) -> Enu2ecefRotationOutputs:
    """R_ecef_enu at (lat, lon) in rad, 'standard' variant (docs/background/online.md).

    Inputs, each at this shape or with one more leading axis of N points:
        lat: () [rad]
        lon: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        R_ecef_enu: (N, 3, 3) [1]
    """
    outputs = get("enu2ecef_rotation_standard")(lat, lon)
    return Enu2ecefRotationOutputs(*outputs)


class FleetPlot2ecefOutputs(NamedTuple):
    """The outputs of :func:`fleet_plot2ecef`, by name."""

    p_ecef: Array
    """(N, 3) [m]"""


def fleet_plot2ecef(
    *,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    att_err: ArrayLike,
    bias: ArrayLike,
    lever_deck: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
) -> FleetPlot2ecefOutputs:
    """Target ECEF (m) of one plot corrected by the registration errors: navigation lat, lon (rad), alt (m),
    reported heading, pitch, roll (rad), attitude errors att_err (rad), sensor biases [range m, bearing
    rad, elevation rad], lever_deck (m, deck frame), measured r (m), q, e (rad). The inverse of
    fleet_residual's predicted plot.

    Inputs, each at this shape or with one more leading axis of N points:
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        att_err: (3,) [rad]
        bias: (3,) [m, rad, rad]
        lever_deck: (3,) [m]
        r: () [m]
        q: () [rad]
        e: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        p_ecef: (N, 3) [m]
    """
    outputs = get("fleet_plot2ecef")(lat, lon, alt, heading, pitch, roll, att_err, bias, lever_deck, r, q, e)
    return FleetPlot2ecefOutputs(*outputs)


class FleetPlot2ecefEccOutputs(NamedTuple):
    """The outputs of :func:`fleet_plot2ecef_ecc`, by name."""

    p_ecef: Array
    """(N, 3) [m]"""


def fleet_plot2ecef_ecc(
    *,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    att_err: ArrayLike,
    bias: ArrayLike,
    gain: ArrayLike,
    pos_err: ArrayLike,
    ecc: ArrayLike,
    lever_deck: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
) -> FleetPlot2ecefEccOutputs:
    """Target ECEF (m) of one plot corrected by the extended registration errors and the azimuth eccentricity:
    the inputs of fleet_plot2ecef_ext and ecc = [a, b] (rad) after pos_err. The inverse of
    fleet_residual_ecc's predicted plot at dt = 0.

    Inputs, each at this shape or with one more leading axis of N points:
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        att_err: (3,) [rad]
        bias: (3,) [m, rad, rad]
        gain: () [1]
        pos_err: (3,) [m]
        ecc: (2,) [rad]
        lever_deck: (3,) [m]
        r: () [m]
        q: () [rad]
        e: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        p_ecef: (N, 3) [m]
    """
    outputs = get("fleet_plot2ecef_ecc")(
        lat, lon, alt, heading, pitch, roll, att_err, bias, gain, pos_err, ecc, lever_deck, r, q, e
    )
    return FleetPlot2ecefEccOutputs(*outputs)


class FleetPlot2ecefExtOutputs(NamedTuple):
    """The outputs of :func:`fleet_plot2ecef_ext`, by name."""

    p_ecef: Array
    """(N, 3) [m]"""


def fleet_plot2ecef_ext(
    *,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    att_err: ArrayLike,
    bias: ArrayLike,
    gain: ArrayLike,
    pos_err: ArrayLike,
    lever_deck: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
) -> FleetPlot2ecefExtOutputs:
    """Target ECEF (m) of one plot corrected by the extended registration errors: navigation lat, lon (rad),
    alt (m), reported heading, pitch, roll (rad), att_err (rad), biases [m, rad, rad], range gain (1),
    sensor position error pos_err (m, ENU, stated - true), lever_deck (m), measured r (m), q, e (rad). The
    inverse of fleet_residual_ext's predicted plot at dt = 0.

    Inputs, each at this shape or with one more leading axis of N points:
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        att_err: (3,) [rad]
        bias: (3,) [m, rad, rad]
        gain: () [1]
        pos_err: (3,) [m]
        lever_deck: (3,) [m]
        r: () [m]
        q: () [rad]
        e: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        p_ecef: (N, 3) [m]
    """
    outputs = get("fleet_plot2ecef_ext")(
        lat, lon, alt, heading, pitch, roll, att_err, bias, gain, pos_err, lever_deck, r, q, e
    )
    return FleetPlot2ecefExtOutputs(*outputs)


class FleetResidualOutputs(NamedTuple):
    """The outputs of :func:`fleet_residual`, by name."""

    residual: Array
    """(N, 3) [m, rad, rad]"""
    J: Array
    """(N, 3, 9) [m/m, m/rad, 1; rad/m, 1, 1]"""
    plot: Array
    """(N, 3) [m, rad, rad]"""


def fleet_residual(
    *,
    p_ecef: ArrayLike,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    att_err: ArrayLike,
    bias: ArrayLike,
    lever_deck: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
) -> FleetResidualOutputs:
    """One plot of fleet registration: target p_ecef (m); platform navigation lat, lon (rad), alt (m) and
    reported heading, pitch, roll (rad); attitude errors att_err (rad; true = reported - error); sensor
    biases [range m, bearing rad, elevation rad]; lever_deck (m, deck frame); measured r (m), q, e (rad).
    Outputs residual = measured - predicted (bearing wrapped to (-pi, pi]), J = d residual / d(p_ecef,
    att_err, bias) (3x9), and the predicted plot (true plot + bias, bearing wrapped).

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        att_err: (3,) [rad]
        bias: (3,) [m, rad, rad]
        lever_deck: (3,) [m]
        r: () [m]
        q: () [rad]
        e: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        residual: (N, 3) [m, rad, rad]
        J: (N, 3, 9) [m/m, m/rad, 1; rad/m, 1, 1]
        plot: (N, 3) [m, rad, rad]
    """
    outputs = get("fleet_residual")(
        p_ecef, lat, lon, alt, heading, pitch, roll, att_err, bias, lever_deck, r, q, e
    )
    return FleetResidualOutputs(*outputs)


class FleetResidualEccOutputs(NamedTuple):
    """The outputs of :func:`fleet_residual_ecc`, by name."""

    residual: Array
    """(N, 3) [m, rad, rad]"""
    J: Array
    """(N, 3, 16) [m/m, m/rad, 1, m, m/s, 1, m/rad; rad/m, 1, 1, rad, rad/s, rad/m, 1]"""
    plot: Array
    """(N, 3) [m, rad, rad]"""


def fleet_residual_ecc(
    *,
    p_ecef: ArrayLike,
    v_ecef: ArrayLike,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    nav_rate: ArrayLike,
    att_err: ArrayLike,
    bias: ArrayLike,
    gain: ArrayLike,
    dt: ArrayLike,
    pos_err: ArrayLike,
    ecc: ArrayLike,
    lever_deck: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
) -> FleetResidualEccOutputs:
    """One plot of fleet registration with the extended sensor errors and the azimuth eccentricity: the inputs
    of fleet_residual_ext and ecc = [a, b] (rad), the bearing seen with the error a sin q + b cos q at the
    measured bearing q. Outputs residual = measured - predicted (bearing wrapped), J = d residual /
    d(p_ecef, att_err, bias, gain, dt, pos_err, ecc) (3x16) and the predicted plot.

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        v_ecef: (3,) [m/s]
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        nav_rate: (6,) [rad/s, rad/s, m/s, rad/s, rad/s, rad/s]
        att_err: (3,) [rad]
        bias: (3,) [m, rad, rad]
        gain: () [1]
        dt: () [s]
        pos_err: (3,) [m]
        ecc: (2,) [rad]
        lever_deck: (3,) [m]
        r: () [m]
        q: () [rad]
        e: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        residual: (N, 3) [m, rad, rad]
        J: (N, 3, 16) [m/m, m/rad, 1, m, m/s, 1, m/rad; rad/m, 1, 1, rad, rad/s, rad/m, 1]
        plot: (N, 3) [m, rad, rad]
    """
    outputs = get("fleet_residual_ecc")(
        p_ecef,
        v_ecef,
        lat,
        lon,
        alt,
        heading,
        pitch,
        roll,
        nav_rate,
        att_err,
        bias,
        gain,
        dt,
        pos_err,
        ecc,
        lever_deck,
        r,
        q,
        e,
    )
    return FleetResidualEccOutputs(*outputs)


class FleetResidualExtOutputs(NamedTuple):
    """The outputs of :func:`fleet_residual_ext`, by name."""

    residual: Array
    """(N, 3) [m, rad, rad]"""
    J: Array
    """(N, 3, 14) [m/m, m/rad, 1, m, m/s, 1; rad/m, 1, 1, rad, rad/s, rad/m]"""
    plot: Array
    """(N, 3) [m, rad, rad]"""


def fleet_residual_ext(
    *,
    p_ecef: ArrayLike,
    v_ecef: ArrayLike,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    nav_rate: ArrayLike,
    att_err: ArrayLike,
    bias: ArrayLike,
    gain: ArrayLike,
    dt: ArrayLike,
    pos_err: ArrayLike,
    lever_deck: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
) -> FleetResidualExtOutputs:
    """One plot of fleet registration with the extended sensor errors: target p_ecef (m) and velocity v_ecef
    (m/s); platform navigation lat, lon (rad), alt (m), reported heading, pitch, roll (rad) and their rates
    nav_rate (rad/s, m/s); attitude errors att_err (rad); biases [range m, bearing rad, elevation rad];
    range gain (1); dt (s): target and platform seen dt earlier, to first order; sensor position error
    pos_err (m, ENU, stated - true); lever_deck (m); measured r (m), q, e (rad). Outputs residual =
    measured - predicted (bearing wrapped), J = d residual / d(p_ecef, att_err, bias, gain, dt, pos_err)
    (3x14) and the predicted plot.

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        v_ecef: (3,) [m/s]
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        nav_rate: (6,) [rad/s, rad/s, m/s, rad/s, rad/s, rad/s]
        att_err: (3,) [rad]
        bias: (3,) [m, rad, rad]
        gain: () [1]
        dt: () [s]
        pos_err: (3,) [m]
        lever_deck: (3,) [m]
        r: () [m]
        q: () [rad]
        e: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        residual: (N, 3) [m, rad, rad]
        J: (N, 3, 14) [m/m, m/rad, 1, m, m/s, 1; rad/m, 1, 1, rad, rad/s, rad/m]
        plot: (N, 3) [m, rad, rad]
    """
    outputs = get("fleet_residual_ext")(
        p_ecef,
        v_ecef,
        lat,
        lon,
        alt,
        heading,
        pitch,
        roll,
        nav_rate,
        att_err,
        bias,
        gain,
        dt,
        pos_err,
        lever_deck,
        r,
        q,
        e,
    )
    return FleetResidualExtOutputs(*outputs)


class FleetRows1Outputs(NamedTuple):
    """The outputs of :func:`fleet_rows_1`, by name."""

    rows_t: Array
    """(N, 10, 3) [1/m, 1/rad]"""


def fleet_rows_1(
    *,
    p_ecef: ArrayLike,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    att_err: ArrayLike,
    bias: ArrayLike,
    lever_deck: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
    weight: ArrayLike,
    basis: ArrayLike,
) -> FleetRows1Outputs:
    """Rows of the batch normal equations for one plot, polynomial basis of size 1: the inputs of
    fleet_residual, channel weights w = mask / sigma (1/m, 1/rad, 1/rad) and the basis values at the plot
    time. Output rows_t (10x3) = Z^T, Z = [basis^T (x) diag(w) J_p | diag(w) J_x | w * residual], J_x over
    the 6 states.

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        att_err: (3,) [rad]
        bias: (3,) [m, rad, rad]
        lever_deck: (3,) [m]
        r: () [m]
        q: () [rad]
        e: () [rad]
        weight: (3,) [1/m, 1/rad, 1/rad]
        basis: () [1]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        rows_t: (N, 10, 3) [1/m, 1/rad]
    """
    outputs = get("fleet_rows_1")(
        p_ecef, lat, lon, alt, heading, pitch, roll, att_err, bias, lever_deck, r, q, e, weight, basis
    )
    return FleetRows1Outputs(*outputs)


class FleetRows4Outputs(NamedTuple):
    """The outputs of :func:`fleet_rows_4`, by name."""

    rows_t: Array
    """(N, 19, 3) [1/m, 1/rad]"""


def fleet_rows_4(
    *,
    p_ecef: ArrayLike,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    att_err: ArrayLike,
    bias: ArrayLike,
    lever_deck: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
    weight: ArrayLike,
    basis: ArrayLike,
) -> FleetRows4Outputs:
    """Rows of the batch normal equations for one plot, polynomial basis of size 4: the inputs of
    fleet_residual, channel weights w = mask / sigma (1/m, 1/rad, 1/rad) and the basis values at the plot
    time. Output rows_t (19x3) = Z^T, Z = [basis^T (x) diag(w) J_p | diag(w) J_x | w * residual], J_x over
    the 6 states.

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        att_err: (3,) [rad]
        bias: (3,) [m, rad, rad]
        lever_deck: (3,) [m]
        r: () [m]
        q: () [rad]
        e: () [rad]
        weight: (3,) [1/m, 1/rad, 1/rad]
        basis: (4,) [1]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        rows_t: (N, 19, 3) [1/m, 1/rad]
    """
    outputs = get("fleet_rows_4")(
        p_ecef, lat, lon, alt, heading, pitch, roll, att_err, bias, lever_deck, r, q, e, weight, basis
    )
    return FleetRows4Outputs(*outputs)


class FleetRowsEcc31Outputs(NamedTuple):
    """The outputs of :func:`fleet_rows_ecc3_1`, by name."""

    rows_t: Array
    """(N, 12, 3) [1/m, 1/rad]"""


def fleet_rows_ecc3_1(
    *,
    p_ecef: ArrayLike,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    att_err: ArrayLike,
    bias: ArrayLike,
    ecc: ArrayLike,
    lever_deck: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
    weight: ArrayLike,
    basis: ArrayLike,
) -> FleetRowsEcc31Outputs:
    """Rows of the batch normal equations for one plot, polynomial basis of size 1, of fleet_residual_ecc with
    the extended errors held at 0 (v_ecef, nav_rate, gain, dt, pos_err): its other inputs, channel weights
    w = mask / sigma (1/m, 1/rad, 1/rad) and the basis values at the plot time. Output rows_t (12x3) = Z^T,
    Z = [basis^T (x) diag(w) J_p | diag(w) J_x | w * residual], J_x over the 8 states (attitude errors,
    biases, eccentricity sin and cos).

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        att_err: (3,) [rad]
        bias: (3,) [m, rad, rad]
        ecc: (2,) [rad]
        lever_deck: (3,) [m]
        r: () [m]
        q: () [rad]
        e: () [rad]
        weight: (3,) [1/m, 1/rad, 1/rad]
        basis: () [1]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        rows_t: (N, 12, 3) [1/m, 1/rad]
    """
    outputs = get("fleet_rows_ecc3_1")(
        p_ecef, lat, lon, alt, heading, pitch, roll, att_err, bias, ecc, lever_deck, r, q, e, weight, basis
    )
    return FleetRowsEcc31Outputs(*outputs)


class FleetRowsEcc34Outputs(NamedTuple):
    """The outputs of :func:`fleet_rows_ecc3_4`, by name."""

    rows_t: Array
    """(N, 21, 3) [1/m, 1/rad]"""


def fleet_rows_ecc3_4(
    *,
    p_ecef: ArrayLike,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    att_err: ArrayLike,
    bias: ArrayLike,
    ecc: ArrayLike,
    lever_deck: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
    weight: ArrayLike,
    basis: ArrayLike,
) -> FleetRowsEcc34Outputs:
    """Rows of the batch normal equations for one plot, polynomial basis of size 4, of fleet_residual_ecc with
    the extended errors held at 0 (v_ecef, nav_rate, gain, dt, pos_err): its other inputs, channel weights
    w = mask / sigma (1/m, 1/rad, 1/rad) and the basis values at the plot time. Output rows_t (21x3) = Z^T,
    Z = [basis^T (x) diag(w) J_p | diag(w) J_x | w * residual], J_x over the 8 states (attitude errors,
    biases, eccentricity sin and cos).

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        att_err: (3,) [rad]
        bias: (3,) [m, rad, rad]
        ecc: (2,) [rad]
        lever_deck: (3,) [m]
        r: () [m]
        q: () [rad]
        e: () [rad]
        weight: (3,) [1/m, 1/rad, 1/rad]
        basis: (4,) [1]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        rows_t: (N, 21, 3) [1/m, 1/rad]
    """
    outputs = get("fleet_rows_ecc3_4")(
        p_ecef, lat, lon, alt, heading, pitch, roll, att_err, bias, ecc, lever_deck, r, q, e, weight, basis
    )
    return FleetRowsEcc34Outputs(*outputs)


class FleetRowsEcc1Outputs(NamedTuple):
    """The outputs of :func:`fleet_rows_ecc_1`, by name."""

    rows_t: Array
    """(N, 17, 3) [1/m, 1/rad]"""


def fleet_rows_ecc_1(
    *,
    p_ecef: ArrayLike,
    v_ecef: ArrayLike,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    nav_rate: ArrayLike,
    att_err: ArrayLike,
    bias: ArrayLike,
    gain: ArrayLike,
    pos_err: ArrayLike,
    ecc: ArrayLike,
    lever_deck: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
    weight: ArrayLike,
    basis: ArrayLike,
) -> FleetRowsEcc1Outputs:
    """Rows of the batch normal equations for one plot, polynomial basis of size 1: the inputs of
    fleet_residual_ecc (without dt), channel weights w = mask / sigma (1/m, 1/rad, 1/rad) and the basis
    values at the plot time. Output rows_t (17x3) = Z^T, Z = [basis^T (x) diag(w) J_p | diag(w) J_x | w *
    residual], J_x over the 13 states (attitude errors, biases, range gain, time bias, position errors,
    eccentricity sin and cos; the time bias's column is d residual / d dt at dt = 0).

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        v_ecef: (3,) [m/s]
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        nav_rate: (6,) [rad/s, rad/s, m/s, rad/s, rad/s, rad/s]
        att_err: (3,) [rad]
        bias: (3,) [m, rad, rad]
        gain: () [1]
        pos_err: (3,) [m]
        ecc: (2,) [rad]
        lever_deck: (3,) [m]
        r: () [m]
        q: () [rad]
        e: () [rad]
        weight: (3,) [1/m, 1/rad, 1/rad]
        basis: () [1]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        rows_t: (N, 17, 3) [1/m, 1/rad]
    """
    outputs = get("fleet_rows_ecc_1")(
        p_ecef,
        v_ecef,
        lat,
        lon,
        alt,
        heading,
        pitch,
        roll,
        nav_rate,
        att_err,
        bias,
        gain,
        pos_err,
        ecc,
        lever_deck,
        r,
        q,
        e,
        weight,
        basis,
    )
    return FleetRowsEcc1Outputs(*outputs)


class FleetRowsEcc4Outputs(NamedTuple):
    """The outputs of :func:`fleet_rows_ecc_4`, by name."""

    rows_t: Array
    """(N, 26, 3) [1/m, 1/rad]"""


def fleet_rows_ecc_4(
    *,
    p_ecef: ArrayLike,
    v_ecef: ArrayLike,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    nav_rate: ArrayLike,
    att_err: ArrayLike,
    bias: ArrayLike,
    gain: ArrayLike,
    pos_err: ArrayLike,
    ecc: ArrayLike,
    lever_deck: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
    weight: ArrayLike,
    basis: ArrayLike,
) -> FleetRowsEcc4Outputs:
    """Rows of the batch normal equations for one plot, polynomial basis of size 4: the inputs of
    fleet_residual_ecc (without dt), channel weights w = mask / sigma (1/m, 1/rad, 1/rad) and the basis
    values at the plot time. Output rows_t (26x3) = Z^T, Z = [basis^T (x) diag(w) J_p | diag(w) J_x | w *
    residual], J_x over the 13 states (attitude errors, biases, range gain, time bias, position errors,
    eccentricity sin and cos; the time bias's column is d residual / d dt at dt = 0).

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        v_ecef: (3,) [m/s]
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        nav_rate: (6,) [rad/s, rad/s, m/s, rad/s, rad/s, rad/s]
        att_err: (3,) [rad]
        bias: (3,) [m, rad, rad]
        gain: () [1]
        pos_err: (3,) [m]
        ecc: (2,) [rad]
        lever_deck: (3,) [m]
        r: () [m]
        q: () [rad]
        e: () [rad]
        weight: (3,) [1/m, 1/rad, 1/rad]
        basis: (4,) [1]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        rows_t: (N, 26, 3) [1/m, 1/rad]
    """
    outputs = get("fleet_rows_ecc_4")(
        p_ecef,
        v_ecef,
        lat,
        lon,
        alt,
        heading,
        pitch,
        roll,
        nav_rate,
        att_err,
        bias,
        gain,
        pos_err,
        ecc,
        lever_deck,
        r,
        q,
        e,
        weight,
        basis,
    )
    return FleetRowsEcc4Outputs(*outputs)


class FleetRowsExt1Outputs(NamedTuple):
    """The outputs of :func:`fleet_rows_ext_1`, by name."""

    rows_t: Array
    """(N, 15, 3) [1/m, 1/rad]"""


def fleet_rows_ext_1(
    *,
    p_ecef: ArrayLike,
    v_ecef: ArrayLike,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    nav_rate: ArrayLike,
    att_err: ArrayLike,
    bias: ArrayLike,
    gain: ArrayLike,
    pos_err: ArrayLike,
    lever_deck: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
    weight: ArrayLike,
    basis: ArrayLike,
) -> FleetRowsExt1Outputs:
    """Rows of the batch normal equations for one plot, polynomial basis of size 1: the inputs of
    fleet_residual_ext (without dt), channel weights w = mask / sigma (1/m, 1/rad, 1/rad) and the basis
    values at the plot time. Output rows_t (15x3) = Z^T, Z = [basis^T (x) diag(w) J_p | diag(w) J_x | w *
    residual], J_x over the 11 states (attitude errors, biases, range gain, time bias, position errors; the
    time bias's column is d residual / d dt at dt = 0).

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        v_ecef: (3,) [m/s]
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        nav_rate: (6,) [rad/s, rad/s, m/s, rad/s, rad/s, rad/s]
        att_err: (3,) [rad]
        bias: (3,) [m, rad, rad]
        gain: () [1]
        pos_err: (3,) [m]
        lever_deck: (3,) [m]
        r: () [m]
        q: () [rad]
        e: () [rad]
        weight: (3,) [1/m, 1/rad, 1/rad]
        basis: () [1]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        rows_t: (N, 15, 3) [1/m, 1/rad]
    """
    outputs = get("fleet_rows_ext_1")(
        p_ecef,
        v_ecef,
        lat,
        lon,
        alt,
        heading,
        pitch,
        roll,
        nav_rate,
        att_err,
        bias,
        gain,
        pos_err,
        lever_deck,
        r,
        q,
        e,
        weight,
        basis,
    )
    return FleetRowsExt1Outputs(*outputs)


class FleetRowsExt4Outputs(NamedTuple):
    """The outputs of :func:`fleet_rows_ext_4`, by name."""

    rows_t: Array
    """(N, 24, 3) [1/m, 1/rad]"""


def fleet_rows_ext_4(
    *,
    p_ecef: ArrayLike,
    v_ecef: ArrayLike,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    nav_rate: ArrayLike,
    att_err: ArrayLike,
    bias: ArrayLike,
    gain: ArrayLike,
    pos_err: ArrayLike,
    lever_deck: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
    weight: ArrayLike,
    basis: ArrayLike,
) -> FleetRowsExt4Outputs:
    """Rows of the batch normal equations for one plot, polynomial basis of size 4: the inputs of
    fleet_residual_ext (without dt), channel weights w = mask / sigma (1/m, 1/rad, 1/rad) and the basis
    values at the plot time. Output rows_t (24x3) = Z^T, Z = [basis^T (x) diag(w) J_p | diag(w) J_x | w *
    residual], J_x over the 11 states (attitude errors, biases, range gain, time bias, position errors; the
    time bias's column is d residual / d dt at dt = 0).

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        v_ecef: (3,) [m/s]
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        nav_rate: (6,) [rad/s, rad/s, m/s, rad/s, rad/s, rad/s]
        att_err: (3,) [rad]
        bias: (3,) [m, rad, rad]
        gain: () [1]
        pos_err: (3,) [m]
        lever_deck: (3,) [m]
        r: () [m]
        q: () [rad]
        e: () [rad]
        weight: (3,) [1/m, 1/rad, 1/rad]
        basis: (4,) [1]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        rows_t: (N, 24, 3) [1/m, 1/rad]
    """
    outputs = get("fleet_rows_ext_4")(
        p_ecef,
        v_ecef,
        lat,
        lon,
        alt,
        heading,
        pitch,
        roll,
        nav_rate,
        att_err,
        bias,
        gain,
        pos_err,
        lever_deck,
        r,
        q,
        e,
        weight,
        basis,
    )
    return FleetRowsExt4Outputs(*outputs)


class Geodetic2ecefOutputs(NamedTuple):
    """The outputs of :func:`geodetic2ecef`, by name."""

    p_ecef: Array
    """(N, 3) [m]"""


def geodetic2ecef(*, lat: ArrayLike, lon: ArrayLike, alt: ArrayLike) -> Geodetic2ecefOutputs:
    """ECEF position (m) of a geodetic point (lat, lon in rad; alt in m above WGS-84). Eq. (1).

    Inputs, each at this shape or with one more leading axis of N points:
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        p_ecef: (N, 3) [m]
    """
    outputs = get("geodetic2ecef")(lat, lon, alt)
    return Geodetic2ecefOutputs(*outputs)


def information_step_paper(
    *, info: ArrayLike, x: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> InformationStepOutputs:
    """Fisher information accumulation, T variant 'paper': info_new = info + H^T R^-1 H, H and R at the row
    corrected by the fixed estimate x. Input info carried from output info_new.

    Inputs, each at this shape or with one more leading axis of N points:
        info: (12, 12) [1/rad^2, 1/m^2]
        x: (12,) [rad, m]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
    """
    outputs = get("information_step_paper")(info, x, row, sigma0)
    return InformationStepOutputs(*outputs)


def information_step_standard(
    *, info: ArrayLike, x: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> InformationStepOutputs:
    """Fisher information accumulation, T variant 'standard': info_new = info + H^T R^-1 H, H and R at the row
    corrected by the fixed estimate x. Input info carried from output info_new.

    Inputs, each at this shape or with one more leading axis of N points:
        info: (12, 12) [1/rad^2, 1/m^2]
        x: (12,) [rad, m]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
    """
    outputs = get("information_step_standard")(info, x, row, sigma0)
    return InformationStepOutputs(*outputs)


def kalman_step_fitted_paper(
    *, x: ArrayLike, P: ArrayLike, info: ArrayLike, Q: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> KalmanStepFittedOutputs:
    """One registration Kalman step (eqs. 18-23), linearisation 'fitted', T variant 'paper'. Inputs x, P, info
    carried from outputs x_new, P_new, info_new of the previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get("kalman_step_fitted_paper")(x, P, info, Q, row, sigma0)
    return KalmanStepFittedOutputs(*outputs)


class KalmanStepFittedPaperCarlsonOutputs(NamedTuple):
    """The outputs of :func:`kalman_step_fitted_paper_carlson`, by name."""

    x_new: Array
    """(N, 12) [rad, m]"""
    P_new: Array
    """(N, 12, 12) [rad^2, m^2]"""
    info_new: Array
    """(N, 12, 12) [1/rad^2, 1/m^2]"""
    nu: Array
    """(N, 3) [m]"""
    S: Array
    """(N, 3, 3) [m^2]"""
    nis: Array
    """(N,) [1]"""


def kalman_step_fitted_paper_carlson(
    *, x: ArrayLike, P: ArrayLike, info: ArrayLike, Q: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> KalmanStepFittedPaperCarlsonOutputs:
    """One registration Kalman step (eqs. 18-23), linearisation 'fitted', T variant 'paper', covariance update
    'carlson'. Inputs x, P, info carried from outputs x_new, P_new, info_new of the previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get("kalman_step_fitted_paper_carlson")(x, P, info, Q, row, sigma0)
    return KalmanStepFittedPaperCarlsonOutputs(*outputs)


def kalman_step_fitted_standard(
    *, x: ArrayLike, P: ArrayLike, info: ArrayLike, Q: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> KalmanStepFittedOutputs:
    """One registration Kalman step (eqs. 18-23), linearisation 'fitted', T variant 'standard'. Inputs x, P,
    info carried from outputs x_new, P_new, info_new of the previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get("kalman_step_fitted_standard")(x, P, info, Q, row, sigma0)
    return KalmanStepFittedOutputs(*outputs)


class KalmanStepFittedStandardCarlsonOutputs(NamedTuple):
    """The outputs of :func:`kalman_step_fitted_standard_carlson`, by name."""

    x_new: Array
    """(N, 12) [rad, m]"""
    P_new: Array
    """(N, 12, 12) [rad^2, m^2]"""
    info_new: Array
    """(N, 12, 12) [1/rad^2, 1/m^2]"""
    nu: Array
    """(N, 3) [m]"""
    S: Array
    """(N, 3, 3) [m^2]"""
    nis: Array
    """(N,) [1]"""


def kalman_step_fitted_standard_carlson(
    *, x: ArrayLike, P: ArrayLike, info: ArrayLike, Q: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> KalmanStepFittedStandardCarlsonOutputs:
    """One registration Kalman step (eqs. 18-23), linearisation 'fitted', T variant 'standard', covariance
    update 'carlson'. Inputs x, P, info carried from outputs x_new, P_new, info_new of the previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get("kalman_step_fitted_standard_carlson")(x, P, info, Q, row, sigma0)
    return KalmanStepFittedStandardCarlsonOutputs(*outputs)


def kalman_step_paper_paper(
    *, x: ArrayLike, P: ArrayLike, info: ArrayLike, Q: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> KalmanStepPaperOutputs:
    """One registration Kalman step (eqs. 18-23), linearisation 'paper', T variant 'paper'. Inputs x, P, info
    carried from outputs x_new, P_new, info_new of the previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get("kalman_step_paper_paper")(x, P, info, Q, row, sigma0)
    return KalmanStepPaperOutputs(*outputs)


class KalmanStepPaperPaperCarlsonOutputs(NamedTuple):
    """The outputs of :func:`kalman_step_paper_paper_carlson`, by name."""

    x_new: Array
    """(N, 12) [rad, m]"""
    P_new: Array
    """(N, 12, 12) [rad^2, m^2]"""
    info_new: Array
    """(N, 12, 12) [1/rad^2, 1/m^2]"""
    nu: Array
    """(N, 3) [m]"""
    S: Array
    """(N, 3, 3) [m^2]"""
    nis: Array
    """(N,) [1]"""


def kalman_step_paper_paper_carlson(
    *, x: ArrayLike, P: ArrayLike, info: ArrayLike, Q: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> KalmanStepPaperPaperCarlsonOutputs:
    """One registration Kalman step (eqs. 18-23), linearisation 'paper', T variant 'paper', covariance update
    'carlson'. Inputs x, P, info carried from outputs x_new, P_new, info_new of the previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get("kalman_step_paper_paper_carlson")(x, P, info, Q, row, sigma0)
    return KalmanStepPaperPaperCarlsonOutputs(*outputs)


def kalman_step_paper_standard(
    *, x: ArrayLike, P: ArrayLike, info: ArrayLike, Q: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> KalmanStepPaperOutputs:
    """One registration Kalman step (eqs. 18-23), linearisation 'paper', T variant 'standard'. Inputs x, P,
    info carried from outputs x_new, P_new, info_new of the previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get("kalman_step_paper_standard")(x, P, info, Q, row, sigma0)
    return KalmanStepPaperOutputs(*outputs)


class KalmanStepPaperStandardCarlsonOutputs(NamedTuple):
    """The outputs of :func:`kalman_step_paper_standard_carlson`, by name."""

    x_new: Array
    """(N, 12) [rad, m]"""
    P_new: Array
    """(N, 12, 12) [rad^2, m^2]"""
    info_new: Array
    """(N, 12, 12) [1/rad^2, 1/m^2]"""
    nu: Array
    """(N, 3) [m]"""
    S: Array
    """(N, 3, 3) [m^2]"""
    nis: Array
    """(N,) [1]"""


def kalman_step_paper_standard_carlson(
    *, x: ArrayLike, P: ArrayLike, info: ArrayLike, Q: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> KalmanStepPaperStandardCarlsonOutputs:
    """One registration Kalman step (eqs. 18-23), linearisation 'paper', T variant 'standard', covariance
    update 'carlson'. Inputs x, P, info carried from outputs x_new, P_new, info_new of the previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get("kalman_step_paper_standard_carlson")(x, P, info, Q, row, sigma0)
    return KalmanStepPaperStandardCarlsonOutputs(*outputs)


def kalman_step_relinearized_paper(
    *, x: ArrayLike, P: ArrayLike, info: ArrayLike, Q: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> KalmanStepRelinearizedOutputs:
    """One registration Kalman step (eqs. 18-23), linearisation 'relinearized', T variant 'paper'. Inputs x,
    P, info carried from outputs x_new, P_new, info_new of the previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get("kalman_step_relinearized_paper")(x, P, info, Q, row, sigma0)
    return KalmanStepRelinearizedOutputs(*outputs)


class KalmanStepRelinearizedPaperCarlsonOutputs(NamedTuple):
    """The outputs of :func:`kalman_step_relinearized_paper_carlson`, by name."""

    x_new: Array
    """(N, 12) [rad, m]"""
    P_new: Array
    """(N, 12, 12) [rad^2, m^2]"""
    info_new: Array
    """(N, 12, 12) [1/rad^2, 1/m^2]"""
    nu: Array
    """(N, 3) [m]"""
    S: Array
    """(N, 3, 3) [m^2]"""
    nis: Array
    """(N,) [1]"""


def kalman_step_relinearized_paper_carlson(
    *, x: ArrayLike, P: ArrayLike, info: ArrayLike, Q: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> KalmanStepRelinearizedPaperCarlsonOutputs:
    """One registration Kalman step (eqs. 18-23), linearisation 'relinearized', T variant 'paper', covariance
    update 'carlson'. Inputs x, P, info carried from outputs x_new, P_new, info_new of the previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get("kalman_step_relinearized_paper_carlson")(x, P, info, Q, row, sigma0)
    return KalmanStepRelinearizedPaperCarlsonOutputs(*outputs)


def kalman_step_relinearized_standard(
    *, x: ArrayLike, P: ArrayLike, info: ArrayLike, Q: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> KalmanStepRelinearizedOutputs:
    """One registration Kalman step (eqs. 18-23), linearisation 'relinearized', T variant 'standard'. Inputs
    x, P, info carried from outputs x_new, P_new, info_new of the previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get("kalman_step_relinearized_standard")(x, P, info, Q, row, sigma0)
    return KalmanStepRelinearizedOutputs(*outputs)


class KalmanStepRelinearizedStandardCarlsonOutputs(NamedTuple):
    """The outputs of :func:`kalman_step_relinearized_standard_carlson`, by name."""

    x_new: Array
    """(N, 12) [rad, m]"""
    P_new: Array
    """(N, 12, 12) [rad^2, m^2]"""
    info_new: Array
    """(N, 12, 12) [1/rad^2, 1/m^2]"""
    nu: Array
    """(N, 3) [m]"""
    S: Array
    """(N, 3, 3) [m^2]"""
    nis: Array
    """(N,) [1]"""


def kalman_step_relinearized_standard_carlson(
    *, x: ArrayLike, P: ArrayLike, info: ArrayLike, Q: ArrayLike, row: ArrayLike, sigma0: ArrayLike
) -> KalmanStepRelinearizedStandardCarlsonOutputs:
    """One registration Kalman step (eqs. 18-23), linearisation 'relinearized', T variant 'standard',
    covariance update 'carlson'. Inputs x, P, info carried from outputs x_new, P_new, info_new of the
    previous step.

    Inputs, each at this shape or with one more leading axis of N points:
        x: (12,) [rad, m]
        P: (12, 12) [rad^2, m^2]
        info: (12, 12) [1/rad^2, 1/m^2]
        Q: (12, 12) [rad^2, m^2 per step]
        row: (18,) [nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        x_new: (N, 12) [rad, m]
        P_new: (N, 12, 12) [rad^2, m^2]
        info_new: (N, 12, 12) [1/rad^2, 1/m^2]
        nu: (N, 3) [m]
        S: (N, 3, 3) [m^2]
        nis: (N,) [1]
    """
    outputs = get("kalman_step_relinearized_standard_carlson")(x, P, info, Q, row, sigma0)
    return KalmanStepRelinearizedStandardCarlsonOutputs(*outputs)


class LandingCamera2ctdOutputs(NamedTuple):
    """The outputs of :func:`landing_camera2ctd`, by name."""

    angles_ctd: Array
    """(N, 2) [rad]"""
    J: Array
    """(N, 2, 2) [1]"""


def landing_camera2ctd(
    *, angles_cam: ArrayLike, attitude: ArrayLike, angled_deck: ArrayLike
) -> LandingCamera2ctdOutputs:
    """Camera angles [a, b] (rad, deck-fixed landing-area axes) -> angles about the camera in td axes (ctd),
    and J = dangles_ctd/dangles_cam (2x2) for the camera's error transfer.

    Inputs, each at this shape or with one more leading axis of N points:
        angles_cam: (2,) [rad]
        attitude: (3,) [rad: yaw deviation from the mean heading, pitch, roll]
        angled_deck: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        angles_ctd: (N, 2) [rad]
        J: (N, 2, 2) [1]
    """
    outputs = get("landing_camera2ctd")(angles_cam, attitude, angled_deck)
    return LandingCamera2ctdOutputs(*outputs)


class LandingCtd2tdOutputs(NamedTuple):
    """The outputs of :func:`landing_ctd2td`, by name."""

    p_td: Array
    """(N, 3) [m]"""
    J: Array
    """(N, 3, 3) [1, m/rad]"""


def landing_ctd2td(
    *, polar_ctd: ArrayLike, attitude: ArrayLike, angled_deck: ArrayLike, d_camera_deck: ArrayLike
) -> LandingCtd2tdOutputs:
    """Polar [r m, a rad, b rad] about the camera in td axes -> p_td (m), and J = dp_td/dpolar (rebuilds the
    fused position, eq. 12).

    Inputs, each at this shape or with one more leading axis of N points:
        polar_ctd: (3,) [m, rad, rad]
        attitude: (3,) [rad: yaw deviation from the mean heading, pitch, roll]
        angled_deck: () [rad]
        d_camera_deck: (3,) [m]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        p_td: (N, 3) [m]
        J: (N, 3, 3) [1, m/rad]
    """
    outputs = get("landing_ctd2td")(polar_ctd, attitude, angled_deck, d_camera_deck)
    return LandingCtd2tdOutputs(*outputs)


class LandingDeck2tdRotationOutputs(NamedTuple):
    """The outputs of :func:`landing_deck2td_rotation`, by name."""

    R_td_deck: Array
    """(N, 3, 3) [1]"""


def landing_deck2td_rotation(*, attitude: ArrayLike, angled_deck: ArrayLike) -> LandingDeck2tdRotationOutputs:
    """M = R_td_deck = T_A(phi_c) T_L R_level_deck(yaw, pitch, roll) (eqs. 7-8); angles in rad.

    Inputs, each at this shape or with one more leading axis of N points:
        attitude: (3,) [rad: yaw deviation from the mean heading, pitch, roll]
        angled_deck: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        R_td_deck: (N, 3, 3) [1]
    """
    outputs = get("landing_deck2td_rotation")(attitude, angled_deck)
    return LandingDeck2tdRotationOutputs(*outputs)


class LandingMtd2tdOutputs(NamedTuple):
    """The outputs of :func:`landing_mtd2td`, by name."""

    p_td: Array
    """(N, 3) [m]"""


def landing_mtd2td(
    *, p_mtd: ArrayLike, attitude: ArrayLike, angled_deck: ArrayLike, l_td_deck: ArrayLike
) -> LandingMtd2tdOutputs:
    """Simulation: point in the mean touchdown frame p_mtd (m) -> touchdown frame p_td (m), the touchdown
    point at l_td_deck (m, from the motion centre) moving with the attitude (rad).

    Inputs, each at this shape or with one more leading axis of N points:
        p_mtd: (3,) [m]
        attitude: (3,) [rad: yaw deviation from the mean heading, pitch, roll]
        angled_deck: () [rad]
        l_td_deck: (3,) [m]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        p_td: (N, 3) [m]
    """
    outputs = get("landing_mtd2td")(p_mtd, attitude, angled_deck, l_td_deck)
    return LandingMtd2tdOutputs(*outputs)


class LandingRadar2ctdOutputs(NamedTuple):
    """The outputs of :func:`landing_radar2ctd`, by name."""

    polar_ctd: Array
    """(N, 3) [m, rad, rad]"""
    BMA: Array
    """(N, 3, 3) [1, m/rad, rad/m]"""


def landing_radar2ctd(
    *,
    polar_rdr: ArrayLike,
    attitude: ArrayLike,
    angled_deck: ArrayLike,
    d_radar_deck: ArrayLike,
    d_camera_deck: ArrayLike,
) -> LandingRadar2ctdOutputs:
    """Eqs. (7)-(10): radar polar [r m, a rad, b rad] (deck axes) -> polar about the camera in td axes (ctd),
    and BMA = dpolar_ctd/dpolar_rdr for P_RL = BMA P_R BMA^T (eq. 11).

    Inputs, each at this shape or with one more leading axis of N points:
        polar_rdr: (3,) [m, rad, rad]
        attitude: (3,) [rad: yaw deviation from the mean heading, pitch, roll]
        angled_deck: () [rad]
        d_radar_deck: (3,) [m]
        d_camera_deck: (3,) [m]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        polar_ctd: (N, 3) [m, rad, rad]
        BMA: (N, 3, 3) [1, m/rad, rad/m]
    """
    outputs = get("landing_radar2ctd")(polar_rdr, attitude, angled_deck, d_radar_deck, d_camera_deck)
    return LandingRadar2ctdOutputs(*outputs)


class LandingRadar2tdOutputs(NamedTuple):
    """The outputs of :func:`landing_radar2td`, by name."""

    p_td: Array
    """(N, 3) [m]"""
    u_deck: Array
    """(N, 3) [m]"""
    A: Array
    """(N, 3, 3) [1, m/rad]"""
    M: Array
    """(N, 3, 3) [1]"""
    J: Array
    """(N, 3, 3) [1, m/rad]"""


def landing_radar2td(
    *, polar_rdr: ArrayLike, attitude: ArrayLike, angled_deck: ArrayLike, d_radar_deck: ArrayLike
) -> LandingRadar2tdOutputs:
    """Eq. (7): radar polar [r m, a rad, b rad] in deck axes -> target p_td (m) in the touchdown frame, with
    u_deck (m), A = du_deck/dpolar, M = R_td_deck and J = dp_td/dpolar = M A.

    Inputs, each at this shape or with one more leading axis of N points:
        polar_rdr: (3,) [m, rad, rad]
        attitude: (3,) [rad: yaw deviation from the mean heading, pitch, roll]
        angled_deck: () [rad]
        d_radar_deck: (3,) [m]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        p_td: (N, 3) [m]
        u_deck: (N, 3) [m]
        A: (N, 3, 3) [1, m/rad]
        M: (N, 3, 3) [1]
        J: (N, 3, 3) [1, m/rad]
    """
    outputs = get("landing_radar2td")(polar_rdr, attitude, angled_deck, d_radar_deck)
    return LandingRadar2tdOutputs(*outputs)


class LandingTd2cameraOutputs(NamedTuple):
    """The outputs of :func:`landing_td2camera`, by name."""

    angles_cam: Array
    """(N, 2) [rad]"""


def landing_td2camera(
    *, p_td: ArrayLike, attitude: ArrayLike, angled_deck: ArrayLike, d_camera_deck: ArrayLike
) -> LandingTd2cameraOutputs:
    """Simulation: p_td (m) -> the camera angles [a, b] (rad) in its deck-fixed landing-area axes.

    Inputs, each at this shape or with one more leading axis of N points:
        p_td: (3,) [m]
        attitude: (3,) [rad: yaw deviation from the mean heading, pitch, roll]
        angled_deck: () [rad]
        d_camera_deck: (3,) [m]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        angles_cam: (N, 2) [rad]
    """
    outputs = get("landing_td2camera")(p_td, attitude, angled_deck, d_camera_deck)
    return LandingTd2cameraOutputs(*outputs)


class LandingTd2ctdOutputs(NamedTuple):
    """The outputs of :func:`landing_td2ctd`, by name."""

    polar_ctd: Array
    """(N, 3) [m, rad, rad]"""
    B: Array
    """(N, 3, 3) [1, rad/m]"""


def landing_td2ctd(
    *, p_td: ArrayLike, attitude: ArrayLike, angled_deck: ArrayLike, d_camera_deck: ArrayLike
) -> LandingTd2ctdOutputs:
    """Touchdown-frame point p_td (m) -> polar [r m, a rad, b rad] about the camera in td axes (ctd), and B =
    dpolar/dp_td (eq. 9).

    Inputs, each at this shape or with one more leading axis of N points:
        p_td: (3,) [m]
        attitude: (3,) [rad: yaw deviation from the mean heading, pitch, roll]
        angled_deck: () [rad]
        d_camera_deck: (3,) [m]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        polar_ctd: (N, 3) [m, rad, rad]
        B: (N, 3, 3) [1, rad/m]
    """
    outputs = get("landing_td2ctd")(p_td, attitude, angled_deck, d_camera_deck)
    return LandingTd2ctdOutputs(*outputs)


class LandingTd2radarOutputs(NamedTuple):
    """The outputs of :func:`landing_td2radar`, by name."""

    polar_rdr: Array
    """(N, 3) [m, rad, rad]"""


def landing_td2radar(
    *, p_td: ArrayLike, attitude: ArrayLike, angled_deck: ArrayLike, d_radar_deck: ArrayLike
) -> LandingTd2radarOutputs:
    """Simulation (inverse of eq. 7): p_td (m) -> the radar polar [r m, a rad, b rad] in deck axes.

    Inputs, each at this shape or with one more leading axis of N points:
        p_td: (3,) [m]
        attitude: (3,) [rad: yaw deviation from the mean heading, pitch, roll]
        angled_deck: () [rad]
        d_radar_deck: (3,) [m]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        polar_rdr: (N, 3) [m, rad, rad]
    """
    outputs = get("landing_td2radar")(p_td, attitude, angled_deck, d_radar_deck)
    return LandingTd2radarOutputs(*outputs)


def plot2ecef_paper(
    *,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
) -> Plot2ecefOutputs:
    """Eq. (3), T variant 'paper': a radar plot (r m, q rad, e rad) from a ship at (lat, lon rad; alt m) with
    attitude (heading, pitch, roll rad) -> target ECEF (m).

    Inputs, each at this shape or with one more leading axis of N points:
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        r: () [m]
        q: () [rad]
        e: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        p_ecef: (N, 3) [m]
    """
    outputs = get("plot2ecef_paper")(lat, lon, alt, heading, pitch, roll, r, q, e)
    return Plot2ecefOutputs(*outputs)


def plot2ecef_standard(
    *,
    lat: ArrayLike,
    lon: ArrayLike,
    alt: ArrayLike,
    heading: ArrayLike,
    pitch: ArrayLike,
    roll: ArrayLike,
    r: ArrayLike,
    q: ArrayLike,
    e: ArrayLike,
) -> Plot2ecefOutputs:
    """Eq. (3), T variant 'standard': a radar plot (r m, q rad, e rad) from a ship at (lat, lon rad; alt m)
    with attitude (heading, pitch, roll rad) -> target ECEF (m).

    Inputs, each at this shape or with one more leading axis of N points:
        lat: () [rad]
        lon: () [rad]
        alt: () [m]
        heading: () [rad]
        pitch: () [rad]
        roll: () [rad]
        r: () [m]
        q: () [rad]
        e: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        p_ecef: (N, 3) [m]
    """
    outputs = get("plot2ecef_standard")(lat, lon, alt, heading, pitch, roll, r, q, e)
    return Plot2ecefOutputs(*outputs)


class Polar2cartesian2Outputs(NamedTuple):
    """The outputs of :func:`polar2cartesian2`, by name."""

    p: Array
    """(N, 2) [m]"""
    J: Array
    """(N, 2, 2) [1, m/rad]"""


def polar2cartesian2(*, polar: ArrayLike) -> Polar2cartesian2Outputs:
    """2-D: polar [r m, az rad] -> Cartesian p [m] and J = dp/dpolar.

    Inputs, each at this shape or with one more leading axis of N points:
        polar: (2,) [m, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        p: (N, 2) [m]
        J: (N, 2, 2) [1, m/rad]
    """
    outputs = get("polar2cartesian2")(polar)
    return Polar2cartesian2Outputs(*outputs)


class Polar2cartesian3Outputs(NamedTuple):
    """The outputs of :func:`polar2cartesian3`, by name."""

    p: Array
    """(N, 3) [m]"""
    J: Array
    """(N, 3, 3) [1, m/rad]"""


def polar2cartesian3(*, polar: ArrayLike) -> Polar2cartesian3Outputs:
    """3-D: polar [r m, az rad, el rad] -> Cartesian p [m] and J = dp/dpolar.

    Inputs, each at this shape or with one more leading axis of N points:
        polar: (3,) [m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        p: (N, 3) [m]
        J: (N, 3, 3) [1, m/rad]
    """
    outputs = get("polar2cartesian3")(polar)
    return Polar2cartesian3Outputs(*outputs)


def pseudo_measurement_paper(
    *,
    nav_a: ArrayLike,
    att_a: ArrayLike,
    meas_a: ArrayLike,
    nav_b: ArrayLike,
    att_b: ArrayLike,
    meas_b: ArrayLike,
    sigma0: ArrayLike,
) -> PseudoMeasurementOutputs:
    """Two-sensor pseudo-measurement (eqs. 7-19), T variant 'paper'. Inputs per sensor: nav [lat rad, lon rad,
    alt m], att [heading, pitch, roll rad], meas [r m, q rad, e rad]; sigma0 = [sr_A m, sq_A rad, se_A rad,
    sr_B, sq_B, se_B]. Outputs Z = X_A - X_B (m), H (3x12), M (3x6), R = M R0 M^T (m^2), and X_A, X_B (ECEF
    m).

    Inputs, each at this shape or with one more leading axis of N points:
        nav_a: (3,) [rad, rad, m]
        att_a: (3,) [rad]
        meas_a: (3,) [m, rad, rad]
        nav_b: (3,) [rad, rad, m]
        att_b: (3,) [rad]
        meas_b: (3,) [m, rad, rad]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        Z: (N, 3) [m]
        H: (N, 3, 12) [m/rad, m/m]
        M: (N, 3, 6) [m/m, m/rad]
        R: (N, 3, 3) [m^2]
        p_a_ecef: (N, 3) [m]
        p_b_ecef: (N, 3) [m]
    """
    outputs = get("pseudo_measurement_paper")(nav_a, att_a, meas_a, nav_b, att_b, meas_b, sigma0)
    return PseudoMeasurementOutputs(*outputs)


def pseudo_measurement_standard(
    *,
    nav_a: ArrayLike,
    att_a: ArrayLike,
    meas_a: ArrayLike,
    nav_b: ArrayLike,
    att_b: ArrayLike,
    meas_b: ArrayLike,
    sigma0: ArrayLike,
) -> PseudoMeasurementOutputs:
    """Two-sensor pseudo-measurement (eqs. 7-19), T variant 'standard'. Inputs per sensor: nav [lat rad, lon
    rad, alt m], att [heading, pitch, roll rad], meas [r m, q rad, e rad]; sigma0 = [sr_A m, sq_A rad, se_A
    rad, sr_B, sq_B, se_B]. Outputs Z = X_A - X_B (m), H (3x12), M (3x6), R = M R0 M^T (m^2), and X_A, X_B
    (ECEF m).

    Inputs, each at this shape or with one more leading axis of N points:
        nav_a: (3,) [rad, rad, m]
        att_a: (3,) [rad]
        meas_a: (3,) [m, rad, rad]
        nav_b: (3,) [rad, rad, m]
        att_b: (3,) [rad]
        meas_b: (3,) [m, rad, rad]
        sigma0: (6,) [m, rad, rad, m, rad, rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        Z: (N, 3) [m]
        H: (N, 3, 12) [m/rad, m/m]
        M: (N, 3, 6) [m/m, m/rad]
        R: (N, 3, 3) [m^2]
        p_a_ecef: (N, 3) [m]
        p_b_ecef: (N, 3) [m]
    """
    outputs = get("pseudo_measurement_standard")(nav_a, att_a, meas_a, nav_b, att_b, meas_b, sigma0)
    return PseudoMeasurementOutputs(*outputs)


class RadiiOfCurvatureOutputs(NamedTuple):
    """The outputs of :func:`radii_of_curvature`, by name."""

    radii: Array
    """(N, 2) [m]"""


def radii_of_curvature(*, lat: ArrayLike) -> RadiiOfCurvatureOutputs:
    """Meridian radius M and prime-vertical radius N (m) of WGS-84 at latitude lat (rad).

    Inputs, each at this shape or with one more leading axis of N points:
        lat: () [rad]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        radii: (N, 2) [m]
    """
    outputs = get("radii_of_curvature")(lat)
    return RadiiOfCurvatureOutputs(*outputs)


class SurfaceResidualOutputs(NamedTuple):
    """The outputs of :func:`surface_residual`, by name."""

    residual: Array
    """(N,) [m]"""
    J: Array
    """(N, 1, 3) [1]"""


def surface_residual(*, p_ecef: ArrayLike, alt_surface: ArrayLike) -> SurfaceResidualOutputs:
    """Height residual of a target on a surface of known height (a ship on the sea): residual = alt_surface (m
    above WGS-84) - the geodetic height of p_ecef (m, the inverse of eq. (1)), and J = d residual / d
    p_ecef (1x3; minus the geodetic up at the point).

    Inputs, each at this shape or with one more leading axis of N points:
        p_ecef: (3,) [m]
        alt_surface: () [m]
    Outputs, over the N points (N = 1 when no input has the leading axis):
        residual: (N,) [m]
        J: (N, 1, 3) [1]
    """
    outputs = get("surface_residual")(p_ecef, alt_surface)
    return SurfaceResidualOutputs(*outputs)
