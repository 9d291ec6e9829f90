"""``fleet register --memory-limit SIZE`` (registration.cli.fleet.memory): sizes as 1GiB or 512MiB;
tables that would need more than the limit in memory are registered by partitions of a length the
run chooses (and says), with the in-memory run's estimates; a limit below what one partition needs
stops the run with exit 2 before any output, naming the smallest limit that works, and that limit
works."""

from __future__ import annotations

import argparse
import json
import re

import numpy as np
import pandas as pd
import pytest

from registration.cli import main
from registration.cli.fleet.memory import parse_size
from registration.fleet import fleet_scenario
from registration.fleet.batch.partitioned import sizing
from registration.fleet.batch.partitioned.sizing import MiB, choose_partition_s, partition_bytes
from registration.io import write_fleet_tables


@pytest.fixture(scope="module")
def tables(tmp_path_factory):
    sc = fleet_scenario(0)
    folder = tmp_path_factory.mktemp("tables")
    write_fleet_tables(
        folder, sc.plots, sc.navigation, sc.sensors, sc.platforms, sc.references, fmt="parquet"
    )
    return folder, int(sc.plots["time"].size)


def test_sizes_are_read_with_their_units():
    assert parse_size("1GiB") == 1 << 30
    assert parse_size("512MiB") == 512 << 20
    assert parse_size("1.5G") == 3 << 29
    assert parse_size("2GB") == 2 * 10**9
    assert parse_size("4096") == 4096
    for bad in ("", "12XB", "-1GiB", "0MiB", "GiB"):
        with pytest.raises(argparse.ArgumentTypeError):
            parse_size(bad)


def test_the_chosen_length_is_the_longest_that_fits():
    """A plot rate of 80/s with a burst of 400/s for 300 s: the busiest partition fits the limit,
    and the next longer round length would not."""
    t = np.concatenate([np.linspace(0, 20_000, 1_600_000), np.linspace(5_000, 5_300, 120_000)])
    counts, edges = np.histogram(t, 8192)
    c = np.concatenate([[0], np.cumsum(counts)])
    bin_s = edges[1] - edges[0]

    def most_rows(length):
        k = int(np.ceil(length / bin_s)) + 1
        return int(np.max(c[k:] - c[:-k]))

    limit = 600 * MiB
    got = choose_partition_s(most_rows, t.size, 20_000.0, limit, 20.0)
    assert partition_bytes(most_rows(got.partition_s + 40.0)) <= limit
    longer = {1: 2, 2: 5, 5: 10}[int(round(got.partition_s / 10 ** np.floor(np.log10(got.partition_s))))]
    longer_s = longer * 10 ** np.floor(np.log10(got.partition_s))
    assert partition_bytes(most_rows(longer_s + 40.0)) > limit
    with pytest.raises(ValueError, match=r"smallest limit that works is \d+MiB"):
        choose_partition_s(most_rows, t.size, 20_000.0, sizing.PARTITION_BASE, 20.0)


def _estimates(out):
    frame = pd.read_csv(out / "estimates.csv").set_index(["object", "state"])
    return frame["estimate"].to_numpy(), frame["sigma"].to_numpy()


def test_tables_too_large_for_the_limit_are_partitioned_by_the_run(tables, tmp_path, monkeypatch, capsys):
    """With the estimate of the memory in memory made large (so the small tables exceed 1 GiB), the
    run partitions by itself, says so, and gives the in-memory run's estimates."""
    folder, plots = tables
    base = ["fleet", "register", "--tables", str(folder), "--no-plots", "--window-s", "20"]
    assert main([*base, "--out", str(tmp_path / "memory"), "--memory-limit", "64GiB"]) == 0
    assert "by partitions" not in capsys.readouterr().out
    monkeypatch.setattr(sizing, "IN_MEMORY_PER_PLOT", 2 * (1 << 30) // plots)
    monkeypatch.setattr(sizing, "PARTITION_PER_PLOT", 200_000)  # partitions shorter than the run
    out = tmp_path / "auto"
    assert main([*base, "--out", str(out), "--memory-limit", "1GiB"]) == 0
    text = capsys.readouterr().out
    assert "registering the archive by partitions" in text
    chosen = re.search(r"memory limit 1\.0 GiB: partitions of ([0-9.]+) s", text)
    assert chosen, text
    summary = json.loads((out / "summary.json").read_text())
    assert summary["partition_s_chosen"] and summary["partition_s"] == float(chosen.group(1))
    assert summary["partitions"] > 1 and summary["memory_limit_bytes"] == 1 << 30
    (a, sa), (b, sb) = _estimates(tmp_path / "memory"), _estimates(out)
    assert np.allclose(a, b, rtol=1e-6, atol=1e-9) and np.allclose(sa, sb, rtol=1e-6)


def test_a_limit_below_one_partition_exits_2_naming_the_smallest_that_works(tables, tmp_path, capsys):
    folder, _ = tables
    out = tmp_path / "out"
    base = ["fleet", "register", "--tables", str(folder), "--no-plots", "--out", str(out)]
    for extra in ([], ["--partition-s", "100"]):
        assert main([*base, "--memory-limit", "100MiB", *extra]) == 2
        err = capsys.readouterr().err
        found = re.search(r"smallest limit that works is (\d+)MiB", err)
        assert found, err
        assert not out.exists() or not any(out.iterdir())
        smallest = f"{found.group(1)}MiB"
        assert int(found.group(1)) > 100
        # the limit named is enough: in memory, or for that partition length
        assert main([*base, "--memory-limit", smallest, *extra]) == 0
        assert (out / "estimates.csv").is_file()
        for p in out.iterdir():
            p.unlink() if p.is_file() else __import__("shutil").rmtree(p)
