"""The whole registration Kalman step (Wang et al. 2011, eqs. (18)-(23)) composed in CasADi.

Built from the sympy-derived pseudo-measurement (derive/pseudo_measurement.py), so the step
has no second copy of the model. One step, for state x (12) = [dC_A, dphi_A, dtheta_A, dr_A,
dq_A, de_A, dC_B, ..., de_B] (rad and m), covariance P (12x12), random-walk process noise Q:

* predict: ``x- = x``, ``P- = P + Q``;
* linearisation ``paper``: Z, H, M at the raw measurements, innovation ``nu = Z - H x-``;
  ``relinearized``: Z, H, M at the measurements corrected by x- (attitude and plot minus the
  estimated errors), innovation ``nu = Z(corrected)`` (an extended Kalman filter step);
  ``fitted``: H, M at the fitted plots t: the maximum a posteriori estimate of the noise-free
  plots given this row and the prior N(x-, P-) of the registration errors. With Z, H, M, R
  at the corrected plots c, ``S = H P- H^T + R`` and ``v = R0 M^T S^-1 Z(c)`` (the MAP noise
  of the linearised model ``Z(c) = H (x - x-) + M v``), ``t = c - v`` (plots only; the
  attitude is not noisy). The noise-free constraint ``X_A(c_A - v_A) - X_B(c_B - v_B) = 0``
  is linearised there: ``nu = Z(t) + M(t) (c - t)``, ``H = H(t)``, ``R = R(t)``.
  Once P is small, S ~ R and t is the plot pair of the fused target (the two radars' positions
  weighted by their covariances), which carries only the fused position's small error: H no
  longer shares the angle noise of the innovation. That correlation is an errors-in-variables
  bias of order sigma^2 which the weakly determined range biases amplify to about 1 sigma at
  the paper's 0.5 deg noise (docs/background/online.md). While P is large, S >> R and t stays near c
  (the ``relinearized`` point): a large misregistration is not mistaken for noise;
* ``R = M R0 M^T``, ``S = H P- H^T + R``, gain by a linear solve (no explicit inverse),
  ``K = P- H^T S^-1``; Joseph-form covariance update, symmetric by construction (upper triangle
  mirrored), which keeps P positive definite; normalised innovation squared ``nis = nu^T S^-1 nu``;
  the ``_carlson`` functions compute the same P+ as ``C+ C+^T`` from the upper Cholesky factor
  C of P- by Carlson's triangular square-root update, one whitened measurement row at a time
  (:func:`carlson_update`): positive definite by construction, x, nu, S, nis unchanged;
* ``info`` accumulates the Fisher information ``H^T R^-1 H`` for the observability report.

The first three inputs are carried from the first three outputs of the previous step
(``mapaccum`` convention), so a whole run is one compiled loop.
"""

import casadi as ca

from .emit import to_casadi_function
from .pseudo_measurement import PAIR_DOMAIN
from .pseudo_measurement import specs as pair_specs
from .spec import CasadiPort, CasadiSpec
from .triangular import chol_upper, mirror_upper, tree_sum, whitened

LINEARIZATIONS = ("paper", "relinearized", "fitted")
#: Covariance updates: ``joseph`` (the functions without a suffix) and ``carlson`` (``_carlson``).
COVARIANCE_UPDATES = ("joseph", "carlson")
N_STATE = 12

INPUTS = (
    CasadiPort("x", (N_STATE, 1), "rad, m"),
    CasadiPort("P", (N_STATE, N_STATE), "rad^2, m^2"),
    CasadiPort("info", (N_STATE, N_STATE), "1/rad^2, 1/m^2"),
    CasadiPort("Q", (N_STATE, N_STATE), "rad^2, m^2 per step"),
    CasadiPort("row", (18, 1), "nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)"),
    CasadiPort("sigma0", (6, 1), "m, rad, rad, m, rad, rad"),
)
OUTPUTS = (
    CasadiPort("x_new", (N_STATE, 1), "rad, m"),
    CasadiPort("P_new", (N_STATE, N_STATE), "rad^2, m^2"),
    CasadiPort("info_new", (N_STATE, N_STATE), "1/rad^2, 1/m^2"),
    CasadiPort("nu", (3, 1), "m"),
    CasadiPort("S", (3, 3), "m^2"),
    CasadiPort("nis", (1, 1), "1"),
)


def _pair_function(variant: str) -> ca.Function:
    spec = next(s for s in pair_specs() if s.name == f"pseudo_measurement_{variant}")
    return to_casadi_function(spec)


