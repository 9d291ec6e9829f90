"""The Monte Carlo in chunks of seeds: in this process and on a dask LocalCluster of 1, 2 and 4
worker processes, the statistics equal one in-process run bit for bit."""

from __future__ import annotations

import json
import sys

import numpy as np
import pytest

from registration.core.parallel import (
    DASK_MISSING,
    chunk_ranges,
    dask_client,
    map_chunks,
    require_distributed,
)
from registration.online import RegistrationConfig
from registration.online.distributed import (
    MonteCarloJob,
    merge_runs,
    run_montecarlo_chunked,
    run_montecarlo_jobs,
)
from registration.online.montecarlo import collect_runs, run_montecarlo

ARRAYS = ("rmse", "mean_error", "filter_sigma", "filter_two_sigma_mean", "crlb_sigma", "nees", "nis")


def assert_identical(a, b):
    for name in ARRAYS:
        x, y = getattr(a, name), getattr(b, name)
        assert x.tobytes() == y.tobytes(), name  # bit for bit, not approximately
    assert json.dumps(a.to_json(), sort_keys=True) == json.dumps(b.to_json(), sort_keys=True)
    assert list(a.status_counts.items()) == list(b.status_counts.items())


def test_chunk_ranges_cover_every_seed_once():
    assert chunk_ranges(7, 3, start=5) == [(5, 8), (8, 11), (11, 12)]
    assert chunk_ranges(3, 10) == [(0, 3)]
    with pytest.raises(ValueError, match="chunk"):
        chunk_ranges(3, 0)


@pytest.mark.parametrize("chunk", [1, 4, 7, 23])
def test_chunks_merged_in_seed_order_equal_one_run(chunk):
    ref = run_montecarlo(23, 5, n_steps=40)
    assert_identical(ref, run_montecarlo_chunked(23, 5, chunk_runs=chunk, n_steps=40))


def test_adaptive_q_weak_states_and_sums_in_chunks():
    cfg = RegistrationConfig(sigma0=(50.0, np.radians(0.5), np.radians(0.5)) * 2, q_mode="adaptive")
    kw = dict(n_steps=30, include_weak=True, extra_sums=["dC_a+dq_a"])
    assert_identical(run_montecarlo(6, 2, cfg, **kw), run_montecarlo_chunked(6, 2, cfg, chunk_runs=4, **kw))


def test_merge_adds_counts_and_rejects_different_scenarios():
    a = collect_runs(3, 0, None, False, {"n_steps": 20})
    b = collect_runs(2, 3, None, False, {"n_steps": 20})
    merged = merge_runs([a, b])
    assert merged["err"].shape[0] == 5
    assert sum(merged["status_counts"]["dC_a"].values()) == 5
    with pytest.raises(ValueError, match="different scenarios"):
        merge_runs([a, collect_runs(2, 3, None, False, {"n_steps": 21})])


def test_jobs_are_independent_of_their_batch():
    jobs = [
        MonteCarloJob(4, 0, scenario_kwargs={"n_steps": 20, "angle_sigma": np.radians(s)}) for s in (0.2, 0.5)
    ]
    both = run_montecarlo_jobs(jobs, chunk_runs=3)
    for job, res in zip(jobs, both):
        assert_identical(res, run_montecarlo(4, 0, **job.scenario_kwargs))


def test_missing_dask_is_reported_with_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "dask.distributed", None)
    with pytest.raises(ImportError, match=r"pip install \"dask\[distributed\]\""):
        require_distributed()
    assert 'pip install "dask[distributed]"' in DASK_MISSING
    with dask_client() as client:  # in-process needs no dask
        assert client is None
        assert map_chunks(abs, [-1, 2], client) == [1, 2]


def test_scheduler_and_workers_are_exclusive():
    with pytest.raises(ValueError, match="one or the other"):
        with dask_client("tcp://127.0.0.1:1", 2):
            pass


def test_local_cluster_processes_1_2_4_workers_equal_in_process():
    """Worker processes (not threads), chunks of 3 seeds: the same bits whatever the worker count."""
    pytest.importorskip("dask.distributed")
    ref = run_montecarlo(20, 3, n_steps=40)
    for workers in (1, 2, 4):
        with dask_client(workers=workers) as client:
            assert len(client.scheduler_info()["workers"]) == workers
            assert_identical(ref, run_montecarlo_chunked(20, 3, client=client, chunk_runs=3, n_steps=40))


def test_an_error_in_a_chunk_is_raised_by_the_caller():
    pytest.importorskip("dask.distributed")
    with dask_client(workers=1) as client:
        with pytest.raises(ValueError, match="math domain"):
            map_chunks(__import__("math").sqrt, [1.0, -1.0], client)
