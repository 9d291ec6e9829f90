"""`registration simulate` end to end (short run) and its summary.json contract."""

import json

import pytest

from registration.cli import main


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
    assert names[:12] == ["dC_a", "dphi_a", "dtheta_a", "dr_a", "dq_a", "de_a", "dC_b", "dphi_b", "dtheta_b", "dr_b", "dq_b", "de_b"]
    assert all({"name", "estimate", "sigma", "truth"} <= set(e) for e in summary["estimates"])
    obs = summary["observability"]
    assert len(obs["singular_values"]) == 12 and isinstance(obs["unobservable"], list) and isinstance(obs["weak"], list)
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
