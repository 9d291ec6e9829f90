"""Parquet archives of one row group (as pandas writes them, rows not in time order) and of many
small row groups give the same estimates on two Dask workers as in process: each partition is
streamed out of the row groups it overlaps (registration.io.fleet.archive.parquet), or out of the copy by
time buckets made when the row groups do not follow time (registration.io.fleet.archive.timeorder), whose
reads give the original's rows in the original's order."""

from __future__ import annotations

import pickle
import shutil

import numpy as np
import pytest

from registration.fleet import fleet_scenario
from registration.fleet.batch.partitioned import solve_batch_partitioned
from registration.io import write_fleet_tables
from registration.io.fleet.archive import timeorder
from registration.io.fleet.archive.parquet import ParquetSource

NAMES = ("plots", "navigation", "sensors", "platforms", "reference")


@pytest.fixture(scope="module")
def folders(tmp_path_factory):
    """``one``: every table in one row group, plots not in time order; ``many``: the same files
    rewritten in row groups of 400 rows, time order kept as it was."""
    import pyarrow.parquet as pq

    sc = fleet_scenario(0)
    one = tmp_path_factory.mktemp("one")
    write_fleet_tables(one, sc.plots, sc.navigation, sc.sensors, sc.platforms, sc.references, fmt="parquet")
    assert pq.ParquetFile(one / "plots.parquet").num_row_groups == 1
    assert not np.all(np.diff(sc.plots["time"]) >= 0)
    many = tmp_path_factory.mktemp("many")
    for n in NAMES:
        pq.write_table(pq.read_table(one / f"{n}.parquet"), many / f"{n}.parquet", row_group_size=400)
    assert pq.ParquetFile(many / "plots.parquet").num_row_groups > 10
    return one, many


def _solve(source, client=None):
    return solve_batch_partitioned(source, partition_s=60.0, client=client, cache=0)


def test_one_and_many_row_groups_give_the_same_estimates_on_workers(folders, tmp_path, monkeypatch):
    pytest.importorskip("dask.distributed")
    from registration.core.parallel import dask_client

    one, many = folders
    ref = _solve(ParquetSource(one))
    assert ref.plan.n_partitions >= 4
    monkeypatch.setattr(timeorder, "MAX_GROUP_ROWS", 1000)  # the small tables count as large
    monkeypatch.setattr(timeorder, "BUCKET_ROWS", 1500)
    copied = ParquetSource(one).time_ordered(tmp_path / "copy")
    assert {"plots", "navigation"} <= set(copied.copies)
    assert len(list((tmp_path / "copy" / "plots").iterdir())) > 2
    for lo, hi in ref.plan.plot_ranges[:2]:  # a partition's rows and their order, as in the original
        a, b = ParquetSource(one).read_plots(lo, hi), copied.read_plots(lo, hi)
        assert a.keys() == b.keys()
        for k in a:
            assert np.array_equal(np.asarray(a[k]), np.asarray(b[k]), equal_nan=a[k].dtype.kind == "f")
    assert _solve(copied).estimate.tobytes() == ref.estimate.tobytes()
    with dask_client(workers=2) as client:
        runs = {
            "one row group": _solve(ParquetSource(one), client),
            "many row groups": _solve(ParquetSource(many), client),
        }
    for name, got in runs.items():
        assert got.iterations == ref.iterations, name
        assert np.allclose(got.estimate, ref.estimate, rtol=1e-9, atol=1e-12), name
        assert np.allclose(got.sigma, ref.sigma, rtol=1e-9), name


def test_a_copy_the_worker_cannot_see_falls_back_to_the_original(folders, tmp_path, monkeypatch):
    one, _ = folders
    monkeypatch.setattr(timeorder, "MAX_GROUP_ROWS", 1000)
    copied = ParquetSource(one).time_ordered(tmp_path / "copy")
    lo, hi = 30.0, 90.0
    shutil.rmtree(tmp_path / "copy")
    fresh = pickle.loads(pickle.dumps(copied))  # as a worker on another machine gets it
    a, b = ParquetSource(one).read_plots(lo, hi), fresh.read_plots(lo, hi)
    for k in a:
        assert np.array_equal(np.asarray(a[k]), np.asarray(b[k]), equal_nan=a[k].dtype.kind == "f")


def test_which_layouts_are_copied(folders, tmp_path, monkeypatch):
    """Copied: one large row group, or groups that each span most of the time; not copied: groups
    in time order, or (navigation) sorted by platform, then time."""
    import pyarrow.dataset as ds
    import pyarrow.parquet as pq

    one, _ = folders
    monkeypatch.setattr(timeorder, "MAX_GROUP_ROWS", 1000)
    nav = pq.read_table(one / "navigation.parquet")
    plots = pq.read_table(one / "plots.parquet")
    layouts = {
        "one group": (plots, None, True),
        "time order": (plots.sort_by("time_s"), None, False),
        "shuffled": (plots.take(np.random.default_rng(1).permutation(plots.num_rows)), None, True),
        "platform, then time": (
            nav.sort_by([("platform", "ascending"), ("time_s", "ascending")]),
            "platform",
            False,
        ),
    }
    for name, (table, key, copied) in layouts.items():
        path = tmp_path / f"{name}.parquet"
        pq.write_table(table, path, row_group_size=table.num_rows if name == "one group" else 400)
        assert timeorder.needs_copy(ds.dataset(path), "time_s", key) is copied, name
