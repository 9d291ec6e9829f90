"""The trajectories of the anchor targets that tracks are tested against (:mod:`.attach`), with
their uncertainty.

* **Registered targets** (target ids given, reference targets with plots, targets the
  position-fixing sensors confirmed): the batch's own trajectory model, each window a cubic in
  ECEF (:mod:`registration.fleet.batch.blocks`), fitted to the registered plots with the states
  held at the estimate ``x`` (Gauss-Newton on the windows from their plots' means, or from an
  earlier fit's windows: :func:`.windowfit.fit_windows`). Its coefficients ``c_b`` have the covariance
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

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from registration.fleet.association.joining.windowfit import WindowFit, Windows, fit_windows
from registration.fleet.batch.solver import BatchOptions
from registration.fleet.data.known_targets import References, SurfaceTargets
from registration.fleet.data.problem import FleetProblem

__all__ = ["Curves", "NO_HEIGHT_SIGMA_M", "Prediction", "anchor_curves"]

#: The vertical sigma (m) a reference position without a height predicts with when its target is not
#: on a surface of known height.
NO_HEIGHT_SIGMA_M = 1000.0


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
class Curves:
    """Anchor targets ``names`` (the first ``n_batch`` registered, the others reference-only) and
    what predicts their positions (module docstring). ``blocks`` the batch windows (:class:`Windows`),
    ``order`` those determined, sorted by (target, centre); per window ``coef`` (B, K, 3) m, ``V_inv``
    (B, q, q), ``Y`` (B, q, w g), ``local`` (B, w g) state indices (n: none). References sorted by
    (target, time): ``ref_target`` (R,) index into ``names``, ``ref_time`` (R,) s, ``ref_p`` (R, 3)
    m, ``ref_sigma`` (R,) m. ``fit``: the windows' :class:`WindowFit`."""

    names: tuple
    n_batch: int
    blocks: Windows
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
    fit: WindowFit

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
            for axis in range(3):
                A[:, axis, axis::3] = basis
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
    assert sigma_up is not None  # References fills it in (with sigma where not given)
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
