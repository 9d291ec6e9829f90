"""Symmetric and triangular matrix pieces in CasADi SX, shared by the Kalman steps of
derive/kalman.py and the association tracker's filter of derive/tracking.py (one definition each):
a symmetric matrix from its upper triangle, sums by pairs, the Cholesky factors with the
reciprocals of their diagonals, and forward and back substitution with them.
"""

import casadi as ca

__all__ = [
    "backward_substitution",
    "chol_lower",
    "chol_upper",
    "forward_substitution",
    "mirror_upper",
    "tree_sum",
    "whitened",
]


def mirror_upper(A: ca.SX) -> ca.SX:
    """Symmetric matrix from the upper triangle of A: the lower entries are never computed
    (about 20 % fewer operations in the step than averaging A and A^T)."""
    n = A.shape[0]
    out = ca.SX.zeros(n, n)
    for i in range(n):
        for j in range(i, n):
            out[i, j] = A[i, j]
            out[j, i] = A[i, j]
    return out


def tree_sum(terms) -> ca.SX:
    """Sum by pairs: a dependency chain of log2(n) additions instead of n (the C compiler keeps the
    order CasADi writes, and the step's time is bound by its longest chain, not its operations)."""
    terms = list(terms)
    if not terms:
        return ca.SX(0)
    while len(terms) > 1:
        terms = [terms[i] + terms[i + 1] if i + 1 < len(terms) else terms[i] for i in range(0, len(terms), 2)]
    return terms[0]


def chol_upper(A: ca.SX) -> tuple[ca.SX, list]:
    """Upper-triangular U with positive diagonal and ``A = U U^T`` (A symmetric positive definite;
    only its upper triangle is read), and the reciprocals of its diagonal. The diagonal is a square
    root of a Schur complement s of A: NaN, never a silently wrong factor, if A is not numerically
    positive definite. ``1/U_jj = sqrt(1/s)`` and ``U_jj = s sqrt(1/s)``: one division per column
    (CasADi folds a product with ``1/d`` back into a division, and divisions, not products, bound
    the step's time)."""
    n = A.shape[0]
    U = ca.SX.zeros(n, n)
    inv: list = [None] * n  # 1/U_jj, filled from the last column
    for j in reversed(range(n)):
        s = A[j, j] - tree_sum(U[j, k] ** 2 for k in range(j + 1, n))
        inv[j] = ca.sqrt(1 / s)
        U[j, j] = s * inv[j]
        for i in range(j):
            U[i, j] = (A[i, j] - tree_sum(U[i, k] * U[j, k] for k in range(j + 1, n))) * inv[j]
    return U, inv


def chol_lower(A: ca.SX) -> tuple[ca.SX, list]:
    """Lower-triangular L with positive diagonal and ``A = L L^T`` (only the lower triangle of A is
    read; from the upper factor of A reversed, :func:`chol_upper`), and the reciprocals of its
    diagonal."""
    m = A.shape[0]
    J = ca.SX(ca.DM.eye(m)[list(reversed(range(m))), :])
    U, inv = chol_upper(J @ A @ J)
    return J @ U @ J, inv[::-1]


def forward_substitution(L: ca.SX, inv: list, B: ca.SX) -> ca.SX:
    """``L^-1 B`` for lower-triangular L with the reciprocals ``inv`` of its diagonal, row by row."""
    rows: list = []
    for i in range(L.shape[0]):
        acc = B[i, :] - sum((L[i, k] * rows[k] for k in range(i)), ca.SX.zeros(1, B.shape[1]))
        rows.append(acc * inv[i])
    return ca.vertcat(*rows)


def backward_substitution(L: ca.SX, inv: list, Y: ca.SX) -> ca.SX:
    """``L^-T Y`` for lower-triangular L with the reciprocals ``inv`` of its diagonal, row by row
    from the last."""
    m = L.shape[0]
    rows: list = [None] * m
    for i in reversed(range(m)):
        acc = Y[i, :] - sum((L[k, i] * rows[k] for k in range(i + 1, m)), ca.SX.zeros(1, Y.shape[1]))
        rows[i] = acc * inv[i]
    return ca.vertcat(*rows)


def whitened(R: ca.SX, H: ca.SX) -> ca.SX:
    """``L^-1 H`` with L the lower Cholesky factor of R (:func:`chol_lower`), by forward
    substitution: rows of unit noise."""
    return forward_substitution(*chol_lower(R), H)
