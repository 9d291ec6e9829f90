"""One (damped) Gauss-Newton step of the batch problem with the target blocks eliminated by the
Schur complement, as in bundle adjustment.

With ``V_b`` the block of window b, ``W_g`` the coupling of group g (one sensor in one window)
with its w states (6, or 11 with the extended errors), ``U`` the states' block and damping
``lambda D`` (Marquardt: D the diagonal of the normal matrix):

* with the groups of block b side by side, ``W_b`` (q x w g) over the states ``local_state[b]``:
  ``Y_b = V_b^-1 W_b``, ``y_b = V_b^-1 b_c,b`` (batched inverses of the small blocks);
* ``S = U - sum_b W_b^T Y_b`` and ``r = b_x - sum_b W_b^T y_b``, each block's terms scattered
  into the states by index with ``bincount``;
* ``S_ff dx = r_f`` on the free states, solved in coordinates scaled by each state's prior (or
  reference) sigma within the directions the undamped information determines (scaled eigenvalue
  at least the core's UNOBSERVABLE_BELOW, :func:`determined_directions`): what the data cannot
  see is left where it is (minimum-norm step) and the damping cannot hide it;
* ``dc_b = y_b - Y_b dx[local_state[b]]``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.core.observability import UNOBSERVABLE_BELOW
from registration.fleet.batch.blocks import Blocks
from registration.fleet.batch.normal import Normal

__all__ = [
    "Reduced",
    "block_inverses",
    "determined_directions",
    "masked_blocks",
    "reduce",
    "solve_reduced",
    "damped_step",
    "super_blocks",
]


@dataclass
class Reduced:
    """The Schur complement on all states and what back-substitution needs."""

    S: np.ndarray  # (n + 1, n + 1); row/column n is the sink of absent biases
    r: np.ndarray  # (n + 1,)
    V_inv: np.ndarray  # (B, q, q)
    Y: np.ndarray  # (B, q, w g): V_b^-1 W_b over the block's local states
    y: np.ndarray  # (B, q)


def masked_blocks(blk: Blocks, V: np.ndarray) -> np.ndarray:
    """Put 1 on the diagonal of masked (unused) coefficients so the blocks can be inverted."""
    unused = np.repeat(~blk.coef_mask, 3, axis=1).astype(np.float64)  # (B, q), coefficient-major
    out = V.copy()
    q = V.shape[1]
    out[:, np.arange(q), np.arange(q)] += unused
    return out


def block_inverses(
    blk: Blocks, normal: Normal, lam: float = 0.0
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(V_inv (B, q, q), Y (B, q, w g [+ 1]), y (B, q)) of the target blocks damped by ``lam`` times
    their diagonal: what back-substitution and a window's covariance need, without the Schur
    complement (a fit of the windows with the states held needs only these)."""
    V = masked_blocks(blk, normal.V)
    q = V.shape[1]
    diag_V = V[:, np.arange(q), np.arange(q)]
    V[:, np.arange(q), np.arange(q)] += lam * diag_V
    V_inv = np.linalg.inv(V)
    V_inv = 0.5 * (V_inv + V_inv.transpose(0, 2, 1))
    Y = np.matmul(V_inv, normal.W)
    y = np.matmul(V_inv, normal.b_c[:, :, None])[:, :, 0]
    return V_inv, Y, y


def reduce(blk: Blocks, normal: Normal, lam: float = 0.0) -> Reduced:
    """Eliminate the target blocks (damped by ``lam`` times the diagonal)."""
    V_inv, Y, y = block_inverses(blk, normal, lam)
    W = normal.W  # (B, q, w g [+ 1])
    n1 = normal.U.shape[0]
    if blk.coupled_width > 6:
        WY, idx = _pattern_sums(blk, W, Y)
    else:
        WY = np.matmul(W.transpose(0, 2, 1), Y)  # (B, w g, w g)
        idx = blk.local_state
    flat = (idx[:, :, None] * n1 + idx[:, None, :]).reshape(-1)
    S: np.ndarray = normal.U - np.bincount(flat, WY.reshape(-1), n1 * n1).reshape(n1, n1)
    S[np.diag_indices(n1)] += lam * np.diag(normal.U)
    Wy = np.matmul(W.transpose(0, 2, 1), y[:, :, None])[:, :, 0]  # (B, w g)
    r = normal.b_x - np.bincount(blk.local_state.reshape(-1), Wy.reshape(-1), n1)
    return Reduced(0.5 * (S + S.T), r, V_inv, Y, y)


#: Above this many distinct patterns of states the blocks' products are scattered one by one.
MAX_PATTERNS = 64
#: Multiply-adds of one matrix product up to which OpenBLAS computes it on one thread (its
#: GEMM_MULTITHREAD_THRESHOLD, 4 x 65536). Above it the product waits for threads on other cores:
#: on a machine whose cores are busy with other work, the one product of a whole pattern took 50 to
#: 100 times as long as the same sums in products below it.
ONE_THREAD_PRODUCT = 4 * 65536


