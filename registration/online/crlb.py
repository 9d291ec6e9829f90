"""Consistency statistics of the online filter: the Cramér-Rao bound with a prior, NEES and its interval.

The bound is ``CRLB_k = (P0^-1 + sum_{i<=k} H_i^T R_i^-1 H_i)^-1`` with H and R from the generated
pair model at the scenario's TRUE plots and attitudes (H is never re-derived here). For M runs of a
consistent filter with m dimensions, ``M * mean NEES ~ chi2(M m)``.
"""

from __future__ import annotations

import numpy as np

from registration._generated import api as generated
from registration.online.contract import SENSORS

__all__ = ["crlb_information", "nees_series", "crlb_from_information", "quadratic_forms"]


def crlb_information(scenario, sigma0=None, t_variant: str | None = None) -> np.ndarray:
    """Per-step Fisher information ``H_i^T R_i^-1 H_i`` (K, 12, 12) at the scenario's true values.

    H and R come from the generated ``pseudo_measurement_<t_variant>`` evaluated at the exact
    navigation, the TRUE attitude and the TRUE plots (``scenario.truth``), with the noise sigmas
    ``sigma0`` (default: those the scenario was simulated with). ``t_variant`` defaults to the
    variant the scenario was simulated with.
    """
    t_variant = t_variant or scenario.description.get("t_variant", "standard")
    sigma0 = np.asarray(scenario.sigma0 if sigma0 is None else sigma0, dtype=float)
    d, tr = scenario.data, scenario.truth
    ports = {}
    for p in SENSORS:
        ports[f"nav_{p}"] = np.stack([d[f"{p}_lat"], d[f"{p}_lon"], d[f"{p}_alt"]], axis=1)
        ports[f"att_{p}"] = np.stack([tr[f"{p}_heading"], tr[f"{p}_pitch"], tr[f"{p}_roll"]], axis=1)
        ports[f"meas_{p}"] = np.asarray(tr[f"{p}_plot"], dtype=float)
    out = generated.pseudo_measurement(t_variant=t_variant, sigma0=sigma0, **ports)
    H, R = out.H, out.R
    RinvH = np.linalg.solve(R, H)  # (K, 3, 12)
    info = np.einsum("kai,kaj->kij", H, RinvH)
    return 0.5 * (info + info.transpose(0, 2, 1))


def nees_series(err: np.ndarray, P: np.ndarray, T: np.ndarray) -> np.ndarray:
    """NEES of the part ``T x`` of the state: ``e^T (T P T^T)^-1 e`` with ``e = T err``.

    ``err`` (runs, K, n) estimate - truth, ``P`` (runs, K, n, n) the filter covariances, ``T``
    (m, n) the directions. Returns (runs, K).
    """
    e = err @ T.T
    C = quadratic_forms(P, T)
    return np.einsum("rkq,rkq->rk", e, np.linalg.solve(C, e[..., None])[..., 0])


def _unit_rows(T: np.ndarray):
    """For T whose rows each hold one or two entries equal to 1 and zeros elsewhere: the first and
    last column of each row's ones and whether it has two; None for any other T."""
    ones = T == 1.0
    counts = ones.sum(axis=1)
    if T.ndim != 2 or not ((ones | (T == 0.0)).all() and ((counts == 1) | (counts == 2)).all()):
        return None
    first = np.argmax(ones, axis=1)
    last = T.shape[1] - 1 - np.argmax(ones[:, ::-1], axis=1)
    return first, last, counts == 2


def quadratic_forms(P: np.ndarray, T: np.ndarray, *, diagonal: bool = False) -> np.ndarray:
    """``T P T^T`` for a stack of finite matrices P (..., n, n) and directions T (m, n): (..., m, m),
    or only its diagonal (..., m) (the variances along the directions, in P's units).

    Directions that are single states or sums of two (rows of T holding one or two ones) are
    gathered and added: each stage of ``numpy.einsum('qi,...ij,pj->...qp', T, P, T, optimize=True)``
    (over i, then over j) adds at most two non-zero terms, so the result is the einsum's bit for
    bit, without its large intermediates. Any other T goes through that einsum.
    """
    T = np.asarray(T, dtype=float)
    unit = _unit_rows(T) if T.size else None
    if unit is None:
        if diagonal:
            return np.einsum("qi,...ij,qj->...q", T, P, T, optimize=True)
        return np.einsum("qi,...ij,pj->...qp", T, P, T, optimize=True)
    a, b, pair = unit
    if diagonal:  # (P_aa + P_ba) + (P_ab + P_bb) for a sum, P_aa for a state
        out = P[..., a, a]
        if pair.any():
            ap, bp = a[pair], b[pair]
            out[..., pair] = (P[..., ap, ap] + P[..., bp, ap]) + (P[..., ap, bp] + P[..., bp, bp])
        return out
    # C_qp = (P[a_q, a_p] + P[b_q, a_p]) + (P[a_q, b_p] + P[b_q, b_p]), the b terms only for sums
    C = P[..., a[:, None], a[None, :]]
    if pair.any():
        bq = b[pair][:, None]
        C[..., pair, :] += P[..., bq, a[None, :]]
        second = P[..., a[:, None], bq.T]
        second[..., pair, :] += P[..., bq, bq.T]
        C[..., pair] += second
    return C


def crlb_from_information(info_steps: np.ndarray, prior_sigma) -> np.ndarray:
    """``(P0^-1 + cumsum information)^-1`` for every step (K, 12, 12)."""
    p0_inv = np.diag(1.0 / np.square(np.asarray(prior_sigma, dtype=float)))
    J = p0_inv[None] + np.cumsum(info_steps, axis=0)
    # scale to unit diagonal before inverting: the states mix radians and metres
    s = 1.0 / np.sqrt(np.einsum("kii->ki", J))
    Js = s[:, :, None] * J * s[:, None, :]
    C = s[:, :, None] * np.linalg.inv(Js) * s[:, None, :]
    return 0.5 * (C + C.transpose(0, 2, 1))