def _pair_at(pair: ca.Function, row: ca.SX, sigma0: ca.SX):
    """The pair model at an 18-row (nav_a, att_a, meas_a, nav_b, att_b, meas_b)."""
    return pair(row[0:3], row[3:6], row[6:9], row[9:12], row[12:15], row[15:18], sigma0)


def _corrected(row: ca.SX, x: ca.SX) -> ca.SX:
    """Attitudes and plots of the row minus the estimated errors x (navigation untouched)."""
    return row - ca.vertcat(ca.SX.zeros(3), x[0:6], ca.SX.zeros(3), x[6:12])


def _add_information(info: ca.SX, H: ca.SX, R: ca.SX) -> ca.SX:
    """``info + H^T R^-1 H``, symmetric by construction."""
    return mirror_upper(info + H.T @ ca.solve(R, H))


def _carlson_scalar(C: ca.SX, h: ca.SX) -> ca.SX:
    """Carlson's triangular square-root update (Carlson 1973) for one scalar measurement of unit
    variance: upper-triangular C (P = C C^T) to C+ with ``C+ C+^T = P - P h h^T P / (h^T P h + 1)``.
    Each diagonal entry is multiplied by ``sqrt(alpha_{j-1} / alpha_j)`` in (0, 1], alpha_j >= 1:
    C+ keeps a positive diagonal, so P+ is positive definite by construction."""
    n = C.shape[0]
    C = ca.SX(C)
    alpha = ca.SX(1.0)
    w = [ca.SX(0)] * n
    for j in range(n):
        sigma = tree_sum(C[i, j] * h[i] for i in range(j + 1))
        beta = alpha
        alpha = beta + sigma**2
        inv_gamma = ca.sqrt(1 / (alpha * beta))  # not 1/sqrt: kept a product (see chol_upper)
        eta, zeta = beta * inv_gamma, sigma * inv_gamma
        for i in range(j + 1):
            tau = C[i, j]
            C[i, j] = eta * tau - zeta * w[i]
            w[i] = w[i] + tau * sigma
    return C


def carlson_update(P_pred: ca.SX, H: ca.SX, R: ca.SX) -> ca.SX:
    """``P+ = P- - P- H^T S^-1 H P-`` (S = H P- H^T + R) as ``C+ C+^T``: the upper Cholesky factor
    C of P-, the rows of H whitened by the lower Cholesky factor of R (``L^-1 H``, unit noise),
    then one Carlson update per whitened row. Symmetric by construction (upper triangle of the
    product, mirrored) and positive definite whenever C+ has a positive diagonal (always, for
    a finite P- whose factor exists)."""
    C, _ = chol_upper(P_pred)
    Hw = whitened(R, H)
    for k in range(R.shape[0]):
        C = _carlson_scalar(C, Hw[k, :].T)
    n = C.shape[0]
    P_new = ca.SX.zeros(n, n)
    for i in range(n):
        for j in range(i, n):
            P_new[i, j] = tree_sum(C[i, k] * C[j, k] for k in range(j, n))
            P_new[j, i] = P_new[i, j]
    return P_new


def _fitted_linearisation(pair: ca.Function, c: ca.SX, P_pred: ca.SX, sigma0: ca.SX):
    """Innovation, H and R at the MAP plots t = c - R0 M^T S^-1 Z(c) (module docstring)."""
    Z, H, M, R, _, _ = _pair_at(pair, c, sigma0)
    S = H @ P_pred @ H.T + R
    v = ca.diag(sigma0**2) @ M.T @ ca.solve(0.5 * (S + S.T), Z)
    t = c - ca.vertcat(ca.SX.zeros(6), v[0:3], ca.SX.zeros(6), v[3:6])  # plots only
    Z, H, M, R, _, _ = _pair_at(pair, t, sigma0)
    return Z + M @ v, H, R


def _build(variant: str, linearization: str, update: str = "joseph"):
    suffix = "" if update == "joseph" else f"_{update}"

    def build() -> ca.Function:
        pair = _pair_function(variant)
        x = ca.SX.sym("x", N_STATE)
        P = ca.SX.sym("P", N_STATE, N_STATE)
        info = ca.SX.sym("info", N_STATE, N_STATE)
        Q = ca.SX.sym("Q", N_STATE, N_STATE)
        row = ca.SX.sym("row", 18)
        sigma0 = ca.SX.sym("sigma0", 6)

        P_pred = P + Q
        corrected = _corrected(row, x)
        if linearization == "fitted":
            nu, H, R = _fitted_linearisation(pair, corrected, P_pred, sigma0)
        else:
            at = row if linearization == "paper" else corrected
            Z, H, M, R, _, _ = _pair_at(pair, at, sigma0)
            nu = Z - H @ x if linearization == "paper" else Z
        S = H @ P_pred @ H.T + R
        S = 0.5 * (S + S.T)
        K = ca.solve(S, H @ P_pred).T
        x_new = x + K @ nu
        if update == "joseph":
            IKH = ca.SX.eye(N_STATE) - K @ H
            P_new = mirror_upper(IKH @ P_pred @ IKH.T + K @ R @ K.T)
        else:
            P_new = carlson_update(P_pred, H, R)
        info_new = _add_information(info, H, R)
        nis = nu.T @ ca.solve(S, nu)
        return ca.Function(
            f"kalman_step_{linearization}_{variant}{suffix}",
            [x, P, info, Q, row, sigma0],
            [x_new, P_new, info_new, nu, S, nis],
            [p.name for p in INPUTS],
            [p.name for p in OUTPUTS],
            {"cse": True},
        )

    return build


