"""One command-line style: entry points, --version, --out defaults, flag names, help texts, early checks."""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

import registration
from registration.cli import build_parser, main

ROOT = Path(__file__).resolve().parents[2]
#: the sub-commands whose options this style covers (register's module has its own owner)
OWN = ("simulate", "montecarlo", "fuse", "landing", "schema")
#: a numeric option's help names its unit (or says it counts something)
UNITS = re.compile(r"\b(deg|m|s|Hz|mrad|ms|m/s|metres)\b")
JARGON = re.compile(r"seed \d{3}|\bSPEC\b|\.\./shared|#\d+|issue")


def subparsers() -> dict[str, argparse.ArgumentParser]:
    action = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    return dict(action.choices)


def options(name: str) -> list[argparse.Action]:
    return [
        a
        for a in subparsers()[name]._actions
        if a.option_strings and a.help != argparse.SUPPRESS and not isinstance(a, argparse._HelpAction)
    ]


def test_python_dash_m_registration_runs_the_cli(tmp_path):
    """Before: 'registration' is a package and cannot be directly executed."""
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    done = subprocess.run(
        [sys.executable, "-m", "registration", "--version"],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 0 and done.stdout == f"registration {registration.__version__}\n"


def test_version(capsys):
    """Before: 'unrecognized arguments: --version'."""
    assert main(["--version"]) == 0
    assert capsys.readouterr().out == f"registration {registration.__version__}\n"


def test_help_ends_with_the_exit_codes(capsys):
    """Each command's own codes: fuse has no consistency gate, so no 3 (see test_errors)."""
    for argv, gate in ((["--help"], True), (["simulate", "--help"], True), (["fuse", "--help"], False)):
        assert main(argv) == 0
        text = capsys.readouterr().out
        for code in ("0 ", "2 ", "130", "141"):
            assert re.search(rf"^  {code}", text, re.M), (argv, code)
        assert bool(re.search(r"^  3 ", text, re.M)) == gate and ("--allow-inconsistent" in text) == gate, (
            argv
        )
        assert "REGISTRATION_DEBUG=1" in text


@pytest.mark.parametrize("name", [n for n in OWN if n != "schema"])
def test_out_has_a_stated_default_under_out(name, capsys):
    """Before: landing required --out; fuse had no default and wrote nothing without it."""
    out = next(a for a in options(name) if "--out" in a.option_strings)
    assert out.default == Path("out") / name and not out.required
    main([name, "--help"])
    assert f"(default: out/{name})" in " ".join(capsys.readouterr().out.split())


@pytest.mark.parametrize(
    "name, argv, files",
    [
        ("fuse", ["--trials", "10", "--no-plots"], ["summary.json"]),
        ("landing", ["--runs", "2", "--start-range-m", "600", "--no-plots"], ["summary.json"]),
    ],
)
def test_fuse_and_landing_write_by_default(tmp_path, monkeypatch, capsys, name, argv, files):
    monkeypatch.chdir(tmp_path)
    assert main([name, *argv]) == 0
    assert sorted(p.name for p in (tmp_path / "out" / name).iterdir()) == sorted(files)
    assert f"wrote out/{name}/summary.json" in capsys.readouterr().out


@pytest.mark.parametrize("name", [n for n in OWN if n != "schema"])
def test_every_plotting_command_spells_no_plots_the_same(name):
    """Before: --no-plots (simulate) but --no-plot (montecarlo); fuse and landing had none."""
    flags = {s for a in options(name) for s in a.option_strings}
    assert "--no-plots" in flags and "--no-plot" not in flags


def test_montecarlo_keeps_no_plot_as_a_hidden_deprecated_alias(tmp_path, capsys):
    assert main(["montecarlo", "--runs", "2", "--steps", "20", "--no-plot", "--out", str(tmp_path)]) == 0
    assert "--no-plot is deprecated; use --no-plots" in capsys.readouterr().err
    assert not (tmp_path / "montecarlo.png").exists()
    main(["montecarlo", "--help"])
    assert "--no-plot " not in capsys.readouterr().out


@pytest.mark.parametrize("name", OWN)
def test_every_option_has_help_with_its_default(name, capsys):
    """Before: --q-mode had no help; fuse's geometry options did not say what they default to."""
    assert all(a.help for a in options(name))
    main([name, "--help"])
    text = capsys.readouterr().out
    for a in options(name):
        if a.nargs != 0:  # the option's block of the --help text: its line up to the next option or section
            block = re.search(rf"\n  {re.escape(a.option_strings[0])}\b.*?(?=\n  -|\n\n)", text, re.S)
            assert block and "default" in block.group(0), a.option_strings


@pytest.mark.parametrize("name", OWN)
def test_every_float_option_states_its_unit(name):
    for a in options(name):
        if a.type is float:
            assert UNITS.search(a.help), (a.option_strings, a.help)


@pytest.mark.parametrize("argv", [["--help"], *([n, "--help"] for n in OWN)])
def test_no_internal_jargon_in_help(argv, capsys):
    main(argv)
    assert not JARGON.search(capsys.readouterr().out)


def test_no_internal_jargon_in_the_simulate_report(tmp_path, capsys):
    """Before: 'Paper scenario (seed 000 section 4)'."""
    assert main(["simulate", "--steps", "20", "--no-plots", "--out", str(tmp_path)]) == 0
    text = capsys.readouterr().out
    assert not JARGON.search(text) and "Wang et al. 2011" in text


@pytest.mark.parametrize("export", ["x.xlsx", "x", "data.CSV.gz"])
def test_simulate_rejects_an_export_type_before_simulating(tmp_path, capsys, monkeypatch, export):
    """Before: the whole simulation ran, then the extension was rejected."""
    import registration.online

    monkeypatch.setattr(registration.online, "register", lambda *a, **k: pytest.fail("simulation started"))
    assert main(["simulate", "--out", str(tmp_path / "o"), "--export", str(tmp_path / export)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("registration simulate: error: --export:") and ".csv" in err and ".parquet" in err
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize(
    "argv",
    [
        ["simulate", "--steps", "1"],
        ["simulate", "--seed", "-1"],
        ["simulate", "--ship-motion", "90,8,5,12"],
        ["simulate", "--range-sigma-m", "inf"],
        ["montecarlo", "--steps", "0"],
        ["fuse", "--seed", "-3"],
        ["landing", "--radar-rate-hz", "inf"],
        ["landing", "--start-range-m", "nan"],
    ],
)
def test_bad_values_are_rejected_before_the_work(tmp_path, capsys, argv):
    assert main([*argv, "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"registration {argv[0]}: error: {argv[1]}") and err.count("\n") == 1
    assert not (tmp_path / "o").exists()
