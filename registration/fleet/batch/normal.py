"""Whitened residuals and the Gauss-Newton normal equations of the batch problem, block by block.

Unknowns: the registration states ``x`` (n) and the window coefficients ``c`` (B blocks of
``n_coef x 3``, :mod:`registration.fleet.batch.blocks`). Each plot's whitened residual and Jacobian
rows come from the generated ``fleet_rows_<n_coef>`` (``fleet_residual`` weighted by
``mask / sigma``, so unmeasured channels weigh nothing, and multiplied out with the window's
polynomial basis) in one batched call. With whitened residuals ``e`` and Jacobians ``A``
(``e(theta + d) ~ e + A d``) the normal equations ``A^T A d = b`` with ``b = -A^T e`` are held
in their block form:

* ``V`` (B, q, q), q = 3 n_coef: the target-window blocks (plots and reference positions);
* ``W`` (B, q, w g [+ 1]): coupling of each block with its local states (``Blocks.local_state``):
  the w states of each of its sensors' groups side by side (platform attitude errors, sensor
  biases and, with the extended model, range gain, time bias, position errors), then, with flight
  levels, the height offset;
* ``U`` (n + 1, n + 1): the states' block (index n collects the absent biases and is dropped);
* ``b_c`` (B, q) and ``b_x`` (n + 1,).

A reference position ``y`` (sigma s) of a target adds the residual ``(y - p(t)) / s``; the prior
of state i adds ``(0 - x_i) / sigma_i``. A reference whose vertical sigma ``s_up`` differs from its
horizontal one is whitened in its local frame instead: ``e = L (y - p(t))`` with
``L = diag(1/s, 1/s, 1/s_up) R_enu_ecef(lat, lon of y)``
(:func:`registration.fleet.batch.design.reference_whitening`), so its three residuals are east,
north and up; its terms are ``V += sum basis_k basis_m L^T L`` and
``b_c += basis_k L^T e``. While every reference used has ``s_up == s`` the scalar weight ``1/s``
is used as before (the same numbers, bit for bit). All sums over plots are segment sums over the
(block, sensor) order: no Python loop over plots.

With the extended errors the rows come from ``fleet_rows_ext_<n_coef>`` (``fleet_rows_ecc_<n_coef>``,
13 state columns, when some sensor has an azimuth eccentricity). A sensor with a time
bias ``dt`` sees its target and its platform at ``t - dt``: each evaluation takes the window
polynomial, its velocity (the polynomial's derivative) and the platform's navigation and its rate
at that time (the navigation tracks interpolated again), so the residual is exact and the time
bias's Jacobian column carries the target's and the platform's motion. A row seen outside its
platform's navigation (near the navigation's ends) weighs 0 in that evaluation: the solver sets
those plots aside (:func:`registration.fleet.batch.solver.fit`).

A *surface target* (a ship on the sea: the targets table's ``surface_alt``, ``sigma_surface``)
adds to each of its windows the height constraints ``e = (alt_surface - alt(p(t_k))) / s`` at the
window's ``K`` Gauss-Legendre nodes ``t_k`` (K its used coefficients), from the generated
``surface_residual`` (the height and its Jacobian, minus the geodetic up, derived from the inverse
of the geodetic position): as many values as the height coefficients they determine, so a window
whose height the plots do not fix (a 2-D radar's, or references without a height) is determined
without counting the known surface as measurements. Their terms are those of a reference with
whitening ``L = -J / s`` (:class:`registration.fleet.batch.design.SurfaceRows`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration._generated import api as generated
from registration.fleet.batch.blocks import Blocks
from registration.fleet.batch.design import Design, plot_model_inputs
from registration.fleet.batch.reference_terms import add_reference_terms, add_whitened_terms
from registration.fleet.batch.segments import segment_sums
from registration.fleet.data.layout import (
    ATTITUDE_COLUMNS,
    BIAS_COLUMNS,
    ECCENTRICITY_COLUMNS,
    POSITION_ERROR_COLUMNS,
    RANGE_GAIN_COLUMN,
    TIME_BIAS_COLUMN,
)

__all__ = [
    "Evaluation",
    "Normal",
    "chunk_positions",
    "evaluate",
    "local_coupling",
    "normal_equations",
    "positions",
]


def positions(basis: np.ndarray, block: np.ndarray, coef: np.ndarray) -> np.ndarray:
    """(M, 3) ECEF positions sum_k basis[:, k] coef[block, k] (m)."""
    return np.einsum("mk,mkj->mj", basis, coef[block])


@dataclass(frozen=True)
class Evaluation:
    """At (x, coef): the whitened rows ``Z`` (rows, 3, q + w + 1) = [A_c | A_x | e] of every plot (A_c:
    Jacobian w.r.t. its window's coefficients, A_x: w.r.t. the w states of the model's rows, e:
    whitened residual),
    the whitened reference residuals ``e_ref`` (R', 3) (per ECEF axis; east, north, up with
    ``Design.ref_whiten``), the total sum of squares and, with surface targets, the whitened
    height residuals ``e_surface`` (S,) and their whitening rows ``surface_whiten`` (S, 1, 3) 1/m."""

    x: np.ndarray
    coef: np.ndarray
    Z: np.ndarray
    e_ref: np.ndarray
    cost: float  # sum of squares of every whitened residual, references, surface heights and priors included
    e_surface: np.ndarray = field(default_factory=lambda: np.zeros(0))
    surface_whiten: np.ndarray = field(default_factory=lambda: np.zeros((0, 1, 3)))

    @property
    def e(self) -> np.ndarray:
        """(rows, 3) whitened residuals of the plots (0 where not measured)."""
        return self.Z[:, :, -1]


def chunk_positions(design: Design, basis: np.ndarray, coef: np.ndarray) -> np.ndarray:
    """(rows, 3) ECEF sum_k basis[:, k] coef[block, k] (m), one (C x n_coef)(n_coef x 3) product per
    chunk of C rows (a chunk lies in one block), one batched product per class of chunks."""
    out = np.empty((basis.shape[0], 3))
    K = basis.shape[1]
    for C, rows, chunks in design.blocks.chunks.classes():
        at = coef[design.chunk_block[chunks]]
        np.matmul(basis[rows].reshape(-1, C, K), at, out=out[rows].reshape(-1, C, 3))
    return out


def _seen(design: Design, time_bias: np.ndarray) -> tuple:
    """(basis, basis rate, nav, nav rate, set aside) of the rows seen at ``time - time_bias`` (rows,),
    kept while the time biases stay the same (the targets-only phase and rejected trial steps).
    ``set aside`` (rows,) bool: seen outside the platform's navigation, unless that would empty
    the row's window (the solver then drops those plots and solves anew)."""
    hit = design.seen_cache.get("key")
    if hit is not None and np.array_equal(hit, time_bias):
        return design.seen_cache["value"]
    t_seen = design.time - time_bias
    nav, rate, outside = design.seen_at(t_seen)
    if outside.any():
        left = design.block_sums((design.weight.any(axis=1) & ~outside).astype(np.int64))
        outside = outside & (left > 0)[design.block]
    value = (*design.blocks.basis_and_rate_at(design.block, t_seen), nav, rate, outside)
    design.seen_cache.update(key=time_bias, value=value)
    return value


