"""`registration simulate` end to end (short run) and its summary.json contract."""

import json

import numpy as np
import pytest

from registration.cli import main
from tests.colours import colours_told_apart


def test_simulate_writes_summary_and_plots(tmp_path, capsys):
    out = tmp_path / "sim"
    assert main(["simulate", "--steps", "60", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "paper before" in text and "UNOBSERVABLE" in text and "not a converged estimate" in text
    summary = json.loads((out / "summary.json").read_text())
    for key in ("before", "after"):
        assert set(summary[key]) == {"max", "mean", "std"}
        assert all(len(summary[key][s]) == 3 for s in ("max", "mean", "std"))
    names = [e["name"] for e in summary["estimates"]]
    assert names[:12] == [
        "dC_a",
        "dphi_a",
        "dtheta_a",
        "dr_a",
        "dq_a",
        "de_a",
        "dC_b",
        "dphi_b",
        "dtheta_b",
        "dr_b",
        "dq_b",
        "de_b",
    ]
    assert all({"name", "estimate", "sigma", "truth"} <= set(e) for e in summary["estimates"])
    obs = summary["observability"]
    assert (
        len(obs["singular_values"]) == 12
        and isinstance(obs["unobservable"], list)
        and isinstance(obs["weak"], list)
    )
    assert any("dC_a + dq_a" in t for t in obs["unobservable"])
    for png in ("tracks.png", "differences.png", "estimates.png"):
        assert (out / png).stat().st_size > 10_000


def test_simulate_with_ship_motion_changes_the_report(tmp_path):
    out = tmp_path / "sim"
    assert main(["simulate", "--steps", "60", "--ship-motion", "--no-plots", "--out", str(out)]) == 0
    obs = json.loads((out / "summary.json").read_text())["observability"]
    assert not any("dC_a + dq_a" in t for t in obs["unobservable"])


@pytest.mark.parametrize("args", [["--angle-sigma-deg", "-1"], ["--ship-motion", "2,8,5"]])
def test_simulate_bad_options_give_a_clear_error(tmp_path, args, capsys):
    assert main(["simulate", "--no-plots", "--out", str(tmp_path), *args]) == 2
    assert "error" in capsys.readouterr().err


def test_simulate_prints_the_sigma_it_writes(tmp_path, capsys):
    """One sigma convention: the console's σ column is the 1σ of summary.json (it printed 2σ)."""
    out = tmp_path / "sim"
    assert main(["simulate", "--steps", "60", "--no-plots", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    header = next(line for line in text.splitlines() if line.strip().startswith("state"))
    assert "σ" in header and "2σ" not in header
    for e in json.loads((out / "summary.json").read_text())["estimates"]:
        k = np.degrees(1.0) if e["unit"] == "rad" else 1.0
        line = next(line for line in text.splitlines() if line.startswith(f"  {e['name']} "))
        assert f"{e['sigma'] * k:.3g}" in line.split()


def test_differences_are_drawn_in_colours_told_apart_without_red_green_vision():
    from registration.online.plots import difference_figure

    t = np.arange(10.0)
    fig = difference_figure(t, np.ones((10, 3)), np.zeros((10, 3)))
    for ax in fig.axes:
        colours = {
            line.get_label(): line.get_color()
            for line in ax.get_lines()
            if line.get_label() in ("before", "after")
        }
        assert colours_told_apart(colours["before"], colours["after"]), colours
