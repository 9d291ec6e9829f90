"""`registration register` into a folder that is reused: never a mixture of two runs.

A run works in ``OUT/partial-<pid>-<token>`` and replaces the outputs of the run before only when
it has finished; a failed or interrupted run leaves ``OUT`` as it was; a checkpointed run stopped
half-way says so (``INCOMPLETE``) and resumes in its folder.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys

import pandas as pd
import pytest

import registration.io.output.outfolder as outfolder
import registration.recorded.run.filtering as filtering
from registration.cli import main
from registration.io.output.outfolder import MARKER, RunFolder, prepare_out, publish
from registration.recorded import OUTPUT_NAMES, RunOptions, load_checkpoint, run_register

from ._register_data import frame
from .test_register_async import write_async

FAST = ["--no-plots", "--no-progress"]


def _run(*args):
    return main(["register", *map(str, args)])


def _snapshot(folder):
    """{relative path: bytes} of every file under ``folder``."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


@pytest.fixture(scope="module")
def good_template(tmp_path_factory):
    """One good run with plots (the slow part), copied into each test that needs an earlier run."""
    base = tmp_path_factory.mktemp("good")
    inp, out = base / "good.csv", base / "reg"
    frame(120).to_csv(inp, index=False)
    assert _run(inp, "--out", out, "--no-progress") == 0  # with plots
    return base


def _good_run(tmp_path, template):
    """The input and the output folder of a finished good run, in ``tmp_path`` (paths as if run there)."""
    inp, out = tmp_path / "good.csv", tmp_path / "reg"
    shutil.copyfile(template / "good.csv", inp)
    shutil.copytree(template / "reg", out)
    summary = out / "summary.json"
    summary.write_text(summary.read_text().replace(str(template), str(tmp_path)))
    return inp, out


@pytest.mark.parametrize("mistake", ["bad_row", "unreadable", "header_only"])
def test_a_failed_run_leaves_the_earlier_run_untouched(tmp_path, capsys, mistake, good_template):
    _, out = _good_run(tmp_path, good_template)
    before = _snapshot(out)
    assert {"summary.json", "estimates.png", "estimates.csv"} <= set(before)
    bad = tmp_path / "bad.csv"
    f = frame(120)
    if mistake == "bad_row":
        f.loc[40, "a_range_m"] = -1.0
        f.to_csv(bad, index=False)
    elif mistake == "unreadable":
        bad.write_text(
            f.to_csv(index=False) + "1,2,3," * 10 + "\n"
        )  # a malformed line: the file cannot be read
    else:
        f.iloc[:0].to_csv(bad, index=False)
    assert _run(bad, "--out", out, *FAST) == 2
    capsys.readouterr()
    assert _snapshot(out) == before
    assert not list(out.glob("partial-*")) and not (out / MARKER).exists()


def test_every_row_rejected_replaces_the_earlier_run_whole(tmp_path, good_template):
    """All rows rejected is an answer (rejected.csv says why): published, with nothing of the run before."""
    _, out = _good_run(tmp_path, good_template)
    bad = tmp_path / "bad.csv"
    f = frame(50)
    f["b_range_m"] = 0.0
    f.to_csv(bad, index=False)
    assert _run(bad, "--out", out, "--on-bad-row", "skip", *FAST) == 2
    names = {p.name for p in out.iterdir()}
    assert names == {"estimates.csv", "positions.csv", "rejected.csv"}
    assert pd.read_csv(out / "rejected.csv")["row"].tolist() == list(range(50))
    assert pd.read_csv(out / "estimates.csv").empty


def test_a_synchronous_run_after_an_asynchronous_one_removes_the_pairing_files(tmp_path):
    _, paths, nav, _ = write_async(tmp_path)
    out = tmp_path / "reg"
    assert (
        main(["register", *map(str, paths[:2]), *nav, "--clock-offset-b", "0.3", "--out", str(out), *FAST])
        == 0
    )
    assert {"paired.csv", "pairing.json", "unpaired.csv"} <= {p.name for p in out.iterdir()}
    (out / "my_notes.txt").write_text("kept\n")  # not a file a run writes: never touched
    sync = tmp_path / "sync.csv"
    frame(60).to_csv(sync, index=False)
    assert _run(sync, "--out", out, *FAST) == 0
    assert {p.name for p in out.iterdir()} == {
        "estimates.csv",
        "positions.csv",
        "rejected.csv",
        "summary.json",
        "my_notes.txt",
    }
    assert (out / "my_notes.txt").read_text() == "kept\n"
    assert json.loads((out / "summary.json").read_text())["form"] == "synchronous"


def test_a_rerun_with_the_same_pairing_takes_it_over_without_duplicating_rejected_rows(tmp_path, capsys):
    _, paths, nav, _ = write_async(tmp_path)
    b = pd.read_parquet(paths[1])
    b.loc[7, "b_range_m"] = -5.0  # a bad plot row: the pairing's part of rejected.csv
    b.loc[20, "b_range_m"] = (
        1e300  # valid, but no finite filter step at the instants next to it: the filter's part
    )
    b.to_parquet(paths[1], index=False)
    out = tmp_path / "reg"
    args = [
        "register",
        *map(str, paths[:2]),
        *nav,
        "--clock-offset-b",
        "0.3",
        "--on-bad-row",
        "skip",
        "--out",
        str(out),
        *FAST,
    ]
    assert main(args) == 0
    first = _snapshot(out)
    rejected = pd.read_csv(out / "rejected.csv")
    assert rejected["reason_code"].tolist()[0] == "non_positive_range" and "filter_non_finite" in set(
        rejected["reason_code"]
    )
    assert set(rejected["file"]) == {
        str(paths[1]),
        str(out / "paired.csv"),
    }  # the table by its published name
    capsys.readouterr()
    assert main(args) == 0
    assert "reusing the pairing" in capsys.readouterr().err
    second = _snapshot(out)
    assert second.pop("summary.json") and first.pop("summary.json")  # (elapsed time differs)
    assert second == first


