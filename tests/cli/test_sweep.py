"""``registration montecarlo`` with --workers/--scheduler and --sweep."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest

from registration.cli import main
from registration.cli.montecarlo import parse_sweep
from registration.online.montecarlo import run_montecarlo
from registration.online.sweep import SWEEP_COLUMNS


def test_sweep_writes_one_row_per_point_and_quantity(tmp_path, capsys):
    out = tmp_path / "o"
    argv = [
        "montecarlo",
        "--runs",
        "6",
        "--steps",
        "30",
        "--sweep",
        "angle-sigma-deg=0.2,0.5",
        "--out",
        str(out),
        "--chunk-runs",
        "4",
        "--allow-inconsistent",
    ]
    assert main(argv) == 0
    assert sorted(p.name for p in out.iterdir()) == ["sweep.csv", "sweep.png"]
    table = pd.read_csv(out / "sweep.csv")
    assert list(table.columns) == list(SWEEP_COLUMNS)
    assert sorted(set(table["value"])) == [0.2, 0.5] and set(table["parameter"]) == {"angle-sigma-deg"}
    # each point is the Monte Carlo of that value, in display units (deg or m)
    ref = run_montecarlo(6, 0, n_steps=30, angle_sigma=np.radians(0.5))
    point = table[table["value"] == 0.5]
    assert list(point["quantity"]) == [q.name for q in ref.quantities]
    np.testing.assert_array_equal(
        point["rmse"].to_numpy(), [q.scale * ref.rmse[-1, j] for j, q in enumerate(ref.quantities)]
    )
    np.testing.assert_array_equal(
        point["crlb_sigma"].to_numpy(),
        [q.scale * ref.crlb_sigma[-1, j] for j, q in enumerate(ref.quantities)],
    )
    assert (point["nees"] == ref.nees[-1]).all()
    assert "wrote" in capsys.readouterr().out


def test_sweep_parquet_and_no_plots(tmp_path):
    out = tmp_path / "o"
    assert (
        main(
            [
                "montecarlo",
                "--runs",
                "3",
                "--steps",
                "20",
                "--sweep",
                "steps=20,25",
                "--format",
                "parquet",
                "--no-plots",
                "--out",
                str(out),
                "--allow-inconsistent",
            ]
        )
        == 0
    )
    assert sorted(p.name for p in out.iterdir()) == ["sweep.parquet"]
    assert sorted(set(pd.read_parquet(out / "sweep.parquet")["value"])) == [20, 25]


@pytest.mark.parametrize(
    "text, message",
    [
        ("angle-sigma=0.1", "NAME one of"),
        ("steps", "NAME one of"),
        ("steps=2.5", "int values"),
        ("range-sigma-m=5,5", "distinct"),
        ("angle-sigma-deg=", "distinct"),
    ],
)
def test_bad_sweeps_are_rejected(text, message):
    with pytest.raises(ValueError, match=message):
        parse_sweep(text)


@pytest.mark.parametrize(
    "argv, message",
    [
        (["--sweep", "angle-sigma-deg=0.1,30"], "--sweep: angle-sigma-deg=30.0: --angle-sigma-deg"),
        (["--workers", "0"], "--workers: expected at least 1"),
        (["--workers", "2", "--scheduler", "tcp://127.0.0.1:1"], "one or the other"),
        (["--chunk-runs", "0"], "--chunk-runs"),
    ],
)
def test_bad_options_fail_before_any_work(tmp_path, capsys, argv, message):
    assert main(["montecarlo", "--runs", "3", *argv, "--out", str(tmp_path / "o")]) == 2
    assert message in capsys.readouterr().err
    assert not (tmp_path / "o").exists()


def test_missing_dask_is_a_clear_error(tmp_path, capsys, monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "dask.distributed", None)
    assert main(["montecarlo", "--runs", "3", "--workers", "2", "--out", str(tmp_path / "o")]) == 2
    assert 'pip install "dask[distributed]"' in capsys.readouterr().err


def test_workers_give_the_in_process_json(tmp_path):
    pytest.importorskip("dask.distributed")
    common = [
        "montecarlo",
        "--runs",
        "8",
        "--steps",
        "30",
        "--no-plots",
        "--chunk-runs",
        "3",
        "--allow-inconsistent",
    ]
    assert main([*common, "--out", str(tmp_path / "a")]) == 0
    assert main([*common, "--workers", "2", "--out", str(tmp_path / "b")]) == 0
    a, b = (json.loads((tmp_path / d / "montecarlo.json").read_text()) for d in "ab")
    a.pop("command"), b.pop("command")
    assert a == b
