"""Starting values of the batch solver: registration errors zero, each target window at the mean
of the positions its plots give with zero errors.

Each plot becomes an ECEF position through :func:`registration.fleet.corrected.corrected_positions`
with zero registration errors. A plot without range (passive angle sensor, bearing-only) is placed at
:data:`ASSUMED_RANGE_M` along its line of sight, and one without elevation at elevation 0 (the
deck plane). A window's constant coefficient is the mean over its plots that have a range (over
all its plots if none has); the higher coefficients start at zero. The solver then refines the
windows alone before it frees the registration states (:mod:`registration.fleet.batch.solver`).
"""

from __future__ import annotations

import numpy as np

from registration.fleet.batch.design import Design
from registration.fleet.corrected import corrected_positions

__all__ = ["ASSUMED_RANGE_M", "fitted_coefficients", "initial_coefficients", "plot_positions"]

#: Range (m) assumed for a plot that has none, to start its target somewhere on its line of sight.
ASSUMED_RANGE_M = 30_000.0


def plot_positions(design: Design, x: np.ndarray | None = None) -> np.ndarray:
    """(rows, 3) ECEF position of each design row, corrected by states ``x`` (default zeros)."""
    xs = np.zeros(design.n_state + 1) if x is None else np.append(x, 0.0)
    has = design.weight > 0
    r = np.where(has[:, 0], design.meas[:, 0], ASSUMED_RANGE_M)  # an absent channel's bias is 0
    e = np.where(has[:, 2], design.meas[:, 2], 0.0)
    nav = design.seen_at(design.seen_time(xs[:-1]))[0] if design.time_biased else design.nav
    return corrected_positions(
        nav, design.state, xs, design.lever, np.stack([r, design.meas[:, 1], e], axis=1)
    )


def initial_coefficients(design: Design, x: np.ndarray | None = None) -> np.ndarray:
    """(B, n_coef, 3) starting coefficients: window means of the plot positions corrected by the
    states ``x`` (default zeros; module docstring)."""
    return _means(design, plot_positions(design, x))


def _means(design: Design, p: np.ndarray) -> np.ndarray:
    """:func:`initial_coefficients` from the rows' positions ``p`` (rows, 3)."""
    blk = design.blocks
    ranged = (design.weight[:, 0] > 0).astype(np.float64)
    real = design.real.astype(np.float64)
    n_ranged = design.block_sums(ranged)
    n_all = design.block_sums(real)
    sum_ranged = design.block_sums(p * ranged[:, None])
    sum_all = design.block_sums(p * real[:, None])
    mean = np.where(
        (n_ranged > 0)[:, None], sum_ranged / np.maximum(n_ranged, 1)[:, None], sum_all / n_all[:, None]
    )
    coef = np.zeros((blk.n_blocks, blk.n_coef, 3))
    coef[:, 0] = mean
    return coef


#: A window whose Jacobi-scaled sums of basis products have an eigenvalue below this times the
#: largest is not fitted by :func:`fitted_coefficients` (it keeps the mean).
UNFITTED_BELOW = 1e-10


def fitted_coefficients(design: Design, x: np.ndarray | None = None) -> np.ndarray:
    """(B, n_coef, 3) starting coefficients: each window's polynomial fitted by least squares to the
    positions, corrected by the states ``x``, of its plots that fix a position (range, bearing and
    elevation), where they determine it; elsewhere the means of :func:`initial_coefficients`.
    Closer than the means for a target that crosses its window at speed (a constant misses it by
    its speed times half the window): a fit of the windows alone converges from it in fewer steps.
    A window of 2-D plots only keeps its mean: they lie at elevation 0, kilometres below an
    aircraft, and a polynomial through them started some of those fits elsewhere than the mean did
    (a window whose height only slant ranges measure has more than one nearby optimum)."""
    blk = design.blocks
    p = plot_positions(design, x)
    coef = _means(design, p)
    fixed: np.ndarray = np.all(design.weight > 0, axis=1)  # range, bearing and elevation measured
    b = design.basis * fixed[:, None]  # (rows, K), masked coefficients 0
    K = blk.n_coef
    BB = design.block_sums((b[:, :, None] * design.basis[:, None, :]).reshape(-1, K * K)).reshape(-1, K, K)
    Bp = design.block_sums((b[:, :, None] * p[:, None, :]).reshape(-1, K * 3)).reshape(-1, K, 3)
    unused = ~blk.coef_mask
    BB[:, np.arange(K), np.arange(K)] += unused
    n_used = blk.coef_mask.sum(axis=1)
    fit = np.flatnonzero((design.block_sums(fixed.astype(np.float64)) >= n_used) & (n_used > 1))
    if fit.size:  # those whose fixing plots determine the polynomial (Jacobi-scaled, as singular_blocks)
        d = np.sqrt(BB[fit][:, np.arange(K), np.arange(K)]) + 1e-300
        w = np.linalg.eigvalsh(BB[fit] / d[:, :, None] / d[:, None, :])
        fit = fit[w[:, 0] > UNFITTED_BELOW * w[:, -1]]
    if fit.size:
        c = np.linalg.solve(BB[fit], Bp[fit])
        c[unused[fit]] = 0.0
        finite = np.isfinite(c).all(axis=(1, 2))
        coef[fit[finite]] = c[finite]
    return coef
