"""The partitioned solve (registration.fleet.batch.partitioned) on an ATC recording whose flight
levels became heights without ADS-B heights, so they share one unknown offset (the state
``flight_levels:height_offset``, the reference column ``height_offset_prior_m``): the recording is
simulated (tests/io/asterix/atc.py), encoded by libasterix and imported by ``registration import
asterix``; the primary-only plots, which have no target id (the partitioned solver needs ids), are
left out. Partitions of 50 s or 30 s, in this process, read lazily and on two Dask workers, give
the in-memory solve's estimates and sigmas (the offset's included) to the archive tests' 1e-9
relative, also when a partition holds no flight-level height; so do the CLI's outputs, and
``--memory-limit`` partitions such tables by itself. Rows whose offset priors differ are an
error naming the reference file."""

from __future__ import annotations

import json
import re

import numpy as np
import pandas as pd
import pytest

from registration.cli import main
from registration.fleet import BatchOptions, solve_batch
from registration.fleet.batch.outputs import archive_outputs
from registration.fleet.batch.partitioned import sizing, solve_batch_partitioned
from registration.fleet.batch.partitioned.plan import make_plan
from registration.fleet.batch.partitioned.task import PartitionTask, partition_problem
from registration.io import read_fleet_tables
from registration.io.fleet.sources import open_fleet_tables
from tests.fleet.test_archive import RTOL, assert_same
from tests.io.asterix.atc import atc_truth, encode_atc

NAMES = ("plots", "navigation", "sensors", "platforms", "reference")
OFFSET = "flight_levels:height_offset"
DAY = (12.0, 102500.0)  # ISA + 12 K, QNH 1025 hPa


@pytest.fixture(scope="module")
def imported(tmp_path_factory):
    """The imported tables (CSV) of a 240 s recording without ADS-B flight levels, the plots
    without a target id left out."""
    work = tmp_path_factory.mktemp("atc")
    truth = atc_truth(31, 240.0, flight_levels=DAY)
    del truth.adsb["fl_raw"]  # no ADS-B report gives a flight level: the heights share an offset
    rec = encode_atc(truth.plots, truth.adsb, truth.sites, truth.date, truth.scans)
    (work / "atc.ast").write_bytes(rec.raw())
    truth.sites.to_csv(work / "SITES.csv", index=False)
    raw = work / "imported"
    argv = ["import", "asterix", str(work / "atc.ast"), "--sites", str(work / "SITES.csv"), "--out", str(raw)]
    assert main([*argv, "--date", truth.date.isoformat()]) == 0
    tables = work / "tables"
    tables.mkdir()
    for name in NAMES[1:]:
        (tables / f"{name}.csv").write_bytes((raw / f"{name}.csv").read_bytes())
    plots = pd.read_csv(raw / "plots.csv", dtype={"target": str}, keep_default_na=False)
    plots[plots["target"] != ""].to_csv(tables / "plots.csv", index=False)
    reference = pd.read_csv(tables / "reference.csv")
    assert np.isfinite(reference["height_offset_prior_m"]).sum() > 300
    return tables


def _read(folder):
    return read_fleet_tables(*(folder / f"{n}.csv" for n in NAMES))


@pytest.fixture(scope="module")
def in_memory(imported):
    tables = _read(imported)
    batch = solve_batch(tables.problem())
    assert batch.layout.names[-1] == OFFSET and batch.converged
    return tables, batch


def _assert_offset_same(part, batch):
    """The offset's estimate and sigma: the same state, to RTOL, determined by the heights."""
    k = batch.layout.height_offset_index
    assert part.layout.names == batch.layout.names and part.layout.height_offset_index == k >= 0
    assert abs(part.estimate[k] - batch.estimate[k]) <= RTOL * abs(batch.estimate[k])
    assert abs(part.sigma[k] - batch.sigma[k]) <= RTOL * batch.sigma[k]
    assert batch.sigma[k] < 0.2 * batch.layout.prior_sigma[k]  # the data determine it, not its prior


