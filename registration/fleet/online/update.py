"""The Kalman update of the online fleet filter in information form (:func:`information_update`,
the module docstring of :mod:`registration.fleet.online.filter`) and its starting point
(:func:`start_state`: the tables' priors, or a batch result)."""

from __future__ import annotations

import numpy as np

__all__ = ["DETERMINED_SHARE", "DIFFUSE", "PRIOR_DOMINATED", "information_update", "start_state"]

#: Prior sigma of a state without prior, in units of its reference scale (1 deg, 1 km).
DIFFUSE = 10.0
#: Directions of an epoch's scaled information below this share of its largest are not updated.
DETERMINED_SHARE = 1e-12
#: The innovation check leaves out the components whose prior variance exceeds this many times
#: their noise variance: such an innovation measures the spread of the prior, not the fit of the
#: data (the first epochs of states that start without prior, at DIFFUSE).
PRIOR_DOMINATED = 100.0


def information_update(
    x: np.ndarray, P: np.ndarray, L: np.ndarray, b: np.ndarray, free: np.ndarray, scale: np.ndarray
) -> tuple[np.ndarray, np.ndarray, float, int]:
    """The Kalman update of (x (n,), P (n, n)) with information ``L`` (n, n) and gradient ``b`` (n,)
    on the states ``free``, in coordinates scaled by ``scale`` (n,) (module docstring).
    Returns the new x and P (copies), the normalised innovation squared and its degrees of freedom,
    both over the innovation components whose prior variance is at most PRIOR_DOMINATED times their
    noise variance."""
    x, P = x.copy(), P.copy()
    d = scale[free]
    Ls = d[:, None] * L[np.ix_(free, free)] * d[None, :]
    w, V = np.linalg.eigh(0.5 * (Ls + Ls.T))
    keep = w > DETERMINED_SHARE * max(float(w[-1]) if w.size else 0.0, 0.0)
    if not keep.any():
        return x, P, 0.0, 0
    w, V = w[keep], V[:, keep]
    H = np.sqrt(w)[:, None] * V.T
    nu = (V.T @ (d * b[free])) / np.sqrt(w)
    Ps = P[np.ix_(free, free)] / d[:, None] / d[None, :]
    PHt = Ps @ H.T
    HPHt = H @ PHt
    S = HPHt + np.eye(w.size)
    K = np.linalg.solve(S, PHt.T).T
    A = np.eye(free.size) - K @ H
    Ps = A @ Ps @ A.T + K @ K.T
    x[free] += d * (K @ nu)
    P[np.ix_(free, free)] = d[:, None] * (0.5 * (Ps + Ps.T)) * d[None, :]
    lam, U = np.linalg.eigh(0.5 * (HPHt + HPHt.T))  # S = U diag(1 + lam) U^T
    tested = lam <= PRIOR_DOMINATED
    return x, P, float(np.sum((U.T @ nu)[tested] ** 2 / (1.0 + lam[tested]))), int(tested.sum())


def start_state(layout, prior) -> tuple[np.ndarray, np.ndarray]:
    """Initial estimate and covariance: the layout's priors, or a result over the same states."""
    n = layout.n
    if prior is None:
        sigma = np.where(np.isfinite(layout.prior_sigma), layout.prior_sigma, DIFFUSE * layout.scale)
        return np.zeros(n), np.diag(sigma**2)
    names = tuple(getattr(getattr(prior, "layout", None), "names", ()))
    if names != layout.names:
        raise ValueError(f"prior: its states {list(names)} are not this filter's {list(layout.names)}")
    x = np.array(prior.estimate, dtype=float)
    P = np.array(prior.covariance, dtype=float)
    if x.shape != (n,) or P.shape != (n, n) or not (np.isfinite(x).all() and np.isfinite(P).all()):
        raise ValueError(f"prior: expected a finite estimate ({n},) and covariance ({n}, {n})")
    fixed = layout.fixed
    x[fixed], P[fixed], P[:, fixed] = 0.0, 0.0, 0.0
    undetermined = ~np.isfinite(np.asarray(getattr(prior, "sigma", np.zeros(n)), dtype=float))
    P[np.diag_indices(n)] += np.where(
        undetermined & (layout.prior_sigma > 0), (DIFFUSE * layout.scale) ** 2, 0.0
    )
    return x, P