def _eccentric_rows(design: Design, xs: np.ndarray, coef: np.ndarray) -> np.ndarray:
    """(rows, 3 n_coef + 9, 3) rows of the eccentric model with the extended errors held at 0
    (``fleet_rows_ecc3_<n_coef>``) at states ``xs`` (n + 1,, sink last)."""
    state = design.state
    known = plot_model_inputs(design.nav, design.lever, design.meas) | dict(
        p_ecef=chunk_positions(design, design.basis, coef),
        att_err=xs[state[:, ATTITUDE_COLUMNS]],
        bias=xs[state[:, BIAS_COLUMNS]],
        ecc=xs[state[:, ECCENTRICITY_COLUMNS]],
        weight=design.weight,
    )
    if design.blocks.n_coef == 1:
        return generated.fleet_rows_ecc3_1(**known, basis=design.basis[:, 0]).rows_t
    return generated.fleet_rows_ecc3_4(**known, basis=design.basis).rows_t


def _extended_rows(design: Design, xs: np.ndarray, coef: np.ndarray) -> np.ndarray:
    """(rows, 3 n_coef + 12 or 14, 3) rows of the extended (or eccentric) model at states ``xs``
    (n + 1,, sink last); a row seen outside its platform's navigation weighs 0 (module docstring)."""
    blk, state = design.blocks, design.state
    basis, nav, weight = design.basis, design.nav, design.weight
    v, rate = np.zeros((basis.shape[0], 3)), np.zeros((basis.shape[0], 6))
    if design.time_biased:
        basis, basis_rate, nav, rate, aside = _seen(design, xs[state[:, TIME_BIAS_COLUMN]])
        v = chunk_positions(design, basis_rate, coef)
        if aside.any():
            weight = np.where(aside[:, None], 0.0, weight)
    p = chunk_positions(design, basis, coef)
    known = plot_model_inputs(nav, design.lever, design.meas) | dict(
        p_ecef=p,
        v_ecef=v,
        nav_rate=rate,
        att_err=xs[state[:, ATTITUDE_COLUMNS]],
        bias=xs[state[:, BIAS_COLUMNS]],
        gain=xs[state[:, RANGE_GAIN_COLUMN]],
        pos_err=xs[state[:, POSITION_ERROR_COLUMNS]],
        weight=weight,
    )
    if state.shape[1] > ECCENTRICITY_COLUMNS.start:  # some sensor has an eccentricity
        known["ecc"] = xs[state[:, ECCENTRICITY_COLUMNS]]
        if blk.n_coef == 1:
            return generated.fleet_rows_ecc_1(**known, basis=basis[:, 0]).rows_t
        return generated.fleet_rows_ecc_4(**known, basis=basis).rows_t
    if blk.n_coef == 1:
        return generated.fleet_rows_ext_1(**known, basis=basis[:, 0]).rows_t
    return generated.fleet_rows_ext_4(**known, basis=basis).rows_t


