"""Normalised residuals of a fleet problem at given registration states: each target window's
trajectory fitted to its plots with the states held (as the batch solver's first phase does), then
``(measured - predicted) / sigma`` per plot and channel, and their chi-square check."""

from __future__ import annotations

import numpy as np

from registration.fleet.normal import Design, Evaluation
from registration.fleet.problem import FleetProblem
from registration.fleet.result import ChiSquareCheck
from registration.fleet.solver import BatchOptions, determined_design, fit_windows

__all__ = ["residual_table", "residuals_at"]


def residual_table(problem: FleetProblem, design: Design, ev: Evaluation) -> np.ndarray:
    """(input plot rows, 3) normalised residuals of an evaluation; NaN where not measured or excluded."""
    out = np.full((problem.n_input_plots, 3), np.nan)
    e = np.where(design.weight > 0, ev.e, np.nan)
    out[problem.row[design.blocks.order]] = e[design.slot]
    return out


def residuals_at(problem: FleetProblem, x: np.ndarray, options: BatchOptions | None = None
                 ) -> tuple[np.ndarray, ChiSquareCheck, FleetProblem]:
    """Normalised residuals (input plot rows, 3) at states ``x`` (n,; rad, m) with the trajectories
    fitted, their chi-square check (degrees of freedom: measured values minus trajectory
    coefficients; the states count as known) and the problem they were computed on (windows whose
    position the plots do not determine set aside, as in the batch)."""
    options = options or BatchOptions()
    found = determined_design(problem, options, np.asarray(x, dtype=np.float64), priors=False)
    if found is None:
        raise ValueError("no plots to evaluate (every window was set aside)")
    problem, design, start, normal = found
    ev, _ = fit_windows(design, start, normal, options)
    n_values = int(np.count_nonzero(design.weight)) + 3 * design.ref_p.shape[0]
    dof = n_values - 3 * int(design.blocks.coef_mask.sum())
    return residual_table(problem, design, ev), ChiSquareCheck(ev.cost, dof), problem
