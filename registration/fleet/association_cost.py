"""Costs of pairing tracklets with groups (:mod:`registration.fleet.association_match`): the
squared Mahalanobis distance and the log-determinant of its covariance, so that the negative
log-likelihood is ``0.5 (d2 + logdet)`` up to a constant.

* :func:`line_cost`, for a sensor that measures range, bearing and elevation: the difference of
  the two ECEF lines (a, b), covariance ``C_b + C_g + (G_b - G_g) P (G_b - G_g)^T``.
* :func:`measurement_cost`, for a sensor lacking a channel (a 2-D radar, a passive sensor), whose
  plots have no ECEF position of their own (a 2-D radar's plot put in its deck plane is off by
  about ``r e^2 / 2`` horizontally, 400 m at 30 km and 10 deg): the residuals of the tracklet's
  first, middle and last plots against the group's line, in the sensor's own channels, through
  the generated ``fleet_residual`` (residual r, J = d r / d(p_ecef, att_err, bias)), covariance
  ``A C_g A^T + R + D P D^T`` with A = J_p [I, tau I] and D = A G_g + J_x (the sensor's columns).
  Channels not measured count neither in the distance nor in the determinant.
"""

from __future__ import annotations

import numpy as np

from registration import _codegen
from registration.fleet.association_geometry import N_COEF, N_LINE, state_columns
from registration.fleet.problem import FleetProblem

__all__ = ["line_cost", "measurement_cost"]


def _mahalanobis(d: np.ndarray, S: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    d2 = np.einsum("...i,...i->...", d, np.linalg.solve(S, d[..., None])[..., 0])
    return d2, np.linalg.slogdet(S)[1]


def line_cost(tl, b: np.ndarray, line: np.ndarray, cov: np.ndarray, G: np.ndarray, P: np.ndarray):
    """(d2, logdet), each (K,), of K pairs: tracklets ``b`` (K,) against group curves ``line`` (K, 9)
    with covariance ``cov`` (K, 9, 9) and sensitivity ``G`` (K, 9, n); P (n, n) the states' covariance."""
    d = tl.line[b] - line
    dG = tl.G[b] - G
    S = tl.cov[b] + cov + dG @ P @ np.swapaxes(dG, -1, -2)
    return _mahalanobis(d, S)


def measurement_cost(problem: FleetProblem, x: np.ndarray, tl, b: np.ndarray, line: np.ndarray, cov: np.ndarray,
                     G: np.ndarray, P: np.ndarray):
    """(d2, logdet), each (K,), of K pairs as :func:`line_cost`, in the channels of the tracklets'
    sensors (module docstring), under the states ``x`` (n,)."""
    k_pairs, n = b.size, P.shape[0]
    plot = tl.rep[b].reshape(-1)
    tau = tl.rep_tau[b].reshape(-1)
    grp = np.repeat(np.arange(k_pairs), 3)
    basis = np.concatenate([(tau**k)[:, None, None] * np.eye(3) for k in range(N_COEF)], axis=2)  # (M, 3, L)
    p = (basis @ line[grp][..., None])[..., 0]
    xs = np.append(np.asarray(x, dtype=np.float64), 0.0)
    cols = state_columns(problem, plot)
    meas, mask = problem.meas[plot], problem.mask[plot]
    res, J = _codegen.get("fleet_residual")(p, *problem.nav[plot].T, xs[cols[:, :3]], xs[cols[:, 3:]],
                                           problem.sensor_lever[problem.sensor[plot]], *meas.T)[:2]
    res, J = np.asarray(res).reshape(-1, 3), np.asarray(J).reshape(-1, 3, 9)
    res, J = np.where(mask, res, 0.0), np.where(mask[..., None], J, 0.0)
    A = J[:, :, :3] @ basis  # (M, 3, L)
    Dx = np.zeros((tau.size, 3, n + 1))
    rows = np.arange(tau.size)
    for k in range(6):
        Dx[rows, :, cols[:, k]] += J[:, :, 3 + k]
    D = A @ G[grp] + Dx[:, :, :n]  # (M, 3, n)
    sigma = np.nan_to_num(problem.sensor_sigma[problem.sensor[plot]], nan=1.0)
    A, D, r = A.reshape(k_pairs, 9, N_LINE), D.reshape(k_pairs, 9, n), res.reshape(k_pairs, 9)
    S = A @ cov @ np.swapaxes(A, -1, -2) + D @ P @ np.swapaxes(D, -1, -2)
    S = S + np.eye(9) * (sigma**2).reshape(k_pairs, 9)[..., None]
    return _mahalanobis(r, S)
