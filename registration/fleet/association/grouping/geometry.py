"""Plot geometry for association: each plot's ECEF position corrected by a registration estimate,
the position's information matrix from the sensor noise, and how the position moves with the
registration states; and the global assignment (negative log-likelihood costs with a no-match
cost) that the association stages share.

Positions come from the generated ``fleet_plot2ecef``
(:func:`registration.fleet.corrected.corrected_positions`) and the Jacobians from the generated
``fleet_residual`` (J = d residual / d(p_ecef, att_err, bias)). A plot lacking a channel is
placed as :mod:`registration.fleet.batch.initial` places it (no range: :data:`ASSUMED_RANGE_M` along the
line of sight; no elevation: in the deck plane). Its position information is then
``J_p^T W J_p + I / UNCONSTRAINED_SIGMA_M^2`` (W = 1/sigma^2 on the measured channels): nearly no
information along the unmeasured direction, so comparisons there are left to the other sensors.

**Extended errors** (layout width 11: range gain, time bias, sensor position error east, north,
up; :mod:`registration.fleet.data.layout`). Positions then come from ``fleet_plot2ecef_ext`` and the
Jacobians from ``fleet_residual_ext`` (J = d residual / d(p_ecef, att_err, bias, gain, dt,
pos_err), 3x14), and a plot of a sensor with a time bias ``dt`` belongs to the time it was seen,
``t - dt`` (s; the reported time minus the estimated bias), with its platform's navigation at
that time (:meth:`FleetProblem.navigation_at`). The tracks and tracklets use that time, on the
common time axis of all sensors, so that the estimate lines the sensors' curves up.

The time bias's column of ``dp_dx``, and of ``J`` here, is the platform's motion only
(``fleet_residual_ext`` with the target velocity 0 and the navigation rates): a change of the estimate
moves the navigation the plot is placed from (position and attitude), while the target the plot measured
stays where it was. The target's own motion enters through the time stamp: the plot is re-stamped, which
moves a tracklet along its own curve, and that term is the curve's derivative, added per tracklet from its
fit (:mod:`registration.fleet.association.grouping.match`). Where a group's curve is compared with a
sensor's own channels (:mod:`registration.fleet.association.grouping.cost`), both motions are in the
generated column, the target's velocity coming from the group's curve.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from registration._generated import api as generated
from registration.core.linalg import aos, inv, soa
from registration.fleet.batch.initial import ASSUMED_RANGE_M
from registration.fleet.corrected import corrected_positions
from registration.fleet.data.problem import FleetProblem
from registration.fleet.data.tables import NAV_COLUMNS

__all__ = [
    "N_COEF",
    "N_LINE",
    "TIME_BIAS_SLOT",
    "FORBIDDEN",
    "UNCONSTRAINED_SIGMA_M",
    "PlotGeometry",
    "plot_geometry",
    "state_columns",
    "Assigner",
]

#: Standard deviation (m) given to a plot position along a direction its sensor does not measure.
UNCONSTRAINED_SIGMA_M = 1.0e5
#: A tracklet's ECEF position is a quadratic in time: N_COEF coefficients per axis, N_LINE in all.
N_COEF = 3
N_LINE = 3 * N_COEF
#: Slot of the time bias among a sensor's 11 states (:func:`state_columns` with the extended errors).
TIME_BIAS_SLOT = 7
#: Cost standing for "not allowed" in the assignment matrices.
FORBIDDEN = 1.0e12


@dataclass(frozen=True)
class PlotGeometry:
    """Per plot (N,): ``p_ecef`` (N, 3) m; ``info`` (N, 3, 3) 1/m^2 and ``cov`` (N, 3, 3) m^2 of the
    position from the sensor noise; ``dp_dx`` (N, 3, w) d p_ecef / d(the w states of
    :func:`state_columns`: att_err (3), bias (3) and, when extended, range gain, time bias,
    position error (3)) of the plot's platform and sensor (the time bias's column: the platform's
    motion only, module docstring); ``J`` (N, 3, 3 + w) of ``fleet_residual`` or
    ``fleet_residual_ext`` at the position; ``weight`` (N, 3) 1/sigma^2 of each channel (0 where
    not measured); ``plots`` (N,) the problem's plot index of each row (increasing); ``time`` (N,)
    s, the time the plot's target and platform were seen (the reported time minus the estimated
    time bias); ``nav`` (N, 6) the platform's navigation then (rad, m) and ``rate`` (N, 6) its rate
    (rad/s, m/s; 0 without time biases)."""

    p_ecef: np.ndarray
    info: np.ndarray
    cov: np.ndarray
    dp_dx: np.ndarray
    J: np.ndarray
    weight: np.ndarray
    plots: np.ndarray
    time: np.ndarray
    nav: np.ndarray
    rate: np.ndarray

    def rows(self, plots: np.ndarray) -> np.ndarray:
        """The rows of the problem's plots ``plots`` (each must be among :attr:`plots`)."""
        return np.searchsorted(self.plots, plots)


