"""Batch maximum-likelihood registration of a fleet: :func:`solve_batch`.

The solver (:mod:`registration.fleet.batch.solver`) finds the estimate; this module evaluates what is
known about it there: the states' covariance (the Cramér-Rao bound at the estimate, targets
eliminated), the fused target positions with their covariance, the normalised residuals and
their chi-square check, and the observability report.
"""

from __future__ import annotations

import numpy as np

from registration.fleet.batch.covariance import estimate_from_information, fused_targets, solution_information
from registration.fleet.batch.residuals import (
    chi_square_parts,
    reference_residuals,
    residual_table,
    unused_references,
)
from registration.fleet.batch.solver import BatchOptions, StartCoefficients, fit
from registration.fleet.data.problem import FleetProblem
from registration.fleet.result import BatchResult, ChiSquareCheck, FusedTargets

__all__ = ["HEIGHT_WARNING", "solve_batch"]

#: The warning for targets whose height only slant ranges measure (FleetProblem.targets_without_height).
HEIGHT_WARNING = (
    "{} targets have no measured height ({}): no plot with an elevation, no reference with a height and "
    "no surface; their heights are determined only weakly by the slant ranges and trade off against the "
    "range biases, so those may be wrong by more than their sigma. Give the surface they move on (the "
    "targets table's surface_alt_m, sigma_surface_m; ships: mean sea level) or references with heights"
)


def _per_input_row(problem: FleetProblem, values: np.ndarray) -> np.ndarray:
    """Per-plot ``values`` placed at the plots' input rows ('' for excluded rows)."""
    out = np.full(problem.n_input_plots, "", dtype=values.dtype if values.size else str)
    out[problem.row] = values
    return out


def _chi_square(fit_, ev) -> ChiSquareCheck:
    """The chi-square of the solution: plots, reference positions and priors, each term kept."""
    design, layout = fit_.design, fit_.problem.layout
    parts = chi_square_parts(design, ev, layout.free)
    n_values = sum(n for _, n in parts.values())
    n_params = layout.free.size + 3 * int(design.blocks.coef_mask.sum())
    return ChiSquareCheck(ev.cost, n_values - n_params, parts)


def solve_batch(
    problem: FleetProblem,
    options: BatchOptions | None = None,
    x0: np.ndarray | None = None,
    *,
    progress: bool = False,
    coefficients: StartCoefficients | None = None,
    fused: bool = True,
) -> BatchResult:
    """Register a fleet: maximum-likelihood (or, with finite priors, maximum a posteriori)
    estimates of every platform's attitude errors and every sensor's biases, jointly with the
    target trajectories, from all plots at once. See docs/background/fleet-model.md for the model and the
    method.
    ``x0`` (n,; rad, m): starting states, for example an earlier estimate (default zeros); the
    solution is the same optimum to within the stopping tolerance, reached in fewer iterations.
    ``coefficients(problem, design, x0)``: starting window coefficients (B, n_coef, 3) m, for
    example an earlier fit's windows (default None: the window means of the plots); a warm start
    too.
    ``progress``: a bar over the solver's iterations on standard error, shown only on a terminal
    and after about a second (:func:`registration.core.progress.progress_bar`).
    ``fused`` False: ``targets`` is left empty (:meth:`FusedTargets.empty`), for a caller that needs
    the estimate only (the association's solves between passes, which never read the fused
    positions: on the 10-radar benchmark they cost 0.2 s of those five solves' 1.0 s).
    """
    fit_ = fit(problem, options or BatchOptions(), x0, progress=progress, coefficients=coefficients)
    problem = fit_.problem
    layout = problem.layout
    free = layout.free
    sol = solution_information(fit_)
    known = estimate_from_information(
        layout,
        sol.information,
        sol.information_data,
        problem.sensor_platform,
        problem.platform_ids,
        problem.sensor_ids,
    )
    n = layout.n
    P_sink = np.zeros((n + 1, n + 1))
    P_sink[:n, :n] = known.covariance
    ref_target, ref_residuals = reference_residuals(problem, fit_.design, sol.evaluation)
    unused = unused_references(problem, fit_.design)
    flat = problem.targets_without_height()
    height = (
        (HEIGHT_WARNING.format(len(flat), ", ".join(flat[:5]) + (", ..." if len(flat) > 5 else "")),)
        if flat
        else ()
    )
    return BatchResult(
        layout=layout,
        estimate=fit_.x.copy(),
        covariance=known.covariance,
        sigma=known.sigma,
        status=known.status,
        targets=fused_targets(fit_, sol.reduced, P_sink) if fused else FusedTargets.empty(),
        residuals=residual_table(problem, fit_.design, sol.evaluation),
        chi_square=_chi_square(fit_, sol.evaluation),
        observability=known.report,
        excluded=problem.excluded,
        information=sol.information_data,
        free_names=tuple(layout.names[i] for i in free),
        scale=known.scale,
        undetermined=known.undetermined,
        converged=fit_.converged,
        iterations=fit_.iterations,
        plot_target=_per_input_row(problem, np.array(problem.target_ids, dtype=str)[problem.target]),
        plot_sensor=_per_input_row(problem, np.array(problem.sensor_ids, dtype=str)[problem.sensor]),
        cost_history=fit_.cost_history,
        warnings=fit_.warnings + ((unused,) if unused else ()) + height,
        reference_target=ref_target,
        reference_residuals=ref_residuals,
        references_given=int(problem.references.time.size),
    )
