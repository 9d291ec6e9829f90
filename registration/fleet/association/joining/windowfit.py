"""The windows of the registered targets fitted to their plots with the states held at the
estimate ``x`` (:func:`fit_windows`): the batch's own trajectory model, each window a cubic in ECEF
(:mod:`registration.fleet.batch.blocks`), Gauss-Newton on the windows from their plots' means, or
from an earlier fit's windows. A fit's coefficients ``c_b`` have the covariance ``V_b^-1`` given the
states and move with them as ``dc_b = -Y_b dx`` (``Y_b = V_b^-1 W_b`` over the window's local
states, :mod:`registration.fleet.batch.schur`); :mod:`.curves` predicts the anchors from them.

The model is nearly linear in the windows: over the fits of the 10-radar benchmark and of the robust
table's fleets, a step that predicted a reduction Δ (chi-square units) was followed by one that
predicted at most 2.2e-7 Δ² where the fit converged. A step that predicts at most LINEAR_REDUCTION
is therefore the last, and the residuals after it are the linearised model's ``e + A_c dc`` (the
rows' Jacobian in their windows' coefficients): below 0.2 from those of a new evaluation in total,
where a new evaluation of every plot and its normal equations would cost a third of the fit. The
windows' covariances are then those at the step's start.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import cast

import numpy as np

from registration.fleet.batch.blocks import Blocks
from registration.fleet.batch.design import Design
from registration.fleet.batch.initial import fitted_coefficients, initial_coefficients
from registration.fleet.batch.normal import evaluate, normal_equations
from registration.fleet.batch.schur import block_inverses, masked_blocks
from registration.fleet.batch.solver import BatchOptions, determined_design, singular_blocks
from registration.fleet.data.problem import FleetProblem

__all__ = [
    "LINEAR_REDUCTION",
    "WINDOW_ITERATIONS",
    "WINDOW_TOLERANCE",
    "WindowFit",
    "Windows",
    "fit_windows",
    "join_fits",
    "start_coefficients",
    "window_steps",
]

#: Gauss-Newton steps on the target windows at most when their curves are fitted with the states held.
WINDOW_ITERATIONS = 10
#: ... until a step would lower the sum of squares by less than this (chi-square units; over all the
#: windows together, as the solves between passes stop: the residuals and curves the tests use then
#: move by far less than a sigma). Warm fits had taken a third step to go from about 1e-3 to 1e-8.
WINDOW_TOLERANCE = 1e-2
#: A step that predicts a reduction of at most this (chi-square units, all windows together) is the
#: last, taken on the linearised model (module docstring). Steps of fits that wander (a window whose
#: height only slant ranges measure) predicted 7.9e3 and more, and are evaluated.
LINEAR_REDUCTION = 1e3


@dataclass(frozen=True)
class Windows:
    """The batch windows of the registered targets, as far as the curves evaluate them (the fields
    of the batch's :class:`~registration.fleet.batch.blocks.Blocks` that its basis needs): per
    window (B,) ``block_target``, ``block_centre``, ``block_half`` (s), ``coef_mask`` (B, n_coef)."""

    n_coef: int
    block_target: np.ndarray
    block_centre: np.ndarray
    block_half: np.ndarray
    coef_mask: np.ndarray

    def basis_and_rate_at(self, block: np.ndarray, time: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        # duck-typed: it reads only n_coef, block_centre, block_half and coef_mask, which Windows has
        return Blocks.basis_and_rate_at(cast(Blocks, self), block, time)

    def take(self, sel: np.ndarray, target: np.ndarray | None = None) -> "Windows":
        """The windows ``sel``, with the target indices ``target`` (default theirs)."""
        return Windows(
            self.n_coef,
            self.block_target[sel] if target is None else target,
            self.block_centre[sel],
            self.block_half[sel],
            self.coef_mask[sel],
        )


@dataclass(frozen=True)
class WindowFit:
    """The windows of the targets ``names`` fitted with the states held at ``x`` (:func:`fit_windows`):
    ``windows``, per window ``coef`` (B, K, 3) m, ``V_inv`` (B, q, q), ``Y`` (B, q, w g), ``local``
    (B, w g) state indices (``n_state``: none), ``determined`` (B,) bool (the others predict nothing)."""

    names: tuple
    windows: Windows
    coef: np.ndarray
    V_inv: np.ndarray
    Y: np.ndarray
    local: np.ndarray
    determined: np.ndarray
    x: np.ndarray
    n_state: int
    rows: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    row_target: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    residuals: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))

    def residual_table(self, n_rows: int) -> np.ndarray:
        """(n_rows, 3) the normalised residuals of the fitted plots at their input rows (NaN elsewhere,
        and where not measured): the residuals under the states ``x`` with the windows fitted."""
        out = np.full((n_rows, 3), np.nan)
        out[self.rows] = self.residuals
        return out

    @classmethod
    def empty(cls, x: np.ndarray, n_coef: int = 4) -> "WindowFit":
        q = 3 * n_coef
        return cls(
            (),
            Windows(
                n_coef,
                np.zeros(0, dtype=np.int64),
                np.zeros(0),
                np.zeros(0),
                np.zeros((0, n_coef), dtype=bool),
            ),
            np.zeros((0, n_coef, 3)),
            np.zeros((0, q, q)),
            np.zeros((0, q, 0)),
            np.zeros((0, 0), dtype=np.int64),
            np.zeros(0, dtype=bool),
            np.asarray(x, dtype=np.float64),
            int(np.size(x)),
        )

    def without(self, drop: set) -> "WindowFit":
        """The fit of the targets not in ``drop`` (names)."""
        keep_t = np.array([t not in drop for t in self.names], dtype=bool)
        if keep_t.all():
            return self
        new_index = np.cumsum(keep_t) - 1
        sel = (
            np.flatnonzero(keep_t[self.windows.block_target])
            if self.windows.block_target.size
            else np.zeros(0, dtype=np.int64)
        )
        plots = keep_t[self.row_target]
        return WindowFit(
            tuple(t for t, k in zip(self.names, keep_t) if k),
            self.windows.take(sel, new_index[self.windows.block_target[sel]]),
            self.coef[sel],
            self.V_inv[sel],
            self.Y[sel],
            self.local[sel],
            self.determined[sel],
            self.x,
            self.n_state,
            self.rows[plots],
            new_index[self.row_target[plots]],
            self.residuals[plots],
        )


def join_fits(a: WindowFit, b: WindowFit) -> WindowFit:
    """The fits of the targets of ``a`` and of ``b`` (different targets, the same states ``x``) as one:
    with the states held, each window is fitted to its own plots, so this is the fit of all of them."""
    if not b.names:
        return a
    if not a.names:
        return b
    width = max(a.Y.shape[2], b.Y.shape[2])

    def pad(f: WindowFit):
        extra = width - f.Y.shape[2]
        return (
            np.concatenate([f.Y, np.zeros(f.Y.shape[:2] + (extra,))], axis=2),
            np.concatenate([f.local, np.full((f.local.shape[0], extra), f.n_state, dtype=np.int64)], axis=1),
        )

    (Ya, la), (Yb, lb) = pad(a), pad(b)
    wa, wb = a.windows, b.windows
    windows = Windows(
        wa.n_coef,
        np.concatenate([wa.block_target, wb.block_target + len(a.names)]),
        np.concatenate([wa.block_centre, wb.block_centre]),
        np.concatenate([wa.block_half, wb.block_half]),
        np.concatenate([wa.coef_mask, wb.coef_mask]),
    )
    return WindowFit(
        a.names + b.names,
        windows,
        np.concatenate([a.coef, b.coef]),
        np.concatenate([a.V_inv, b.V_inv]),
        np.concatenate([Ya, Yb]),
        np.concatenate([la, lb]),
        np.concatenate([a.determined, b.determined]),
        a.x,
        a.n_state,
        np.concatenate([a.rows, b.rows]),
        np.concatenate([a.row_target, b.row_target + len(a.names)]),
        np.concatenate([a.residuals, b.residuals]),
    )


def _window_keys(names: tuple, windows) -> list:
    """(target name, centre, half length in microseconds) of each window."""
    centre = np.round(windows.block_centre * 1e6).astype(np.int64).tolist()
    half = np.round(windows.block_half * 1e6).astype(np.int64).tolist()
    return [(names[t], c, h) for t, c, h in zip(windows.block_target.tolist(), centre, half)]


def start_coefficients(
    design: Design,
    names: tuple,
    x: np.ndarray,
    prior: WindowFit,
    start: Callable[[Design, np.ndarray], np.ndarray] = initial_coefficients,
) -> np.ndarray:
    """(B, K, 3) starting coefficients: ``start(design, x)`` (default the plots' window means, the
    batch's start), and for each window that ``prior`` determined (same target, centre, length and
    degree) its coefficients there."""
    blk = design.blocks
    coef = start(design, x)
    if not prior.names or blk.n_blocks == 0 or prior.coef.shape[1:] != coef.shape[1:]:
        return coef
    known = {key: i for i, key in enumerate(_window_keys(prior.names, prior.windows)) if prior.determined[i]}
    i = np.array([known.get(key, -1) for key in _window_keys(names, blk)], dtype=np.int64)
    b = np.flatnonzero(i >= 0)
    b = b[(prior.windows.coef_mask[i[b]] == blk.coef_mask[b]).all(axis=1)]
    coef[b] = prior.coef[i[b]]
    return coef


def _warm_design(problem: FleetProblem, options: BatchOptions, x: np.ndarray, prior: WindowFit):
    """:func:`~registration.fleet.batch.solver.determined_design` started from :func:`start_coefficients`."""
    return determined_design(
        problem,
        options,
        x,
        coefficients=lambda p, design, x0: start_coefficients(
            design, tuple(str(t) for t in p.target_ids), x0, prior, fitted_coefficients
        ),
    )


def _fitted(problem: FleetProblem, design, x: np.ndarray) -> np.ndarray:
    """The windows' polynomials fitted to their plots' positions (:func:`fitted_coefficients`): a fit of
    the windows alone from them took half the Gauss-Newton steps it took from the plots' means."""
    return fitted_coefficients(design, x)


def window_steps(V: np.ndarray, b_c: np.ndarray, singular: np.ndarray) -> np.ndarray:
    """The Gauss-Newton steps ``V_b^+ b_b`` (B, q) of the blocks ``V`` (B, q, q), ``b_c`` (B, q): the
    pseudo-inverse's step for the blocks ``singular`` (indices: windows their plots do not determine,
    :func:`~registration.fleet.batch.solver.singular_blocks`), one batched LU solve for the others (the
    same step; a batched SVD of every block cost 30 times as much). A block the solve cannot invert
    exactly, or that gives no finite step, takes the pseudo-inverse's step too."""
    dc = np.zeros_like(b_c)
    regular = np.ones(V.shape[0], dtype=bool)
    regular[singular] = False
    try:
        dc[regular] = np.linalg.solve(V[regular], b_c[regular, :, None])[:, :, 0]
        regular &= np.isfinite(dc).all(axis=1)
    except np.linalg.LinAlgError:  # an exactly singular block stops the whole batch
        regular[:] = False
    if not regular.all():
        dc[~regular] = (np.linalg.pinv(V[~regular]) @ b_c[~regular, :, None])[:, :, 0]
    return dc


def _gauss_newton(design: Design, ev, normal):
    """Gauss-Newton on the windows alone (the states held) from the evaluation ``ev`` and its normal
    equations ``normal``: (coefficients (B, n_coef, 3), whitened residuals (rows, 3) there, the normal
    equations of the last evaluation, the windows found undetermined there). A step that predicts
    a reduction of at most LINEAR_REDUCTION is the last: its residuals are the linearised model's
    ``e + A_c dc`` (module docstring), not a new evaluation."""
    blk = design.blocks
    mask = np.repeat(blk.coef_mask, 3, axis=1)
    bad = np.zeros(0, dtype=np.int64)  # determined_design leaves no singular window at its start
    for _ in range(WINDOW_ITERATIONS):  # nearly linear in the windows
        dc = window_steps(masked_blocks(blk, normal.V), normal.b_c, bad) * mask
        reduction = float(np.sum(dc * normal.b_c))
        if not reduction > WINDOW_TOLERANCE:
            break
        if reduction <= LINEAR_REDUCTION:
            q = dc.shape[1]
            e = ev.e + np.einsum("rij,rj->ri", ev.Z[:, :, :q], dc[design.block])
            return ev.coef + dc.reshape(ev.coef.shape), e, normal, bad
        ev = evaluate(design, ev.x, ev.coef + dc.reshape(ev.coef.shape))
        normal = normal_equations(design, ev)
        bad = singular_blocks(design, normal)  # windows the plots do not determine here: they predict nothing
    return ev.coef, ev.e, normal, bad


def fit_windows(
    problem: FleetProblem | None, x: np.ndarray, options: BatchOptions, prior: WindowFit | None = None
) -> WindowFit:
    """The windows of the targets of ``problem`` (the registered labelled plots; None: none) fitted
    to its plots with the states held at ``x``: Gauss-Newton on the windows from the plots' means,
    or, where an earlier fit ``prior`` has the same window, from its coefficients (fewer steps)."""
    x = np.asarray(x, dtype=np.float64)
    if problem is None:
        return WindowFit.empty(x)
    found = (
        determined_design(problem, options, x, coefficients=_fitted)
        if prior is None
        else _warm_design(problem, options, x, prior)
    )
    if found is None:
        return WindowFit.empty(x)
    problem, design, ev, normal = found
    blk = design.blocks
    coef, e, normal, bad = _gauss_newton(design, ev, normal)
    V = normal.V.copy()
    q = V.shape[1]
    V[bad] += np.eye(q) * np.maximum(np.abs(V[bad]).max(axis=(1, 2)), 1.0)[:, None, None]
    V_inv, Y, _ = block_inverses(blk, replace(normal, V=V))
    determined = np.ones(blk.n_blocks, dtype=bool)
    determined[bad] = False
    windows = Windows(blk.n_coef, blk.block_target, blk.block_centre, blk.block_half, blk.coef_mask)
    residuals = np.where(design.weight > 0, e, np.nan)[design.slot]  # as the batch's residual table
    return WindowFit(
        tuple(str(t) for t in problem.target_ids),
        windows,
        coef,
        V_inv,
        Y,
        blk.local_state,
        determined,
        x,
        problem.layout.n,
        problem.row[blk.order],
        problem.target[blk.order],
        residuals,
    )