def _flight_level_partitions(source, plan) -> list[bool]:
    """Per partition with plots: whether its references hold heights that carry the offset."""
    empty = np.zeros((0, 2), dtype=np.int64)
    found = []
    for k in range(plan.n_partitions):
        problem = partition_problem(PartitionTask(source, plan, k, BatchOptions(), empty))
        if problem is not None:
            found.append(bool(problem.references.offset.any()))
    return found


def test_partitions_give_the_in_memory_estimates_with_the_height_offset(imported, in_memory):
    tables, batch = in_memory
    for partition_s in (50.0, 30.0):
        part = solve_batch_partitioned(tables, partition_s=partition_s)
        assert part.plan.n_partitions >= 4 and part.plan.height_offset_prior is not None
        assert sum(_flight_level_partitions(tables, part.plan)) >= 4
        assert_same(part, batch)
        _assert_offset_same(part, batch)
    with open_fleet_tables(imported, lazy=True) as source:  # read lazily, spilled to disk
        part = solve_batch_partitioned(source, partition_s=50.0)
        assert_same(part, batch)
        _assert_offset_same(part, batch)
        # the output pass: fused targets, residual sums and chi-square parts as solve_batch's
        out = archive_outputs(part, source, BatchOptions())
    for key in ("plots", "references"):
        assert out.parts[key][1] == batch.chi_square.parts[key][1]
        assert out.parts[key][0] == pytest.approx(batch.chi_square.parts[key][0], rel=RTOL)
    fused = pd.concat([pd.DataFrame(t) for t in out.tables], ignore_index=True)
    fused = fused.sort_values(["target", "time_s"], kind="stable")
    ft = batch.targets
    order = np.lexsort((ft.time, ft.target))
    assert len(fused) == ft.time.size == out.fused_rows
    assert (fused["target"].to_numpy() == ft.target[order]).all()
    np.testing.assert_allclose(fused[["x_m", "y_m", "z_m"]], ft.p_ecef[order], rtol=0, atol=1e-4)
    cov = ft.covariance[order]
    np.testing.assert_allclose(fused["cov_zz_m2"], cov[:, 2, 2], rtol=1e-7, atol=1e-6 * np.abs(cov).max())
    check = batch.residual_check("sensor")
    for i, sensor in enumerate(out.sensor_ids):
        n = int(out.count[i].sum())
        assert n == check[sensor][1]
        assert out.squares[i].sum() / n == pytest.approx(check[sensor][0], rel=RTOL)


def test_a_partition_without_flight_level_heights(imported, tmp_path):
    """The first 80 s of the recording without the heights that carry the offset: the first
    partition has none (its windows' coupling with the offset is zero), the later ones have."""
    folder = tmp_path / "tables"
    folder.mkdir()
    for name in NAMES:
        (folder / f"{name}.csv").write_bytes((imported / f"{name}.csv").read_bytes())
    reference = pd.read_csv(folder / "reference.csv")
    start = pd.read_csv(folder / "plots.csv")["time_s"].min()
    carries = np.isfinite(reference["height_offset_prior_m"])
    reference[~(carries & (reference["time_s"] < start + 80.0))].to_csv(folder / "reference.csv", index=False)
    tables = _read(folder)
    batch = solve_batch(tables.problem())
    part = solve_batch_partitioned(tables, partition_s=50.0)
    with_heights = _flight_level_partitions(tables, part.plan)
    assert not with_heights[0] and sum(with_heights) >= 3
    assert_same(part, batch)
    _assert_offset_same(part, batch)


def test_offset_priors_that_differ_are_named(imported, tmp_path):
    folder = tmp_path / "tables"
    folder.mkdir()
    for name in NAMES:
        (folder / f"{name}.csv").write_bytes((imported / f"{name}.csv").read_bytes())
    reference = pd.read_csv(folder / "reference.csv")
    row = int(np.flatnonzero(np.isfinite(reference["height_offset_prior_m"]))[-1])
    reference.loc[row, "height_offset_prior_m"] += 10.0
    reference.to_csv(folder / "reference.csv", index=False)
    with pytest.raises(ValueError, match="the same on every row"):  # as the in-memory reader
        _read(folder).problem()
    with open_fleet_tables(folder, lazy=True) as source:
        with pytest.raises(ValueError, match="the same on every row") as err:
            make_plan(source, 20.0, partition_s=50.0)
        assert source.name("reference") in str(err.value) and "\n" not in str(err.value)


