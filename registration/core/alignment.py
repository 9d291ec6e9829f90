"""Time alignment: sliding-window least-squares polynomial fits evaluated at requested instants.

Wang, Liu, Gao, "A self-calibration method based on fusion of landing guidance radar and
centerline camera" (Ship Science and Technology 39(3), 2017), eqs. (5)-(6): each measured
coordinate is fitted over a window of samples with a small basis and the fit is evaluated at the
fusion instants. This module is sensor-agnostic: give it one
sensor's timestamps ``t`` (s) and samples ``y`` (one or many columns) and the instants at which
you need values; it tells you which instants could not be evaluated and why.

Numerics. For every requested instant ``tau`` the window's times are centred and scaled,
``u = (t - tau) / s`` with ``s`` the largest ``|t - tau|`` in the window, so ``u`` lies in [-1, 1],
and the basis is the Legendre polynomials ``P_0..P_degree`` in ``u`` (the same span as
``1, u, ..., u^degree``, better conditioned). The least-squares problem is solved by the
SVD-based pseudo-inverse, batched over windows (no normal equations). Because the fit is linear in
the data, the value at ``tau`` is ``sum_i w_i y_i`` with smoother weights ``w`` that depend only on
the times; they are computed once per window and applied to every column, so many columns (or
many Monte Carlo runs sharing one clock) cost one fit. ``variance_factor = sum_i w_i^2`` is the
variance of the fitted value per unit variance of one sample when the sample noise is white,
which the fusion uses to weight sensors honestly.

Clocks. A sensor whose clock reads ``reference time + clock_offset_s`` is aligned by passing
``clock_offset_s``; its timestamps are shifted onto the reference clock before fitting.

Units: times in seconds; ``y`` in whatever units it has (angle columns in radians, see
``angle_columns``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.polynomial import legendre

from registration.core.angles import wrap_angle
from registration.core.validation import as_float_array

__all__ = [
    "AlignedSamples",
    "align",
    "REASON_OK",
    "REASON_TOO_FEW",
    "REASON_EXTRAPOLATION",
    "REASON_ILL_CONDITIONED",
]

REASON_OK = ""
REASON_TOO_FEW = "too few samples"
REASON_EXTRAPOLATION = "extrapolation beyond limit"
REASON_ILL_CONDITIONED = "ill-conditioned window"

#: windows whose scaled design matrix has a larger 2-norm condition number are refused
MAX_CONDITION = 1.0e8


@dataclass(frozen=True)
class AlignedSamples:
    """Result of :func:`align` for M requested instants and K columns.

    Attributes:
        t: (M,) requested instants on the reference clock, s.
        y: (M, K) fitted values (NaN where ``valid`` is False); a 1-D ``y`` input gives (M, 1).
        valid: (M,) True where the instant could be evaluated.
        reason: (M,) why an instant could not be evaluated ("" when valid).
        variance_factor: (M,) variance of the fitted value divided by the variance of one sample,
            for white sample noise (NaN where invalid). 1/n for a mean of n samples.
        n_samples: (M,) samples in the window.
        extrapolation_s: (M,) how far the instant lies outside the window's sample span, s.
        degree: polynomial degree used.
    """

    t: np.ndarray
    y: np.ndarray
    valid: np.ndarray
    reason: np.ndarray
    variance_factor: np.ndarray
    n_samples: np.ndarray
    extrapolation_s: np.ndarray
    degree: int

    @property
    def invalid_instants(self) -> np.ndarray:
        """The requested instants (s) that could not be evaluated."""
        return self.t[~self.valid]


def _check_times(name: str, t: np.ndarray) -> None:
    if t.ndim != 1:
        raise ValueError(f"{name}: expected a 1-D array of times in s, got shape {t.shape}")
    bad = ~np.isfinite(t)
    if bad.any():
        i = int(np.argmax(bad))
        raise ValueError(f"{name}: non-finite time {float(t[i])} at index {i}; expected finite times in s")


def _check_sample_times(t: np.ndarray) -> None:
    _check_times("t", t)
    d = np.diff(t)
    if (d == 0).any():
        i = int(np.argmax(d == 0))
        raise ValueError(
            f"t: duplicate timestamp {float(t[i])!r} s at indices {i} and {i + 1}; timestamps must be "
            "strictly increasing"
        )
    if (d < 0).any():
        i = int(np.argmax(d < 0))
        raise ValueError(
            f"t: timestamps not sorted: t[{i}] = {float(t[i])!r} s > t[{i + 1}] = {float(t[i + 1])!r} s; "
            "sort the samples by time first"
        )


def _windows_half_width(t: np.ndarray, tau: np.ndarray, half: float) -> tuple[np.ndarray, np.ndarray]:
    lo = np.searchsorted(t, tau - half, side="left")
    hi = np.searchsorted(t, tau + half, side="right")
    return lo, hi - lo


def _windows_nearest(t: np.ndarray, tau: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    """The n samples nearest each instant form a contiguous run [lo, lo + n): pick the tightest."""
    m = t.size
    if n > m:
        return np.zeros(tau.size, dtype=np.intp), np.full(tau.size, m, dtype=np.intp)
    i = np.searchsorted(t, tau)
    cand = np.clip(i[:, None] - n + np.arange(n + 1)[None, :], 0, m - n)  # (W, n+1) candidate starts
    spread = np.maximum(np.abs(tau[:, None] - t[cand]), np.abs(t[cand + n - 1] - tau[:, None]))
    lo = cand[np.arange(tau.size), np.argmin(spread, axis=1)]
    return lo, np.full(tau.size, n, dtype=np.intp)


def _check_samples(t, y) -> tuple[np.ndarray, np.ndarray]:
    """Timestamps (n,) and samples as (n, K)."""
    t = as_float_array("t", t)
    _check_sample_times(t)
    y = as_float_array("y", y)
    y2 = y.reshape(-1, 1) if y.ndim == 1 else y
    if y2.ndim != 2 or y2.shape[0] != t.size:
        raise ValueError(f"y: expected shape ({t.size},) or ({t.size}, K) to match t, got {y.shape}")
    bad = ~np.isfinite(y2)
    if bad.any():
        i, k = (int(v) for v in np.argwhere(bad)[0])
        raise ValueError(
            f"y: non-finite sample {float(y2[i, k])} at index {i}, column {k} (t = {float(t[i])!r} s); "
            "remove or fill it before aligning"
        )
    return t, y2


def _check_instants(t_eval) -> np.ndarray:
    tau = as_float_array("t_eval", t_eval)
    tau = tau.reshape(-1) if tau.ndim == 0 else tau
    _check_times("t_eval", tau)
    return tau


def _check_options(
    degree, half_window_s, n_nearest, max_extrapolation_s, clock_offset_s, angle_columns, n_columns: int
) -> tuple[int, list[int]]:
    """Validated degree and angle column indices."""
    if not isinstance(degree, (int, np.integer)) or degree < 0:
        raise ValueError(f"degree: expected an integer >= 0, got {degree!r}")
    degree = int(degree)
    if (half_window_s is None) == (n_nearest is None):
        raise ValueError("give exactly one of half_window_s (s) and n_nearest (samples)")
    if half_window_s is not None and not (np.isfinite(half_window_s) and half_window_s > 0):
        raise ValueError(f"half_window_s: expected a finite number > 0 s, got {half_window_s!r}")
    if n_nearest is not None and (not isinstance(n_nearest, (int, np.integer)) or n_nearest < degree + 1):
        raise ValueError(
            f"n_nearest: expected an integer >= degree + 1 = {degree + 1} samples, got {n_nearest!r}"
        )
    if not (np.isfinite(max_extrapolation_s) and max_extrapolation_s >= 0):
        raise ValueError(f"max_extrapolation_s: expected a finite number >= 0 s, got {max_extrapolation_s!r}")
    if not np.isfinite(clock_offset_s):
        raise ValueError(f"clock_offset_s: expected a finite number in s, got {clock_offset_s!r}")
    cols = [int(c) for c in angle_columns]
    for c in cols:
        if not -n_columns <= c < n_columns:
            raise ValueError(f"angle_columns: column {c} does not exist (y has {n_columns} columns)")
    return degree, cols


def _windows(t_ref: np.ndarray, tau: np.ndarray, half_window_s, n_nearest) -> tuple[np.ndarray, np.ndarray]:
    """Each instant's window as first sample index and sample count."""
    if half_window_s is not None:
        return _windows_half_width(t_ref, tau, float(half_window_s))
    return _windows_nearest(t_ref, tau, int(n_nearest))


