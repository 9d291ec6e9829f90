"""Batched linear algebra on stacks of tiny matrices (d <= 3), held "structure of arrays".

A matrix stack is (rows, cols, N) and a vector stack (rows, N): every entry is one contiguous
array of N values, so each product is a handful of whole-array operations (much faster in numpy
than ``(N, d, d) @ (N, d, d)``). :func:`soa` and :func:`aos` convert from and to the usual
leading-axis layout (N, ...). :func:`forward_solve` takes leading-axis stacks of larger
triangular systems (the association's tests: up to 60 x 60).
"""

from __future__ import annotations

import numpy as np

__all__ = ["soa", "aos", "mm", "mv", "transpose", "sym", "sandwich", "inv", "forward_solve"]


def soa(m: np.ndarray) -> np.ndarray:
    """(N, ...) -> (..., N), contiguous: a leading-axis stack to structure of arrays."""
    return np.ascontiguousarray(np.moveaxis(m, 0, -1))


def aos(m: np.ndarray) -> np.ndarray:
    """(..., N) -> (N, ...), contiguous: structure of arrays back to a leading-axis stack."""
    return np.ascontiguousarray(np.moveaxis(m, -1, 0))


def mm(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Matrix products of two stacks: (i, k, N) x (k, j, N) -> (i, j, N)."""
    out = a[:, 0, None, :] * b[None, 0, :, :]
    for k in range(1, a.shape[1]):
        out += a[:, k, None, :] * b[None, k, :, :]
    return out


def mv(a: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Matrix-vector products: (i, k, N) x (k, N) -> (i, N)."""
    out = a[:, 0, :] * v[0]
    for k in range(1, a.shape[1]):
        out += a[:, k, :] * v[k]
    return out


def transpose(a: np.ndarray) -> np.ndarray:
    """Transpose of every matrix of a (i, j, N) stack: (j, i, N), a view."""
    return a.transpose(1, 0, 2)


def sym(m: np.ndarray) -> np.ndarray:
    """Symmetric part (m + m^T) / 2 of a (d, d, N) stack."""
    return 0.5 * (m + transpose(m))


def sandwich(a: np.ndarray, diag: np.ndarray) -> np.ndarray:
    """a diag(diag) a^T: a (i, k, N), diag (k, N) -> symmetric (i, i, N).

    The covariance of ``a x`` for ``x`` with independent components of variances ``diag``.
    """
    return sym(mm(a * diag[None, :, :], transpose(a)))


def inv(m: np.ndarray) -> np.ndarray:
    """Inverse of a (d, d, N) stack, d = 2 or 3, by the adjugate.

    Raises ValueError when a matrix is singular to working precision (a degenerate geometry):
    |det| not above 1e-13 times a bound on it (the Hadamard bound in 3-D).
    """
    d = m.shape[0]
    out = np.empty_like(m)
    if d == 2:
        a, b, c, e = m[0, 0], m[0, 1], m[1, 0], m[1, 1]
        det = a * e - b * c
        scale = np.abs(a * e) + np.abs(b * c)
        out[0, 0], out[0, 1], out[1, 0], out[1, 1] = e, -b, -c, a
    else:
        r0, r1, r2 = m[0], m[1], m[2]
        out[:, 0] = np.cross(r1, r2, axis=0)
        out[:, 1] = np.cross(r2, r0, axis=0)
        out[:, 2] = np.cross(r0, r1, axis=0)
        det = np.sum(r0 * out[:, 0], axis=0)
        scale = np.sqrt(np.sum(r0 * r0, axis=0) * np.sum(r1 * r1, axis=0) * np.sum(r2 * r2, axis=0))
    bad = ~(np.abs(det) > 1e-13 * scale)
    if bad.any():
        i = int(np.argwhere(bad)[0][0])
        raise ValueError(f"singular {d}x{d} covariance or information matrix at row {i}: degenerate geometry")
    out /= det
    return out


def forward_solve(L: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``L^-1 b`` for lower-triangular ``L`` (c, m, m) and ``b`` (c, m) or (c, m, p): forward
    substitution, row by row over the m rows, each row for all c pairs at once. A general batched
    solve factorises each triangular L again (LU, m^3 / 3 per pair instead of m^2 / 2): with
    m = 60 (20 plots of 3 values) that was most of the pairs' tests."""
    y = np.empty(b.shape, dtype=np.result_type(L, b))
    for i in range(L.shape[1]):
        acc = b[:, i]
        if i:
            acc = acc - np.einsum("cj,cj...->c...", L[:, i, :i], y[:, :i])
        y[:, i] = acc / (L[:, i, i] if b.ndim == 2 else L[:, i, i, None])
    return y
