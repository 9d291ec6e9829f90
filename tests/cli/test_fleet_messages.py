"""Messages (issue 31, 8): no error line over MAX_MESSAGE characters (paths counted as a word); a
long list (every excluded target) goes to a file the line names; `--method online` with no usable
plot exits 2 with one line."""

import json
import re
from pathlib import Path

import pandas as pd
import pytest

from registration.cli import main
from registration.cli.errors import MAX_MESSAGE, short_message


@pytest.fixture(scope="module")
def one_sensor(tmp_path_factory):
    """30 targets, the plots of one sensor only and no reference: every target is excluded."""
    out = tmp_path_factory.mktemp("fleet") / "sim"
    argv = ["fleet", "simulate", "--no-plots", "--duration-s", "30", "--targets", "30", "--out", str(out)]
    assert main(argv) == 0
    for name in ("estimates.csv", "summary.json", "reference.csv"):
        (out / name).unlink()
    plots = pd.read_csv(out / "plots.csv", dtype=str, keep_default_na=False)
    plots[plots["sensor"] == "A-3D"].to_csv(out / "plots.csv", index=False)
    return out


def _named_file(line: str) -> Path:
    found = re.search(r"the whole message, \d+ characters: (\S+)\)$", line)
    assert found, line
    return Path(found.group(1))


def test_a_short_line_is_left_as_it_is():
    line = "prog: error: /a/very/long/path/" + "x" * 400 + "/plots.csv: row 3, column 'range_m': bad"
    assert short_message(line) == line  # a path is one word


def test_a_long_line_is_cut_and_the_whole_written_to_the_file_it_names():
    line = "prog: error: every target was excluded: " + "; ".join(
        f"target T{i}: one sensor" for i in range(500)
    )
    short = short_message(line)
    assert len(short) <= MAX_MESSAGE + 60 and short.startswith(
        "prog: error: every target was excluded: target T0"
    )
    path = _named_file(short)
    try:
        assert path.read_text() == line + "\n"
    finally:
        path.unlink()


def test_every_target_excluded_is_one_short_line_naming_the_list(one_sensor, tmp_path, capsys):
    """Before: a 5 KB line (11 KB on a real recording) listing every excluded target."""
    out = tmp_path / "out"
    assert main(["fleet", "register", "--tables", str(one_sensor), "--out", str(out), "--no-plots"]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "every target was excluded" in err
    path = _named_file(err)
    try:
        assert len(err) - len(str(path)) <= MAX_MESSAGE
        assert "target T29" in path.read_text()
    finally:
        path.unlink()
    assert not out.exists()


def test_online_with_no_usable_plot_exits_2_with_one_line(one_sensor, tmp_path, capsys):
    """Before: exit 0, 0 of 446 plots used, empty figures."""
    out = tmp_path / "out"
    argv = [
        "fleet",
        "register",
        "--tables",
        str(one_sensor),
        "--out",
        str(out),
        "--no-plots",
        "--method",
        "online",
    ]
    assert main(argv) == 2
    captured = capsys.readouterr()
    lines = captured.err.strip().splitlines()
    assert (
        len(lines) == 1 and "the online filter used none of the" in lines[0] and len(lines[0]) <= MAX_MESSAGE
    )
    assert "consistency" not in captured.out and not out.exists()


@pytest.fixture(scope="module")
def mostly_one_sensor(tmp_path_factory):
    """30 targets; B-3D sees T1 to T3 as A-3D does, A-3D alone the 27 others: 27 targets excluded
    from a run that succeeds."""
    out = tmp_path_factory.mktemp("fleet") / "sim"
    argv = ["fleet", "simulate", "--no-plots", "--duration-s", "30", "--targets", "30", "--out", str(out)]
    assert main(argv) == 0
    for name in ("estimates.csv", "summary.json", "reference.csv"):
        (out / name).unlink()
    plots = pd.read_csv(out / "plots.csv", dtype=str, keep_default_na=False)
    keep = (plots["sensor"] == "A-3D") | (
        (plots["sensor"] == "B-3D") & plots["target"].isin(["T1", "T2", "T3"])
    )
    plots[keep].to_csv(out / "plots.csv", index=False)
    return out


def test_a_run_with_many_excluded_targets_prints_no_line_over_the_limit(mostly_one_sensor, tmp_path, capsys):
    """Before: one line per excluded target (27 here, thousands on a long recording) and lines of
    the observability report up to 347 characters (a joint change of seven states)."""
    from registration.cli.fleet.output import EXCLUDED_SHOWN

    out = tmp_path / "out"
    assert (
        main(["fleet", "register", "--tables", str(mostly_one_sensor), "--out", str(out), "--no-plots"]) == 0
    )
    captured = capsys.readouterr()
    lines = (captured.out + captured.err).splitlines()
    too_long = [line for line in lines if len(line) > MAX_MESSAGE]
    assert not too_long, too_long
    excluded = [line for line in lines if line.startswith("  excluded: ")]
    listed = json.loads((out / "summary.json").read_text())["excluded"]
    assert len(listed) == 27 and len(excluded) == EXCLUDED_SHOWN + 1
    assert (
        excluded[-1]
        == f"  excluded: {27 - EXCLUDED_SHOWN} more targets (summary.json lists all 27 under 'excluded')"
    )
