"""What one epoch of plots tells the online fleet filter about the registration states.

An *epoch* is the plots of the target windows that close together (:mod:`registration.fleet.online.filter`).
Its information about the states is the batch problem's, restricted to those plots and taken at
the filter's current estimate ``x-`` (docs/background/fleet-online.md):

1. each target window's trajectory coefficients are fitted to its plots with the states held at
   ``x-`` (:func:`~registration.fleet.batch.solver.fit_windows`: Gauss-Newton on the coefficients alone,
   window by window, from the window means of the plots corrected by ``x-``; Levenberg-Marquardt if a step
   fails to lower the sum of squares): the fitted plots, as the two-ship filter's ``fitted`` linearisation
   uses them;
2. there the plots' whitened rows give the normal equations, and the windows are eliminated by the
   Schur complement (:func:`registration.fleet.batch.schur.reduce`): the states' information ``L`` and the
   gradient ``b`` of the epoch, so that ``L dx = b`` is the Gauss-Newton step from ``x-``.

Windows that carry no registration information are set aside before that: a target seen by one
sensor only in the epoch (and no reference position in it), and a window whose position its plots
do not determine (:func:`registration.fleet.batch.solver.determined_design`). After the fit
(:func:`~registration.fleet.batch.window_fit.fit_each_window`, each window on its own), a window
still more than one of its own standard deviations from its minimum (its remaining predicted
reduction above ``UNCONVERGED_REMAINING``, one chi-square unit) is set aside too, and its plots
counted (``EpochInformation.n_unconverged``): its gradient is not that of a minimum and would
enter the filter as if it were data.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fleet.batch.schur import reduce
from registration.fleet.batch.solver import BatchOptions, determined_design
from registration.fleet.batch.window_fit import UNCONVERGED_REMAINING, fit_each_window
from registration.fleet.data.problem import FleetProblem

__all__ = ["EpochInformation", "epoch_information", "informative_plots"]


@dataclass(frozen=True)
class EpochInformation:
    """The epoch's information ``L`` (n, n) and gradient ``b`` (n,) over all states (rad, m), at
    the estimate it was linearised at, from ``n_plots`` plots; ``n_unconverged``: the plots of
    windows set aside because their fit did not converge."""

    L: np.ndarray
    b: np.ndarray
    n_plots: int
    n_unconverged: int = 0


def informative_plots(target: np.ndarray, sensor: np.ndarray, ref_target: np.ndarray) -> np.ndarray:
    """(N,) bool: the plots of targets seen by two or more sensors, or with a reference position."""
    if target.size == 0:
        return np.zeros(0, dtype=bool)
    pairs = np.unique(np.stack([target, sensor]), axis=1)
    n_sensors = np.bincount(pairs[0], minlength=int(target.max()) + 1)
    has_ref = np.zeros(n_sensors.size, dtype=bool)
    has_ref[ref_target[ref_target < n_sensors.size]] = True
    return (n_sensors[target] >= 2) | has_ref[target]


def epoch_information(problem: FleetProblem, x: np.ndarray, options: BatchOptions) -> EpochInformation | None:
    """The information of the epoch ``problem`` at states ``x`` (n,), or None when its plots carry
    none (module docstring). ``options``: the window length and degree, and the iteration limits
    of the coefficient fit."""
    keep = informative_plots(problem.target, problem.sensor, problem.ref_target)
    if not keep.any():
        return None
    problem = problem.drop_plots(~keep, ())
    n_unconverged = 0
    for _ in range(2):  # once more without the windows whose fit did not converge, if any
        found = determined_design(problem, options, x, priors=False)  # the filter carries the prior
        if found is None:
            return None
        problem, design, start, normal = found
        _, normal, remaining = fit_each_window(design, start, normal, options)
        converged = ~(remaining > UNCONVERGED_REMAINING)
        if converged.all():
            break
        blk = design.blocks
        drop = np.zeros(problem.n_plots, dtype=bool)
        drop[blk.order[~converged[blk.block]]] = True
        n_unconverged += int(drop.sum())
        problem = problem.drop_plots(drop, ())
        keep = informative_plots(problem.target, problem.sensor, problem.ref_target)
        if not keep.any():
            return None
        problem = problem.drop_plots(~keep, ())
    else:
        return None  # a window that converged alone did not the second time: nothing trustworthy
    red = reduce(design.blocks, normal, 0.0)
    n = design.n_state
    return EpochInformation(red.S[:n, :n], red.r[:n], problem.n_plots, n_unconverged)
