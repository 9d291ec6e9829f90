"""The terms of the reference positions and the surface heights in the batch normal equations
(:mod:`registration.fleet.batch.normal`).

A reference position ``y`` of a target is linear in its window's coefficients: its residual is
``e = L (y - sum_k basis_k c_k)`` with a whitening ``L`` that does not depend on the point (the
scalar ``1/sigma``, or :func:`registration.fleet.batch.design.reference_whitening`). Its share of
the window block, ``V += sum basis_k basis_m L^T L``, is therefore the same at every iteration:
:func:`reference_information` computes it once, when the design is made
(:attr:`registration.fleet.batch.design.Design.ref_information`), and each normal equations add it
(:func:`add_reference_terms`) with only the gradient ``b_c += basis_k L^T e`` computed anew. On an
imported ATC day (ADS-B positions every second, more of them than radar plots) the share took a
fifth of every pass of the partitioned solver. The numbers are those of computing it each time, bit
for bit: each entry of ``V`` receives one reference term either way.

The surface heights' whitening depends on the point (the Jacobian of the height), so their terms
are computed whole at each evaluation (:func:`add_whitened_terms`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fleet.batch.blocks import Blocks

__all__ = [
    "ReferenceInformation",
    "add_reference_terms",
    "add_whitened_terms",
    "reference_information",
    "whitened_information",
]


def whitened_information(
    block: np.ndarray, basis: np.ndarray, whiten: np.ndarray, n_blocks: int
) -> np.ndarray:
    """(B, K, 3, K, 3) ``sum basis_k basis_m L^T L`` over the positions in each block: positions in
    blocks ``block`` (R,) with basis values ``basis`` (R, K) and whitening rows ``whiten`` (R, a, 3)."""
    K, B = basis.shape[1], n_blocks
    rows = np.ascontiguousarray(whiten.transpose(1, 2, 0))  # (a, 3, R)
    products = np.zeros((3, 3, block.size))  # L^T L, (3, 3, R): sums over a in order, as einsum's
    for row in rows:
        products += row[:, None, :] * row[None, :, :]
    gram = products.reshape(9, -1)
    at9 = (block[None, :] * 9 + np.arange(9)[:, None]).reshape(-1)  # gram's order; each bin's terms by r
    out = np.zeros((B, K, 3, K, 3))
    for k in range(K):
        for m in range(k, K):  # the (m, k) term is the (k, m) one, number for number
            w = (basis[:, k] * basis[:, m])[None, :] * gram
            term = np.bincount(at9, w.reshape(-1), 9 * B).reshape(B, 3, 3)
            out[:, k, :, m, :] = term
            if m != k:
                out[:, m, :, k, :] = term
    return out


def _whitened_gradient(
    block: np.ndarray, basis: np.ndarray, whiten: np.ndarray, e: np.ndarray, b_c: np.ndarray
) -> None:
    """Add ``basis_k L^T e`` of residuals ``e`` (R, a) to b_c (B, K, 3) in place."""
    K, B = b_c.shape[1], b_c.shape[0]
    grad = np.einsum("rai,ra->ri", whiten, e)  # L^T e
    at3 = (block[:, None] * 3 + np.arange(3)).reshape(-1)
    for k in range(K):
        b_c[:, k, :] += np.bincount(at3, (basis[:, k, None] * grad).reshape(-1), 3 * B).reshape(B, 3)


def add_whitened_terms(
    block: np.ndarray, basis: np.ndarray, whiten: np.ndarray, e: np.ndarray, V: np.ndarray, b_c: np.ndarray
) -> None:
    """Add to V (B, K, 3, K, 3) and b_c (B, K, 3) in place the terms of residuals ``e`` (R, a) =
    ``L (y - p(t))`` (up to a constant) of positions in blocks ``block`` (R,) with basis values
    ``basis`` (R, K) and whitening rows ``whiten`` (R, a, 3): ``V += basis_k basis_m L^T L``,
    ``b_c += basis_k L^T e``."""
    V += whitened_information(block, basis, whiten, V.shape[0])
    _whitened_gradient(block, basis, whiten, e, b_c)


def reference_information(
    blk: Blocks, ref_weight: np.ndarray, whiten: np.ndarray | None
) -> np.ndarray | None:
    """(B, K, 3, K, 3) the reference positions' share of the window blocks: with the scalar weights
    ``ref_weight`` (R',) 1/m, or with the whitening matrices ``whiten`` (R', 3, 3) 1/m; None when
    no reference is used."""
    if blk.ref_block.size == 0:
        return None
    K, B = blk.n_coef, blk.n_blocks
    if whiten is not None:
        return whitened_information(blk.ref_block, blk.ref_basis, whiten, B)
    w2 = ref_weight**2
    out = np.zeros((B, K, 3, K, 3))
    for k in range(K):
        for m in range(k, K):  # the (m, k) term is the (k, m) one, number for number
            ref = np.bincount(blk.ref_block, blk.ref_basis[:, k] * blk.ref_basis[:, m] * w2, B)
            out[:, k, np.arange(3), m, np.arange(3)] = ref[:, None]
            if m != k:
                out[:, m, np.arange(3), k, np.arange(3)] = ref[:, None]
    return out


@dataclass(frozen=True)
class ReferenceInformation:
    """The references' share ``V`` (B_r, K, 3, K, 3) of the window blocks ``rows`` (B_r,) that have
    reference positions (the others have none: kept out, so a design with one reference target
    among many holds only that target's windows), and the arrays it was computed from
    (:func:`reference_information`). It holds for a design only while those are the design's own:
    a design replaced with other reference weights or other blocks (a test that drops the
    references, say) has its share computed anew."""

    blocks: Blocks
    weight: np.ndarray
    whiten: np.ndarray | None
    rows: np.ndarray
    V: np.ndarray

    @classmethod
    def of(cls, blocks: Blocks, weight: np.ndarray, whiten: np.ndarray | None) -> ReferenceInformation:
        rows = np.unique(blocks.ref_block)
        dense = reference_information(blocks, weight, whiten)
        V = np.zeros((0, blocks.n_coef, 3, blocks.n_coef, 3)) if dense is None else dense[rows]
        return cls(blocks, weight, whiten, rows, V)

    def holds_for(self, blocks: Blocks, weight: np.ndarray, whiten: np.ndarray | None) -> bool:
        return self.blocks is blocks and self.weight is weight and self.whiten is whiten


def add_reference_terms(
    blk: Blocks,
    e_ref: np.ndarray,
    ref_weight: np.ndarray,
    V: np.ndarray,
    b_c: np.ndarray,
    whiten: np.ndarray | None = None,
    information: ReferenceInformation | None = None,
) -> None:
    """Add the reference positions' terms to V (B, K, 3, K, 3) and b_c (B, K, 3) in place, for their
    residuals ``e_ref`` (R', 3): with the scalar weights ``ref_weight`` (R',), or with the whitening
    matrices ``whiten`` (R', 3, 3). ``information``: their share of V computed before (used when it
    holds for these arrays; else computed here)."""
    if blk.ref_block.size == 0:
        return
    if information is not None and information.holds_for(blk, ref_weight, whiten):
        V[information.rows] += information.V  # rows are distinct: one addition per entry, as below
    else:
        V += reference_information(blk, ref_weight, whiten)
    if whiten is not None:
        _whitened_gradient(blk.ref_block, blk.ref_basis, whiten, e_ref, b_c)
        return
    K, B = blk.n_coef, blk.n_blocks
    for k in range(K):
        for a in range(3):
            b_c[:, k, a] += np.bincount(blk.ref_block, blk.ref_basis[:, k] * ref_weight * e_ref[:, a], B)
