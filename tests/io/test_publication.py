"""Publication into ``--out`` cannot be turned against the user, and is old-or-new at every step.

A marker file in ``--out`` is input like any other: it may name only a run folder this tool made
(``partial-<pid>-<hex>``, a direct child, no symbolic link) and plain file names; anything else is
refused before a file is moved or deleted. Ctrl-C and SIGTERM during publication take effect once
the outputs are whole, and say so; a SIGKILL at any rename leaves a marker the next run completes.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from registration.cli import main
from registration.cli.errors import EXIT_TERMINATED
from registration.io.output.outfolder import MARKER, OutputFolderError, prepare_out
from registration.io.output.signals import HOOK_ENV

FUSE = ["fuse", "--trials", "200", "--max-plot-points", "50"]
FUSE_NAMES = frozenset({"summary.json", "measurements.png", "fused.png"})


def _dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


def _snapshot(folder: Path) -> dict:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def _victim(tmp_path: Path) -> Path:
    victim = tmp_path / "v"
    victim.mkdir()
    (victim / "precious.txt").write_text("keep me\n")
    return victim


@pytest.mark.parametrize(
    "publishing", ["../v", "{victim}", "partial-1-ab/../../v", "partial-12-zz", "summary.json"]
)
def test_a_marker_naming_anything_but_a_run_folder_is_refused_and_nothing_is_deleted(tmp_path, publishing):
    victim = _victim(tmp_path)
    out = tmp_path / "out"
    out.mkdir()
    (out / "summary.json").write_text("{}")
    name = publishing.format(victim=victim)
    (out / MARKER).write_text(f"publishing: {name}\nfiles: []\n")
    before = _snapshot(out)
    with pytest.raises(OutputFolderError, match="nothing was moved or deleted"):
        prepare_out(out)
    assert (victim / "precious.txt").read_text() == "keep me\n"
    assert _snapshot(out) == before


@pytest.mark.parametrize("files", [["../v/precious.txt"], ["/etc/passwd"], [".."], "not a list", [3]])
def test_a_marker_listing_anything_but_plain_file_names_is_refused(tmp_path, files):
    victim = _victim(tmp_path)
    out = tmp_path / "out"
    work = out / f"partial-{_dead_pid()}-abcdef"
    work.mkdir(parents=True)
    (out / MARKER).write_text(f"publishing: {work.name}\nfiles: {json.dumps(files)}\n")
    with pytest.raises(OutputFolderError, match="nothing was moved or deleted"):
        prepare_out(out)
    assert work.is_dir() and (victim / "precious.txt").exists()


def test_a_run_folder_that_is_a_symbolic_link_is_never_followed(tmp_path):
    victim = _victim(tmp_path)
    out = tmp_path / "out"
    out.mkdir()
    link = out / f"partial-{_dead_pid()}-abcdef"
    link.symlink_to(victim, target_is_directory=True)
    (out / MARKER).write_text(f"publishing: {link.name}\nfiles: []\n")
    with pytest.raises(OutputFolderError, match="symbolic link"):
        prepare_out(out)
    (out / MARKER).unlink()
    prepare_out(out)  # as a leftover of a dead run: not followed either
    assert (victim / "precious.txt").exists() and link.is_symlink()


def test_the_command_exits_2_on_a_crafted_marker_and_deletes_nothing(tmp_path, capsys):
    victim = _victim(tmp_path)
    out = tmp_path / "out"
    out.mkdir()
    (out / MARKER).write_text("publishing: ../v\nfiles: []\n")
    assert main([*FUSE, "--no-plots", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "not a run folder" in err and len(err.strip().splitlines()) == 1
    assert (victim / "precious.txt").exists()


@pytest.mark.parametrize("marker", [None, "", "This folder holds the unfinished outputs\n"])
def test_stale_run_folders_without_a_checkpoint_line_are_removed(tmp_path, marker):
    out = tmp_path / "out"
    stale = out / f"partial-{_dead_pid()}-0a0b0c"
    stale.mkdir(parents=True)
    if marker is not None:
        (stale / MARKER).write_text(marker)
    prepare_out(out)
    assert not stale.exists()


def _fuse(out: Path, seed: int, hook: str | None = None) -> subprocess.CompletedProcess:
    env = {**os.environ, "MPLBACKEND": "Agg"}
    env.pop(HOOK_ENV, None)
    if hook:
        env[HOOK_ENV] = hook
    return subprocess.run(
        [sys.executable, "-m", "registration", *FUSE, "--seed", str(seed), "--no-plots", "--out", str(out)],
        capture_output=True,
        text=True,
        env=env,
        timeout=120,
        # a suite started in the background by a shell ignores SIGINT, and a child inherits that:
        # give the command the default handler, as in a terminal
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )


@pytest.fixture(scope="module")
def old_and_new(tmp_path_factory):
    """An earlier run with plots (old: three files) and the outputs the next run (no plots) gives."""
    base = tmp_path_factory.mktemp("publication")
    old = base / "old"
    assert main([*FUSE, "--seed", "1", "--out", str(old)]) == 0
    new = base / "new"
    assert _fuse(new, 2).returncode == 0
    return _snapshot(old), _snapshot(new)


def _restore(folder: Path, snapshot: dict) -> None:
    folder.mkdir(parents=True)
    for name, data in snapshot.items():
        (folder / name).write_bytes(data)


def _without_paths(snapshot: dict, folder: Path) -> dict:
    return {k: v.replace(str(folder).encode(), b"OUT") for k, v in snapshot.items()}


# three old files leave (steps 0-2), the new summary arrives (step 3); step 4 is past the last rename
@pytest.mark.parametrize("step", range(5))
def test_ctrl_c_at_any_step_of_publication_leaves_the_new_outputs_whole_and_says_so(
    tmp_path, old_and_new, step
):
    old, new = old_and_new
    out = tmp_path / "out"
    _restore(out, old)
    done = _fuse(out, 2, hook=f"INT:{step}")
    got = _without_paths(_snapshot(out), out)
    if step < 4:
        assert done.returncode == 130, done.stderr
        assert "interrupted once the outputs were published" in done.stderr
    else:
        assert done.returncode == 0, done.stderr
    assert got == _without_paths(new, out.parent / "new")  # exactly new, never a mixture
    assert sorted(p.name for p in out.iterdir()) == ["summary.json"]


@pytest.mark.parametrize("step", range(4))
def test_a_kill_at_any_step_of_publication_is_new_once_the_next_run_starts(tmp_path, old_and_new, step):
    old, new = old_and_new
    out = tmp_path / "out"
    _restore(out, old)
    done = _fuse(out, 2, hook=f"KILL:{step}")
    assert done.returncode == -signal.SIGKILL
    assert (out / MARKER).exists()  # marked: a reader can tell the folder is not whole
    prepare_out(out, FUSE_NAMES)  # what the next run into OUT does first
    assert _without_paths(_snapshot(out), out) == _without_paths(new, out.parent / "new")
    assert not any(p.name.startswith(("partial-", ".replaced-")) for p in out.iterdir())


def test_sigterm_during_publication_ends_the_process_after_the_outputs_are_whole(tmp_path, old_and_new):
    old, new = old_and_new
    out = tmp_path / "out"
    _restore(out, old)
    done = _fuse(out, 2, hook="TERM:1")
    assert done.returncode == EXIT_TERMINATED  # the CLI's SIGTERM: SystemExit(143) once published
    assert _without_paths(_snapshot(out), out) == _without_paths(new, out.parent / "new")
