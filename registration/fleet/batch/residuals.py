"""Normalised residuals of a fleet problem at given registration states: each target window's
trajectory fitted to its plots with the states held (as the batch solver's first phase does), then
``(measured - predicted) / sigma`` per plot and channel, and their chi-square check with its parts
(plots, reference positions, priors), so that each term's share of the sum is visible."""

from __future__ import annotations

import numpy as np

from registration.fleet.batch.design import Design
from registration.fleet.batch.normal import Evaluation
from registration.fleet.batch.solver import BatchOptions, determined_design, fit_windows
from registration.fleet.data.problem import FleetProblem
from registration.fleet.result import ChiSquareCheck

__all__ = [
    "UNUSED_REFERENCES_WARN",
    "chi_square_parts",
    "reference_residuals",
    "residual_table",
    "residuals_at",
    "unused_references",
]


def chi_square_parts(design: Design, ev: Evaluation, free: np.ndarray | None = None) -> dict:
    """The terms of the sum of squares ``ev.cost``: {"plots": (sum of squared normalised residuals,
    number of measured values), "references": (the same over the reference positions used, 3 values
    each: (known - fitted position) / sigma per ECEF axis, sigma the reference file's ``sigma_m``;
    with a vertical sigma, east, north, up over ``sigma_m``, ``sigma_m``, ``sigma_up_m``; 2 values for a
    reference without a height), with surface targets "surface": (the same over the windows' height
    constraints, one value each), "priors": (the same over the priors of the states ``free``
    (indices), if given)}."""
    e = np.where(design.weight > 0, ev.e, 0.0)
    parts = {
        "plots": (float(np.sum(e * e)), int(np.count_nonzero(design.weight))),
        "references": (float(np.sum(ev.e_ref * ev.e_ref)), design.n_reference_values),
    }
    if design.surface is not None:
        parts["surface"] = (float(np.sum(ev.e_surface * ev.e_surface)), design.surface.size)
    if free is not None:
        prior = (ev.x * design.prior_weight)[free]
        parts["priors"] = (float(np.sum(prior * prior)), int(np.count_nonzero(design.prior_weight[free])))
    return parts


def reference_residuals(
    problem: FleetProblem, design: Design, ev: Evaluation
) -> tuple[np.ndarray, np.ndarray]:
    """(target ids (R',), normalised residuals (R', 3)): per reference position used, ``(known -
    fitted position) / sigma`` per ECEF axis (dimensionless; sigma in m per axis). When some
    reference used has ``sigma_up`` not equal to its ``sigma`` (:attr:`Design.ref_whiten`), the three
    values of every reference are instead the whitened east, north and up components, ``L (known -
    fitted)`` with ``L = diag(1/sigma, 1/sigma, 1/sigma_up) R_enu_ecef`` at the known position (the up
    value NaN for a reference without a height)."""
    refs = problem.references
    e = np.array(ev.e_ref, dtype=float)
    if design.ref_whiten is not None:
        e[~np.any(design.ref_whiten != 0.0, axis=2)] = np.nan  # a reference without a height has no up value
    return refs.target[design.blocks.ref_index].astype(str), e


#: Reference positions left unused are warned about from this share of a target's positions on
#: (a few at the ends of the plotted span are normal: a window cannot hold them).
UNUSED_REFERENCES_WARN = 0.1


def unused_references(problem: FleetProblem, design: Design) -> str | None:
    """A warning when many reference positions of the problem's targets are not used: at least
    UNUSED_REFERENCES_WARN of some target's (they lie outside their target's plotted time span, or
    with ``window_s = 0`` at no instant of its plots, so no window holds them); None otherwise."""
    refs = problem.references
    n = refs.time.size
    used = np.zeros(n, dtype=bool)
    used[design.blocks.ref_index] = True
    target = refs.target.astype(str)
    names = list(dict.fromkeys(target))
    share = {t: float(np.mean(~used[target == t])) for t in names}
    flagged = [t for t in names if share[t] >= UNUSED_REFERENCES_WARN]
    if not flagged:
        return None
    first = int(np.flatnonzero(~used & np.isin(target, flagged))[0])
    return (
        f"{int(np.sum(~used))} of {n} reference positions are not used (of targets "
        + ", ".join(f"{t}: {share[t]:.0%}" for t in flagged)
        + f"; the first at {refs.time[first]:g} s): no "
        "window holds them, as they lie outside their target's plotted time span (with window_s = 0: at no "
        "instant of its plots) or its plots there were set aside, so neither they nor their sigma enter the "
        "estimate or the chi-square. That is expected where the reference track runs longer than the "
        "plots (AIS before and after the radar holds a vessel); otherwise check the reference file's "
        "time_s against the plots' time origin"
    )


def residual_table(problem: FleetProblem, design: Design, ev: Evaluation) -> np.ndarray:
    """(input plot rows, 3) normalised residuals of an evaluation; NaN where not measured or excluded."""
    out = np.full((problem.n_input_plots, 3), np.nan)
    e = np.where(design.weight > 0, ev.e, np.nan)
    out[problem.row[design.blocks.order]] = e[design.slot]
    return out


def residuals_at(
    problem: FleetProblem, x: np.ndarray, options: BatchOptions | None = None
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
    parts = chi_square_parts(design, ev)
    dof = sum(n for _, n in parts.values()) - 3 * int(design.blocks.coef_mask.sum())
    return residual_table(problem, design, ev), ChiSquareCheck(ev.cost, dof, parts), problem
