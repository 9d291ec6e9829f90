"""GDOP: the root of the trace of a position covariance, in metres (the paper's eq. 18), from a
covariance or from a set of sample points."""

from __future__ import annotations

import numpy as np

from registration.core.validation import as_float_array

__all__ = ["gdop", "gdop_from_samples"]


def gdop(cov) -> np.ndarray:
    """GDOP (eq. 18) = sqrt(trace(cov)) in metres for a covariance (d, d) or a stack (..., d, d) in m^2."""
    c = as_float_array("cov", cov)
    if c.ndim < 2 or c.shape[-1] != c.shape[-2]:
        raise ValueError(f"cov: expected a square covariance (..., d, d) in m^2, got shape {c.shape}")
    return np.sqrt(np.trace(c, axis1=-2, axis2=-1))


def gdop_from_samples(p, truth=None) -> float:
    """GDOP (m) of sample points ``p`` (N, d) in metres.

    Without ``truth``: sqrt(trace of the sample covariance about the sample mean), the definition
    of eq. (18). With ``truth`` (d,): the root-mean-square distance to it (includes any bias).
    """
    x = as_float_array("p", p)
    if x.ndim != 2 or x.shape[0] < 2:
        raise ValueError(f"p: expected at least 2 sample points of shape (N, d) in metres, got {x.shape}")
    if truth is None:
        dev = x - x.mean(axis=0)
        return float(np.sqrt(np.sum(dev * dev) / (x.shape[0] - 1)))
    t = as_float_array("truth", truth)
    if t.shape != (x.shape[1],):
        raise ValueError(f"truth: expected shape ({x.shape[1]},) in metres, got {t.shape}")
    dev = x - t
    return float(np.sqrt(np.sum(dev * dev) / x.shape[0]))
