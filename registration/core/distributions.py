"""Quantiles and tail probabilities of the chi-square and standard normal distributions, as
scipy.stats computes them (the same scipy.special functions), without importing scipy.stats: that
import costs about a second, which every command and every Dask worker that loads the association
paid at start.

``dof`` may be an array (broadcast against the probabilities); degrees of freedom must be positive.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike
from scipy import special

__all__ = ["chi2_ppf", "chi2_sf", "chi2_logsf", "norm_isf"]


def chi2_ppf(q: ArrayLike, dof: ArrayLike) -> np.ndarray:
    """The chi-square quantile: x with P(X <= x) = ``q`` for X ~ chi2(``dof``). With one ``q`` and
    many ``dof`` (a gate per tested pair: a few distinct values among thousands), each distinct
    value is computed once (the inverse incomplete gamma function costs microseconds a value)."""
    dof = np.asarray(dof, dtype=float)
    if np.ndim(q) == 0 and dof.size > 16:
        values, inverse = np.unique(dof, return_inverse=True)
        return (2.0 * special.gammaincinv(values / 2.0, q))[inverse].reshape(dof.shape)
    return 2.0 * special.gammaincinv(dof / 2.0, q)


def chi2_sf(x: ArrayLike, dof: ArrayLike) -> np.ndarray:
    """The chi-square tail probability P(X > ``x``) for X ~ chi2(``dof``)."""
    return special.chdtrc(dof, x)


def chi2_logsf(x: ArrayLike, dof: ArrayLike) -> np.ndarray:
    """log P(X > ``x``) for X ~ chi2(``dof``); -inf where the tail underflows (near 1, through
    log1p of the lower tail, for its last digits)."""
    sf = special.chdtrc(dof, x)
    with np.errstate(divide="ignore"):
        return np.where(sf > 0.5, np.log1p(-special.chdtr(dof, x)), np.log(sf))


def norm_isf(q: ArrayLike) -> np.ndarray:
    """The standard normal's upper quantile: z with P(Z > z) = ``q``."""
    return -special.ndtri(q)