def state_columns(problem: FleetProblem, sel: np.ndarray | None = None) -> np.ndarray:
    """(M, w) state index of the attitude errors of the platform and the biases of the sensor of
    plots ``sel`` (default all) and, when the layout is extended (w = 11, else 6), the sensor's
    range gain, time bias and east, north, up position errors (the order of the generated
    functions' state inputs); -1 for a state the sensor does not have."""
    sensor = problem.sensor if sel is None else problem.sensor[sel]
    return problem.layout.sensor_states(sensor, problem.sensor_platform, absent=-1)


def _positions(
    problem: FleetProblem,
    xs: np.ndarray,
    cols: np.ndarray,
    sel: np.ndarray,
    nav: np.ndarray,
    rate: np.ndarray,
) -> tuple[np.ndarray, np.ndarray]:
    """(p_ecef (M, 3) m, J (M, 3, 3 + w)) of plots ``sel`` with states ``xs`` (n + 1,, 0 last)."""
    att, bias = xs[cols[:, :3]], xs[cols[:, 3:6]]
    mask, meas = problem.mask[sel], problem.meas[sel]
    lever = problem.sensor_lever[problem.sensor[sel]]
    r = np.where(mask[:, 0], meas[:, 0], ASSUMED_RANGE_M + bias[:, 0])
    e = np.where(mask[:, 2], meas[:, 2], bias[:, 2])
    p = corrected_positions(
        nav, cols, xs, lever, np.stack([r, meas[:, 1], e], axis=1)
    )  # cols -1 reads xs[-1] = 0
    ports = dict(zip(NAV_COLUMNS, nav.T))
    ports.update(att_err=att, bias=bias, lever_deck=lever, r=r, q=meas[:, 1], e=e)
    if cols.shape[1] == 6:
        J = generated.fleet_residual(p_ecef=p, **ports).J
        return p, np.asarray(J).reshape(-1, 3, 9)
    gain, pos_err = xs[cols[:, 6]], xs[cols[:, 8:11]]
    # the target velocity 0: the time bias's column is the platform's motion (module docstring)
    if cols.shape[1] > 11:  # and the eccentricity
        J = generated.fleet_residual_ecc(
            p_ecef=p,
            v_ecef=np.zeros(3),
            nav_rate=rate,
            gain=gain,
            dt=0.0,
            pos_err=pos_err,
            ecc=xs[cols[:, 11:13]],
            **ports,
        ).J
        return p, np.asarray(J).reshape(-1, 3, 16)
    J = generated.fleet_residual_ext(
        p_ecef=p, v_ecef=np.zeros(3), nav_rate=rate, gain=gain, dt=0.0, pos_err=pos_err, **ports
    ).J
    return p, np.asarray(J).reshape(-1, 3, 14)


def plot_geometry(problem: FleetProblem, x: np.ndarray, sel: np.ndarray | None = None) -> PlotGeometry:
    """The geometry of the problem's plots ``sel`` (increasing indices; default all) under the
    states ``x`` (n,) rad/m (and 1, s with the extended errors)."""
    sel = np.arange(problem.n_plots) if sel is None else np.asarray(sel)
    xs = np.append(np.asarray(x, dtype=np.float64), 0.0)  # index -1 (absent channel) reads 0
    cols = state_columns(problem, sel)
    t, nav, rate = problem.seen(x, sel)
    p, J = _positions(problem, xs, cols, sel, nav, rate)
    mask = problem.mask[sel]
    sigma = np.nan_to_num(problem.sensor_sigma[problem.sensor[sel]], nan=np.inf)
    weight = np.where(mask, 1.0 / sigma**2, 0.0)
    Jp, Jx = J[:, :, :3], J[:, :, 3:]
    JtW = np.swapaxes(Jp, 1, 2) * weight[:, None, :]
    info = JtW @ Jp + np.eye(3) / UNCONSTRAINED_SIGMA_M**2
    try:  # by the adjugate over the whole batch: numpy's inv pays a LAPACK call per 3x3 matrix
        cov = aos(inv(soa(info)))
    except ValueError:  # a matrix singular to the adjugate's test: LAPACK's inverse decides
        cov = np.linalg.inv(info)
    dp_dx = -cov @ (JtW @ Jx)
    return PlotGeometry(p, info, cov, dp_dx, J, weight, sel, t, nav, rate)


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
        from scipy.optimize import linear_sum_assignment  # scipy.optimize: a second to import

        t0 = time.perf_counter()
        rows, cols = linear_sum_assignment(full)
        self.seconds += time.perf_counter() - t0
        self.calls += 1
        real = (cols < n_cols) & (full[rows, cols] < FORBIDDEN)
        out[rows[real]] = cols[real]
        return out