def evaluate(design: Design, x: np.ndarray, coef: np.ndarray) -> Evaluation:
    """Residuals at states ``x`` (n,) and coefficients ``coef`` (B, n_coef, 3): one call of the
    generated ``fleet_rows_<n_coef>`` (``fleet_rows_ext_<n_coef>`` with the extended errors) for
    all plots."""
    blk = design.blocks
    xs = np.append(x, 0.0)
    if blk.state_columns is not None:  # the eccentricity without the extended errors
        rows_t = _eccentric_rows(design, xs, coef)
    elif design.extended:
        rows_t = _extended_rows(design, xs, coef)
    else:
        p = positions(design.basis, design.block, coef)
        known = plot_model_inputs(design.nav, design.lever, design.meas) | dict(
            p_ecef=p, att_err=xs[design.att_state], bias=xs[design.bias_state], weight=design.weight
        )
        if blk.n_coef == 1:
            rows_t = generated.fleet_rows_1(**known, basis=design.basis[:, 0]).rows_t
        else:
            rows_t = generated.fleet_rows_4(**known, basis=design.basis).rows_t
    Z = rows_t.swapaxes(1, 2)  # each plot's 3 rows, contiguous
    e = Z[:, :, -1]
    if design.ref_whiten is None:
        e_ref = (design.ref_p - positions(blk.ref_basis, blk.ref_block, coef)) * design.ref_weight[:, None]
    else:
        e_ref = np.einsum(
            "rij,rj->ri", design.ref_whiten, design.ref_p - positions(blk.ref_basis, blk.ref_block, coef)
        )
    prior = x * design.prior_weight
    if design.ref_offset_up is not None:  # the flight levels' heights carry the common offset
        assert design.ref_whiten is not None  # heights alone are whitened in their local frame
        a = np.einsum("rij,rj->ri", design.ref_whiten, design.ref_offset_up)
        e_ref = e_ref + a * x[design.offset_state]
    cost = float(np.sum(e * e) + np.sum(e_ref * e_ref) + np.sum(prior * prior))
    surf = design.surface
    if surf is None:
        return Evaluation(x, coef, Z, e_ref, cost)
    residual, J = generated.surface_residual(
        p_ecef=positions(surf.basis, surf.block, coef), alt_surface=surf.alt
    )
    e_surface = residual * surf.weight
    return Evaluation(
        x,
        coef,
        Z,
        e_ref,
        cost + float(np.sum(e_surface * e_surface)),
        e_surface,
        -J * surf.weight[:, None, None],
    )


@dataclass
class Normal:
    """The normal equations in block form (module docstring)."""

    V: np.ndarray  # (B, q, q)
    # (B, q, L): each block's coupling with its local states (Blocks.local_state; local_coupling)
    W: np.ndarray
    U: np.ndarray  # (n + 1, n + 1)
    b_c: np.ndarray  # (B, q)
    b_x: np.ndarray  # (n + 1,)


def _group_products(design: Design, ev: Evaluation) -> tuple[np.ndarray, np.ndarray | None]:
    """The sums over each group of Z^T Z (m = q + w + 1 columns of Evaluation.Z), stacked (S, m, m),
    and the row of each group in that stack (G,) (None: row g is group g's).

    The rows are in chunks (Design), so each chunk's product is one small dense matrix product,
    those of a class of chunks (:mod:`registration.fleet.batch.chunks`) one batched product. When
    every group is one chunk the chunks' products are the groups' sums, left in the classes' order:
    copying them into the groups' order takes a second stack as large, which cost as much as the
    products themselves (a fresh allocation each time); the sums below take their parts by row
    instead, as they copy them anyway.
    """
    chunks = design.blocks.chunks
    m = ev.Z.shape[2]
    gram = np.empty((chunks.n_chunks, m, m))
    for C, rows, at in chunks.classes():
        Z = ev.Z[rows].reshape(-1, 3 * C, m)
        np.matmul(np.ascontiguousarray(Z.transpose(0, 2, 1)), Z, out=gram[at])
    order = None if chunks.in_group_order else chunks.group_chunks
    if chunks.one_per_group:
        return gram, order
    return segment_sums(gram, chunks.group_first, order), None


