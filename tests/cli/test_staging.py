"""Every command publishes its outputs whole: a rerun with --no-plots leaves no PNG of the earlier
run, a run that fails half way leaves the earlier outputs byte for byte, and no ``partial-*``
folder stays behind either way."""

import errno
import importlib

import pytest

from registration.cli import main
from registration.cli.staging import staged_outputs

# command line (smallest options) and the function, "module:attribute[.attribute]", that fails once
# some of the run's files are in its run folder
CASES = {
    "simulate": (["simulate", "--steps", "20"], "registration.online.plots:plot_estimates"),
    "montecarlo": (
        ["montecarlo", "--runs", "2", "--steps", "20"],
        "registration.online.mcresult:MonteCarloResult.plot",
    ),
    "montecarlo --sweep": (
        ["montecarlo", "--runs", "2", "--steps", "20", "--sweep", "steps=20,21"],
        "registration.online.sweep:plot_sweep",
    ),
    "fuse": (["fuse", "--trials", "20"], "registration.fusion.plots:write_plots"),
    "landing": (
        ["landing", "--runs", "2", "--start-range-m", "600", "--plot-bin-m", "250"],
        "registration.cli.landing:write_plots",
    ),
}


def _contents(out) -> dict:
    return {p.name: (p.read_bytes() if p.is_file() else None) for p in out.iterdir()}


def _fail_after_writing(monkeypatch, target: str, seen: list) -> None:
    """Make ``target`` do its work, note the run folder's files, then fail as a full disk would."""
    module, attrs = target.split(":")
    owner = importlib.import_module(module)
    *path, name = attrs.split(".")
    for a in path:
        owner = getattr(owner, a)
    real = getattr(owner, name)

    def failing(*args, **kwargs):
        real(*args, **kwargs)
        seen.append(None)
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(owner, name, failing)


@pytest.mark.parametrize("case", list(CASES))
def test_a_run_replaces_the_earlier_runs_outputs_whole(case, tmp_path, monkeypatch, capsys):
    argv, target = CASES[case]
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.txt").write_text("not an output of any command\n")
    assert main([*argv, "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    first = _contents(out)
    assert any(n.endswith(".png") for n in first) and "notes.txt" in first
    table = next(n for n in first if n.endswith((".json", ".csv")))
    assert (
        "partial-" not in printed and str(out / table) in printed
    )  # where the file is, not where it was written

    seen = []
    with monkeypatch.context() as patch:
        _fail_after_writing(patch, target, seen)
        assert (
            main([*argv, "--seed", "7", "--out", str(out)]) == 2
        )  # another seed: other bytes, were they written
    assert seen, "the run should fail inside its staging, after writing"
    assert "No space left on device" in capsys.readouterr().err
    assert _contents(out) == first  # byte for byte, no partial-* folder, no marker

    assert main([*argv, "--no-plots", "--out", str(out)]) == 0
    after = _contents(out)
    assert not [n for n in after if n.endswith(".png")], after.keys()
    assert not [n for n in after if n.startswith("partial-") or n == "INCOMPLETE"]
    assert after["notes.txt"] == first["notes.txt"]
    assert set(after) < set(first)


def test_a_sweep_replaces_a_single_runs_outputs(tmp_path, capsys):
    """montecarlo with and without --sweep declare the same outputs: --out holds one run."""
    out = tmp_path / "out"
    assert main([*CASES["montecarlo"][0], "--no-plots", "--out", str(out)]) == 0
    assert main([*CASES["montecarlo --sweep"][0], "--no-plots", "--out", str(out)]) == 0
    assert sorted(p.name for p in out.iterdir()) == ["sweep.csv"]
    capsys.readouterr()


def test_simulate_export_is_written_outside_the_published_folder(tmp_path, capsys):
    out, export = tmp_path / "out", tmp_path / "data" / "sim.csv"
    assert main([*CASES["simulate"][0], "--no-plots", "--out", str(out), "--export", str(export)]) == 0
    assert export.stat().st_size > 0 and sorted(p.name for p in out.iterdir()) == ["summary.json"]
    assert str(export) in capsys.readouterr().out


def test_staged_outputs_publishes_only_on_success(tmp_path):
    out = tmp_path / "out"
    names = frozenset({"a.txt", "b.png"})
    with staged_outputs(out, "test", names) as folder:
        (folder.path / "a.txt").write_text("1")
        (folder.path / "b.png").write_text("1")
        assert not (out / "a.txt").exists()
    with pytest.raises(KeyboardInterrupt):
        with staged_outputs(out, "test", names) as folder:
            (folder.path / "a.txt").write_text("2")
            raise KeyboardInterrupt
    assert sorted(p.name for p in out.iterdir()) == ["a.txt", "b.png"] and (out / "a.txt").read_text() == "1"
    with staged_outputs(out, "test", names) as folder:
        (folder.path / "a.txt").write_text("3")
    assert sorted(p.name for p in out.iterdir()) == ["a.txt"] and (out / "a.txt").read_text() == "3"
    assert folder.final(folder.path / "a.txt") == out / "a.txt"


@pytest.mark.parametrize("case", list(CASES))
def test_a_failed_run_aimed_at_a_new_out_leaves_no_folder(case, tmp_path, monkeypatch, capsys):
    """Before: the command created --out (and its parents) first and left them empty."""
    argv, target = CASES[case]
    out = tmp_path / "new" / "out"
    seen = []
    _fail_after_writing(monkeypatch, target, seen)
    assert main([*argv, "--out", str(out)]) == 2
    assert seen and "No space left on device" in capsys.readouterr().err
    assert not (tmp_path / "new").exists()


def test_a_run_failing_before_its_outputs_leaves_no_folder(tmp_path, monkeypatch, capsys):
    import registration.online

    def failing(*args, **kwargs):
        raise ValueError("the simulation failed")

    monkeypatch.setattr(registration.online, "register", failing)
    assert main(["simulate", "--out", str(tmp_path / "new" / "out")]) == 2
    assert "the simulation failed" in capsys.readouterr().err
    assert not (tmp_path / "new").exists()


def test_an_interrupted_staging_removes_only_the_folders_it_made(tmp_path):
    names = frozenset({"a.txt"})
    for out, kept in ((tmp_path / "new" / "out", None), (tmp_path / "empty", tmp_path / "empty")):
        if kept is not None:
            kept.mkdir()  # the user's own empty folder: kept
        with pytest.raises(KeyboardInterrupt):
            with staged_outputs(out, "test", names) as folder:
                (folder.path / "a.txt").write_text("2")
                raise KeyboardInterrupt
        assert out.exists() == (kept is not None) and not (tmp_path / "new").exists()
        if kept is not None:
            assert not any(kept.iterdir())
