"""The trajectories of the anchor targets that tracks are tested against (:mod:`.attach`), with
their uncertainty.

* **Registered targets** (target ids given, reference targets with plots, targets the
  position-fixing sensors confirmed): the batch's own trajectory model, each window a cubic in
  ECEF (:mod:`registration.fleet.batch.blocks`), fitted to the registered plots with the states
  held at the estimate ``x`` (Gauss-Newton on the windows from their plots' means, or from an
  earlier fit's windows: :func:`fit_windows`). Its coefficients ``c_b`` have the covariance
  ``V_b^-1`` given the states and move with them as ``dc_b = -Y_b dx`` (``Y_b = V_b^-1 W_b`` over
  the window's local states, :mod:`registration.fleet.batch.schur`): the covariance of the curve is
  ``V_b^-1 + Y_b P Y_b^T`` and its covariance with the states ``-Y_b P``.
* **Reference-only targets** (ADS-B, AIS positions of targets no plot has been joined to yet):
  the reference positions interpolated linearly in time between two positions at most
  ``reference_gap_s`` apart, with the variance ``(1 - w)^2 s_a^2 + w^2 s_b^2 + (a (t - t_a)
  (t_b - t) / 2)^2`` per axis (``s``: the positions' sigmas, ``a``: ``reference_accel_sigma``,
  the bound of the linear interpolation's error under that acceleration; ``s`` the larger of the
  horizontal and vertical sigma; a reference without a height takes as its vertical sigma its
  target's surface sigma, or :data:`NO_HEIGHT_SIGMA_M` off a surface); independent of the states.

Windows are located by the plots' reported times (as the batch cuts them) and evaluated at the
time each plot was seen (reported time minus its sensor's estimated time bias).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from registration.fleet.batch.blocks import Blocks
from registration.fleet.batch.initial import initial_coefficients
from registration.fleet.batch.normal import evaluate, normal_equations
from registration.fleet.batch.schur import masked_blocks, reduce
from registration.fleet.batch.solver import BatchOptions, determined_design, singular_blocks
from registration.fleet.data.known_targets import References, SurfaceTargets
from registration.fleet.data.problem import FleetProblem

__all__ = [
    "Curves",
    "NO_HEIGHT_SIGMA_M",
    "Prediction",
    "WindowFit",
    "anchor_curves",
    "fit_windows",
    "join_fits",
]

#: The vertical sigma (m) a reference position without a height predicts with when its target is not
#: on a surface of known height.
NO_HEIGHT_SIGMA_M = 1000.0

#: Gauss-Newton steps on the target windows at most when their curves are fitted with the states held.
WINDOW_ITERATIONS = 10
#: ... until a step would lower the sum of squares by less than this (chi-square units).
WINDOW_TOLERANCE = 1e-4


@dataclass(frozen=True)
class Prediction:
    """Per query (M,): ``p`` (M, 3) ECEF m, ``v`` (M, 3) m/s, ``block`` (M,) the batch window (-1 for
    a reference-only target), ``A`` (M, 3, q) d p / d coefficients of the window (0 for references),
    ``cov`` (M, 3, 3) m^2 the position's own covariance for a reference-only target (0 else)."""

    p: np.ndarray
    v: np.ndarray
    block: np.ndarray
    A: np.ndarray
    cov: np.ndarray


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
        return Blocks.basis_and_rate_at(self, block, time)

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


