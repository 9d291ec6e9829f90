"""SIGTERM ends a command cleanly: exit 143, its temporary folders (a partitioned run's spill: up to
gigabytes) removed, ``--out`` not created. A real process, terminated while it works."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import pytest

from registration.cli.errors import EXIT_TERMINATED
from registration.fleet import fleet_scenario
from registration.io import write_fleet_tables


@pytest.fixture(scope="module")
def tables(tmp_path_factory):
    sc = fleet_scenario(0, duration_s=1500.0)
    folder = tmp_path_factory.mktemp("tables")
    write_fleet_tables(
        folder, sc.plots, sc.navigation, sc.sensors, sc.platforms, sc.references, fmt="parquet"
    )
    return folder


def _spill_with_files(tmp):
    """The run's work folder in ``tmp`` once it holds a file (a spilled partition)."""
    for d in tmp.glob("registration-archive-*"):
        if any(d.iterdir()):
            return d
    return None


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
def test_sigterm_removes_the_spill_and_leaves_no_output(tables, tmp_path):
    tmp, out = tmp_path / "tmp", tmp_path / "out"
    tmp.mkdir()
    env = dict(os.environ, TMPDIR=str(tmp))
    cmd = [sys.executable, "-m", "registration", "fleet", "register", "--tables", str(tables)]
    proc = subprocess.Popen(
        [*cmd, "--partition-s", "60", "--no-plots", "--out", str(out)],
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
    )
    try:
        deadline = time.monotonic() + 120.0
        while _spill_with_files(tmp) is None:
            assert proc.poll() is None, "the run ended before its spill folder held a partition"
            assert time.monotonic() < deadline, "no spill folder after 120 s"
            time.sleep(0.01)
        proc.send_signal(signal.SIGTERM)
        _, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert proc.returncode == EXIT_TERMINATED, err.decode(errors="replace")
    assert list(tmp.iterdir()) == [], "temporary folders left behind"
    assert not out.exists()
