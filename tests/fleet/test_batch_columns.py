"""The batch solver's sums: the segment sums of the normal equations against ``np.add.reduceat``,
the state columns that only the sink holds (the eccentric model's extended columns when no sensor
has extended errors) left out of the sums without changing the solution, and the Schur
complement's sums per pattern of states (in super-blocks) against the per-block scatter, and the
eccentric rows without the extended errors (``fleet_rows_ecc3_4``) against the full ones."""

from __future__ import annotations

import numpy as np
import pytest

from registration._generated import api as generated
from registration.fleet import solve_batch
from registration.fleet.batch import blocks as blocks_module
from registration.fleet.batch import schur
from registration.fleet.batch.blocks import ECC3_COLUMNS, make_blocks, unique_rows, used_state_columns
from registration.fleet.batch.schur import super_blocks
from registration.fleet.batch.segments import segment_sums
from registration.fleet.batch.solver import BatchOptions, determined_design
from registration.fleet.simulation.channels import atc_channel_scenario


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_segment_sums_are_reduceat_bit_for_bit(seed):
    rng = np.random.default_rng(seed)
    lengths = rng.integers(1, 7, size=40)
    starts = np.r_[0, np.cumsum(lengths)[:-1]]
    a = rng.normal(size=(int(lengths.sum()), 5, 4))
    for stack in (a, a[:, 1:4, :3]):  # contiguous and a strided view, as normal_equations passes
        got = segment_sums(stack, starts)
        np.testing.assert_array_equal(got, np.add.reduceat(stack, starts, axis=0))
    assert segment_sums(a, np.zeros(0, dtype=np.int64)).shape == (0, 5, 4)


@pytest.fixture(scope="module")
def scenario():
    return atc_channel_scenario(7, duration_s=150.0)


def test_the_sink_only_columns_are_left_out(scenario):
    problem = scenario.problem()
    assert problem.layout.width == 13  # the eccentric model: attitude, biases, 5 extended, 2 terms
    columns = used_state_columns(problem)
    np.testing.assert_array_equal(columns, [0, 1, 2, 3, 4, 5, 11, 12])
    blk = make_blocks(problem, 20.0, 3)
    assert blk.width == 8 and blk.group_state.shape[1] == 8
    assert not (blk.group_state == problem.layout.n).all(axis=0).any()


def test_leaving_them_out_changes_no_estimate(scenario, monkeypatch):
    problem = scenario.problem()
    fewer = solve_batch(problem)
    monkeypatch.setattr(blocks_module, "used_state_columns", lambda problem: None)
    every = solve_batch(problem)
    assert fewer.iterations == every.iterations
    scale = np.abs(every.estimate).max()
    np.testing.assert_allclose(fewer.estimate, every.estimate, rtol=1e-9, atol=1e-9 * scale)
    np.testing.assert_allclose(fewer.sigma, every.sigma, rtol=1e-9)
    np.testing.assert_allclose(fewer.covariance, every.covariance, rtol=1e-9, atol=1e-15)


@pytest.mark.parametrize("k", [1, 3, 7])
def test_super_blocks_hold_every_block_once_and_one_pattern_each(k):
    rng = np.random.default_rng(k)
    block_pattern = rng.integers(0, 5, size=60)
    place, first = super_blocks(block_pattern, 5, k)
    assert np.array_equal(np.sort(place[place >= 0]), np.arange(60))
    assert first[-1] * k == place.size
    for p in range(5):  # pattern p's super-blocks hold its blocks and padding only
        mine = place[first[p] * k : first[p + 1] * k]
        assert np.array_equal(np.sort(mine[mine >= 0]), np.flatnonzero(block_pattern == p))
        assert np.count_nonzero(mine < 0) < k


def test_pattern_sums_equal_the_per_block_scatter(scenario, monkeypatch):
    problem = scenario.problem()
    _, design, start, normal = determined_design(problem, BatchOptions(), np.zeros(problem.layout.n))
    assert design.blocks.width > 6 and design.blocks.patterns.shape[0] > 1
    by_pattern = schur.reduce(design.blocks, normal, 0.1)
    monkeypatch.setattr(schur, "MAX_PATTERNS", 0)  # every block's product scattered on its own
    by_block = schur.reduce(design.blocks, normal, 0.1)
    np.testing.assert_allclose(by_pattern.S, by_block.S, rtol=1e-12, atol=1e-12 * np.abs(by_block.S).max())
    np.testing.assert_array_equal(by_pattern.r, by_block.r)


def test_the_rows_without_extended_errors_are_the_eccentric_rows_at_zero():
    """fleet_rows_ecc3_4 equals fleet_rows_ecc_4's coefficient, attitude, bias, eccentricity and
    residual columns with the velocity, navigation rate, gain and position error at 0."""
    rng = np.random.default_rng(5)
    n = 50
    shared = dict(
        p_ecef=rng.normal(4.4e6, 1e5, (n, 3)),
        lat=rng.uniform(0.7, 0.9, n),
        lon=rng.uniform(0.05, 0.2, n),
        alt=rng.uniform(0, 500, n),
        heading=rng.uniform(-3, 3, n),
        pitch=rng.normal(0, 0.02, n),
        roll=rng.normal(0, 0.02, n),
        att_err=rng.normal(0, 1e-3, (n, 3)),
        bias=rng.normal(0, [30, 1e-3, 1e-3], (n, 3)),
        ecc=rng.normal(0, 3e-3, (n, 2)),
        lever_deck=rng.normal(0, 5, (n, 3)),
        r=rng.uniform(5e3, 1e5, n),
        q=rng.uniform(-3, 3, n),
        e=rng.uniform(0, 0.1, n),
        weight=np.tile([0.01, 500.0, 500.0], (n, 1)),
        basis=rng.uniform(-1, 1, (n, 4)),
    )
    ecc3 = generated.fleet_rows_ecc3_4(**shared).rows_t
    zeros = np.zeros
    held = dict(v_ecef=zeros((n, 3)), nav_rate=zeros((n, 6)), gain=zeros(n), pos_err=zeros((n, 3)))
    full = generated.fleet_rows_ecc_4(**shared, **held).rows_t
    assert ecc3.shape == (n, 21, 3) and full.shape == (n, 26, 3)
    columns = np.r_[0:12, 12 + ECC3_COLUMNS, 25]
    np.testing.assert_allclose(ecc3, full[:, columns], rtol=1e-12, atol=1e-15)


@pytest.mark.parametrize("shape", [(0, 4), (1, 3), (60, 5), (425, 32)])
def test_unique_rows_is_numpys_unique_on_rows(shape):
    rng = np.random.default_rng(shape[0])
    a = rng.integers(0, 4, size=(6, shape[1]))[rng.integers(0, 6, size=shape[0])]
    got, inverse = unique_rows(a)
    want, want_inverse = np.unique(a, axis=0, return_inverse=True)
    assert np.array_equal(got, want) and np.array_equal(inverse, want_inverse.reshape(-1))
    assert np.array_equal(got[inverse], a)
