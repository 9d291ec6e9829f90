"""A real kill-and-resume: SIGKILL a `registration register` subprocess twice, resume, compare bit for bit."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from registration.cli import main
from registration.recorded import CheckpointError, load_checkpoint

from ._register_data import tiled

ROOT = Path(__file__).resolve().parents[2]


def _command(inp, out, ckpt):
    return [
        "register",
        str(inp),
        "--out",
        str(out),
        "--checkpoint",
        str(ckpt),
        "--checkpoint-every",
        "1000",
        "--chunk-rows",
        "500",
        "--on-bad-row",
        "skip",
        "--no-plots",
        "--no-progress",
    ]


def _start(args):
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    return subprocess.Popen(
        [sys.executable, "-m", "registration.cli", *args],
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )


def _kill_when(proc, ckpt, ready, timeout=60.0):
    """SIGKILL the process as soon as the checkpoint satisfies ``ready``; return the state seen."""
    t_end = time.monotonic() + timeout
    while time.monotonic() < t_end:
        if proc.poll() is not None:
            out, err = proc.communicate()
            pytest.fail(
                f"the run ended before it could be killed (rc {proc.returncode}): {err.decode()[-2000:]}"
            )
        if ckpt.exists():
            try:
                state = load_checkpoint(ckpt)
            except CheckpointError:
                state = None  # being replaced right now: try again
            if state is not None and ready(state):
                time.sleep(0.05)  # land somewhere inside a block, after the checkpoint
                proc.send_signal(signal.SIGKILL)
                proc.wait()
                return state
        time.sleep(0.01)
    proc.kill()
    pytest.fail("timed out waiting for the checkpoint")


def test_sigkill_twice_then_resume_equals_an_uninterrupted_run(tmp_path):
    data = tiled(120)  # 36,000 rows
    bad = [5, 1234, 20_001, 35_999]
    data = data.astype({"a_range_m": object})
    data.loc[bad[0], "a_range_m"] = -1.0
    data.loc[bad[1], "a_range_m"] = "n/a"
    data.loc[bad[2], "time_s"] = data.loc[bad[2] - 1, "time_s"]
    data.loc[bad[3], "b_lat_deg"] = 123.0
    inp = tmp_path / "long.csv"
    data.to_csv(inp, index=False)
    n_rows = len(data)

    ref_out = tmp_path / "ref"
    assert main(_command(inp, ref_out, tmp_path / "ref.ckpt")) == 0

    out, ckpt = tmp_path / "run", tmp_path / "run.ckpt"
    args = _command(inp, out, ckpt)
    seen1 = _kill_when(
        _start(args), ckpt, lambda s: s["phase"] == "filter" and s["state"]["rows_done"] >= 8000
    )
    assert 0 < seen1["state"]["rows_done"] < n_rows
    # a kill leaves rows after the checkpoint in the outputs: resume must cut them, not duplicate them
    seen2 = _kill_when(
        _start(args),
        ckpt,
        lambda s: (
            s["phase"] == "observability"
            and s["state"]["obs_rows_done"] >= 4000
            or s["phase"] == "filter"
            and s["state"]["rows_done"] >= seen1["state"]["rows_done"] + 12000
        ),
    )
    assert seen2["state"]["rows_done"] > seen1["state"]["rows_done"]
    proc = _start(args)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 0, err.decode()[-3000:]
    assert b"resuming from checkpoint" in err

    for name in ("estimates.csv", "positions.csv", "rejected.csv"):
        assert (out / name).read_bytes() == (ref_out / name).read_bytes(), name
    import pandas as pd

    est = pd.read_csv(out / "estimates.csv")
    rej = pd.read_csv(out / "rejected.csv")
    assert est["row"].is_unique and rej["row"].is_unique
    assert sorted(est["row"].tolist() + rej["row"].tolist()) == list(range(n_rows))
    assert sorted(rej["row"]) == bad
    got, ref = (
        json.loads((out / "summary.json").read_text()),
        json.loads((ref_out / "summary.json").read_text()),
    )
    for key in ("estimates", "before", "after", "observability", "rows", "mean_nis", "time_span_s"):
        assert got[key] == ref[key], key
    assert load_checkpoint(ckpt)["phase"] == "done"
    # a rerun of a finished run says so and changes nothing
    before = (out / "estimates.csv").read_bytes()
    assert main(args) == 0
    assert (out / "estimates.csv").read_bytes() == before
