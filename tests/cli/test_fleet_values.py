"""`registration fleet register` on values that cannot be held (issue 32, 3): priors and sigmas
beyond float64 arithmetic are refused by the reader with file, row, column and unit; option values
and tables that build no problem exit 2 naming the cause before any report; summary.json is always
written (NaN and inf as null)."""

import json
import math
import shutil

import numpy as np
import pandas as pd
import pytest

from registration.cli import main
from registration.io.files.jsonfile import json_text, write_json


@pytest.fixture(scope="module")
def simulated(tmp_path_factory):
    out = tmp_path_factory.mktemp("fleet") / "sim"
    assert main(["fleet", "simulate", "--no-plots", "--duration-s", "60", "--out", str(out)]) == 0
    for name in ("estimates.csv", "summary.json"):
        (out / name).unlink()
    return out


def _copy(simulated, tmp_path):
    folder = tmp_path / "in"
    shutil.copytree(simulated, folder)
    return folder


@pytest.mark.parametrize(
    "column, value",
    [
        ("prior_time_bias_s", "1e308"),
        ("prior_time_bias_s", "1e-300"),
        ("prior_range_bias_m", "1e308"),
        ("prior_bearing_bias_deg", "1e-300"),
        ("prior_position_m", "1e308"),
        ("sigma_range_m", "1e-300"),
        ("sigma_bearing_deg", "1e-300"),
    ],
)
def test_priors_and_sigmas_beyond_float64_are_refused_by_the_reader(
    simulated, tmp_path, capsys, column, value
):
    """Before: exit 4 (or a failed summary.json) after lines of RuntimeWarning."""
    folder = _copy(simulated, tmp_path)
    sensors = pd.read_csv(folder / "sensors.csv", dtype=str)
    sensors[column] = (
        [value] + list(sensors[column][1:]) if column in sensors else [value] + [""] * (len(sensors) - 1)
    )
    sensors.to_csv(folder / "sensors.csv", index=False)
    code = main(["fleet", "register", "--tables", str(folder), "--out", str(tmp_path / "out"), "--no-plots"])
    err = capsys.readouterr().err
    assert code == 2, err
    assert "RuntimeWarning" not in err and len(err.strip().splitlines()) == 1
    unit = column.rsplit("_", 1)[1]
    assert f"sensors.csv: row 0, column {column!r}" in err and f" {unit} " in err and "cannot be held" in err
    assert not (tmp_path / "out").exists()


def test_zero_and_infinite_priors_keep_their_meaning_and_held_values_pass(simulated, tmp_path):
    folder = _copy(simulated, tmp_path)
    sensors = pd.read_csv(folder / "sensors.csv", dtype=str)
    sensors["prior_range_bias_m"] = ["0", "inf", "1e-12", "1e12"] + [""] * (len(sensors) - 4)
    sensors.to_csv(folder / "sensors.csv", index=False)
    out = tmp_path / "out"
    assert main(["fleet", "register", "--tables", str(folder), "--out", str(out), "--no-plots"]) == 0


@pytest.mark.parametrize("rows", [1, 2])
def test_one_or_two_plots_exit_2_naming_the_cause(simulated, tmp_path, capsys, rows):
    folder = _copy(simulated, tmp_path)
    pd.read_csv(folder / "plots.csv", dtype=str).iloc[:rows].to_csv(folder / "plots.csv", index=False)
    out = tmp_path / "out"
    assert main(["fleet", "register", "--tables", str(folder), "--out", str(out), "--no-plots"]) == 2
    captured = capsys.readouterr()
    assert f"{rows} plot(s) are too few" in captured.err and "consistency" not in captured.out
    assert not out.exists()


def test_window_s_0_exits_2_naming_the_option(simulated, tmp_path, capsys):
    """Before: a whole report, then exit 2 failing to write summary.json (NaN)."""
    out = tmp_path / "out"
    argv = [
        "fleet",
        "register",
        "--tables",
        str(simulated),
        "--out",
        str(out),
        "--no-plots",
        "--window-s",
        "0",
    ]
    assert main(argv) == 2
    captured = capsys.readouterr()
    assert "--window-s" in captured.err and len(captured.err.strip().splitlines()) == 1
    assert "estimates" not in captured.out and not out.exists()


def test_the_json_writer_writes_nan_and_inf_as_null(tmp_path):
    obj = {
        "a": math.nan,
        "b": [1.0, math.inf, -math.inf, np.float64("nan")],
        "c": np.array([[1.0, np.nan], [np.inf, 2.0]]),
        "d": (np.int64(3), np.float32(0.5), np.bool_(True)),
        "e": {"f": None, "g": "text"},
    }
    path = tmp_path / "s.json"
    write_json(path, obj)
    assert json.loads(path.read_text()) == {
        "a": None,
        "b": [1.0, None, None, None],
        "c": [[1.0, None], [None, 2.0]],
        "d": [3, 0.5, True],
        "e": {"f": None, "g": "text"},
    }
    write_json(path, {"x": math.nan}, atomic=True)
    assert path.read_text() == '{\n  "x": null\n}\n' and not path.with_name("s.json.tmp").exists()
    with pytest.raises(TypeError):
        json_text({"x": object()})


def test_window_s_0_with_the_partitioned_solver_names_the_option(simulated, tmp_path, capsys):
    """Before: 'window_s: the partitioned solver needs target windows', not the option's name."""
    out = tmp_path / "out"
    argv = ["fleet", "register", "--tables", str(simulated), "--out", str(out), "--no-plots"]
    assert main([*argv, "--window-s", "0", "--partition-s", "30"]) == 2
    assert "--window-s 0" in capsys.readouterr().err and not out.exists()