def super_blocks(block_pattern: np.ndarray, n_patterns: int, k: int) -> tuple[np.ndarray, np.ndarray]:
    """The blocks in pattern order, cut into *super-blocks* of ``k`` blocks of one pattern each:
    (the block of each place (S k,), -1 where a pattern's last super-block is padded; the first
    super-block of each pattern (n_patterns + 1,), the last entry S)."""
    counts = np.bincount(block_pattern, minlength=n_patterns)
    first = np.r_[0, np.cumsum(-(-counts // k))]
    order = np.argsort(block_pattern, kind="stable")
    pattern = block_pattern[order]
    rank = np.arange(order.size) - np.r_[0, np.cumsum(counts)[:-1]][pattern]
    place = np.full(first[-1] * k, -1, dtype=np.int64)
    place[first[pattern] * k + rank] = order
    return place, first


def _pattern_sums(blk: Blocks, W: np.ndarray, Y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(sum over the blocks of each pattern of W_b^T Y_b (K, L, L), the patterns' state indices
    (K, L)): the blocks whose groups hold the same states side by side (Blocks.patterns) summed
    before the scatter into the states, so that it is per pattern, not per block. Used with the
    extended errors (w = 11) and the eccentricity, where the per-block scatter of (w g)^2 entries
    dominated; the three-error path keeps its per-block sums (and so its results, bit for bit).

    The blocks of a pattern are taken ``k`` at a time (:func:`super_blocks`): one (L x k q)(k q x L)
    product each, with ``k`` as large as keeps a product on one thread (ONE_THREAD_PRODUCT) and
    the padding under a quarter of the blocks."""
    B, q, L = W.shape
    K = blk.patterns.shape[0]
    if K > MAX_PATTERNS:
        return np.matmul(W.transpose(0, 2, 1), Y), blk.local_state
    k = max(1, min(ONE_THREAD_PRODUCT // (L * L * q), B // (4 * K)))
    place, first = super_blocks(blk.block_pattern, K, k)
    pad = place < 0
    Ws, Ys = W[place], Y[place]
    Ws[pad], Ys[pad] = 0.0, 0.0
    P = np.matmul(Ws.reshape(-1, k * q, L).transpose(0, 2, 1), Ys.reshape(-1, k * q, L))
    WY = np.stack([P[a:b].sum(axis=0) for a, b in zip(first[:-1], first[1:], strict=True)])
    return WY, blk.patterns


def determined_directions(S: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """(n, k) orthonormal basis, in coordinates scaled by ``scale``, of the directions whose scaled
    information (undamped Schur complement ``S``) is at least UNOBSERVABLE_BELOW."""
    if S.shape[0] == 0:
        return np.zeros((0, 0))
    Ss = scale[:, None] * S * scale[None, :]
    w, v = np.linalg.eigh(0.5 * (Ss + Ss.T))
    return v[:, w >= UNOBSERVABLE_BELOW]


def solve_reduced(S: np.ndarray, r: np.ndarray, scale: np.ndarray, determined: np.ndarray) -> np.ndarray:
    """Solution of S dx = r within the ``determined`` directions (scaled coordinates): what the data
    and priors leave undetermined is not moved (the minimum-norm step)."""
    if S.shape[0] == 0 or determined.shape[1] == 0:
        return np.zeros(S.shape[0])
    Q = determined
    Ss = scale[:, None] * S * scale[None, :]
    z = np.linalg.solve(Q.T @ Ss @ Q, Q.T @ (scale * r))
    return scale * (Q @ z)


def damped_step(
    blk: Blocks, normal: Normal, free: np.ndarray, scale: np.ndarray, determined: np.ndarray, lam: float
):
    """The step (dx (n,), dcoef (B, n_coef, 3)) and its predicted cost reduction."""
    red = reduce(blk, normal, lam)
    n = normal.U.shape[0] - 1
    dx = np.zeros(n + 1)
    dx[free] = solve_reduced(red.S[np.ix_(free, free)], red.r[free], scale, determined)
    dc = red.y - np.matmul(red.Y, dx[blk.local_state][:, :, None])[:, :, 0]
    dc = dc * np.repeat(blk.coef_mask, 3, axis=1)
    # predicted reduction of the sum of squares for the damped step: d^T b + lam d^T D d
    q = dc.shape[1]
    diag_V = normal.V[:, np.arange(q), np.arange(q)]
    b_dot = float(dx[free] @ normal.b_x[free] + np.sum(dc * normal.b_c))
    damp = lam * float(np.sum(np.diag(normal.U)[free] * dx[free] ** 2) + np.sum(diag_V * dc**2))
    return dx[:n], dc.reshape(blk.n_blocks, blk.n_coef, 3), b_dot + damp
