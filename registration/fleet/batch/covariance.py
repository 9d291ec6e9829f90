"""Uncertainty at the solution: the states' covariance (the inverse of the information with the
target trajectories eliminated: the Cramér-Rao bound at the estimate) and the fused target
positions with their covariance.

Directions of the state space that the data (and priors) do not determine, scaled eigenvalue
below the core's UNOBSERVABLE_BELOW (see :mod:`registration.fleet.observability`), are left out
of the inverse (a pseudo-inverse): the covariance then describes the determined combinations
only, and the states involved in the left-out directions are reported with sigma ``inf``.

A target position at time t in window b is ``p = sum_k P_k(tau) c_bk``. The coefficients' covariance is
``V_b^-1 + Y_b P Y_b^T`` (``Y_b = V_b^-1 W_b``: how the registration estimate moves them).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.core.observability import UNOBSERVABLE_BELOW, ObservabilityReport
from registration.fleet.batch.normal import Evaluation, Normal, positions
from registration.fleet.batch.schur import Reduced, reduce
from registration.fleet.batch.solver import NumericalError, singular_blocks
from registration.fleet.data.layout import StateLayout
from registration.fleet.observability import fleet_observability
from registration.fleet.result import FusedTargets

__all__ = [
    "Solution",
    "StateUncertainty",
    "estimate_from_information",
    "fused_targets",
    "instant_covariance",
    "solution_information",
    "state_covariance",
]


@dataclass
class Solution:
    """Residuals, normal equations and their reduction at the estimate (undamped)."""

    evaluation: Evaluation
    normal: Normal
    reduced: Reduced
    information_data: np.ndarray  # (n_free, n_free): data only (priors removed)
    information: np.ndarray  # (n_free, n_free): data and priors


def solution_information(fit) -> Solution:
    """The information at the solution (from the fit's own residuals and normal equations).
    :class:`~registration.fleet.batch.solver.NumericalError` (an internal error, not bad input) if a
    window's block cannot be inverted there, which the solver's checks at the solution exclude."""
    ev, normal = fit.evaluation, fit.normal
    try:
        red = reduce(fit.design.blocks, normal, 0.0)
    except np.linalg.LinAlgError as exc:
        bad = singular_blocks(fit.design, normal)
        names = sorted({fit.problem.target_ids[t] for t in fit.design.blocks.block_target[bad]})
        raise NumericalError(
            f"the information at the solution cannot be computed: {bad.size} target windows "
            f"(targets {', '.join(names) or 'unknown'}) are singular there ({exc})"
        ) from exc
    free = fit.problem.layout.free
    S = red.S[np.ix_(free, free)]
    prior = fit.design.prior_weight[free] ** 2
    return Solution(ev, normal, red, S - np.diag(prior), S)


def state_covariance(information: np.ndarray, scale: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(covariance (n, n), left-out directions (n, k) in scaled coordinates) of the free states.

    Pseudo-inverse of ``information`` in coordinates scaled by ``scale`` (prior or reference
    sigma), leaving out directions whose scaled eigenvalue is below UNOBSERVABLE_BELOW.
    """
    n = information.shape[0]
    if n == 0:
        return np.zeros((0, 0)), np.zeros((0, 0))
    Js = scale[:, None] * information * scale[None, :]
    w, v = np.linalg.eigh(0.5 * (Js + Js.T))
    keep = w >= UNOBSERVABLE_BELOW
    P = (v[:, keep] / w[keep]) @ v[:, keep].T
    return scale[:, None] * P * scale[None, :], v[:, ~keep]


@dataclass(frozen=True)
class StateUncertainty:
    """What the information at an estimate gives of its states (units of the layout: rad, m, 1, s).

    ``covariance`` (n, n) (zero rows and columns for the fixed states), ``sigma`` (n,) (inf: leans on
    a direction the data do not determine), ``undetermined`` (free, k) the directions left out of the
    covariance in scaled coordinates, ``scale`` (free,) the free states' scale, ``status`` per state
    name ("fixed" or the observability report's word) and the observability ``report``.
    """

    covariance: np.ndarray
    sigma: np.ndarray
    undetermined: np.ndarray
    scale: np.ndarray
    status: dict[str, str]
    report: ObservabilityReport


def estimate_from_information(
    layout: StateLayout,
    information: np.ndarray,
    information_data: np.ndarray,
    sensor_platform: np.ndarray,
    platform_ids: tuple,
    sensor_ids: tuple,
) -> StateUncertainty:
    """The states' covariance, sigma and status from the ``information`` (free, free) of the free
    states with their priors and ``information_data`` (free, free) of the data alone (the
    observability report is of that one), for the fleet of ``layout`` (its sensors' platforms
    ``sensor_platform`` (S,) indices into ``platform_ids``; ``sensor_ids``)."""
    free = layout.free
    report = fleet_observability(information_data, free, layout, sensor_platform, platform_ids, sensor_ids)
    scale = layout.scale[free]
    P_free, undetermined = state_covariance(information, scale)
    n = layout.n
    P = np.zeros((n, n))
    P[np.ix_(free, free)] = P_free
    sigma = np.sqrt(np.clip(np.diag(P), 0, None))
    status = {layout.names[i]: "fixed" for i in layout.fixed}
    status.update(report.status)
    if undetermined.size:  # states leaning on a direction left out of the covariance
        sigma[free[np.linalg.norm(undetermined, axis=1) > 0.1]] = np.inf
    return StateUncertainty(P, sigma, undetermined, scale, status, report)


def _coefficient_covariance(blk, red: Reduced, P_full: np.ndarray) -> np.ndarray:
    """(B, q, q) covariance of each window's coefficients: V_b^-1 + Y_b P_b Y_b^T."""
    idx = blk.local_state
    P_local = P_full[idx[:, :, None], idx[:, None, :]]  # (B, w g, w g)
    cov = red.V_inv + np.matmul(np.matmul(red.Y, P_local), red.Y.transpose(0, 2, 1))
    return 0.5 * (cov + cov.transpose(0, 2, 1))


def instant_covariance(basis: np.ndarray, block: np.ndarray, cov_c: np.ndarray) -> np.ndarray:
    """(M, 3, 3) covariance of the positions ``p = sum_k basis_k c_k`` of M instants (``basis`` (M, K)
    in windows ``block`` (M,)) from their windows' coefficient covariances ``cov_c`` (B, 3 K, 3 K),
    coefficient-major: ``sum_k sum_m basis_k basis_m C_km`` with ``C_km`` the (3, 3) block of
    coefficients k and m, the pairs m > k taken once with their transposes. As
    ``(basis (x) I3) cov_c (basis (x) I3)^T`` per instant, without gathering each instant's whole
    window covariance (144 numbers an instant: 200 MB for the 10-radar benchmark's 180 000)."""
    K = basis.shape[1]
    C = cov_c.reshape(-1, K, 3, K, 3)
    cov = np.zeros((block.size, 3, 3))
    for k in range(K):
        for m in range(k, K):
            C_km = np.ascontiguousarray(C[:, k, :, m, :])[block]
            if m > k:
                C_km += C_km.transpose(0, 2, 1)
            cov += (basis[:, k] * basis[:, m])[:, None, None] * C_km
    return cov


def fused_targets(fit, red: Reduced, P_full: np.ndarray) -> FusedTargets:
    """Fused positions and covariances at every measured instant of every target (with time
    biases: the reported times corrected by the estimated biases; the covariance leaves out the
    time biases' own uncertainty)."""
    blk, problem = fit.design.blocks, fit.problem
    time = fit.design.seen_time(fit.x)[fit.design.slot]  # the true instants: reported minus any time bias
    ticks = np.round(time * 1e6).astype(np.int64)
    order = np.lexsort((ticks, blk.block))
    new = np.r_[True, (np.diff(blk.block[order]) != 0) | (np.diff(ticks[order]) != 0)]
    first = order[new]
    counts = np.diff(np.r_[np.flatnonzero(new), order.size])
    block, t = blk.block[first], time[first]
    basis = blk.basis_at(block, t)
    p = positions(basis, block, fit.coef)
    cov = instant_covariance(basis, block, _coefficient_covariance(blk, red, P_full))
    target = np.array(problem.target_ids, dtype=str)[blk.block_target[block]]
    by_target = np.lexsort((t, blk.block_target[block]))
    return FusedTargets(target[by_target], t[by_target], p[by_target], cov[by_target], counts[by_target])