def _by_group(a: np.ndarray, row: np.ndarray | None) -> np.ndarray:
    """The rows ``row`` (G,) of ``a`` (the groups' in turn), or ``a`` itself when ``row`` is None."""
    return a if row is None else a[row]


def normal_equations(design: Design, ev: Evaluation) -> Normal:
    """The block normal equations at an evaluation (undamped)."""
    blk = design.blocks
    K, n1, q, w = blk.n_coef, design.n_state + 1, 3 * blk.n_coef, blk.width
    G, row = _group_products(design, ev)
    V = segment_sums(G[:, :q, :q], blk.group_block_start, row)
    b_c = -segment_sums(G[:, :q, -1], blk.group_block_start, row)
    V5, b_c3 = V.reshape(-1, K, 3, K, 3), b_c.reshape(-1, K, 3)
    add_reference_terms(blk, ev.e_ref, design.ref_weight, V5, b_c3, design.ref_whiten, design.ref_information)
    if design.surface is not None:
        add_whitened_terms(
            design.surface.block, design.surface.basis, ev.surface_whiten, ev.e_surface[:, None], V5, b_c3
        )
    idx = blk.group_state
    flat = (idx[:, :, None] * n1 + idx[:, None, :]).reshape(-1)
    U = np.bincount(flat, _by_group(G[:, q : q + w, q : q + w], row).reshape(-1), n1 * n1).reshape(n1, n1)
    b_x = -np.bincount(idx.reshape(-1), _by_group(G[:, q : q + w, -1], row).reshape(-1), n1)
    pw = np.append(design.prior_weight, 0.0)
    U[np.diag_indices(n1)] += pw**2
    b_x -= pw**2 * np.append(ev.x, 0.0)
    H = None if design.ref_offset_up is None else _offset_terms(design, ev, U, b_x)
    W_group = G[:, :q, q : q + w] if blk.coupled is None else G[:, :q, q + blk.coupled]
    return Normal(V, local_coupling(blk, W_group, row, H), U, b_c, b_x)


def local_coupling(blk: Blocks, W: np.ndarray, row: np.ndarray | None, H: np.ndarray | None) -> np.ndarray:
    """(B, q, w g [+ 1]): each block's coupling with its local states (``blk.local_state``): the
    couplings ``W`` (S, q, w) of its groups (group g's in row ``row[g]``, or row g when ``row`` is
    None) side by side, zeros for padding, then, with the flight levels' height offset
    (``blk.extra_states``), its coupling ``H`` (B, q) (zeros when None). Scattered from the rows
    as they lie: no copy of the groups' couplings into group order first."""
    q, w = W.shape[1], W.shape[2]
    g = (blk.local_state.shape[1] - blk.extra_states) // w
    block, rank = blk.group_block, blk.group_rank
    if row is not None:  # the block and rank of each row
        block, rank = np.empty_like(block), np.empty_like(rank)
        block[row], rank[row] = blk.group_block, blk.group_rank
    out = np.zeros((blk.n_blocks, q, g * w))
    # one scatter into the (B, q, g, w) view: its advanced indices (block, rank) come first
    out.reshape(blk.n_blocks, q, g, w)[block, :, rank, :] = W
    if not blk.extra_states:
        return out
    return np.concatenate([out, np.zeros((blk.n_blocks, q, 1)) if H is None else H[:, :, None]], axis=2)


def _offset_terms(design: Design, ev: Evaluation, U: np.ndarray, b_x: np.ndarray) -> np.ndarray:
    """Add in place to ``U`` and ``b_x`` the terms of the flight levels' height offset ``o`` (its
    heights' whitened residuals ``e = L (y + o up - p(t))``, so ``de/do = a = L up``) and return its
    coupling with the blocks ``H`` (B, q): ``U_oo += sum a.a``, ``b_o -= sum a.e``,
    ``H_b,k += -basis_k L^T a``."""
    blk, k = design.blocks, design.offset_state
    assert design.ref_whiten is not None and design.ref_offset_up is not None
    a = np.einsum("rij,rj->ri", design.ref_whiten, design.ref_offset_up)  # (R', 3)
    U[k, k] += float(np.sum(a * a))
    b_x[k] -= float(np.sum(a * ev.e_ref))
    La = np.einsum("rij,ri->rj", design.ref_whiten, a)  # L^T a (R', 3)
    B, K = blk.n_blocks, blk.n_coef
    H = np.zeros((B, K, 3))
    at3 = (blk.ref_block[:, None] * 3 + np.arange(3)).reshape(-1)
    for c in range(K):
        H[:, c, :] -= np.bincount(at3, (blk.ref_basis[:, c, None] * La).reshape(-1), 3 * B).reshape(B, 3)
    return H.reshape(B, 3 * K)