def _domain():
    row = PAIR_DOMAIN["nav_a"] + PAIR_DOMAIN["att_a"] + [(1.0e4, 1.0e5), (-3.0, 3.0), (0.0, 0.2)]
    row = row + row
    eye = [(1.0, 1.0) if i == j else (0.0, 0.0) for j in range(N_STATE) for i in range(N_STATE)]
    return {
        "x": [(-0.01, 0.01)] * 3
        + [(-1000.0, 1000.0)]
        + [(-0.01, 0.01)] * 5
        + [(-1000.0, 1000.0)]
        + [(-0.01, 0.01)] * 2,
        "P": eye,
        "info": eye,
        "Q": [(0.0, 0.0)] * (N_STATE * N_STATE),
        "row": row,
        "sigma0": PAIR_DOMAIN["sigma0"],
    }


INFO_INPUTS = (
    CasadiPort("info", (N_STATE, N_STATE), "1/rad^2, 1/m^2"),
    CasadiPort("x", (N_STATE, 1), "rad, m"),
    CasadiPort("row", (18, 1), "nav_a, att_a, meas_a, nav_b, att_b, meas_b (rad, m)"),
    CasadiPort("sigma0", (6, 1), "m, rad, rad, m, rad, rad"),
)
INFO_OUTPUTS = (CasadiPort("info_new", (N_STATE, N_STATE), "1/rad^2, 1/m^2"),)


def _build_information(variant: str):
    """``info + H^T R^-1 H`` with H, R at the row corrected by a fixed estimate x: the
    information along the estimated true geometry, for the observability report. Carried like
    the Kalman step, so the sum over a whole run is one compiled loop."""

    def build() -> ca.Function:
        pair = _pair_function(variant)
        info = ca.SX.sym("info", N_STATE, N_STATE)
        x = ca.SX.sym("x", N_STATE)
        row = ca.SX.sym("row", 18)
        sigma0 = ca.SX.sym("sigma0", 6)
        _, H, _, R, _, _ = _pair_at(pair, _corrected(row, x), sigma0)
        info_new = _add_information(info, H, R)
        return ca.Function(
            f"information_step_{variant}",
            [info, x, row, sigma0],
            [info_new],
            [p.name for p in INFO_INPUTS],
            [p.name for p in INFO_OUTPUTS],
            {"cse": True},
        )

    return build


def specs() -> list[CasadiSpec]:
    out = []
    for variant in ("standard", "paper"):
        domain = _domain()
        out.append(
            CasadiSpec(
                name=f"information_step_{variant}",
                doc=(
                    f"Fisher information accumulation, T variant '{variant}': info_new = info + H^T R^-1 "
                    "H, H and R at the row corrected by the fixed estimate x. Input info carried from "
                    "output info_new."
                ),
                inputs=INFO_INPUTS,
                outputs=INFO_OUTPUTS,
                builder=_build_information(variant),
                domain={
                    "info": domain["info"],
                    "x": domain["x"],
                    "row": domain["row"],
                    "sigma0": domain["sigma0"],
                },
            )
        )
    for update in COVARIANCE_UPDATES:
        suffix = "" if update == "joseph" else f"_{update}"
        for variant in ("standard", "paper"):
            for lin in LINEARIZATIONS:
                out.append(
                    CasadiSpec(
                        name=f"kalman_step_{lin}_{variant}{suffix}",
                        doc=(
                            "One registration Kalman step (eqs. 18-23), "
                            f"linearisation '{lin}', T variant '{variant}'"
                            + ("" if update == "joseph" else f", covariance update '{update}'")
                            + ". "
                            "Inputs x, P, info carried from outputs x_new, P_new, info_new "
                            "of the previous step."
                        ),
                        inputs=INPUTS,
                        outputs=OUTPUTS,
                        builder=_build(variant, lin, update),
                        domain=_domain(),
                    )
                )
    return out
