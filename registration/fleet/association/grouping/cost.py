"""Costs of pairing tracklets with groups (:mod:`registration.fleet.association.grouping.match`): the
squared Mahalanobis distance and the log-determinant of its covariance, so that the negative
log-likelihood is ``0.5 (d2 + logdet)`` up to a constant.

* :func:`line_cost`, for a sensor that measures range, bearing and elevation: the difference of
  the two ECEF lines (a, b), covariance ``C_b + C_g + (G_b - G_g) P (G_b - G_g)^T``.
* :func:`measurement_cost`, for a sensor lacking a channel (a 2-D radar, a passive sensor), whose
  plots have no ECEF position of their own (a 2-D radar's plot put in its deck plane is off by
  about ``r e^2 / 2`` horizontally, 400 m at 30 km and 10 deg): the residuals of the tracklet's
  first, middle and last plots against the group's line, in the sensor's own channels, through
  the generated ``fleet_residual`` (residual r, J = d r / d(p_ecef, att_err, bias)), covariance
  ``A C_g A^T + R + D P D^T`` with A = J_p [I, tau I, tau^2 I] and D = A G_g + J_x (the sensor's
  columns). Channels not measured count neither in the distance nor in the determinant.

A sensor's tracklets depend on its w states (w = 6: its platform's attitude errors and its
biases; w = 11 with the extended errors: also its range gain, time bias and position error, the
order of :func:`~registration.fleet.association.grouping.geometry.state_columns`). With the extended
errors :func:`measurement_cost` uses ``fleet_residual_ext``, at the time each plot was seen
(reported time minus the estimated time bias), with the platform's navigation and its rate then
and the group curve's velocity there; its time-bias column then holds the target's and the
platform's motion.
"""

from __future__ import annotations

import numpy as np

from registration._generated import api as generated
from registration.core.linalg import forward_solve
from registration.fleet.association.grouping.geometry import N_COEF, N_LINE
from registration.fleet.data.problem import FleetProblem
from registration.fleet.data.tables import NAV_COLUMNS

__all__ = ["group_covariances", "joint_covariance", "line_cost", "measurement_cost"]


