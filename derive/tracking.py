"""The constant-velocity Kalman filter of the association's tracks, in ECEF, composed in CasADi.

State ``x`` (6) = position (m) and velocity (m/s) in ECEF, covariance ``P`` (6x6). A plot is a
position measurement ``z`` (3, m) with covariance ``R`` (3x3, m^2): ``H = [I 0]``.

* ``cv_start``: a track opened at a plot: ``x = [z, 0]``, ``P = diag(R, max_speed^2 I)`` (the
  velocity unknown up to the largest speed, m/s).
* ``cv_predict``: by ``dt`` (s) with white acceleration noise of spectral density
  ``accel_sigma^2`` (m^2/s^3): ``x- = F x``, ``P- = F P F^T + Q``, ``F = [[I, dt I], [0, I]]``,
  ``Q = accel_sigma^2 [[dt^3/3 I, dt^2/2 I], [dt^2/2 I, dt I]]``; P- mirrored from its upper
  triangle (symmetric by construction).
* ``cv_gate``: the plot against a prediction: ``S = P-_pp + R`` (the position block plus the
  plot's covariance), its lower Cholesky factor ``L``; the squared Mahalanobis distance
  ``d2 = |L^-1 (z - x-_p)|^2`` and ``logdet = log det S = 2 sum log L_ii``. The assignment's cost
  of the pair is ``(d2 + logdet) / 2``, the negative log-likelihood up to a constant.
* ``cv_update``: the Kalman update with the plot: ``K = P- H^T S^-1`` (by the Cholesky factor, no
  inverse), ``x+ = x- + K (z - x-_p)``, ``P+ = P- - K H P-`` made symmetric as ``(P+ + P+^T) / 2``.

A matrix that is not numerically positive definite gives NaN through the square roots, never a
silently wrong factor. The runtime's tracker (``registration.fleet.association.grouping.tracks``)
runs these per track and per candidate pair, in compiled code (``_tracker.c``) or batched.
"""

import casadi as ca

from .spec import CasadiPort, CasadiSpec
from .triangular import backward_substitution, chol_lower, forward_substitution, mirror_upper

STATE = CasadiPort("x", (6, 1), "m, m/s (ECEF position, velocity)")
COVARIANCE = CasadiPort("P", (6, 6), "m^2, m^2/s, m^2/s^2")
PLOT = CasadiPort("z", (3, 1), "m (ECEF)")
PLOT_COVARIANCE = CasadiPort("R", (3, 3), "m^2")

_DOMAIN = {
    "x": [(-7.0e6, 7.0e6)] * 3 + [(-300.0, 300.0)] * 3,
    "z": [(-7.0e6, 7.0e6)] * 3,
    "dt": [(0.0, 20.0)],
    "accel_sigma": [(0.1, 20.0)],
    "max_speed": [(10.0, 1000.0)],
    # covariances diagonally dominant (positive definite); only their upper triangles are read
    "P": [(100.0, 1.0e4) if i == j else (-10.0, 10.0) for j in range(6) for i in range(6)],
    "R": [(100.0, 1.0e4) if i == j else (-30.0, 30.0) for j in range(3) for i in range(3)],
}


def _function(name: str, inputs: list, outputs: list, names_in: list, names_out: list) -> ca.Function:
    """The CasADi function with dense outputs: the runtime reads every output as a dense column-major
    block, and an entry left structurally zero (an eye assigned into a block) would not be written."""
    return ca.Function(name, inputs, [ca.densify(o) for o in outputs], names_in, names_out)


def _start() -> ca.Function:
    z, R = ca.SX.sym("z", 3, 1), ca.SX.sym("R", 3, 3)
    max_speed = ca.SX.sym("max_speed")
    x = ca.vertcat(z, ca.SX.zeros(3, 1))
    P = ca.SX.zeros(6, 6)
    P[:3, :3] = mirror_upper(R)
    for i in range(3):
        P[3 + i, 3 + i] = max_speed**2
    return _function("cv_start", [z, R, max_speed], [x, P], ["z", "R", "max_speed"], ["x", "P"])


def _predict() -> ca.Function:
    x, P = ca.SX.sym("x", 6, 1), ca.SX.sym("P", 6, 6)
    dt, q = ca.SX.sym("dt"), ca.SX.sym("accel_sigma")
    F = ca.SX.eye(6)
    F[:3, 3:] = dt * ca.SX.eye(3)
    Q = ca.SX.zeros(6, 6)
    q2 = q * q
    Q[:3, :3] = q2 * dt**3 / 3 * ca.SX.eye(3)
    Q[:3, 3:] = q2 * dt**2 / 2 * ca.SX.eye(3)
    Q[3:, :3] = q2 * dt**2 / 2 * ca.SX.eye(3)
    Q[3:, 3:] = q2 * dt * ca.SX.eye(3)
    P_sym = mirror_upper(P)
    P_pred = mirror_upper(F @ P_sym @ F.T + Q)
    return _function(
        "cv_predict", [x, P, dt, q], [F @ x, P_pred], ["x", "P", "dt", "accel_sigma"], ["x_pred", "P_pred"]
    )


