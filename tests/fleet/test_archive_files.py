"""Archives as Parquet files read lazily by the partitioned solver (registration.io.fleet.archive.parquet),
and the partitions mapped on Dask workers: the same estimate as solve_batch on the same files, also
when the plots are a folder of files out of time order; a file that breaks mid-run is a one-line
ValueError naming it; 1, 2 and 3 workers give the in-process answer."""

from __future__ import annotations

import numpy as np
import pytest

from registration.core.parallel import dask_client
from registration.fleet import fleet_scenario, solve_batch
from registration.fleet.batch.partitioned import solve_batch_partitioned
from registration.io import read_fleet_tables, write_fleet_tables
from registration.io.fleet.archive.parquet import ParquetSource
from registration.io.fleet.memory import TablesSource
from tests.fleet.test_archive import EXTENDED, assert_same


@pytest.fixture(scope="module")
def archive(tmp_path_factory):
    """The extended scenario written as Parquet, its solve_batch result, and a copy whose plots are a
    folder of two files, each a random half of the rows in shuffled order."""
    import pyarrow.parquet as pq

    sc = fleet_scenario(1, **EXTENDED)
    folder = tmp_path_factory.mktemp("archive")
    write_fleet_tables(
        folder, sc.plots, sc.navigation, sc.sensors, sc.platforms, sc.references, fmt="parquet"
    )
    names = ("plots", "navigation", "sensors", "platforms", "reference")
    tables = read_fleet_tables(*(folder / f"{n}.parquet" for n in names))
    batch = solve_batch(tables.problem())
    split = tmp_path_factory.mktemp("split")
    for n in names[1:]:
        (split / f"{n}.parquet").write_bytes((folder / f"{n}.parquet").read_bytes())
    plots = pq.read_table(folder / "plots.parquet")
    rng = np.random.default_rng(5)
    order = rng.permutation(plots.num_rows)
    (split / "plots").mkdir()
    half = plots.num_rows // 2
    pq.write_table(plots.take(order[:half]), split / "plots" / "part-b.parquet", row_group_size=500)
    pq.write_table(plots.take(order[half:]), split / "plots" / "part-a.parquet", row_group_size=500)
    return sc, folder, split, batch


def test_parquet_archive_equals_solve_batch(archive):
    _, folder, split, batch = archive
    for path, partitions in ((folder, 1), (folder, 3), (split, 2), (split, 7)):
        assert_same(solve_batch_partitioned(ParquetSource(path), partitions=partitions), batch)


def test_a_file_that_breaks_mid_run_is_named(archive, monkeypatch):
    _, _, split, _ = archive
    broken = split.parent / "broken"
    broken.mkdir()
    for p in split.rglob("*.parquet"):
        target = broken / p.relative_to(split)
        target.parent.mkdir(exist_ok=True)
        target.write_bytes(p.read_bytes())
    source = ParquetSource(broken)
    victim = broken / "plots" / "part-a.parquet"
    calls = {"n": 0}
    read = source.read_plots

    def read_then_break(lo, hi):
        calls["n"] += 1
        if calls["n"] == 4:  # after the setup pass and a first reduce pass have read every partition
            victim.write_bytes(b"PAR1 this is not a parquet file any more")
        return read(lo, hi)

    monkeypatch.setattr(source, "read_plots", read_then_break)
    with pytest.raises(ValueError) as err:
        solve_batch_partitioned(source, partitions=3, cache=0, spill=False)  # spill: no file read after setup
    text = str(err.value)
    assert str(victim) in text and "\n" not in text
    with pytest.raises(ValueError, match="no plots table"):
        ParquetSource(broken / "plots")


def test_dask_workers_equal_in_process():
    """1, 2 and 3 worker processes: the reduce adds the partitions in their order, so the estimate is
    the in-process one bit for bit (far inside the 1e-9 asked)."""
    pytest.importorskip("dask.distributed")
    sc = fleet_scenario(0)
    src = TablesSource(sc.plots, sc.sensors, sc.navigation, sc.platforms, sc.references)
    ref = solve_batch_partitioned(src, partitions=3)
    for workers in (1, 2, 3):
        with dask_client(workers=workers) as client:
            assert len(client.scheduler_info()["workers"]) == workers
            got = solve_batch_partitioned(src, partitions=3, client=client, cache=2)
        assert got.estimate.tobytes() == ref.estimate.tobytes()
        assert got.sigma.tobytes() == ref.sigma.tobytes()


def test_every_source_keeps_the_contract_and_opens_one_way(archive, tmp_path):
    """The tables in memory, a checked folder and an archive are FleetSources; open_fleet_tables gives
    the checked folder (in memory) or the archive (lazy) of the same folder, and a CSV archive's
    temporary Parquet folder is gone when the context ends."""
    from registration.fleet.data.source import FleetSource
    from registration.io.fleet.reading.read import FleetTables
    from registration.io.fleet.sources import open_fleet_tables

    sc, folder, _, _ = archive
    assert isinstance(TablesSource(sc.plots, sc.sensors, sc.navigation), FleetSource)
    with open_fleet_tables(folder) as tables:
        assert isinstance(tables, FleetTables) and isinstance(tables, FleetSource) and tables.in_memory
        assert tables.name("references") == str(folder / "reference.parquet")
    with open_fleet_tables(folder, lazy=True) as source:
        assert isinstance(source, ParquetSource) and isinstance(source, FleetSource) and not source.in_memory
        assert source.name("plots") == str(folder / "plots.parquet")
        # the small tables come from the checked reader: SI units, radians, the priors' "no prior" as inf
        assert np.array_equal(
            source.sensors["sigma_bearing"], tables.sensors["sigma_bearing"], equal_nan=True
        )
    csv = tmp_path / "csv"
    csv.mkdir()
    write_fleet_tables(csv, sc.plots, sc.navigation, sc.sensors, sc.platforms, sc.references, fmt="csv")
    with open_fleet_tables(csv, lazy=True) as source:
        temp = source.folder
        assert temp != csv and (temp / "plots.parquet").is_file()
    assert not temp.exists()
