"""Input checks for the landing functions: shapes, units and ranges of lever arms, attitudes,
polar measurements and covariances, with errors that name the argument and its unit."""

from __future__ import annotations

import numpy as np

from registration.core.validation import as_float_array, check_finite, check_positive, check_range

__all__ = ["as_lever_arm", "as_attitude", "as_polar", "as_covariance", "common_count"]


def as_lever_arm(name: str, value) -> np.ndarray:
    """A (3,) deck-frame position, m."""
    arr = as_float_array(name, value)
    if arr.shape != (3,):
        raise ValueError(f"{name}: expected 3 numbers (m, deck axes), got shape {arr.shape}")
    check_finite(name, arr, "m")
    return arr


def as_attitude(attitude) -> np.ndarray:
    """(N, 3) [yaw deviation, pitch, roll], rad, each within [-pi/2, pi/2]; a (3,) input gives N = 1."""
    att = as_float_array("attitude", attitude)
    if att.ndim == 1:
        att = att.reshape(1, 3) if att.shape == (3,) else att
    if att.ndim != 2 or att.shape[1] != 3:
        raise ValueError(
            f"attitude: expected shape (3,) or (N, 3) [yaw, pitch, roll] in rad, got {att.shape}"
        )
    check_range("attitude", att, -np.pi / 2, np.pi / 2, "rad ([yaw deviation, pitch, roll])", angle=True)
    return att


def as_polar(name: str, value, width: int) -> np.ndarray:
    """(N, 3) [r m, a rad, b rad] (``width`` 3) or (N, 2) [a rad, b rad] (``width`` 2); r > 0,
    |a| <= 2 pi, |b| <= pi/2."""
    arr = as_float_array(name, value)
    if arr.ndim == 1:
        arr = arr.reshape(1, -1)
    if arr.ndim != 2 or arr.shape[1] != width:
        what = "[r m, a rad, b rad]" if width == 3 else "[a rad, b rad]"
        raise ValueError(f"{name}: expected shape ({width},) or (N, {width}) {what}, got {arr.shape}")
    check_finite(name, arr, "m / rad")
    if width == 3:
        check_positive(f"{name}[:, 0]", arr[:, 0], "m (range)")
        angles = arr[:, 1:]
    else:
        angles = arr
    check_range(f"{name} azimuth", angles[:, 0], -2 * np.pi, 2 * np.pi, "rad", angle=True)
    check_range(f"{name} elevation", angles[:, 1], -np.pi / 2, np.pi / 2, "rad", angle=True)
    return arr


def as_covariance(name: str, value, n: int, width: int) -> np.ndarray:
    """(n, width, width) covariances (m^2 for range, rad^2 for angles) with positive variances;
    a single (width, width) matrix is shared by all n points."""
    P = as_float_array(name, value)
    if P.shape == (width, width):
        P = np.broadcast_to(P, (n, width, width))
    if P.shape != (n, width, width):
        raise ValueError(
            f"{name}: expected shape ({width}, {width}) or ({n}, {width}, {width}), got {P.shape}"
        )
    check_finite(name, P, "m^2 / rad^2")
    diag = np.diagonal(P, axis1=1, axis2=2)
    if (diag <= 0).any():
        i = tuple(int(v) for v in np.argwhere(diag <= 0)[0])
        raise ValueError(
            f"{name}: variance at (point, component) {i} must be > 0 (units m^2 for range, rad^2 for angles)"
        )
    return np.asarray(P, dtype=np.float64)


def common_count(**arrays: np.ndarray) -> int:
    """The common number of rows N of arrays given with 1 or N rows each."""
    ns = {k: a.shape[0] for k, a in arrays.items()}
    big = {v for v in ns.values() if v != 1}
    if len(big) > 1:
        raise ValueError(f"point counts differ: {ns}; give one row or N rows each")
    return big.pop() if big else 1