def _innovation():
    """Symbols (x-, P-, z, R), the innovation covariance's lower Cholesky factor L with the
    reciprocals of its diagonal, and the residual v = z - x-_p."""
    x, P = ca.SX.sym("x_pred", 6, 1), ca.SX.sym("P_pred", 6, 6)
    z, R = ca.SX.sym("z", 3, 1), ca.SX.sym("R", 3, 3)
    S = mirror_upper(P[:3, :3] + R)
    return x, P, z, R, *chol_lower(S), z - x[:3]


def _gate() -> ca.Function:
    x, P, z, R, L, inv, v = _innovation()
    y = forward_substitution(L, inv, v)
    d2 = ca.dot(y, y)
    logdet = 2 * (ca.log(L[0, 0]) + ca.log(L[1, 1]) + ca.log(L[2, 2]))  # a sum: no product to overflow
    return _function("cv_gate", [x, P, z, R], [d2, logdet], ["x_pred", "P_pred", "z", "R"], ["d2", "logdet"])


def _update() -> ca.Function:
    x, P, z, R, L, inv, v = _innovation()
    P_sym = mirror_upper(P)
    Kt = backward_substitution(L, inv, forward_substitution(L, inv, P_sym[:3, :]))  # K^T = S^-1 H P- (3x6)
    x_new = x + Kt.T @ v
    P_new = P_sym - Kt.T @ P_sym[:3, :]
    P_new = 0.5 * (P_new + P_new.T)
    return _function("cv_update", [x, P, z, R], [x_new, P_new], ["x_pred", "P_pred", "z", "R"], ["x", "P"])


def specs() -> list[CasadiSpec]:
    pred, plot = CasadiPort("x_pred", (6, 1), STATE.unit), CasadiPort("P_pred", (6, 6), COVARIANCE.unit)
    scalar = (1, 1)
    return [
        CasadiSpec(
            name="cv_start",
            doc="Constant-velocity track opened at a plot z (m, ECEF) of covariance R (m^2): x = [z, 0], "
            "P = diag(R, max_speed^2 I) (max_speed m/s).",
            inputs=(PLOT, PLOT_COVARIANCE, CasadiPort("max_speed", scalar, "m/s")),
            outputs=(STATE, COVARIANCE),
            builder=_start,
            domain={k: _DOMAIN[k] for k in ("z", "R", "max_speed")},
        ),
        CasadiSpec(
            name="cv_predict",
            doc="Constant-velocity prediction of state x (ECEF m, m/s) and covariance P by dt (s) with white "
            "acceleration noise of spectral density accel_sigma^2 (m^2/s^3): x- = F x, P- = F P F^T + Q.",
            inputs=(
                STATE,
                COVARIANCE,
                CasadiPort("dt", scalar, "s"),
                CasadiPort("accel_sigma", scalar, "m/s^2/sqrt(Hz)"),
            ),
            outputs=(pred, plot),
            builder=_predict,
            domain={k: _DOMAIN[k] for k in ("x", "P", "dt", "accel_sigma")},
        ),
        CasadiSpec(
            name="cv_gate",
            doc="A plot z (m, ECEF) of covariance R (m^2) against a constant-velocity prediction: squared "
            "Mahalanobis distance d2 of z - x-_p in S = P-_pp + R, and logdet = log det S (log m^6).",
            inputs=(pred, plot, PLOT, PLOT_COVARIANCE),
            outputs=(CasadiPort("d2", scalar, "1"), CasadiPort("logdet", scalar, "log m^6")),
            builder=_gate,
            domain={"x_pred": _DOMAIN["x"], "P_pred": _DOMAIN["P"], "z": _DOMAIN["z"], "R": _DOMAIN["R"]},
        ),
        CasadiSpec(
            name="cv_update",
            doc="Kalman update of a constant-velocity prediction (x-, P-) with a plot z (m, ECEF) of "
            "covariance R (m^2): K = P- H^T S^-1, x = x- + K (z - x-_p), P = sym(P- - K H P-).",
            inputs=(pred, plot, PLOT, PLOT_COVARIANCE),
            outputs=(STATE, COVARIANCE),
            builder=_update,
            domain={"x_pred": _DOMAIN["x"], "P_pred": _DOMAIN["P"], "z": _DOMAIN["z"], "R": _DOMAIN["R"]},
        ),
    ]
