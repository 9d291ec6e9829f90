"""`registration fleet register`: a numerical failure is an internal error (exit 4), not bad input;
the reference positions' term in the printed report and summary.json; the online run's one verdict."""

import json
import shutil

import numpy as np
import pandas as pd
import pytest

import registration.fleet as fleet
from registration.cli import main
from registration.cli.errors import EXIT_BAD_INPUT, EXIT_INCONSISTENT, EXIT_NUMERICAL, run_guarded
from registration.fleet.batch.solver import NumericalError

TABLES = ("plots", "navigation", "sensors", "platforms", "reference")


@pytest.fixture(scope="module")
def simulated(tmp_path_factory):
    out = tmp_path_factory.mktemp("fleet") / "sim"
    assert main(["fleet", "simulate", "--no-plots", "--out", str(out)]) == 0
    return out


def _register_args(folder, out, extra=()):
    args = ["fleet", "register", "--out", str(out), "--no-plots", *extra]
    for name in TABLES:
        args += [f"--{name}", str(folder / f"{name}.csv")]
    return args


def _reference_sigma(simulated, tmp_path, sigma_m: float):
    folder = tmp_path / "in"
    shutil.copytree(simulated, folder)
    ref = pd.read_csv(folder / "reference.csv", dtype={"target": str})
    ref["sigma_m"] = sigma_m
    ref.to_csv(folder / "reference.csv", index=False)
    return folder


def test_the_exit_codes_include_the_internal_numerical_error(capsys):
    assert EXIT_NUMERICAL == 4 and EXIT_NUMERICAL not in (EXIT_BAD_INPUT, EXIT_INCONSISTENT)
    assert main(["fleet", "register", "--help"]) == 0
    assert "  4    internal numerical error" in capsys.readouterr().out


@pytest.mark.parametrize(
    "error",
    [
        np.linalg.LinAlgError("Singular matrix"),
        NumericalError("windows singular"),
        ZeroDivisionError("float division by zero"),
    ],
)
def test_a_numerical_failure_exits_4_as_an_internal_error(simulated, tmp_path, capsys, monkeypatch, error):
    """Before: `registration fleet: error: Singular matrix`, exit 2, as if the files were bad
    (numpy's LinAlgError is a ValueError)."""

    def fail(*args, **kwargs):
        raise error

    monkeypatch.setattr(fleet, "solve_batch", fail)
    assert main(_register_args(simulated, tmp_path / "reg")) == EXIT_NUMERICAL
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert "internal numerical error" in err and str(error) in err and "REGISTRATION_DEBUG=1" in err


def test_a_value_error_is_still_bad_input(capsys):
    def bad(args):
        raise ValueError("--window-s: expected a length >= 0 s")

    assert run_guarded("registration fleet register", bad, None) == EXIT_BAD_INPUT
    assert "internal" not in capsys.readouterr().err


def test_the_reference_term_is_printed_and_written(simulated, tmp_path, capsys):
    assert main(_register_args(simulated, tmp_path / "reg")) == 0
    out = capsys.readouterr().out
    line = next(t for t in out.splitlines() if t.startswith("residual terms"))
    assert "plots" in line and "references" in line and "299 of 300 reference positions used" in line
    summary = json.loads((tmp_path / "reg" / "summary.json").read_text())
    refs = summary["residuals_of_references"]
    assert refs["positions_given"] == 300 and refs["positions_used"] == 299 and refs["values"] == 3 * 299
    assert 0.6 < refs["mean_square"] < 1.3 and set(refs["by_target"]) == {"T1"}
    t1 = summary["residuals_by_target"]["T1"]
    assert t1["reference_values"] == 3 * 299 and t1["reference_mean_square"] == pytest.approx(
        refs["mean_square"]
    )
    assert "reference_values" not in summary["residuals_by_target"]["T2"]
    parts = summary["chi_square"]["parts"]
    assert parts["references"]["values"] == 3 * 299
    assert sum(p["sum_of_squares"] for p in parts.values()) == pytest.approx(summary["chi_square"]["chi2"])


def test_a_reference_sigma_stated_too_small_is_named(simulated, tmp_path, capsys):
    """sigma_m 0.02 m for positions good to 3 m: the references' term is ~2e4 per value and the
    report says which term it is (before: one total, nothing showing why)."""
    folder = _reference_sigma(simulated, tmp_path, 0.02)
    assert main(_register_args(folder, tmp_path / "reg", ["--allow-inconsistent"])) == 0
    out = capsys.readouterr().out
    assert "the references term is" in out and "sigma_m is stated too small" in out
    refs = json.loads((tmp_path / "reg" / "summary.json").read_text())["residuals_of_references"]
    assert refs["mean_square"] > 1000


def test_the_online_run_gives_one_verdict_and_gates_on_it(simulated, tmp_path, capsys):
    """Before: 'residuals at the final estimate ... OUTSIDE the band' and 'consistency: ...
    consistent' on consecutive lines, exit 0. Now one verdict (the residuals at the final estimate,
    as for the batch) that the gate follows; the innovations are printed as information."""
    folder = _reference_sigma(simulated, tmp_path, 0.02)
    assert main(_register_args(folder, tmp_path / "reg", ["--method", "online"])) == EXIT_INCONSISTENT
    captured = capsys.readouterr()
    verdicts = [t for t in captured.out.splitlines() if t.startswith("consistency:")]
    assert (
        len(verdicts) == 1
        and "at the final estimate" in verdicts[0]
        and "grossly inconsistent" in verdicts[0]
    )
    info = [t for t in captured.out.splitlines() if t.startswith("normalised innovations")]
    assert len(info) == 1 and "not the verdict" in info[0] and "consistent" not in info[0]
    assert not any("OUTSIDE the band" in t for t in captured.out.splitlines())
    summary = json.loads((tmp_path / "reg" / "summary.json").read_text())
    assert summary["consistency_basis"] == "residuals at the final estimate"
    assert summary["consistency"]["status"] == "grossly inconsistent"
    assert summary["innovations"]["status"] == "consistent"  # what the gate used to follow
