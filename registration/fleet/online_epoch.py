"""What one epoch of plots tells the online fleet filter about the registration states.

An *epoch* is the plots of the target windows that close together (:mod:`registration.fleet.online`).
Its information about the states is the batch problem's, restricted to those plots and taken at
the filter's current estimate ``x-`` (docs/fleet.md, "Online filter"):

1. each target window's trajectory coefficients are fitted to its plots with the states held at
   ``x-`` (:func:`fit_windows`: Gauss-Newton on the coefficients alone, window by window, from the
   window means of the plots corrected by ``x-``; Levenberg-Marquardt if a step fails to lower the
   sum of squares): the fitted plots, as the two-ship filter's ``fitted`` linearisation uses them;
2. there the plots' whitened rows give the normal equations, and the windows are eliminated by the
   Schur complement (:func:`registration.fleet.schur.reduce`): the states' information ``L`` and the
   gradient ``b`` of the epoch, so that ``L dx = b`` is the Gauss-Newton step from ``x-``.

Windows that carry no registration information are set aside before that: a target seen by one
sensor only in the epoch (and no reference position in it), and a window whose position its plots
do not determine (:func:`registration.fleet.solver.singular_blocks`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from registration.fleet.blocks import make_blocks
from registration.fleet.initial import initial_coefficients
from registration.fleet.inputs import References
from registration.fleet.normal import Design, Evaluation, Normal, evaluate, make_design, normal_equations
from registration.fleet.problem import FleetProblem
from registration.fleet.schur import masked_blocks, reduce
from registration.fleet.solver import BatchOptions, levenberg_marquardt, singular_blocks

__all__ = ["EpochInformation", "epoch_information", "fit_windows", "informative_plots"]


@dataclass(frozen=True)
class EpochInformation:
    """The epoch's information ``L`` (n, n) and gradient ``b`` (n,) over all states (rad, m), at
    the estimate it was linearised at; ``n_plots`` plots used, ``chi2`` the sum of squared
    whitened residuals of the fitted windows at that estimate, ``n_values`` the measured values."""

    L: np.ndarray
    b: np.ndarray
    n_plots: int
    chi2: float
    n_values: int


def informative_plots(target: np.ndarray, sensor: np.ndarray, ref_target: np.ndarray) -> np.ndarray:
    """(N,) bool: the plots of targets seen by two or more sensors, or with a reference position."""
    if target.size == 0:
        return np.zeros(0, dtype=bool)
    pairs = np.unique(np.stack([target, sensor]), axis=1)
    n_sensors = np.bincount(pairs[0], minlength=int(target.max()) + 1)
    has_ref = np.zeros(n_sensors.size, dtype=bool)
    has_ref[ref_target[ref_target < n_sensors.size]] = True
    return (n_sensors[target] >= 2) | has_ref[target]


def fit_windows(design: Design, start: Evaluation, normal: Normal, options: BatchOptions) -> tuple[Evaluation, Normal]:
    """The window coefficients fitted with the states held (Gauss-Newton, each window's step
    ``V_b^-1 b_c,b``), until the predicted reduction of the sum of squares is below
    ``options.tolerance``; Levenberg-Marquardt from there if a step does not lower it."""
    blk = design.blocks
    mask = np.repeat(blk.coef_mask, 3, axis=1)
    ev = start
    for _ in range(options.max_iterations):
        dc = np.linalg.solve(masked_blocks(blk, normal.V), normal.b_c[:, :, None])[:, :, 0] * mask
        if not float(np.sum(dc * normal.b_c)) > options.tolerance:
            return ev, normal
        trial = evaluate(design, ev.x, ev.coef + dc.reshape(ev.coef.shape))
        if not trial.cost < ev.cost:
            break
        ev = trial
        normal = normal_equations(design, ev)
    ev, normal, _, _, _ = levenberg_marquardt(design, ev, np.zeros(0, dtype=np.int64), options, 0.0, normal)
    return ev, normal


def _restricted(problem: FleetProblem, keep: np.ndarray) -> FleetProblem:
    per_plot = {k: getattr(problem, k)[keep] for k in ("time", "sensor", "target", "meas", "mask", "nav", "row")}
    return replace(problem, **per_plot)


def epoch_information(problem: FleetProblem, x: np.ndarray, options: BatchOptions) -> EpochInformation | None:
    """The information of the epoch ``problem`` at states ``x`` (n,), or None when its plots carry
    none (module docstring). ``options``: the window length and degree, and the iteration limits
    of the coefficient fit."""
    keep = informative_plots(problem.target, problem.sensor, problem.ref_target)
    if not keep.any():
        return None
    problem = _restricted(problem, keep)
    for _ in range(3):  # up to two passes to drop undetermined windows
        design = make_design(problem, make_blocks(problem, options.window_s, options.degree))
        design = replace(design, prior_weight=np.zeros_like(design.prior_weight))  # the filter carries the prior
        start = evaluate(design, x, initial_coefficients(design, x))
        normal = normal_equations(design, start)
        bad = singular_blocks(design, normal)
        if bad.size == 0:
            break
        blk = design.blocks
        drop = np.isin(blk.block, bad)
        keep = np.ones(problem.n_plots, dtype=bool)
        keep[blk.order[drop]] = False
        if not keep.any():
            return None
        problem = _restricted(problem, keep)
    else:
        return None
    ev, normal = fit_windows(design, start, normal, options)
    red = reduce(design.blocks, normal, 0.0)
    n = design.n_state
    return EpochInformation(red.S[:n, :n], red.r[:n], problem.n_plots, float(ev.cost),
                            int(np.count_nonzero(design.weight)) + 3 * design.ref_p.shape[0])

