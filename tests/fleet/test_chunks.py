"""The batch solver's padded rows (registration.fleet.batch.chunks): every plot in one row of its
group's chunks, in order, padding only at the end of a group's last chunk and bounded by the cost
rule, the classes' sizes the cheapest by that rule (against every choice), and the groups' sums
of Z^T Z from the chunks' batched products equal to the direct sums over each group's plots."""

from __future__ import annotations

from itertools import combinations

import numpy as np
import pytest

from registration.fleet.batch.blocks import make_blocks
from registration.fleet.batch.chunks import CLASS_COST_ROWS, MAX_CHUNK, chunk_layout, class_sizes
from registration.fleet.batch.design import make_design
from registration.fleet.batch.initial import initial_coefficients
from registration.fleet.batch.normal import _group_products, evaluate
from registration.fleet.batch.segments import segment_sums
from registration.fleet.simulation.channels import atc_channel_scenario


def _cost(sizes: np.ndarray, classes) -> int:
    """Rows plus CLASS_COST_ROWS per class below MAX_CHUNK of groups of ``sizes`` cut into chunks
    of MAX_CHUNK and one remainder chunk of the smallest of ``classes`` that holds it."""
    ascending = np.sort(np.array(classes))
    rem = sizes % MAX_CHUNK
    held = ascending[np.searchsorted(ascending, rem[rem > 0])]
    return int((sizes // MAX_CHUNK).sum() * MAX_CHUNK + held.sum()) + CLASS_COST_ROWS * int(
        np.count_nonzero(ascending < MAX_CHUNK)
    )


def test_class_sizes_of_simple_groups():
    """One size: that size; sizes 4 and 5 in many groups: both (padding the 60 groups of 4 would
    cost more than a class), in few: 5 alone; long groups: MAX_CHUNK and their remainders."""
    assert class_sizes(np.array([7] * 10)) == (7,)
    assert class_sizes(np.array([1] * 10)) == (1,)
    assert class_sizes(np.array([4] * 60 + [5] * 55)) == (5, 4)
    assert class_sizes(np.array([4] * 10 + [5] * 55)) == (5,)
    assert class_sizes(np.array([MAX_CHUNK] * 3)) == (MAX_CHUNK,)
    assert class_sizes(np.array([2 * MAX_CHUNK + 3] * 50)) == (MAX_CHUNK, 3)
    assert class_sizes(np.array([2 * MAX_CHUNK + 3, 5 * MAX_CHUNK + 30])) == (MAX_CHUNK,)
    assert class_sizes(np.zeros(0, dtype=np.int64)) == ()


@pytest.mark.parametrize("seed", range(6))
def test_class_sizes_are_the_cheapest_choice(seed):
    rng = np.random.default_rng(seed)
    lengths = rng.choice(np.arange(1, 3 * MAX_CHUNK), size=7, replace=False)
    sizes = rng.choice(lengths, size=int(rng.integers(5, 300)), p=rng.dirichlet(np.ones(7)))
    rem = np.unique(sizes % MAX_CHUNK)
    rem = rem[rem > 0]
    full = [MAX_CHUNK] if (sizes >= MAX_CHUNK).any() else []
    best = min(
        _cost(sizes, full + list(pick))
        for k in range(rem.size + 1)
        for pick in combinations(rem.tolist(), k)
        if max(full + list(pick), default=0) >= rem.max(initial=0)
    )
    got = class_sizes(sizes)
    assert got == tuple(sorted(got, reverse=True))
    assert _cost(sizes, got) == best


@pytest.mark.parametrize("seed", range(4))
def test_every_plot_has_one_row_of_its_groups_chunks_in_order(seed):
    rng = np.random.default_rng(seed)
    sizes = np.r_[rng.integers(1, 9, 300), rng.integers(1, 4 * MAX_CHUNK, 20)]  # a scan's and long ones
    rng.shuffle(sizes)
    group_start = np.cumsum(sizes) - sizes
    n = int(sizes.sum())
    lay = chunk_layout(group_start, n)
    assert np.unique(lay.slot).size == n and lay.slot.min() >= 0 and lay.slot.max() < lay.n_rows
    assert np.array_equal(np.sort(lay.group_chunks), np.arange(lay.n_chunks))  # each chunk one group's
    plot_of_row = np.full(lay.n_rows, -1)
    plot_of_row[lay.slot] = np.arange(n)
    rows_of_chunk = np.repeat(np.array(lay.sizes), np.diff(lay.chunk_start))
    first = lay.first_rows()
    ends = np.r_[lay.group_first[1:], lay.n_chunks]
    for g in range(sizes.size):
        chunks = lay.group_chunks[lay.group_first[g] : ends[g]]
        assert (rows_of_chunk[chunks[:-1]] == MAX_CHUNK).all()  # full chunks, then the remainder's
        plots = np.concatenate([plot_of_row[first[c] : first[c] + rows_of_chunk[c]] for c in chunks])
        real = plots[plots >= 0]
        np.testing.assert_array_equal(real, np.arange(group_start[g], group_start[g] + sizes[g]))
        assert (plots[real.size :] < 0).all() and plots.size - real.size < rows_of_chunk[chunks[-1]]
    # the padding costs no more than a class for each remainder length of its own would
    rem = np.unique(sizes % MAX_CHUNK)
    below = sum(1 for s in lay.sizes if s < MAX_CHUNK)
    assert lay.n_rows - n <= CLASS_COST_ROWS * (np.count_nonzero(rem) - below)
    for size, rows, at in lay.classes():
        assert rows.stop - rows.start == size * (at.stop - at.start)


def test_groups_of_one_scan_each_fill_their_chunks():
    """Groups of 1 to 8 plots, each size in many groups (a radar split into channels): no padding."""
    sizes = np.random.default_rng(5).integers(1, 9, 2000)
    lay = chunk_layout(np.cumsum(sizes) - sizes, int(sizes.sum()))
    assert lay.sizes == (8, 7, 6, 5, 4, 3, 2, 1) and lay.n_rows == sizes.sum()


@pytest.mark.parametrize("seed", range(3))
def test_segment_sums_with_an_index_are_reduceat_of_the_taken_rows_bit_for_bit(seed):
    rng = np.random.default_rng(seed)
    lengths = rng.integers(1, 5, size=60)
    n = int(lengths.sum())
    starts = np.cumsum(lengths) - lengths
    a = rng.normal(size=(n, 6, 6)) * 10.0 ** rng.integers(-8, 8, size=(n, 1, 1))
    index = rng.permutation(n)
    for view in (a, a[:, :4, :4], a[:, :4, -1]):
        want = np.add.reduceat(view[index], starts, axis=0)
        np.testing.assert_array_equal(segment_sums(view, starts, index), want)


@pytest.fixture(scope="module")
def problem():
    return atc_channel_scenario(11, duration_s=240.0).problem()


@pytest.mark.parametrize("window_s", [0.0, 20.0, 400.0])
def test_group_products_are_the_sums_over_each_groups_plots(problem, window_s):
    """Windows of one instant (groups of one plot), 20 s (a few scans: one class per size) and
    longer than the scenario (groups of 25 to 60 plots: chunks of MAX_CHUNK and remainders)."""
    blk = make_blocks(problem, window_s, 3 if window_s else 0)
    design = make_design(problem, blk)
    ev = evaluate(design, np.zeros(problem.layout.n), initial_coefficients(design))
    assert not ev.Z[~design.real].any()  # padding weighs nothing
    G, row = _group_products(design, ev)
    G = G if row is None else G[row]
    sizes = np.diff(np.r_[blk.group_start, blk.order.size])
    if window_s == 400.0:
        assert sizes.max() > MAX_CHUNK and not blk.chunks.one_per_group
    assert G.shape[0] == sizes.size
    ends = blk.group_start + sizes
    scale = np.abs(G).max()
    for g in range(sizes.size):
        Z = ev.Z[design.slot[blk.group_start[g] : ends[g]]].reshape(-1, G.shape[1])
        np.testing.assert_allclose(G[g], Z.T @ Z, rtol=1e-12, atol=1e-13 * scale)
