"""The outputs of an archive run (registration.fleet.batch.outputs, registration.cli.fleet.archive):
the fused targets, streamed as Parquet parts, equal solve_batch's; the residual sums per sensor and
channel equal its residuals'; the figures' sample is bounded; a folder of CSV files is converted
block by block into the same archive, and its bad rows are named as the ordinary reader names them."""

from __future__ import annotations

import argparse
import json

import numpy as np
import pytest

from registration.cli.fleet.archive import add_archive_arguments, run_archive
from registration.fleet import BatchOptions, fleet_scenario, solve_batch
from registration.fleet.batch.outputs import FUSED_COLUMNS, archive_outputs
from registration.fleet.batch.partitioned import solve_batch_partitioned
from registration.io import read_fleet_tables, write_fleet_tables
from registration.io.fleet.archive.csvfolder import parquet_from_csv
from tests.fleet.test_archive import EXTENDED, source_of

NAMES = ("plots", "navigation", "sensors", "platforms", "reference")


@pytest.fixture(scope="module")
def solved():
    sc = fleet_scenario(1, **EXTENDED)
    batch = solve_batch(sc.problem())
    src = source_of(sc)
    return sc, batch, src, solve_batch_partitioned(src, partitions=3)


def _frame(tables):
    import pandas as pd

    return pd.concat([pd.DataFrame(t) for t in tables], ignore_index=True)


def test_fused_targets_and_residuals_equal_solve_batch(solved, tmp_path):
    import pyarrow.dataset as ds

    _, batch, src, part = solved
    out = archive_outputs(part, src, BatchOptions())
    f = _frame(out.tables).sort_values(["target", "time_s"], kind="stable")
    ft = batch.targets
    order = np.lexsort((ft.time, ft.target))
    assert list(f.columns) == list(FUSED_COLUMNS) and len(f) == ft.time.size == out.fused_rows
    assert (f["target"].to_numpy() == ft.target[order]).all()
    assert (f["n_plots"].to_numpy() == ft.n_plots[order]).all()
    np.testing.assert_allclose(f["time_s"], ft.time[order], rtol=0, atol=1e-9)
    np.testing.assert_allclose(f[["x_m", "y_m", "z_m"]], ft.p_ecef[order], rtol=0, atol=1e-4)
    cov = ft.covariance[order]
    for name, (a, b) in zip(FUSED_COLUMNS[5:11], ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))):
        np.testing.assert_allclose(f[name], cov[:, a, b], rtol=1e-7, atol=1e-6 * np.abs(cov).max())
    # per sensor: the mean square of its whitened residuals, as BatchResult.residual_check gives it
    check = batch.residual_check("sensor")
    for i, sensor in enumerate(out.sensor_ids):
        n = int(out.count[i].sum())
        assert n == check[sensor][1]
        assert out.squares[i].sum() / n == pytest.approx(check[sensor][0], rel=1e-9)
    res = batch.residuals
    sensors = batch.plot_sensor
    for c in range(3):  # per channel too, count, mean and RMS
        i = list(out.sensor_ids).index("A-3D")
        r = res[(sensors == "A-3D") & np.isfinite(res[:, c]), c]
        assert out.count[i, c] == r.size
        assert out.mean[i, c] == pytest.approx(r.mean(), abs=1e-9)
        assert out.rms[i, c] == pytest.approx(np.sqrt(np.mean(r**2)), rel=1e-9)
    for key in ("plots", "references"):
        assert out.parts[key][1] == batch.chi_square.parts[key][1]
        assert out.parts[key][0] == pytest.approx(batch.chi_square.parts[key][0], rel=1e-9)
    assert out.hist.sum() == np.isfinite(res).sum()
    # written as parts by the pass itself: the same rows
    parts = tmp_path / "parts"
    parts.mkdir()
    written = archive_outputs(part, src, BatchOptions(), parts=parts)
    assert written.tables is None
    assert sorted(p.name for p in parts.iterdir()) == [
        f"part-{k:05d}.parquet" for k in range(written.n_parts)
    ]
    back = ds.dataset(str(parts)).to_table().to_pandas()
    assert back.equals(_frame(out.tables))


