"""The target windows fitted with the registration states held (:func:`fit_each_window`): what the
online filter's epochs and the residuals at an estimate need.

With the states held the windows do not interact: the sum of squares is a sum over windows, each a
function of its own coefficients only. Each window is therefore its own Levenberg-Marquardt problem
(vectorised over the windows): Gauss-Newton steps ``V_b^-1 b_c,b`` first (``lambda_b = 0``), a step
kept only when it lowers that window's own sum of squares, Marquardt's damping ``lambda_b D_b``
(``D_b`` the diagonal of ``V_b``) raised on the windows whose step failed (Nielsen's update), until
each window's Gauss-Newton step predicts a reduction below ``tolerance``.

One fit over all windows at once, with one acceptance test and one damping for the sum (as this
module replaced), lets a single window that starts far from its minimum steer the others: its bad
step is refused together with their good ones, and its damping is theirs. That happened to a
target whose height nothing measures flying over a 2-D radar (docs/background/fleet-online.md,
"Targets without a measured height"): its window starts at elevation 0 (the radar's plots on the
ground at their slant range, kilometres from the aircraft), the first steps of the sum were
accepted while that window's own sum of squares grew from 1e5 to 1e7, and it ended in a local
minimum with a sum of squares of 1358 on 13 plots, whose gradient then entered the filter as
data. Fitted on its own the same window reaches 8.7.

Each window's remaining Gauss-Newton prediction at the end is returned (``remaining``, chi-square
units: ``b_c,b^T V_b^-1 b_c,b``, the squared distance of the window from its linearised minimum
in its own standard deviations). A window still far from its minimum when the iterations allowed
are spent (or its damping reached
:data:`~registration.fleet.batch.levenberg_marquardt.LAMBDA_MAX`) has a linearisation that is not at a
minimum, and a caller that turns the fit into information sets it aside
(:data:`UNCONVERGED_REMAINING`).
"""

from __future__ import annotations

import numpy as np

from registration.fleet.batch.design import Design
from registration.fleet.batch.levenberg_marquardt import LAMBDA_MAX, LAMBDA_START
from registration.fleet.batch.normal import Evaluation, Normal, evaluate, normal_equations
from registration.fleet.batch.schur import masked_blocks

__all__ = ["UNCONVERGED_REMAINING", "fit_each_window", "window_costs"]

#: A window whose remaining predicted reduction (chi-square units) exceeds this after the fit is
#: more than one of its own standard deviations from its minimum: its gradient is not that of a
#: minimum and it carries no trustworthy information about the states.
UNCONVERGED_REMAINING = 1.0


def window_costs(design: Design, ev: Evaluation) -> np.ndarray:
    """(B,) each window's sum of squared whitened residuals: its plots, references and surface
    heights (priors excluded: they belong to the states)."""
    B = design.blocks.n_blocks
    cost = np.bincount(design.block, weights=np.einsum("ij,ij->i", ev.e, ev.e), minlength=B)
    if ev.e_ref.size:
        cost += np.bincount(
            design.blocks.ref_block, weights=np.einsum("ij,ij->i", ev.e_ref, ev.e_ref), minlength=B
        )
    if ev.e_surface.size and design.surface is not None:
        cost += np.bincount(design.surface.block, weights=ev.e_surface**2, minlength=B)
    return cost


def _steps(V: np.ndarray, b_c: np.ndarray, lam: np.ndarray, mask: np.ndarray):
    """(Gauss-Newton predicted reduction (B,), damped step (B, q), its predicted reduction (B,))."""
    q = V.shape[1]
    diag = V[:, np.arange(q), np.arange(q)].copy()
    gn = np.linalg.solve(V, b_c[:, :, None])[:, :, 0] * mask
    damped = V.copy()
    damped[:, np.arange(q), np.arange(q)] += lam[:, None] * diag
    dc = np.where((lam > 0)[:, None], np.linalg.solve(damped, b_c[:, :, None])[:, :, 0] * mask, gn)
    pred = np.sum(dc * b_c, axis=1) + lam * np.sum(diag * dc**2, axis=1)
    return np.sum(gn * b_c, axis=1), dc, pred


def fit_each_window(
    design: Design, start: Evaluation, normal: Normal, options
) -> tuple[Evaluation, Normal, np.ndarray]:
    """The window coefficients fitted with the states held, each window on its own (module
    docstring), from ``start`` and its normal equations ``normal``. ``options``: ``tolerance``
    (chi-square units, per window) and ``max_iterations`` (rounds: each tries one step on every
    window not yet converged). Returns the evaluation and normal equations at the fit and each
    window's remaining predicted reduction (B,)."""
    blk = design.blocks
    B = blk.n_blocks
    mask = np.repeat(blk.coef_mask, 3, axis=1).astype(np.float64)
    lam, nu = np.zeros(B), np.full(B, 2.0)
    stuck = np.zeros(B, dtype=bool)
    ev, cost = start, window_costs(design, start)
    for _ in range(int(options.max_iterations)):
        gn, dc, pred = _steps(masked_blocks(blk, normal.V), normal.b_c, lam, mask)
        moving = (gn > options.tolerance) & ~stuck
        if not moving.any():
            break
        coef = ev.coef + (dc * moving[:, None]).reshape(ev.coef.shape)
        trial = evaluate(design, ev.x, coef)
        trial_cost = window_costs(design, trial)
        better = moving & np.isfinite(trial_cost) & (trial_cost < cost)
        worse = moving & ~better
        rho = np.where(better, (cost - trial_cost) / np.where(pred > 0, pred, np.inf), 0.0)
        lam = np.where(better, lam * np.maximum(1.0 / 3.0, 1.0 - (2.0 * rho - 1.0) ** 3), lam)
        lam = np.where(worse, np.where(lam > 0, lam * nu, LAMBDA_START), lam)
        nu = np.where(better, 2.0, np.where(worse, nu * 2.0, nu))
        stuck |= lam >= LAMBDA_MAX
        if worse.any():
            coef = ev.coef + (dc * better[:, None]).reshape(ev.coef.shape)
            trial = evaluate(design, ev.x, coef) if better.any() else ev
            trial_cost = np.where(better, trial_cost, cost)
        if better.any():
            ev, cost = trial, trial_cost
            normal = normal_equations(design, ev)
    else:
        gn, _, _ = _steps(masked_blocks(blk, normal.V), normal.b_c, np.zeros(B), mask)
    return ev, normal, gn
