"""The disk cache of the partitioned solver (registration.fleet.batch.partitioned.spill): each
partition's design and latest normal equations kept in a temporary folder change no bit of the estimate,
against reading and building every partition in every pass and against the in-memory cache; a file that
is missing or broken is built again (as on a worker that does not have it) with the same bits; Dask
workers that share or miss the files give the in-process answer; the folder is removed at the end."""

from __future__ import annotations

import numpy as np
import pytest

from registration.core.parallel import dask_client
from registration.fleet import fleet_scenario
from registration.fleet.batch.partitioned import solve_batch_partitioned, spill
from tests.fleet.test_archive import EXTENDED, source_of


def same_bits(a, b) -> None:
    assert a.estimate.tobytes() == b.estimate.tobytes()
    assert a.sigma.tobytes() == b.sigma.tobytes()
    assert a.chi_square.chi2 == b.chi_square.chi2
    assert a.iterations == b.iterations


@pytest.fixture(scope="module", params=[False, True], ids=["default", "extended"])
def fleet(request):
    sc = fleet_scenario(1, **(EXTENDED if request.param else {}))
    src = source_of(sc)
    return src, solve_batch_partitioned(src, partitions=3, cache=0, spill=False)


def test_spill_changes_no_bit(fleet, tmp_path):
    src, bare = fleet
    same_bits(solve_batch_partitioned(src, partitions=3, cache=0, spill=True, spill_dir=str(tmp_path)), bare)
    same_bits(solve_batch_partitioned(src, partitions=3), bare)  # in-memory cache of every partition
    assert not list(tmp_path.iterdir())  # the folder is removed at the end


def test_missing_or_broken_files_are_built_again(fleet, tmp_path, monkeypatch):
    src, bare = fleet
    load = spill.load
    calls = {"n": 0}

    def forgetful(folder, name, tag=None):
        calls["n"] += 1
        if calls["n"] % 3 == 0:  # as on a worker without the file
            return None
        if calls["n"] % 7 == 0:  # a file cut short
            path = f"{folder}/{name}"
            with open(path, "r+b") as f:
                f.truncate(max(0, f.seek(0, 2) // 2))
        return load(folder, name, tag)

    monkeypatch.setattr(spill, "load", forgetful)
    same_bits(solve_batch_partitioned(src, partitions=3, cache=0, spill=True, spill_dir=str(tmp_path)), bare)
    assert calls["n"] > 10


def test_round_trip_keeps_arrays_and_objects(tmp_path):
    value = {
        "a": np.arange(12.0).reshape(3, 4),
        "b": np.asfortranarray(np.ones((3, 2))),
        "c": ("x", 3),
        "d": np.arange(10)[::2],
        "e": np.zeros((0, 2), dtype=np.int64),
    }
    spill.save(str(tmp_path), "v", value)
    got = spill.load(str(tmp_path), "v")
    for k in ("a", "b", "d", "e"):
        assert got[k].dtype == value[k].dtype and np.array_equal(got[k], value[k])
    got["a"][0, 0] = 5.0  # writable
    assert got["c"] == value["c"]
    assert spill.load(str(tmp_path), "missing") is None


def test_dask_workers_with_spill_equal_in_process(fleet, tmp_path):
    """1, 2 and 3 workers give the same bits. Against the in-process run: the same bits for the three
    errors; with the extended errors the larger products go through BLAS, whose threads (several in
    this process, one in a Dask worker) round differently, so there to 1e-9 relative (measured 4e-11)."""
    pytest.importorskip("dask.distributed")
    src, bare = fleet
    runs = []
    for workers in (1, 2, 3):
        with dask_client(workers=workers) as client:
            runs.append(
                solve_batch_partitioned(
                    src, partitions=3, client=client, cache=0, spill=True, spill_dir=str(tmp_path)
                )
            )
        assert not list(tmp_path.iterdir())
        same_bits(runs[-1], runs[0])
    if bare.layout.extended:
        scale = np.maximum(np.abs(bare.estimate), 1e-12 * bare.layout.scale)
        assert np.max(np.abs(runs[0].estimate - bare.estimate) / scale) < 1e-9
    else:
        same_bits(runs[0], bare)


def test_the_output_pass_reads_the_kept_spill_instead_of_the_archive(fleet, tmp_path):
    """With keep_spill the output pass takes each partition's problem and design from the solve's
    folder: no plot is read, and the outputs equal those of a pass that reads and builds every
    partition again, bit for bit; remove_spill removes the folder."""
    from dataclasses import replace

    from registration.fleet import BatchOptions
    from registration.fleet.batch.outputs import archive_outputs
    from registration.fleet.batch.partitioned import remove_spill

    src, _ = fleet
    kept = solve_batch_partitioned(
        src, partitions=3, cache=0, spill=True, spill_dir=str(tmp_path), keep_spill=True
    )
    assert kept.spill_folder and all(t.spill == kept.spill_folder for t in kept.tasks)
    reads = []
    spy = type(src).__new__(type(src))  # the same tables, every read of plots counted
    spy.__dict__.update(src.__dict__)
    spy.read_plots = lambda lo, hi: reads.append(lo) or src.read_plots(lo, hi)
    fast = archive_outputs(kept, spy, BatchOptions())
    assert reads == []
    slow = archive_outputs(
        replace(kept, tasks=tuple(replace(t, spill=None) for t in kept.tasks)), spy, BatchOptions()
    )
    assert len(reads) == len(kept.tasks)
    for name in ("count", "squares", "hist", "mean", "rms"):
        assert np.array_equal(getattr(fast, name), getattr(slow, name), equal_nan=True)
    assert fast.parts == slow.parts and fast.by_target == slow.by_target
    for a, b in zip(fast.tables, slow.tables):
        assert all(np.array_equal(a[k], b[k]) for k in a)
    for k in fast.sample:
        assert np.array_equal(fast.sample[k], slow.sample[k], equal_nan=True)
    remove_spill(kept.spill_folder, None)
    assert not list(tmp_path.iterdir())