def _mahalanobis(d: np.ndarray, S: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(d2, logdet) of differences d (K, m) with covariances S (K, m, m), from one Cholesky factor
    per pair (LU-based ``solve`` and ``slogdet`` for a batch that is not numerically positive definite)."""
    try:
        L = np.linalg.cholesky(S)
    except np.linalg.LinAlgError:
        return np.einsum("...i,...i->...", d, np.linalg.solve(S, d[..., None])[..., 0]), np.linalg.slogdet(S)[
            1
        ]
    y = forward_solve(L, d)
    diag = np.diagonal(L, axis1=1, axis2=2)
    return np.einsum("ki,ki->k", y, y), 2.0 * np.log(diag).sum(axis=1)


def group_covariances(
    cov: np.ndarray, G: np.ndarray, P: np.ndarray, cols: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per group curve (covariance ``cov`` (G, 9, 9), sensitivity ``G`` (G, 9, n)) under the states'
    covariance P (n, n), for the tracklets of one sensor whose platform's and own states are
    ``cols`` (w,; -1: a state the sensor does not have): the curve's covariance with the
    states' uncertainty ``cov + G P G^T`` (G, 9, 9), its covariance with the w states (G, 9, w),
    and the w states' covariance (w, w) (0 in the rows and columns of index -1)."""
    n = P.shape[0]
    GP = np.zeros((G.shape[0], N_LINE, n + 1))
    GP[:, :, :n] = G @ P
    P_ext = np.zeros((n + 1, n + 1))
    P_ext[:n, :n] = P
    return cov + GP[:, :, :n] @ np.swapaxes(G, 1, 2), GP[:, :, cols], P_ext[np.ix_(cols, cols)]


def joint_covariance(groups: tuple[np.ndarray, np.ndarray, np.ndarray], g: np.ndarray) -> np.ndarray:
    """(K, 9 + w, 9 + w) covariance of (group curve ``g`` (K,), the w states of the tracklets'
    sensor) per pair, from :func:`group_covariances` ``groups``."""
    curve, GP, P_s = groups
    size = N_LINE + P_s.shape[0]
    out = np.empty((g.size, size, size))
    out[:, :N_LINE, :N_LINE] = curve[g]
    cross = GP[g]
    out[:, :N_LINE, N_LINE:] = cross
    out[:, N_LINE:, :N_LINE] = np.swapaxes(cross, 1, 2)
    out[:, N_LINE:, N_LINE:] = P_s
    return out


def line_cost(tl, b: np.ndarray, G_b: np.ndarray, line: np.ndarray, joint: np.ndarray):
    """(d2, logdet), each (K,), of K pairs: tracklets ``b`` (K,) with sensitivity ``G_b`` (K, 9, w) to
    their sensor's w states (their only nonzero columns), against group curves ``line`` (K, 9);
    ``joint`` (K, 9 + w, 9 + w) from :func:`joint_covariance`. Covariance
    ``C_b + C_g + (G_b - G_g) P (G_b - G_g)^T``, written as ``C_b + W joint W^T`` with W = [I, -G_b]."""
    d = tl.line[b] - line
    W = np.concatenate([np.broadcast_to(np.eye(N_LINE), (b.size, N_LINE, N_LINE)), -G_b], axis=2)
    S = tl.cov[b] + W @ joint @ np.swapaxes(W, 1, 2)
    return _mahalanobis(d, S)


def measurement_cost(
    problem: FleetProblem,
    x: np.ndarray,
    tl,
    b: np.ndarray,
    cols: np.ndarray,
    line: np.ndarray,
    joint: np.ndarray,
):
    """(d2, logdet), each (K,), of K pairs as :func:`line_cost`, in the channels of the tracklets'
    sensor (module docstring; ``cols`` (w,) its platform's and its own state columns, -1 where
    it has none), under the states ``x`` (n,). ``A C_g A^T + R + D P D^T`` is written as
    ``W joint W^T + R`` with W = [A, J_x] (J_x: the sensor's w columns)."""
    k_pairs = b.size
    plot = tl.rep[b].reshape(-1)
    tau = tl.rep_tau[b].reshape(-1)
    grp = np.repeat(np.arange(k_pairs), 3)
    basis = np.concatenate([(tau**k)[:, None, None] * np.eye(3) for k in range(N_COEF)], axis=2)  # (M, 3, L)
    p = (basis @ line[grp][..., None])[..., 0]
    xs = np.append(np.asarray(x, dtype=np.float64), 0.0)
    meas, mask = problem.meas[plot], problem.mask[plot]
    att, bias = (np.tile(xs[c], (plot.size, 1)) for c in (cols[:3], cols[3:6]))
    lever = problem.sensor_lever[problem.sensor[plot]]
    ports = dict(att_err=att, bias=bias, lever_deck=lever, r=meas[:, 0], q=meas[:, 1], e=meas[:, 2])
    if cols.size == 6:
        fit = generated.fleet_residual(p_ecef=p, **dict(zip(NAV_COLUMNS, problem.nav[plot].T)), **ports)
        res, J = fit.residual, fit.J
    else:  # at the time seen: the group curve's velocity there (m/s), the platform's navigation and rate
        rate_basis = (
            np.concatenate(
                [(k * tau ** max(k - 1, 0))[:, None, None] * np.eye(3) for k in range(N_COEF)], axis=2
            )
            / tl.half_width
        )
        v = (rate_basis @ line[grp][..., None])[..., 0]
        nav, rate = tl.rep_nav[b].reshape(-1, 6), tl.rep_rate[b].reshape(-1, 6)
        gain, pos_err = xs[cols[6]], xs[cols[8:11]]  # range gain, position error (ENU); the time bias is in t
        nav_ports = dict(zip(NAV_COLUMNS, nav.T))
        if cols.size > 11:  # and the eccentricity
            fit_ecc = generated.fleet_residual_ecc(
                p_ecef=p,
                v_ecef=v,
                **nav_ports,
                nav_rate=rate,
                gain=gain,
                dt=0.0,
                pos_err=pos_err,
                ecc=np.tile(xs[cols[11:13]], (plot.size, 1)),
                **ports,
            )
            res, J = fit_ecc.residual, fit_ecc.J
        else:
            fit_ext = generated.fleet_residual_ext(
                p_ecef=p, v_ecef=v, **nav_ports, nav_rate=rate, gain=gain, dt=0.0, pos_err=pos_err, **ports
            )
            res, J = fit_ext.residual, fit_ext.J
    res, J = np.asarray(res).reshape(-1, 3), np.asarray(J).reshape(-1, 3, 3 + cols.size)
    res, J = np.where(mask, res, 0.0), np.where(mask[..., None], J, 0.0)
    W = np.concatenate([J[:, :, :3] @ basis, J[:, :, 3:]], axis=2).reshape(k_pairs, 9, N_LINE + cols.size)
    sigma = np.nan_to_num(problem.sensor_sigma[problem.sensor[plot]], nan=1.0)
    S = W @ joint @ np.swapaxes(W, 1, 2) + np.eye(9) * (sigma**2).reshape(k_pairs, 9)[..., None]
    return _mahalanobis(res.reshape(k_pairs, 9), S)