@dataclass(frozen=True)
class Curves:
    """Anchor targets ``names`` (the first ``n_batch`` registered, the others reference-only) and
    what predicts their positions (module docstring). ``blocks`` the batch windows (:class:`Windows`),
    ``order`` those determined, sorted by (target, centre); per window ``coef`` (B, K, 3) m, ``V_inv``
    (B, q, q), ``Y`` (B, q, w g), ``local`` (B, w g) state indices (n: none). References sorted by
    (target, time): ``ref_target`` (R,) index into ``names``, ``ref_time`` (R,) s, ``ref_p`` (R, 3)
    m, ``ref_sigma`` (R,) m. ``fit``: the windows' :class:`WindowFit`."""

    names: tuple
    n_batch: int
    blocks: object
    order: np.ndarray
    coef: np.ndarray
    V_inv: np.ndarray
    Y: np.ndarray
    local: np.ndarray
    ref_target: np.ndarray
    ref_time: np.ndarray
    ref_p: np.ndarray
    ref_sigma: np.ndarray
    gap_s: float
    accel_sigma: float
    fit: WindowFit | None = None

    @property
    def n_targets(self) -> int:
        return len(self.names)

    @cached_property
    def Y_states(self) -> np.ndarray:
        """(B, q, n + 1) each window's ``Y`` over all the states (index n: none); a state that two of
        its groups share (a platform's attitude) gets the sum of their columns."""
        B, q, w = self.Y.shape
        out = np.zeros((B, q, self.fit.n_state + 1))
        rows = np.arange(B)
        for i in range(w):
            out[rows, :, self.local[:, i]] += self.Y[:, :, i]
        return out

    def _windows(self, target: int, t_report: np.ndarray) -> np.ndarray:
        """(M,) the batch window of ``target`` holding each reported time, -1 for none."""
        blk = self.blocks
        sel = self.order[blk.block_target[self.order] == target]
        out = np.full(t_report.size, -1, dtype=np.int64)
        if sel.size == 0:
            return out
        lo = blk.block_centre[sel] - blk.block_half[sel]
        k = np.clip(np.searchsorted(lo, t_report, side="right") - 1, 0, sel.size - 1)
        inside = np.abs(t_report - blk.block_centre[sel[k]]) <= blk.block_half[sel[k]] * (1 + 1e-9) + 1e-9
        out[inside] = sel[k[inside]]
        return out

    def _brackets(self, target: int, t_seen: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(index of the reference position at or before each time (-1: none usable), weight w of the
        next one) for a reference-only target."""
        sel = np.flatnonzero(self.ref_target == target)
        out = np.full(t_seen.size, -1, dtype=np.int64)
        if sel.size < 2:
            return out, np.zeros(t_seen.size)
        t = self.ref_time[sel]
        a = np.clip(np.searchsorted(t, t_seen, side="right") - 1, 0, sel.size - 2)
        span = t[a + 1] - t[a]
        ok = (t_seen >= t[a]) & (t_seen <= t[a + 1]) & (span <= self.gap_s) & (span > 0)
        out[ok] = sel[a[ok]]
        return out, np.where(ok, (t_seen - t[a]) / np.where(span > 0, span, 1.0), 0.0)

    def covered(self, target: int, t_report: np.ndarray, t_seen: np.ndarray) -> np.ndarray:
        """(M,) bool: the target's position is predicted at these times (s)."""
        if target < self.n_batch:
            return self._windows(target, t_report) >= 0
        return self._brackets(target, t_seen)[0] >= 0

    def predict(self, target: int, t_report: np.ndarray, t_seen: np.ndarray) -> Prediction:
        """The prediction of ``target`` at the times (each must be :meth:`covered`)."""
        m = t_report.size
        q = 3 * (self.coef.shape[1] if self.coef.size else 4)
        A, cov = np.zeros((m, 3, q)), np.zeros((m, 3, 3))
        if target < self.n_batch:
            block = self._windows(target, t_report)
            basis, rate = self.blocks.basis_and_rate_at(block, t_seen)
            p = np.einsum("mk,mkj->mj", basis, self.coef[block])
            v = np.einsum("mk,mkj->mj", rate, self.coef[block])
            for a in range(3):
                A[:, a, a::3] = basis
            return Prediction(p, v, block, A, cov)
        a, w = self._brackets(target, t_seen)
        b = a + 1
        span = self.ref_time[b] - self.ref_time[a]
        p = (1 - w)[:, None] * self.ref_p[a] + w[:, None] * self.ref_p[b]
        v = (self.ref_p[b] - self.ref_p[a]) / span[:, None]
        bend = 0.5 * self.accel_sigma * (t_seen - self.ref_time[a]) * (self.ref_time[b] - t_seen)
        var = ((1 - w) * self.ref_sigma[a]) ** 2 + (w * self.ref_sigma[b]) ** 2 + bend**2
        cov[:] = var[:, None, None] * np.eye(3)
        return Prediction(p, v, np.full(m, -1, dtype=np.int64), A, cov)


def _window_keys(names: tuple, windows) -> list:
    """(target name, centre, half length in microseconds) of each window."""
    centre = np.round(windows.block_centre * 1e6).astype(np.int64).tolist()
    half = np.round(windows.block_half * 1e6).astype(np.int64).tolist()
    return [(names[t], c, h) for t, c, h in zip(windows.block_target.tolist(), centre, half)]


def _start_coefficients(design, names: tuple, x: np.ndarray, prior: WindowFit) -> np.ndarray:
    """(B, K, 3) starting coefficients: the plots' window means (the batch's start), and for each
    window that ``prior`` determined (same target, centre, length and degree) its coefficients there."""
    blk = design.blocks
    coef = initial_coefficients(design, x)
    if not prior.names or blk.n_blocks == 0 or prior.coef.shape[1:] != coef.shape[1:]:
        return coef
    known = {key: i for i, key in enumerate(_window_keys(prior.names, prior.windows)) if prior.determined[i]}
    i = np.array([known.get(key, -1) for key in _window_keys(names, blk)], dtype=np.int64)
    b = np.flatnonzero(i >= 0)
    b = b[(prior.windows.coef_mask[i[b]] == blk.coef_mask[b]).all(axis=1)]
    coef[b] = prior.coef[i[b]]
    return coef


def _warm_design(problem: FleetProblem, options: BatchOptions, x: np.ndarray, prior: WindowFit):
    """:func:`~registration.fleet.batch.solver.determined_design` started from :func:`_start_coefficients`."""
    return determined_design(
        problem,
        options,
        x,
        coefficients=lambda p, design, x0: _start_coefficients(
            design, tuple(str(t) for t in p.target_ids), x0, prior
        ),
    )


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
        determined_design(problem, options, x) if prior is None else _warm_design(problem, options, x, prior)
    )
    if found is None:
        return WindowFit.empty(x)
    problem, design, ev, normal = found
    blk = design.blocks
    mask = np.repeat(blk.coef_mask, 3, axis=1)
    for _ in range(WINDOW_ITERATIONS):  # Gauss-Newton on the windows alone (nearly linear in them)
        V = masked_blocks(blk, normal.V)
        dc = (np.linalg.pinv(V) @ normal.b_c[:, :, None])[:, :, 0] * mask
        if not float(np.sum(dc * normal.b_c)) > WINDOW_TOLERANCE:
            break
        ev = evaluate(design, ev.x, ev.coef + dc.reshape(ev.coef.shape))
        normal = normal_equations(design, ev)
    bad = singular_blocks(design, normal)  # windows the plots do not determine here: they predict nothing
    V = normal.V.copy()
    q = V.shape[1]
    V[bad] += np.eye(q) * np.maximum(np.abs(V[bad]).max(axis=(1, 2)), 1.0)[:, None, None]
    red = reduce(blk, replace(normal, V=V), 0.0)
    determined = np.ones(blk.n_blocks, dtype=bool)
    determined[bad] = False
    windows = Windows(blk.n_coef, blk.block_target, blk.block_centre, blk.block_half, blk.coef_mask)
    residuals = np.where(design.weight > 0, ev.e, np.nan)[design.slot]  # as the batch's residual table
    return WindowFit(
        tuple(str(t) for t in problem.target_ids),
        windows,
        ev.coef,
        red.V_inv,
        red.Y,
        blk.local_state,
        determined,
        x,
        problem.layout.n,
        problem.row[blk.order],
        problem.target[blk.order],
        residuals,
    )


