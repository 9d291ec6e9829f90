"""The statistics of the residual diagnostics, on one sensor's normalised residuals of one channel
(dimensionless, ``(measured - predicted) / sigma``) and a scale ``s`` (their standard deviation
under "the model fits": 1, or more where the residuals spread wider than the stated sigma):

* :func:`bin_means`: the mean per bin, its ``z = mean / (s / sqrt(n))`` and the chi-square of the
  bin means against zero, ``sum z^2`` over ``B - 1`` degrees of freedom (the sensor's bias, estimated,
  takes out the overall mean);
* :func:`sinusoid_fit`: ``e = c + a sin(theta) + b cos(theta)`` by least squares (equal weights:
  one sensor, one sigma), the amplitude ``sqrt(a^2 + b^2)`` and its z (the two-degree-of-freedom
  chi-square of (a, b) as the two-sided normal z of the same tail probability);
* :func:`slope_fit`: ``e = c + k x``, the slope and its z;
* :func:`best_step`: the difference of the means after and before each candidate time, the largest
  ``|z|`` (a maximum over the candidates: its threshold is a Bonferroni over them);
* :func:`group_difference`: the mean of a group of plots against the mean of the others.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.core.distributions import chi2_sf, norm_isf

__all__ = [
    "BinMeans",
    "Fit",
    "Step",
    "best_step",
    "bin_means",
    "group_difference",
    "p_to_z",
    "sinusoid_fit",
    "slope_fit",
]

#: Fewest values a bin, group or fit needs to be tested.
MIN_VALUES = 10


def p_to_z(p: float) -> float:
    """The two-sided standard normal ``|z|`` of tail probability ``p`` (so a chi-square test and a z
    test share one threshold)."""
    return float(norm_isf(max(float(p), 1e-300) / 2.0))


@dataclass(frozen=True)
class BinMeans:
    """Per bin (B,): ``n`` values, ``mean`` normalised residual, ``z`` of the mean (NaN below
    MIN_VALUES values); ``chi2`` of the tested bins' z against ``dof`` (tested bins - 1), its ``p``."""

    n: np.ndarray
    mean: np.ndarray
    z: np.ndarray
    chi2: float
    dof: int
    p: float


def bin_means(e: np.ndarray, bins: np.ndarray, n_bins: int, s: float) -> BinMeans:
    """:class:`BinMeans` of normalised residuals ``e`` (M,) in bins ``bins`` (M,; 0..n_bins-1)."""
    n = np.bincount(bins, minlength=n_bins).astype(float)
    total = np.bincount(bins, weights=e, minlength=n_bins)
    mean = np.divide(total, n, out=np.full(n_bins, np.nan), where=n > 0)
    z = np.where(n >= MIN_VALUES, mean * np.sqrt(n) / s, np.nan)
    tested = np.isfinite(z)
    q, dof = float(np.sum(z[tested] ** 2)), int(tested.sum()) - 1
    p = float(chi2_sf(q, dof)) if dof > 0 else float("nan")
    return BinMeans(n.astype(int), mean, z, q, dof, p)


@dataclass(frozen=True)
class Fit:
    """A fitted term: ``value`` (normalised-residual units per unit of the regressor), its
    ``sigma``, ``z`` and the ``n`` values fitted; ``phase`` (rad) for a sinusoid, else NaN."""

    value: float
    sigma: float
    z: float
    n: int
    phase: float = float("nan")


_NO_FIT = Fit(float("nan"), float("nan"), float("nan"), 0)


def _least_squares(X: np.ndarray, e: np.ndarray, s: float) -> tuple[np.ndarray, np.ndarray] | None:
    """(coefficients, covariance) of ``e = X c`` with residual sigma ``s``; None if X is singular."""
    normal = X.T @ X
    if np.linalg.cond(normal) > 1e12:
        return None
    cov = np.linalg.inv(normal) * s * s
    return cov @ (X.T @ e), cov