def test_the_sample_is_bounded_and_deterministic(solved):
    _, _, src, part = solved
    a = archive_outputs(part, src, BatchOptions(), sample_max=500)
    b = archive_outputs(part, src, BatchOptions(), sample_max=500)
    assert 0 < a.sample["time"].size <= 500
    assert a.sample_every == -(-part.n_plots // (500 - a.n_parts))
    assert all(np.array_equal(a.sample[k], b.sample[k], equal_nan=True) for k in a.sample)


def parse(argv):
    p = argparse.ArgumentParser()
    p.add_argument("--tables")
    p.add_argument("--out")
    p.add_argument("--window-s", type=float, default=20.0)
    p.add_argument("--no-plots", action="store_true")
    add_archive_arguments(p)
    return p.parse_args(argv)


@pytest.fixture(scope="module")
def folders(tmp_path_factory):
    sc = fleet_scenario(0)
    csv, pq = tmp_path_factory.mktemp("csv"), tmp_path_factory.mktemp("parquet")
    write_fleet_tables(csv, sc.plots, sc.navigation, sc.sensors, sc.platforms, sc.references, fmt="csv")
    write_fleet_tables(pq, sc.plots, sc.navigation, sc.sensors, sc.platforms, sc.references, fmt="parquet")
    return csv, pq


def test_csv_folder_gives_the_parquet_run_and_the_outputs(folders, tmp_path):
    csv, pq = folders
    outs = {}
    for name, folder in (("csv", csv), ("parquet", pq)):
        out = tmp_path / name
        assert run_archive(parse(["--tables", str(folder), "--out", str(out), "--partition-s", "100"])) == 0
        outs[name] = out
    assert (outs["csv"] / "estimates.csv").read_bytes() == (outs["parquet"] / "estimates.csv").read_bytes()
    assert (outs["csv"] / "residuals.csv").read_bytes() == (outs["parquet"] / "residuals.csv").read_bytes()
    out = outs["csv"]
    assert {p.name for p in out.iterdir()} == {
        "estimates.csv",
        "residuals.csv",
        "summary.json",
        "residuals.png",
        "residuals_time.png",
        "map.png",
        "fused_targets",
    }
    summary = json.loads((out / "summary.json").read_text())
    assert summary["fused_targets"]["parts"] == 3 and summary["fused_targets"]["written_by"] == "this process"
    assert set(summary["residuals_by_sensor"]) == {"A-3D", "A-ESM", "B-3D", "C-3D", "C-2D", "S-2D"}
    assert summary["residuals_of_references"]["values"] == summary["chi_square"]["parts"]["references"][1]
    # a second run replaces the folder of parts whole (2 partitions now), and the PNGs stay unless rewritten
    assert (
        run_archive(parse(["--tables", str(csv), "--out", str(out), "--partition-s", "150", "--no-plots"]))
        == 0
    )
    assert sorted(p.name for p in (out / "fused_targets").iterdir()) == [
        "part-00000.parquet",
        "part-00001.parquet",
    ]


def test_csv_converted_in_small_blocks_is_the_same_archive(folders, tmp_path):
    import pyarrow.parquet as pq

    csv, _ = folders
    small, whole = tmp_path / "small", tmp_path / "whole"
    small.mkdir(), whole.mkdir()
    parquet_from_csv(csv, small, block_bytes=4096)
    parquet_from_csv(csv, whole)
    for name in ("plots", "navigation", "reference"):
        a, b = pq.read_table(small / f"{name}.parquet"), pq.read_table(whole / f"{name}.parquet")
        assert a.schema == b.schema and a.to_pandas().equals(b.to_pandas())  # NaN cells equal
    assert pq.ParquetFile(small / "plots.parquet").num_row_groups > 10


@pytest.mark.parametrize(
    "column, value", [("range_m", "12x"), ("bearing_deg", "400"), ("sensor", "nobody"), ("time_s", "")]
)
def test_a_bad_csv_row_is_named_as_the_ordinary_reader_names_it(folders, tmp_path, column, value):
    import pandas as pd

    csv, _ = folders
    bad = tmp_path / "bad"
    bad.mkdir()
    for name in NAMES:
        (bad / f"{name}.csv").write_bytes((csv / f"{name}.csv").read_bytes())
    plots = pd.read_csv(bad / "plots.csv", dtype=str, keep_default_na=False)
    row = len(plots) - 7  # in the last blocks
    plots.loc[row, column] = value
    plots.to_csv(bad / "plots.csv", index=False)
    with pytest.raises(ValueError) as ordinary:
        read_fleet_tables(*(bad / f"{n}.csv" for n in NAMES))
    conv = tmp_path / "conv"
    conv.mkdir()
    with pytest.raises(ValueError) as archive:
        parquet_from_csv(bad, conv, block_bytes=8192)
    assert str(archive.value) == str(ordinary.value)
    assert f"row {row}," in str(archive.value)
    out = tmp_path / "out"
    out.mkdir()
    (out / "estimates.csv").write_text("earlier\n")
    with pytest.raises(ValueError):
        run_archive(parse(["--tables", str(bad), "--out", str(out), "--partition-s", "100"]))
    assert [p.name for p in out.iterdir()] == ["estimates.csv"] and (
        out / "estimates.csv"
    ).read_text() == "earlier\n"