def _screen(
    t_ref: np.ndarray, tau: np.ndarray, lo: np.ndarray, n: np.ndarray, p: int, max_extrapolation_s: float
) -> tuple[np.ndarray, np.ndarray]:
    """Per instant: the reason it cannot be evaluated before fitting ("" if none) and its
    distance (s) outside its window's sample span (inf for an empty window)."""
    reason = np.full(tau.size, REASON_OK, dtype=object)
    ext = np.full(tau.size, np.inf)
    has = n > 0
    first = t_ref[np.minimum(lo, t_ref.size - 1)]
    last = t_ref[np.clip(lo + n - 1, 0, t_ref.size - 1)]
    ext[has] = np.maximum(0.0, np.maximum(first[has] - tau[has], tau[has] - last[has]))
    reason[n < p] = REASON_TOO_FEW
    # a tiny tolerance so an instant exactly on the limit is accepted despite rounding
    too_far = (n >= p) & (ext > max_extrapolation_s * (1 + 1e-12) + 1e-12)
    reason[too_far] = REASON_EXTRAPOLATION
    return reason, ext


def _fit_windows(
    t_ref: np.ndarray, y2: np.ndarray, tau: np.ndarray, lo: np.ndarray, n: np.ndarray, degree: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Fit W windows (``lo``, ``n``) and evaluate at ``tau`` (W,): values (W, K), variance
    factors (W,) and which windows are well conditioned (W,)."""
    nmax = int(n.max())
    offs = np.arange(nmax)
    mask = offs[None, :] < n[:, None]  # (W, nmax)
    idx = np.minimum(lo[:, None] + offs[None, :], t_ref.size - 1)
    dt = np.where(mask, t_ref[idx] - tau[:, None], 0.0)
    scale = np.abs(dt).max(axis=1)
    scale[scale == 0] = 1.0  # a window of one sample exactly at tau (degree 0)
    u = dt / scale[:, None]
    V = legendre.legvander(u, degree) * mask[..., None]  # (W, nmax, p); padded rows are zero
    sv = np.linalg.svd(V, compute_uv=False)
    cond = sv[:, 0] / np.where(sv[:, -1] > 0, sv[:, -1], np.finfo(float).tiny)
    good = cond <= MAX_CONDITION
    e0 = legendre.legvander(np.zeros(1), degree)[0]  # basis values at u = 0, i.e. at tau
    w = np.einsum("p,wpn->wn", e0, np.linalg.pinv(V))  # smoother weights at tau
    w = np.where(mask, w, 0.0)
    vals = np.einsum("wn,wnk->wk", w, y2[idx])
    return vals, np.sum(w * w, axis=1), good


def _fit_instants(
    t_ref: np.ndarray,
    y2: np.ndarray,
    tau: np.ndarray,
    lo: np.ndarray,
    n: np.ndarray,
    degree: int,
    reason: np.ndarray,
    chunk: int,
) -> tuple[np.ndarray, np.ndarray]:
    """Fitted values (M, K) and variance factors (M,) at every instant not yet refused in
    ``reason`` (NaN elsewhere), ``chunk`` windows at a time; ill-conditioned windows are marked
    in ``reason`` (in place)."""
    out = np.full((tau.size, y2.shape[1]), np.nan)
    vf = np.full(tau.size, np.nan)
    todo = np.flatnonzero(reason == REASON_OK)
    for start in range(0, todo.size, chunk):
        sel = todo[start : start + chunk]
        vals, factors, good = _fit_windows(t_ref, y2, tau[sel], lo[sel], n[sel], degree)
        reason[sel[~good]] = REASON_ILL_CONDITIONED
        out[sel[good]] = vals[good]
        vf[sel[good]] = factors[good]
    return out, vf


def _refuse_first_invalid(
    tau: np.ndarray,
    valid: np.ndarray,
    reason: np.ndarray,
    n: np.ndarray,
    ext: np.ndarray,
    degree: int,
    max_extrapolation_s: float,
) -> None:
    i = int(np.argmax(~valid))
    detail = {
        REASON_TOO_FEW: f"its window holds {int(n[i])} sample(s) but degree {degree} needs at least "
        f"{degree + 1}",
        REASON_EXTRAPOLATION: (
            f"it lies {ext[i]:.6g} s outside its window's samples, beyond max_extrapolation_s = "
            f"{max_extrapolation_s:g} s"
        ),
        REASON_ILL_CONDITIONED: "its window's sample times are too clustered (condition number > "
        f"{MAX_CONDITION:g})",
    }[reason[i]]
    raise ValueError(
        f"t_eval: instant {float(tau[i])!r} s (index {i}) cannot be evaluated: {detail}. "
        f"{int((~valid).sum())} of {tau.size} instants fail; pass strict=False to get them flagged instead"
    )


def _wrap_columns(out: np.ndarray, cols: list[int]) -> None:
    """Wrap the angle columns of ``out`` to (-pi, pi] in place."""
    out[:, cols] = wrap_angle(out[:, cols])


def align(
    t,
    y,
    t_eval,
    *,
    degree: int = 2,
    half_window_s: float | None = None,
    n_nearest: int | None = None,
    max_extrapolation_s: float = 0.0,
    clock_offset_s: float = 0.0,
    angle_columns: tuple[int, ...] | list[int] = (),
    strict: bool = True,
    chunk: int = 2048,
) -> AlignedSamples:
    """Fit a sliding-window least-squares polynomial to (t, y) and evaluate it at ``t_eval``.

    Args:
        t: (n,) sample timestamps in s on the sensor's clock; strictly increasing, finite.
        y: (n,) or (n, K) samples; finite. Each column is fitted independently with the same
            window and basis (many columns cost one fit).
        t_eval: (M,) instants in s on the reference clock at which values are wanted.
        degree: polynomial degree d >= 0 (the basis has d + 1 functions; a window needs at least
            d + 1 samples).
        half_window_s: window = the samples with ``|t - tau| <= half_window_s`` (s, > 0) ...
        n_nearest: ... or the ``n_nearest`` samples closest to ``tau`` (give exactly one of the two).
        max_extrapolation_s: largest allowed distance (s, >= 0) from ``tau`` to the window's sample
            span [first, last]; 0 allows interpolation only.
        clock_offset_s: the sensor clock reads reference time + this offset (s); subtracted from ``t``.
        angle_columns: columns holding angles in rad: unwrapped along time before fitting and the
            results wrapped to (-pi, pi].
        strict: if True (default) raise ValueError naming the first instant that cannot be
            evaluated; if False return it flagged in ``valid``/``reason``.
        chunk: windows processed per batch (memory bound).

    Returns:
        :class:`AlignedSamples`.

    Raises:
        ValueError: unsorted or duplicate timestamps, non-finite times or samples, bad options,
            or (``strict``) an instant with too few samples, beyond the extrapolation limit or
            with an ill-conditioned window.
    """
    t, y2 = _check_samples(t, y)
    tau = _check_instants(t_eval)
    degree, cols = _check_options(
        degree, half_window_s, n_nearest, max_extrapolation_s, clock_offset_s, angle_columns, y2.shape[1]
    )
    t_ref = t - clock_offset_s
    if cols:
        y2 = y2.copy()
        y2[:, cols] = np.unwrap(y2[:, cols], axis=0)
    lo, n = _windows(t_ref, tau, half_window_s, n_nearest)
    reason, ext = _screen(t_ref, tau, lo, n, degree + 1, max_extrapolation_s)

    out, vf = _fit_instants(t_ref, y2, tau, lo, n, degree, reason, chunk)
    valid = reason == REASON_OK
    if strict and not valid.all():
        _refuse_first_invalid(tau, valid, reason, n, ext, degree, max_extrapolation_s)
    if cols:
        _wrap_columns(out, cols)
    return AlignedSamples(
        t=tau,
        y=out,
        valid=valid,
        reason=reason,
        variance_factor=vf,
        n_samples=n.astype(int),
        extrapolation_s=ext,
        degree=degree,
    )