def anchor_curves(
    problem: FleetProblem | None,
    x: np.ndarray,
    refs: References,
    options: BatchOptions,
    *,
    gap_s: float,
    accel_sigma: float,
    fit: WindowFit | None = None,
    surface: SurfaceTargets | None = None,
) -> Curves:
    """The anchors: the targets of ``problem`` (the registered labelled plots; None: none) under the
    estimate ``x``, then the reference targets of ``refs`` that are not among them. ``fit``: their
    windows already fitted (:func:`fit_windows`; then ``problem`` is not used). ``surface``: the
    targets on a surface (the vertical sigma of their references without a height)."""
    fit = fit if fit is not None else fit_windows(problem, x, options)
    names, blk, coef, V_inv, Y, local = fit.names, fit.windows, fit.coef, fit.V_inv, fit.Y, fit.local
    order = np.lexsort((blk.block_centre, blk.block_target))
    order = order[fit.determined[order]]
    own = set(names)
    rt = refs.target.astype(str)
    extra = [t for t in dict.fromkeys(rt) if t not in own]
    index = {t: len(names) + k for k, t in enumerate(extra)}
    k = np.array([index.get(t, -1) for t in rt], dtype=np.int64)
    keep = k >= 0
    order_r = np.lexsort((refs.time[keep], k[keep]))
    sigma_up = refs.sigma_up
    if not np.isfinite(sigma_up).all():
        on = surface.of(rt)[1] if surface is not None else np.full(rt.size, np.nan)
        sigma_up = np.where(np.isfinite(sigma_up), sigma_up, np.where(np.isfinite(on), on, NO_HEIGHT_SIGMA_M))
    return Curves(
        names + tuple(extra),
        len(names),
        blk,
        order,
        coef,
        V_inv,
        Y,
        local,
        k[keep][order_r],
        refs.time[keep][order_r],
        refs.p_ecef[keep][order_r],
        np.maximum(refs.sigma, sigma_up)[keep][order_r],
        float(gap_s),
        float(accel_sigma),
        fit,
    )