def sinusoid_fit(e: np.ndarray, theta: np.ndarray, s: float) -> Fit:
    """``e = c + a sin(theta) + b cos(theta)`` (``theta`` rad): amplitude ``sqrt(a^2 + b^2)``, its
    sigma (delta method), z (:func:`p_to_z` of the chi-square of (a, b) on 2 degrees of freedom) and
    ``phase = atan2(b, a)`` (the sinusoid is ``amplitude sin(theta + phase)``)."""
    if e.size < MIN_VALUES:
        return _NO_FIT
    found = _least_squares(np.column_stack([np.ones_like(theta), np.sin(theta), np.cos(theta)]), e, s)
    if found is None:
        return _NO_FIT
    c, cov = found
    ab, cab = c[1:], cov[1:, 1:]
    amplitude = float(np.hypot(*ab))
    q = float(ab @ np.linalg.solve(cab, ab))
    u = ab / amplitude if amplitude > 0 else np.array([1.0, 0.0])
    sigma = float(np.sqrt(u @ cab @ u))
    return Fit(amplitude, sigma, p_to_z(float(chi2_sf(q, 2))), int(e.size), float(np.arctan2(ab[1], ab[0])))


def slope_fit(e: np.ndarray, x: np.ndarray, s: float) -> Fit:
    """``e = c + k x``: the slope ``k`` (per unit of ``x``), its sigma and z."""
    if e.size < MIN_VALUES:
        return _NO_FIT
    x0 = x - np.mean(x)
    found = _least_squares(np.column_stack([np.ones_like(x0), x0]), e, s)
    if found is None:
        return _NO_FIT
    c, cov = found
    sigma = float(np.sqrt(cov[1, 1]))
    return Fit(float(c[1]), sigma, float(c[1]) / sigma, int(e.size))


@dataclass(frozen=True)
class Step:
    """The best single step: at ``time`` (s), ``size`` (mean after - mean before, normalised units),
    its ``sigma``, ``z``, the ``candidates`` tried."""

    time: float
    size: float
    sigma: float
    z: float
    candidates: int


def best_step(e: np.ndarray, t: np.ndarray, edges: np.ndarray, s: float) -> Step:
    """The step of largest ``|z|`` among the inner ``edges`` (s) of the time bins, each splitting
    the values at times ``t`` (s) into before and after (both at least MIN_VALUES values)."""
    inner = np.asarray(edges, dtype=float)[1:-1]
    if e.size < 2 * MIN_VALUES or inner.size == 0:
        return Step(float("nan"), float("nan"), float("nan"), float("nan"), int(inner.size))
    order = np.argsort(t, kind="stable")
    cum = np.concatenate([[0.0], np.cumsum(e[order])])
    k = np.searchsorted(t[order], inner, side="left")  # values before each candidate
    n1, n2 = k.astype(float), float(e.size) - k
    ok = (n1 >= MIN_VALUES) & (n2 >= MIN_VALUES)
    if not ok.any():
        return Step(float("nan"), float("nan"), float("nan"), float("nan"), int(inner.size))
    n1, n2, k, at = n1[ok], n2[ok], k[ok], inner[ok]
    size = (cum[-1] - cum[k]) / n2 - cum[k] / n1
    sigma = s * np.sqrt(1.0 / n1 + 1.0 / n2)
    z = size / sigma
    i = int(np.argmax(np.abs(z)))
    return Step(float(at[i]), float(size[i]), float(sigma[i]), float(z[i]), int(inner.size))


def group_difference(e: np.ndarray, member: np.ndarray, s: float) -> Fit:
    """The mean of the values where ``member`` minus the mean of the others, its sigma and z
    (NaN when either side has fewer than MIN_VALUES values)."""
    n1, n2 = int(member.sum()), int((~member).sum())
    if n1 < MIN_VALUES or n2 < MIN_VALUES:
        return _NO_FIT
    d = float(np.mean(e[member]) - np.mean(e[~member]))
    sigma = s * float(np.sqrt(1.0 / n1 + 1.0 / n2))
    return Fit(d, sigma, d / sigma, n1)