def _estimates(out):
    frame = pd.read_csv(out / "estimates.csv")
    return frame.set_index(["object", "state"])[["estimate", "sigma"]]


def _assert_estimates_same(a, b):
    assert list(a.index) == list(b.index) and ("flight_levels", "height_offset") in a.index
    scale = np.maximum(np.abs(a["estimate"]), 1e-300)
    assert np.max(np.abs(b["estimate"] - a["estimate"]) / scale) < RTOL
    np.testing.assert_allclose(b["sigma"], a["sigma"], rtol=RTOL, atol=0)


@pytest.fixture(scope="module")
def cli_runs(imported, tmp_path_factory):
    """``fleet register`` in memory and by partitions of 50 s in this process."""
    work = tmp_path_factory.mktemp("cli")
    base = ["fleet", "register", "--tables", str(imported), "--no-plots"]
    assert main([*base, "--out", str(work / "memory")]) == 0
    assert main([*base, "--out", str(work / "part"), "--partition-s", "50"]) == 0
    return work / "memory", work / "part"


def test_the_cli_by_partitions_writes_the_in_memory_estimates_and_its_outputs(cli_runs):
    memory, part = cli_runs
    _assert_estimates_same(_estimates(memory), _estimates(part))
    summary = json.loads((part / "summary.json").read_text())
    expected = json.loads((memory / "summary.json").read_text())
    assert summary["partitions"] >= 4 and summary["converged"]
    assert summary["chi_square"]["dof"] == expected["chi_square"]["dof"]
    assert summary["chi_square"]["chi2"] == pytest.approx(expected["chi_square"]["chi2"], rel=RTOL)
    assert summary["residuals_of_references"]["values"] == summary["chi_square"]["parts"]["references"][1]
    residuals = pd.read_csv(part / "residuals.csv")
    assert set(residuals["sensor"]) == set(summary["residuals_by_sensor"]) == {"R1", "R2", "R3"}
    assert summary["fused_targets"]["parts"] == summary["partitions"]
    assert len(list((part / "fused_targets").iterdir())) == summary["partitions"]


def test_the_memory_limit_partitions_such_tables(imported, cli_runs, tmp_path, monkeypatch, capsys):
    memory, _ = cli_runs
    plots = len(pd.read_csv(imported / "plots.csv"))
    monkeypatch.setattr(sizing, "IN_MEMORY_PER_PLOT", 2 * (1 << 30) // plots)  # "too large" for 1 GiB
    monkeypatch.setattr(sizing, "PARTITION_PER_PLOT", 200_000)  # partitions shorter than the run
    out = tmp_path / "auto"
    argv = ["fleet", "register", "--tables", str(imported), "--no-plots", "--out", str(out)]
    assert main([*argv, "--memory-limit", "1GiB"]) == 0
    text = capsys.readouterr().out
    assert "registering the archive by partitions" in text
    assert re.search(r"memory limit 1\.0 GiB: partitions of ([0-9.]+) s", text), text
    summary = json.loads((out / "summary.json").read_text())
    assert summary["partition_s_chosen"] and summary["partitions"] > 1
    _assert_estimates_same(_estimates(memory), _estimates(out))


def test_two_dask_workers_give_the_in_process_run(imported, cli_runs, tmp_path):
    """The reduce adds the partitions in their order: the workers' estimates and residuals are the
    in-process run's, to the last digit written."""
    pytest.importorskip("dask.distributed")
    _, part = cli_runs
    out = tmp_path / "workers"
    argv = ["fleet", "register", "--tables", str(imported), "--no-plots", "--out", str(out)]
    assert main([*argv, "--partition-s", "50", "--workers", "2"]) == 0
    assert json.loads((out / "summary.json").read_text())["workers"] == 2
    for name in ("estimates.csv", "residuals.csv"):
        assert (out / name).read_bytes() == (part / name).read_bytes(), name