def _interrupt_pass_2(monkeypatch):
    """Ctrl-C during the second pass (information matrix), after the filter pass was checkpointed."""

    def stop(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(filtering, "information_at_estimate", stop)


def _options(out, ckpt=None):
    return RunOptions(
        out=out,
        checkpoint=ckpt,
        checkpoint_every=40,
        chunk_rows=40,
        plots=False,
        progress=False,
        log=lambda m: None,
    )


def test_an_interrupted_run_without_checkpoint_changes_nothing(tmp_path, monkeypatch, good_template):
    inp, out = _good_run(tmp_path, good_template)
    before = _snapshot(out)
    other = tmp_path / "other.csv"
    frame(100, seed=3).to_csv(other, index=False)
    _interrupt_pass_2(monkeypatch)
    with pytest.raises(KeyboardInterrupt):
        run_register([other], _options(out))
    assert _snapshot(out) == before and not list(out.glob("partial-*"))


def test_a_checkpointed_run_stopped_half_way_is_marked_and_resumes_into_place(
    tmp_path, monkeypatch, good_template
):
    inp, out = _good_run(tmp_path, good_template)
    before = _snapshot(out)
    other, ckpt = tmp_path / "other.csv", tmp_path / "run.ckpt"
    frame(100, seed=3).to_csv(other, index=False)
    ref = tmp_path / "ref"
    run_register([other], _options(ref))
    with monkeypatch.context() as m:
        _interrupt_pass_2(m)
        with pytest.raises(KeyboardInterrupt):
            run_register([other], _options(out, ckpt))
    # the earlier run is whole; the unfinished one is in its own folder, which says so
    (work,) = out.glob("partial-*")
    assert {k: v for k, v in _snapshot(out).items() if not k.startswith("partial-")} == before
    note = (work / MARKER).read_text()
    assert str(ckpt.resolve()) in note and "rerun the same command" in note
    assert load_checkpoint(ckpt)["outputs"]["folder"] == work.name
    assert len(pd.read_csv(work / "estimates.csv")) == 100
    # a new run into the same folder leaves a resumable folder alone
    prepare_out(out)
    assert work.is_dir()
    # rerunning resumes there and publishes: the outputs of an uninterrupted run, nothing else
    summary = run_register([other], _options(out, ckpt))
    assert not work.exists() and not (out / MARKER).exists()
    for name in ("estimates.csv", "positions.csv", "rejected.csv"):
        assert (out / name).read_bytes() == (ref / name).read_bytes(), name
    assert not (out / "estimates.png").exists()  # the earlier run's plots are gone with it
    assert summary["rows"]["read"] == 100 and load_checkpoint(ckpt)["phase"] == "done"


def _dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


def test_an_interrupted_publication_is_completed_by_the_next_run(tmp_path, monkeypatch, good_template):
    inp, out = _good_run(tmp_path, good_template)
    new = tmp_path / "new"
    frame(60, seed=2).to_csv(tmp_path / "new.csv", index=False)
    assert _run(tmp_path / "new.csv", "--out", new, "--no-progress") == 0
    expected = _snapshot(new)
    work = out / f"partial-{_dead_pid()}-abcdef"  # the finished folder of a process that was killed...
    new.rename(work)
    renames = []

    def rename_then_die(src, dst):  # ... while moving it into place: after three renames
        if len(renames) == 3:
            raise KeyboardInterrupt
        renames.append(src)
        return real_rename(src, dst)

    real_rename = outfolder.os.rename
    with monkeypatch.context() as m:
        m.setattr(outfolder.os, "rename", rename_then_die)
        with pytest.raises(KeyboardInterrupt):
            publish(RunFolder(out, work))
    assert (out / MARKER).exists() and "publishing" in (out / MARKER).read_text()
    prepare_out(out)  # what the next run into OUT does first
    assert _snapshot(out) == expected and not work.exists()
    assert not any(p.name.startswith((".replaced-", "partial-")) for p in out.iterdir())


def test_leftovers_of_dead_runs_that_cannot_resume_are_removed(tmp_path):
    out = tmp_path / "reg"
    out.mkdir()
    pid = _dead_pid()
    no_ckpt = out / f"partial-{pid}-000001"
    gone_ckpt = out / f"partial-{pid}-000002"
    for d, ck in ((no_ckpt, "none"), (gone_ckpt, str(tmp_path / "deleted.ckpt"))):
        d.mkdir()
        (d / MARKER).write_text(f"checkpoint: {ck}\n")
        (d / "estimates.csv").write_text("row\n")
    alive = out / "partial-1-000003"  # process 1 is alive: never touched
    alive.mkdir()
    (alive / MARKER).write_text("checkpoint: none\n")
    prepare_out(out)
    assert sorted(p.name for p in out.iterdir()) == [alive.name]


def test_the_names_a_run_may_replace_are_those_it_writes(tmp_path):
    """Every file of a full asynchronous run with plots is in OUTPUT_NAMES, so none is left behind."""
    _, paths, nav, _ = write_async(tmp_path)
    out = tmp_path / "reg"
    assert (
        main(
            [
                "register",
                *map(str, paths[:2]),
                *nav,
                "--clock-offset-b",
                "0.3",
                "--out",
                str(out),
                "--format",
                "parquet",
                "--no-progress",
            ]
        )
        == 0
    )
    assert {p.name for p in out.iterdir()} <= OUTPUT_NAMES
