"""Normalised residuals of a fleet problem at given registration states: each target window's
trajectory fitted to its plots with the states held (as the batch solver's first phase does), then
``(measured - predicted) / sigma`` per plot and channel, and their chi-square check."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from registration.fleet.blocks import make_blocks
from registration.fleet.initial import initial_coefficients
from registration.fleet.normal import Design, Evaluation, evaluate, make_design, normal_equations
from registration.fleet.problem import FleetProblem
from registration.fleet.result import ChiSquareCheck
from registration.fleet.solver import BatchOptions, exclude_singular, levenberg_marquardt, singular_blocks

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
    x = np.asarray(x, dtype=np.float64)
    while True:
        design = make_design(problem, make_blocks(problem, options.window_s, options.degree))
        design = replace(design, prior_weight=np.zeros_like(design.prior_weight))
        start = evaluate(design, x, initial_coefficients(design, x))
        normal = normal_equations(design, start)
        bad = singular_blocks(design, normal)
        if bad.size == 0:
            break
        problem = exclude_singular(problem, design, bad)
    ev, _, _, _, _ = levenberg_marquardt(design, start, np.zeros(0, dtype=np.int64), options, 0.0, normal)
    n_values = int(np.count_nonzero(design.weight)) + 3 * design.ref_p.shape[0]
    dof = n_values - 3 * int(design.blocks.coef_mask.sum())
    return residual_table(problem, design, ev), ChiSquareCheck(ev.cost, dof), problem
