"""The batch normal equations' faster sums give the numbers of the plain numpy forms, bit for bit
(the association's labels depend on them through every solve)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from registration.fleet import build_problem
from registration.fleet.association.grouping.units import unit_plots
from registration.fleet.batch.blocks import make_blocks
from registration.fleet.batch.design import make_design
from registration.fleet.batch.initial import initial_coefficients
from registration.fleet.batch.normal import evaluate, normal_equations
from registration.fleet.batch.reference_terms import add_whitened_terms
from registration.fleet.batch.segments import MAX_SEGMENT_ROWS, segment_sums
from registration.fleet.simulation.scenario import fleet_scenario


@pytest.mark.parametrize("longest", [1, 2, 3, 5, MAX_SEGMENT_ROWS, MAX_SEGMENT_ROWS + 3])
@pytest.mark.parametrize("width", [7, 24])
def test_segment_sums_are_reduceat_bit_for_bit(longest, width):
    rng = np.random.default_rng([longest, width])
    length = rng.integers(1, longest + 1, size=300)
    n = int(length.sum())
    a = rng.normal(size=(n, width, width)) * 10.0 ** rng.integers(-8, 8, size=(n, 1, 1))
    a[rng.random(a.shape) < 0.05] = -0.0  # signed zeros too
    starts = np.r_[0, np.cumsum(length)[:-1]]
    for view in (a, a[:, :5, :5], a[:, :5, -1]):  # and strided slices, as the normal equations take
        want = np.add.reduceat(view, starts, axis=0)
        got = segment_sums(view, starts)
        assert np.array_equal(got, want) and np.array_equal(np.signbit(got), np.signbit(want))


@pytest.mark.parametrize("seed", [1, 2])
def test_a_few_long_segments_among_short_ones_are_reduceat_bit_for_bit(seed):
    """The long segments go through reduceat alone, the short ones through the fast path: the
    numbers stay reduceat's on the whole stack, with and without an index."""
    rng = np.random.default_rng(seed)
    length = rng.integers(1, 4, size=400)
    length[rng.choice(400, 5, replace=False)] = rng.integers(MAX_SEGMENT_ROWS + 1, 60, size=5)
    n = int(length.sum())
    a = rng.normal(size=(n, 9, 9)) * 10.0 ** rng.integers(-8, 8, size=(n, 1, 1))
    starts = np.r_[0, np.cumsum(length)[:-1]]
    index = rng.permutation(n)
    for view in (a, a[:, :5, -1]):
        assert np.array_equal(segment_sums(view, starts), np.add.reduceat(view, starts, axis=0))
        want = np.add.reduceat(view[index], starts, axis=0)
        assert np.array_equal(segment_sums(view, starts, index), want)
    assert np.array_equal(segment_sums(a, starts[:1]), np.add.reduceat(a, starts[:1], axis=0))


@pytest.mark.parametrize("a_rows", [1, 3])
def test_whitened_terms_are_the_einsum_forms_bit_for_bit(a_rows):
    rng = np.random.default_rng(a_rows)
    R, B, K = 500, 40, 4
    block = np.sort(rng.integers(0, B, size=R))
    basis = rng.normal(size=(R, K))
    whiten = rng.normal(size=(R, a_rows, 3)) * np.where(rng.random((R, a_rows, 3)) < 0.1, 0.0, 1.0)
    e = rng.normal(size=(R, a_rows))
    V, b_c = np.zeros((B, K, 3, K, 3)), np.zeros((B, K, 3))
    add_whitened_terms(block, basis, whiten, e, V, b_c)
    gram = np.einsum("rai,raj->rij", whiten, whiten).reshape(-1, 9)
    grad = np.einsum("rai,ra->ri", whiten, e)
    at3 = (block[:, None] * 3 + np.arange(3)).reshape(-1)
    at9 = (block[:, None] * 9 + np.arange(9)).reshape(-1)
    V0, b0 = np.zeros_like(V), np.zeros_like(b_c)
    for k in range(K):
        b0[:, k, :] += np.bincount(at3, (basis[:, k, None] * grad).reshape(-1), 3 * B).reshape(B, 3)
        for m in range(K):
            w = (basis[:, k] * basis[:, m])[:, None] * gram
            V0[:, k, :, m, :] += np.bincount(at9, w.reshape(-1), 9 * B).reshape(B, 3, 3)
    assert np.array_equal(V, V0) and np.array_equal(b_c, b0)


def test_unit_plots_are_each_units_plots_in_order():
    of_plot = np.random.default_rng(3).integers(-1, 50, size=2000)
    order, start = unit_plots(of_plot, 52)  # two units without plots at the end
    for u in range(52):
        assert np.array_equal(order[start[u] : start[u + 1]], np.flatnonzero(of_plot == u))


@pytest.mark.parametrize("whitened", [False, True])
def test_the_designs_reference_information_is_the_one_computed_at_each_evaluation(whitened):
    """The references' share of the window blocks, computed once when the design is made, gives the
    normal equations of computing it at every evaluation, bit for bit, with scalar weights and
    with whitening in the local frame (a vertical sigma of its own)."""
    sc = fleet_scenario(5, duration_s=120.0)
    refs = dict(sc.references)
    if whitened:
        refs["sigma_up"] = 4.0 * np.asarray(refs["sigma"], dtype=np.float64)
    problem = build_problem(sc.plots, sc.sensors, sc.navigation, sc.platforms, refs)
    design = make_design(problem, make_blocks(problem, 20.0, 3))
    assert design.ref_information is not None and (design.ref_whiten is not None) == whitened
    x = np.random.default_rng(5).normal(size=problem.layout.n) * 1e-3
    ev = evaluate(design, x, initial_coefficients(design, x))
    cached, fresh = normal_equations(design, ev), normal_equations(replace(design, ref_information=None), ev)
    assert np.array_equal(cached.V, fresh.V) and np.array_equal(cached.b_c, fresh.b_c)
    assert np.array_equal(cached.U, fresh.U) and np.array_equal(cached.W, fresh.W)
    # and the references do weigh: without them the blocks differ
    info = design.ref_information
    # only the windows of the reference target are held (one target among the scenario's several)
    assert 0 < info.rows.size < design.blocks.n_blocks
    bare = normal_equations(replace(design, ref_information=replace(info, V=np.zeros_like(info.V))), ev)
    assert not np.array_equal(bare.V, cached.V)
    # a design whose references are replaced does not use the share of the old ones
    half = replace(
        design,
        ref_weight=design.ref_weight * 0.5,
        ref_whiten=None if not whitened else design.ref_whiten * 0.5,
    )
    assert not np.array_equal(normal_equations(half, ev).V, cached.V)
    assert np.array_equal(
        normal_equations(half, ev).V, normal_equations(replace(half, ref_information=None), ev).V
    )
