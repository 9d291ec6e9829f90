"""`registration register` on users' mistakes: angles in radians, sigmas in the wrong unit, an
empty file, an --out that is a file. Each must end with a clear message and a non-zero exit
code (3: the run's innovations grossly contradict the model; 2: bad input)."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest

from registration.cli import main
from registration.cli.errors import EXIT_BAD_INPUT, EXIT_INCONSISTENT
from registration.recorded import SYNC_COLUMNS
from registration.recorded.reading.rowcheck import sync_layout
from registration.recorded.reading.unitcheck import MIN_VALUES, angle_unit_warnings

from ._register_data import frame

FAST = ["--no-plots", "--no-progress"]
CAUSE = "angles in radians in *_deg columns"


def _run(*args):
    return main(["register", *map(str, args)])


def _summary(out):
    return json.loads((out / "summary.json").read_text())


def _in_radians(f: pd.DataFrame, columns) -> pd.DataFrame:
    f = f.copy()
    for c in columns:
        f[c] = np.radians(f[c])
    return f


ATTITUDE_AND_PLOT = [c for c in SYNC_COLUMNS if c.endswith("_deg") and "_lat_" not in c and "_lon_" not in c]
ALL_ANGLES = [c for c in SYNC_COLUMNS if c.endswith("_deg")]


def test_a_correct_file_passes_the_gate_without_warning(tmp_path, capsys):
    inp = tmp_path / "in.csv"
    frame(300).to_csv(inp, index=False)
    assert _run(inp, "--out", tmp_path / "reg", *FAST) == 0
    captured = capsys.readouterr()
    assert "warning" not in captured.err and "warning" not in captured.out
    s = _summary(tmp_path / "reg")
    assert s["warnings"] == [] and s["consistency"]["status"] == "consistent"
    assert s["consistency"]["samples"] == 300 and s["consistency"]["mean"] == s["mean_nis"]
    assert "consistency: mean NIS" in captured.out


def test_radians_in_degree_columns_exit_3_naming_the_cause_and_the_columns(tmp_path, capsys):
    inp = tmp_path / "in.csv"
    _in_radians(frame(300), ATTITUDE_AND_PLOT).to_csv(inp, index=False)
    out = tmp_path / "reg"
    assert _run(inp, "--out", out, *FAST) == EXIT_INCONSISTENT
    err = capsys.readouterr().err
    assert CAUSE in err and "grossly inconsistent" in err and "--allow-inconsistent" in err
    for column in ("a_bearing_deg", "b_bearing_deg", "a_heading_deg", "b_heading_deg"):
        assert f"column '{column}'" in err, column
    s = _summary(out)  # the run is written all the same, and says what is wrong with it
    assert s["consistency"]["status"] == "grossly inconsistent" and s["consistency"]["ratio"] > 10
    assert len(s["warnings"]) == 4 and all("radians?" in w for w in s["warnings"])
    assert len(pd.read_csv(out / "estimates.csv")) == 300
    # accepted on request: exit 0, the verdict still printed as a warning
    assert _run(inp, "--out", out, "--allow-inconsistent", *FAST) == 0
    err = capsys.readouterr().err
    assert "inconsistent run accepted" in err and "column 'a_bearing_deg'" in err


def test_every_angle_in_radians_also_names_the_positions(tmp_path, capsys):
    inp = tmp_path / "in.csv"
    _in_radians(frame(300), ALL_ANGLES).to_csv(inp, index=False)
    assert _run(inp, "--out", tmp_path / "reg", *FAST) == EXIT_INCONSISTENT
    err = capsys.readouterr().err
    assert (
        CAUSE in err
        and "columns 'a_lat_deg' and 'a_lon_deg'" in err
        and "columns 'b_lat_deg' and 'b_lon_deg'" in err
    )


def test_sigmas_in_radians_given_to_a_degree_option_exit_3(tmp_path, capsys):
    inp = tmp_path / "in.csv"
    frame(300).to_csv(inp, index=False)
    assert _run(inp, "--out", tmp_path / "reg", "--sigma", "50,0.008,0.008", *FAST) == EXIT_INCONSISTENT
    err = capsys.readouterr().err
    assert "noise sigmas in the wrong unit" in err and "mean NIS" in err
    assert "warning" not in err.replace(
        "warning: inconsistent", ""
    )  # the columns are right: no column warning


def test_the_unit_warning_needs_enough_values_and_skips_angles_that_are_small_in_degrees(tmp_path):
    f = frame(300)
    small = tmp_path / "small.csv"
    _in_radians(f.iloc[: MIN_VALUES - 1], ALL_ANGLES).to_csv(small, index=False)
    assert angle_unit_warnings(small, sync_layout()) == []  # too few rows to judge
    enough = tmp_path / "enough.csv"
    _in_radians(f.iloc[:MIN_VALUES], ALL_ANGLES).to_csv(enough, index=False)
    assert len(angle_unit_warnings(enough, sync_layout())) == 6
    # elevation, pitch and roll of a few degrees are normal: never a warning, whatever their unit
    low = tmp_path / "low.csv"
    _in_radians(f, [c for c in ALL_ANGLES if c.split("_")[1] in ("elevation", "pitch", "roll")]).to_csv(
        low, index=False
    )
    assert angle_unit_warnings(low, sync_layout()) == []
    # a ship near the equator is not a ship in radians (its longitude is far from 0)
    equator = f.copy()
    equator["a_lat_deg"] = equator["a_lat_deg"] - 19.5
    near = tmp_path / "near.csv"
    equator.to_csv(near, index=False)
    assert angle_unit_warnings(near, sync_layout()) == []


@pytest.mark.parametrize("suffix", [".csv", ".parquet"])
def test_a_file_with_only_a_header_says_so(tmp_path, capsys, suffix):
    inp = tmp_path / f"empty{suffix}"
    empty = frame(3).iloc[:0]
    empty.to_csv(inp, index=False) if suffix == ".csv" else empty.to_parquet(inp, index=False)
    assert _run(inp, "--out", tmp_path / "reg", "--on-bad-row", "skip", *FAST) == EXIT_BAD_INPUT
    err = capsys.readouterr().err
    assert f"{inp}: no data rows" in err and "rejected {}" not in err and "None" not in err
    assert err.count("\n") == 1


def test_every_row_rejected_names_the_reasons_with_counts(tmp_path, capsys):
    inp = tmp_path / "in.csv"
    f = frame(20)
    f["a_range_m"] = -1.0
    f.to_csv(inp, index=False)
    assert _run(inp, "--out", tmp_path / "reg", "--on-bad-row", "skip", *FAST) == EXIT_BAD_INPUT
    err = capsys.readouterr().err
    assert (
        "all 20 rows rejected (20 non_positive_range)" in err
        and "the first at row 0, column 'a_range_m'" in err
    )


def test_out_naming_an_existing_file_is_one_line_naming_it(tmp_path, capsys):
    inp, out = tmp_path / "in.csv", tmp_path / "results.txt"
    frame(30).to_csv(inp, index=False)
    out.write_text("my notes\n")
    assert _run(inp, "--out", out, *FAST) == EXIT_BAD_INPUT
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"--out {out}: is a file, not a folder" in err
    assert out.read_text() == "my notes\n"


def _register_options():
    import argparse

    from registration.cli import build_parser

    sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction)).choices[
        "register"
    ]
    return [a for a in sub._actions if a.option_strings and not isinstance(a, argparse._HelpAction)]


def test_register_options_state_their_default_and_unit(capsys):
    """Before: --out was required, --q-mode and --t-variant had no help, clock offsets named no unit."""
    import re
    from pathlib import Path

    opts = {a.option_strings[0]: a for a in _register_options()}
    assert opts["--out"].default == Path("out/register") and not opts["--out"].required
    assert {"--no-plots", "--allow-inconsistent"} <= set(opts)
    assert main(["register", "--help"]) == 0
    text = capsys.readouterr().out
    assert "(default: out/register)" in " ".join(text.split())
    for name, a in opts.items():
        assert a.help, name
        if a.nargs != 0:  # an option with a value says what it is without one, in its block of the help text
            block = re.search(rf"\n  {re.escape(name)}\b.*?(?=\n  -|\n\n)", text, re.S)
            assert block and "default" in block.group(0), name
        if a.type is float:
            assert re.search(r"\b(s|m|deg)\b", a.help), name


def test_ctrl_c_says_where_the_outputs_are(tmp_path):
    import argparse

    from registration.cli.register import interrupt_hint

    ckpt = interrupt_hint(
        argparse.Namespace(out=tmp_path / "reg", checkpoint=tmp_path / "run.ckpt", validate_only=False)
    )
    assert (
        "rerun the same command to resume" in ckpt
        and str(tmp_path / "run.ckpt") in ckpt
        and "partial-" in ckpt
    )
    plain = interrupt_hint(argparse.Namespace(out=tmp_path / "reg", checkpoint=None, validate_only=False))
    assert "nothing was written" in plain and "--checkpoint" in plain
