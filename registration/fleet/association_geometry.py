"""Plot geometry for association: each plot's ECEF position corrected by a registration estimate,
the position's information matrix from the sensor noise, and how the position moves with the
registration states; and the global assignment (negative log-likelihood costs with a no-match
cost) that the association stages share.

Positions come from the generated ``fleet_plot2ecef`` and the Jacobians from the generated
``fleet_residual`` (J = d residual / d(p_ecef, att_err, bias)). A plot lacking a channel is
placed as :mod:`registration.fleet.initial` places it (no range: :data:`ASSUMED_RANGE_M` along the
line of sight; no elevation: in the deck plane). Its position information is then
``J_p^T W J_p + I / UNCONSTRAINED_SIGMA_M^2`` (W = 1/sigma^2 on the measured channels): nearly no
information along the unmeasured direction, so comparisons there are left to the other sensors.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
from scipy.optimize import linear_sum_assignment

from registration import _codegen
from registration.fleet.initial import ASSUMED_RANGE_M
from registration.fleet.problem import FleetProblem

__all__ = ["N_COEF", "N_LINE", "UNCONSTRAINED_SIGMA_M", "PlotGeometry", "plot_geometry", "state_columns", "Assigner"]

#: Standard deviation (m) given to a plot position along a direction its sensor does not measure.
UNCONSTRAINED_SIGMA_M = 1.0e5
#: A tracklet's ECEF position is a quadratic in time: N_COEF coefficients per axis, N_LINE in all.
N_COEF = 3
N_LINE = 3 * N_COEF
#: Cost standing for "not allowed" in the assignment matrices.
FORBIDDEN = 1.0e12


@dataclass(frozen=True)
class PlotGeometry:
    """Per plot (N,): ``p_ecef`` (N, 3) m; ``info`` (N, 3, 3) 1/m^2 and ``cov`` (N, 3, 3) m^2 of the
    position from the sensor noise; ``dp_dx`` (N, 3, 6) d p_ecef / d(att_err (3), bias (3)) of the
    plot's platform and sensor; ``J`` (N, 3, 9) of ``fleet_residual`` at the position;
    ``weight`` (N, 3) 1/sigma^2 of each channel (0 where not measured); ``plots`` (N,) the
    problem's plot index of each row (increasing)."""

    p_ecef: np.ndarray
    info: np.ndarray
    cov: np.ndarray
    dp_dx: np.ndarray
    J: np.ndarray
    weight: np.ndarray
    plots: np.ndarray

    def rows(self, plots: np.ndarray) -> np.ndarray:
        """The rows of the problem's plots ``plots`` (each must be among :attr:`plots`)."""
        return np.searchsorted(self.plots, plots)


def state_columns(problem: FleetProblem, sel: np.ndarray | None = None) -> np.ndarray:
    """(M, 6) state index of the attitude errors of the platform and the biases of the sensor of
    plots ``sel`` (default all; -1 for a channel the sensor does not measure)."""
    layout = problem.layout
    sensor = problem.sensor if sel is None else problem.sensor[sel]
    return np.concatenate([layout.att_index[problem.sensor_platform[sensor]], layout.bias_index[sensor]], axis=1)


def plot_geometry(problem: FleetProblem, x: np.ndarray, sel: np.ndarray | None = None) -> PlotGeometry:
    """The geometry of the problem's plots ``sel`` (increasing indices; default all) under the
    states ``x`` (n,) rad/m."""
    sel = np.arange(problem.n_plots) if sel is None else np.asarray(sel)
    xs = np.append(np.asarray(x, dtype=np.float64), 0.0)  # index -1 (absent channel) reads 0
    cols = state_columns(problem, sel)
    att, bias = xs[cols[:, :3]], xs[cols[:, 3:]]
    mask, meas, nav = problem.mask[sel], problem.meas[sel], problem.nav[sel]
    lever = problem.sensor_lever[problem.sensor[sel]]
    r = np.where(mask[:, 0], meas[:, 0], ASSUMED_RANGE_M + bias[:, 0])
    e = np.where(mask[:, 2], meas[:, 2], bias[:, 2])
    p = np.asarray(_codegen.get("fleet_plot2ecef")(*nav.T, att, bias, lever, r, meas[:, 1], e)[0]).reshape(-1, 3)
    J = np.asarray(_codegen.get("fleet_residual")(p, *nav.T, att, bias, lever, r, meas[:, 1], e)[1]).reshape(-1, 3, 9)
    sigma = np.nan_to_num(problem.sensor_sigma[problem.sensor[sel]], nan=np.inf)
    weight = np.where(mask, 1.0 / sigma**2, 0.0)
    Jp, Jx = J[:, :, :3], J[:, :, 3:]
    JtW = np.swapaxes(Jp, 1, 2) * weight[:, None, :]
    info = JtW @ Jp + np.eye(3) / UNCONSTRAINED_SIGMA_M**2
    cov = np.linalg.inv(info)
    dp_dx = -cov @ (JtW @ Jx)
    return PlotGeometry(p, info, cov, dp_dx, J, weight, sel)


class Assigner:
    """Global assignments with :func:`scipy.optimize.linear_sum_assignment`, timed.

    :meth:`assign` takes ``cost`` (R, C): the negative log-likelihood of pairing row r with
    column c (``inf`` where the pair is outside the gate) and ``no_match`` (R,): the cost of
    leaving row r unpaired. Columns may stay unpaired at no cost.
    """

    def __init__(self):
        self.seconds = 0.0
        self.calls = 0

    def assign(self, cost: np.ndarray, no_match: np.ndarray) -> np.ndarray:
        """(R,) the column paired with each row, -1 for rows left unpaired."""
        n_rows, n_cols = cost.shape
        out = np.full(n_rows, -1, dtype=np.int64)
        if n_rows == 0 or n_cols == 0:
            return out
        full = np.full((n_rows, n_cols + n_rows), FORBIDDEN)
        full[:, :n_cols] = np.where(np.isfinite(cost), cost, FORBIDDEN)
        full[np.arange(n_rows), n_cols + np.arange(n_rows)] = no_match
        t0 = time.perf_counter()
        rows, cols = linear_sum_assignment(full)
        self.seconds += time.perf_counter() - t0
        self.calls += 1
        real = (cols < n_cols) & (full[rows, cols] < FORBIDDEN)
        out[rows[real]] = cols[real]
        return out
