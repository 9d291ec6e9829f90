"""The consistency gate of `simulate` and `montecarlo`: the NIS line, summary.json, exit code 3 and
--allow-inconsistent."""

from __future__ import annotations

import json

import pytest

import registration.cli.montecarlo as montecarlo_cli
from registration.cli import main
from registration.cli.errors import EXIT_INCONSISTENT
from registration.core.consistency import LIKELY_CAUSES, ConsistencyReport
from registration.online.result import RegistrationResult

#: what a unit mistake looks like: mean NIS 15 times its expectation over 20 rows
GROSS = ConsistencyReport.from_mean(45.0, 20, 3)


def test_simulate_reports_consistency_and_writes_it(tmp_path, capsys):
    assert main(["simulate", "--steps", "40", "--no-plots", "--out", str(tmp_path)]) == 0
    text = capsys.readouterr().out
    line = next(t for t in text.splitlines() if t.startswith("consistency: "))
    assert "mean NIS" in line and "over 40 samples" in line and line.endswith(": consistent")
    doc = json.loads((tmp_path / "summary.json").read_text())["consistency"]
    assert (
        doc["quantity"] == "NIS"
        and doc["samples"] == 40
        and doc["dof"] == 3
        and doc["status"] == "consistent"
    )
    assert doc["mean"] == pytest.approx(json.loads((tmp_path / "summary.json").read_text())["mean_nis"])


@pytest.fixture
def gross_simulation(monkeypatch):
    """Make every registration report the gross inconsistency (simulated data always fit the model)."""
    monkeypatch.setattr(RegistrationResult, "consistency", property(lambda self: GROSS))


def test_an_inconsistent_simulation_exits_3_with_the_causes(tmp_path, capsys, gross_simulation):
    assert main(["simulate", "--steps", "20", "--no-plots", "--out", str(tmp_path)]) == EXIT_INCONSISTENT
    captured = capsys.readouterr()
    assert captured.err.startswith("registration simulate: error: mean NIS 45 ")
    assert all(cause in captured.err for cause in LIKELY_CAUSES) and "--allow-inconsistent" in captured.err
    assert "grossly inconsistent" in captured.out
    # the long text (the causes) once: on standard error with the exit code, not also on the report line
    assert all((captured.out + captured.err).count(cause) == 1 for cause in LIKELY_CAUSES)
    assert "consistency: mean NIS 45 over 20 samples" in captured.out
    doc = json.loads((tmp_path / "summary.json").read_text())  # the outputs are written all the same
    assert doc["consistency"]["status"] == "grossly inconsistent"


def test_allow_inconsistent_accepts_the_run(tmp_path, capsys, gross_simulation):
    assert (
        main(["simulate", "--steps", "20", "--no-plots", "--allow-inconsistent", "--out", str(tmp_path)]) == 0
    )
    captured = capsys.readouterr()
    assert "inconsistent run accepted (--allow-inconsistent)" in captured.err
    assert all((captured.out + captured.err).count(cause) == 1 for cause in LIKELY_CAUSES)


def test_montecarlo_gates_the_pooled_nis(tmp_path, capsys, monkeypatch):
    argv = ["montecarlo", "--runs", "2", "--steps", "20", "--no-plots", "--out", str(tmp_path)]
    assert main(argv) == 0
    out = capsys.readouterr().out
    doc = json.loads((tmp_path / "montecarlo.json").read_text())
    assert doc["consistency"]["samples"] == 2 * 20 and "consistency: mean NIS" in out
    monkeypatch.setattr(montecarlo_cli, "pooled_consistency", lambda result: GROSS)
    assert main(argv) == EXIT_INCONSISTENT
    captured = capsys.readouterr()
    assert "Likely causes" in captured.err and (captured.out + captured.err).count("Likely causes") == 1
    assert main([*argv, "--allow-inconsistent"]) == 0
