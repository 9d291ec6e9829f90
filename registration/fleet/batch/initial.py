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

__all__ = ["ASSUMED_RANGE_M", "plot_positions", "initial_coefficients"]

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
    blk = design.blocks
    p = plot_positions(design, x)
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
