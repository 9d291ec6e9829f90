"""Plot positions corrected by a registration estimate: the one place the runtime turns plots into
ECEF positions (generated ``fleet_plot2ecef``, or ``fleet_plot2ecef_ext`` with the extended
errors, ``fleet_plot2ecef_ecc`` with an azimuth eccentricity), shared by the solver's starting
values, the association and the map of the plots.

With a time bias ``dt`` the plot was seen at ``t - dt``: the caller passes the navigation of the
platform at that time (:meth:`registration.fleet.data.problem.FleetProblem.navigation_at`).
"""

from __future__ import annotations

import numpy as np

from registration._generated import api as generated
from registration.fleet.batch.design import plot_model_inputs
from registration.fleet.data.layout import (
    ATTITUDE_COLUMNS,
    BIAS_COLUMNS,
    ECCENTRICITY_COLUMNS,
    ELEVATION_BIAS_COLUMN,
    POSITION_ERROR_COLUMNS,
    RANGE_GAIN_COLUMN,
)
from registration.fleet.data.problem import FleetProblem

__all__ = ["corrected_plot_positions", "corrected_positions"]


def corrected_positions(
    nav: np.ndarray, state: np.ndarray, xs: np.ndarray, lever: np.ndarray, meas: np.ndarray
) -> np.ndarray:
    """(M, 3) ECEF positions (m) of plots corrected by the states.

    ``nav`` (M, 6): navigation (lat, lon rad, alt m, heading, pitch, roll rad as reported) at the
    time the plot was seen; ``state`` (M, 6, 11 or 13): each plot's state indices
    (:meth:`~registration.fleet.data.layout.StateLayout.sensor_states`, the sink last); ``xs`` (n + 1,):
    the states (rad, m, 1, s) with 0 appended for the sink; ``lever`` (M, 3) m, deck frame;
    ``meas`` (M, 3): range (m), bearing, elevation (rad), every channel filled (the caller places
    a plot without range or elevation).
    """
    known = plot_model_inputs(nav, lever, meas) | dict(
        att_err=xs[state[:, ATTITUDE_COLUMNS]], bias=xs[state[:, BIAS_COLUMNS]]
    )
    if state.shape[1] > ECCENTRICITY_COLUMNS.start:  # and the eccentricity
        gain, pos_err = xs[state[:, RANGE_GAIN_COLUMN]], xs[state[:, POSITION_ERROR_COLUMNS]]
        ecc = xs[state[:, ECCENTRICITY_COLUMNS]]
        p = generated.fleet_plot2ecef_ecc(**known, gain=gain, pos_err=pos_err, ecc=ecc).p_ecef
    elif state.shape[1] > BIAS_COLUMNS.stop:  # the extended layout: gain, time bias, position error
        gain, pos_err = xs[state[:, RANGE_GAIN_COLUMN]], xs[state[:, POSITION_ERROR_COLUMNS]]
        p = generated.fleet_plot2ecef_ext(**known, gain=gain, pos_err=pos_err).p_ecef
    else:
        p = generated.fleet_plot2ecef(**known).p_ecef
    return np.asarray(p).reshape(-1, 3)


def corrected_plot_positions(
    problem: FleetProblem, x: np.ndarray, plots: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """ECEF positions (M, 3) m of the plots ``plots`` (indices into the problem's plots; default
    all) that have a range, corrected by the states ``x`` (n,) (rad, m, 1, s; zeros: as measured),
    and their indices into the problem's plots (M,). A plot without elevation (2-D radar) is placed
    in its deck plane (elevation 0 after correction); with a time bias the platform is taken where
    it was when the plot was seen."""
    layout = problem.layout
    sel = np.flatnonzero(problem.mask[:, 0]) if plots is None else plots[problem.mask[plots, 0]]
    xs = np.append(np.asarray(x, dtype=np.float64), 0.0)  # the sink (absent state) reads 0
    state = layout.sensor_states(problem.sensor[sel], problem.sensor_platform)
    meas = problem.meas[sel].copy()
    meas[:, 2] = np.where(problem.mask[sel, 2], meas[:, 2], xs[state[:, ELEVATION_BIAS_COLUMN]])
    nav = problem.seen(x, sel)[1]
    p = corrected_positions(nav, state, xs, problem.sensor_lever[problem.sensor[sel]], meas)
    return p, sel
