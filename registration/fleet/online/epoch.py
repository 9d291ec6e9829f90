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
do not determine (:func:`registration.fleet.batch.solver.determined_design`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fleet.batch.schur import reduce
from registration.fleet.batch.solver import BatchOptions, determined_design, fit_windows
from registration.fleet.data.problem import FleetProblem

__all__ = ["EpochInformation", "epoch_information", "informative_plots"]


@dataclass(frozen=True)
class EpochInformation:
    """The epoch's information ``L`` (n, n) and gradient ``b`` (n,) over all states (rad, m), at
    the estimate it was linearised at, from ``n_plots`` plots."""

    L: np.ndarray
    b: np.ndarray
    n_plots: int


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
    found = determined_design(
        problem.drop_plots(~keep, ()), options, x, priors=False
    )  # the filter carries the prior
    if found is None:
        return None
    problem, design, start, normal = found
    _, normal = fit_windows(design, start, normal, options)
    red = reduce(design.blocks, normal, 0.0)
    n = design.n_state
    return EpochInformation(red.S[:n, :n], red.r[:n], problem.n_plots)
