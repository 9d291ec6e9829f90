"""The archive pieces of ``fleet register`` (registration.cli.fleet.archive): --partition-s runs the
partitioned solver on a Parquet folder and writes estimates.csv and summary.json; an archive whose
file cannot be read leaves --out as it was; --workers without --tables is refused."""

from __future__ import annotations

import argparse
import json

import numpy as np
import pytest

from registration.cli.fleet.archive import add_archive_arguments, archive_requested, run_archive
from registration.fleet import fleet_scenario
from registration.io import write_fleet_tables


def parse(argv):
    p = argparse.ArgumentParser()
    p.add_argument("--tables")
    p.add_argument("--out")
    p.add_argument("--window-s", type=float, default=20.0)
    add_archive_arguments(p)
    return p.parse_args(argv)


def test_archive_run_writes_estimates_and_leaves_out_on_error(tmp_path):
    sc = fleet_scenario(0)
    tables = tmp_path / "tables"
    tables.mkdir()
    write_fleet_tables(
        tables, sc.plots, sc.navigation, sc.sensors, sc.platforms, sc.references, fmt="parquet"
    )
    out = tmp_path / "out"
    args = parse(["--tables", str(tables), "--out", str(out), "--partition-s", "100"])
    assert archive_requested(args)
    assert run_archive(args) == 0
    import pandas as pd

    frame = pd.read_csv(out / "estimates.csv")
    assert list(frame.columns) == [
        "object",
        "state",
        "unit",
        "estimate",
        "sigma",
        "status",
    ]  # the in-memory layout
    est = frame.set_index(["object", "state"])
    truth = sc.truth_state
    # the heading errors are estimated to within a few hundredths of a degree
    assert abs(est.loc[("A", "heading_error"), "estimate"] - np.degrees(truth["A:heading_error"])) < 0.05
    assert (
        est.loc[("A", "heading_error"), "status"] == "identifiable"
        and est.loc[("A", "heading_error"), "unit"] == "deg"
    )
    summary = json.loads((out / "summary.json").read_text())
    assert summary["partitions"] == 3 and summary["converged"]
    before = {p.relative_to(out): p.read_bytes() for p in out.rglob("*") if p.is_file()}
    (tables / "navigation.parquet").write_bytes(b"not parquet")
    with pytest.raises(ValueError) as err:
        run_archive(args)
    assert "navigation.parquet" in str(err.value) and "\n" not in str(err.value)
    assert {p.relative_to(out): p.read_bytes() for p in out.rglob("*") if p.is_file()} == before


def test_workers_without_an_archive_folder_is_refused():
    """--workers without --partition-s maps partitions of a length the run chooses; without --tables
    DIR there is no archive to map."""
    with pytest.raises(ValueError, match="--tables DIR"):
        archive_requested(parse(["--workers", "2"]))
    assert archive_requested(parse(["--workers", "2", "--tables", "somewhere"]))
    assert not archive_requested(parse([]))


def test_an_archive_whose_data_contradict_the_model_says_so_with_exit_3(tmp_path, capsys):
    """An aircraft declared a surface target at sea level (targets file): the archive run takes the
    surface, the data contradict it, and the run says so as the in-memory run does (exit 3 after
    writing its outputs; 0 with --allow-inconsistent)."""
    sc = fleet_scenario(0)
    tables = tmp_path / "tables"
    tables.mkdir()
    write_fleet_tables(
        tables,
        sc.plots,
        sc.navigation,
        sc.sensors,
        sc.platforms,
        sc.references,
        fmt="parquet",
        targets={"target": ["T2"], "surface_alt": [0.0], "sigma_surface": [5.0]},
    )
    out = tmp_path / "out"
    args = parse(["--tables", str(tables), "--out", str(out), "--partition-s", "100"])
    assert run_archive(args) == 3
    assert (out / "estimates.csv").is_file()
    assert "grossly inconsistent" in capsys.readouterr().out
    args.allow_inconsistent = True
    assert run_archive(args) == 0
