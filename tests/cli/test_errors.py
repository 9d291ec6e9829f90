"""Every failure a user can meet ends with one line on
standard error and a documented exit code, no traceback."""

from __future__ import annotations

import argparse
import errno
import fcntl
import os
import pathlib
import pty
import select
import signal
import struct
import subprocess
import sys
import termios
import time
from pathlib import Path

import pytest

from registration.cli import main
from registration.cli.errors import (
    DEBUG_ENV,
    EXIT_BAD_INPUT,
    EXIT_BROKEN_PIPE,
    EXIT_INCONSISTENT,
    EXIT_INTERRUPTED,
    interrupt_message,
)

ROOT = Path(__file__).resolve().parents[2]


def cli(*args, cwd=None, env=None, **popen):
    """``python -m registration ARGS`` with the checkout on the path."""
    env = {**os.environ, "PYTHONPATH": str(ROOT), **(env or {})}
    return subprocess.Popen([sys.executable, "-m", "registration", *args], cwd=cwd, env=env, **popen)


def test_the_exit_codes_are_the_documented_ones():
    assert (EXIT_BAD_INPUT, EXIT_INCONSISTENT, EXIT_INTERRUPTED, EXIT_BROKEN_PIPE) == (2, 3, 130, 141)


@pytest.mark.parametrize(
    "command",
    [
        ["simulate", "--steps", "20", "--no-plots"],
        ["montecarlo", "--runs", "2", "--steps", "20", "--no-plots"],
        ["fuse", "--trials", "10", "--no-plots"],
        ["landing", "--runs", "2", "--no-plots"],
    ],
)
def test_out_naming_an_existing_file_is_one_line(tmp_path, capsys, command):
    """Before: FileExistsError with a traceback from mkdir."""
    afile = tmp_path / "afile"
    afile.write_text("keep me")
    assert main([*command, "--out", str(afile)]) == EXIT_BAD_INPUT
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith(f"registration {command[0]}: error: ") and str(afile) in err and "--out" in err
    assert afile.read_text() == "keep me"


def test_an_unusable_out_fails_before_the_work(tmp_path, capsys, monkeypatch):
    """The output folder is checked first: the simulation never starts."""
    import registration.online

    monkeypatch.setattr(registration.online, "register", lambda *a, **k: pytest.fail("simulation started"))
    (tmp_path / "afile").write_text("")
    assert main(["simulate", "--out", str(tmp_path / "afile" / "sub")]) == EXIT_BAD_INPUT
    assert "cannot create the output folder" in capsys.readouterr().err


def test_a_read_only_output_names_the_path(tmp_path, capsys, monkeypatch):
    """Before: OSError [Errno 30] with a traceback (running as root, read-only is simulated)."""

    def read_only(self, *args, **kwargs):
        raise OSError(errno.EROFS, os.strerror(errno.EROFS), str(self))

    monkeypatch.setattr(pathlib.Path, "write_text", read_only)
    out = tmp_path / "ro"
    assert main(["simulate", "--steps", "20", "--no-plots", "--out", str(out)]) == EXIT_BAD_INPUT
    err = capsys.readouterr().err
    assert (
        err == f"registration simulate: error: cannot write {out / 'summary.json'}: Read-only file system\n"
    )


def test_an_unwritable_export_names_the_path(tmp_path, capsys, monkeypatch):
    import registration.recorded.reading.formats as formats

    def read_only(frame, path, fmt=None):
        raise OSError(errno.EROFS, os.strerror(errno.EROFS), str(path))

    monkeypatch.setattr(formats, "write_frame", read_only)
    export = tmp_path / "data.csv"
    assert (
        main(
            ["simulate", "--steps", "20", "--no-plots", "--out", str(tmp_path / "o"), "--export", str(export)]
        )
        == 2
    )
    assert (
        capsys.readouterr().err
        == f"registration simulate: error: cannot write {export}: Read-only file system\n"
    )


def test_any_os_error_names_its_path(tmp_path, capsys, monkeypatch):
    """An operating-system error from anywhere in a run: 'PATH: reason', exit 2."""
    import registration.online

    def unreadable(*args, **kwargs):
        raise PermissionError(errno.EACCES, os.strerror(errno.EACCES), "/data/in.csv")

    monkeypatch.setattr(registration.online, "register", unreadable)
    assert main(["simulate", "--out", str(tmp_path)]) == EXIT_BAD_INPUT
    assert capsys.readouterr().err == "registration simulate: error: /data/in.csv: Permission denied\n"


def test_a_folder_where_a_file_goes_is_one_line(tmp_path, capsys):
    """A real operating-system error while writing (root cannot be kept out by permissions; a folder can)."""
    (tmp_path / "summary.json").mkdir()
    assert main(["fuse", "--trials", "10", "--no-plots", "--out", str(tmp_path)]) == EXIT_BAD_INPUT
    err = capsys.readouterr().err
    assert err.startswith("registration fuse: error: cannot write ") and "summary.json: Is a directory" in err
    assert "Traceback" not in err
    assert (tmp_path / "summary.json").is_dir()  # not an earlier run's output: never replaced
    assert not list(tmp_path.glob("partial-*"))


def test_the_debug_variable_shows_the_traceback(tmp_path, capsys, monkeypatch):
    (tmp_path / "afile").write_text("")
    monkeypatch.setenv(DEBUG_ENV, "1")
    assert main(["fuse", "--trials", "10", "--out", str(tmp_path / "afile")]) == EXIT_BAD_INPUT
    err = capsys.readouterr().err
    assert "Traceback" in err and err.rstrip().endswith("(--out)")


def test_ctrl_c_says_where_it_stopped(tmp_path, capsys, monkeypatch):
    """Before: a raw KeyboardInterrupt traceback."""
    import registration.online

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(registration.online, "register", interrupted)
    out = tmp_path / "new" / "sim"
    assert main(["simulate", "--out", str(out)]) == EXIT_INTERRUPTED
    assert (
        capsys.readouterr().err
        == f"\nregistration simulate: interrupted; nothing was written (no earlier outputs in {out})\n"
    )
    assert not (
        tmp_path / "new"
    ).exists()  # before: an empty folder, "keeping the outputs of the last finished run"
    out.mkdir(parents=True)
    (out / "summary.json").write_text("{}")
    assert main(["simulate", "--out", str(out)]) == EXIT_INTERRUPTED
    assert (
        capsys.readouterr().err
        == f"\nregistration simulate: interrupted; nothing was written: {out} keeps what it held before\n"
    )
    assert (out / "summary.json").read_text() == "{}"


def test_every_message_names_the_full_command(tmp_path, capsys, monkeypatch):
    """Before: `registration fleet: error: ...` beside
    `registration fleet register: error: ...` (the gate)."""
    missing = [f"--{t}={tmp_path / t}.csv" for t in ("plots", "navigation", "sensors")]
    assert main(["fleet", "register", *missing, "--out", str(tmp_path / "o")]) == EXIT_BAD_INPUT
    assert capsys.readouterr().err.startswith("registration fleet register: error: ")
    import registration.fleet

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(registration.fleet, "fleet_scenario", interrupted)
    assert main(["fleet", "simulate", "--out", str(tmp_path / "o")]) == EXIT_INTERRUPTED
    assert capsys.readouterr().err.startswith("\nregistration fleet simulate: interrupted")


def _exit_codes(argv, capsys) -> set[int]:
    assert main([*argv, "--help"]) == 0
    table = capsys.readouterr().out.split("exit codes:\n")[1]
    return {
        int(line.split()[0])
        for line in table.splitlines()
        if line.startswith("  ") and line.split()[0].isdigit()
    }


@pytest.mark.parametrize(
    "argv, codes",
    [
        ([], {0, 1, 2, 3, 130, 141}),
        (["register"], {0, 1, 2, 3, 130, 141}),
        (["simulate"], {0, 2, 3, 130, 141}),
        (["montecarlo"], {0, 2, 3, 130, 141}),
        (["fleet"], {0, 2, 3, 130, 141}),
        (["fleet", "register"], {0, 2, 3, 130, 141}),
        (["fleet", "simulate"], {0, 2, 3, 130, 141}),
        (["fuse"], {0, 2, 130, 141}),
        (["landing"], {0, 2, 130, 141}),
        (["schema"], {0, 2, 130, 141}),
    ],
)
def test_each_help_lists_the_exit_codes_of_its_command(capsys, argv, codes):
    """Before: every --help listed 1 (register --validate-only) and 3 (the consistency gate)."""
    listed = _exit_codes(argv, capsys)
    assert listed & {1, 3} == codes & {1, 3} and {0, 2, 130, 141} <= listed


def test_ctrl_c_with_a_checkpoint_says_how_to_resume():
    args = argparse.Namespace(checkpoint=Path("run.ckpt"), out=Path("reg"))
    text = interrupt_message("registration register", args)
    assert (
        text
        == "registration register: interrupted; rerun the same command to resume from its checkpoint run.ckpt"
    )
    assert "resume" not in interrupt_message(
        "registration register", argparse.Namespace(checkpoint=None, out=Path("r"))
    )


def _default_sigint() -> None:
    """In the child before exec: SIGINT back to its default, so that Python installs its handler even
    when the test run itself ignores SIGINT (a suite started in the background by a non-interactive
    shell inherits SIG_IGN, and the command would then never see the signal)."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def _read_all(fd: int, timeout_s: float) -> bytes:
    """What is left to read from a pseudo-terminal's master ``fd`` until its other end closes."""
    out, deadline = b"", time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        if not select.select([fd], [], [], 1.0)[0]:
            continue
        try:
            chunk = os.read(fd, 4096)
        except OSError:  # EIO: the command's end of the terminal is closed
            break
        if not chunk:
            break
        out += chunk
    return out


def test_a_real_sigint_exits_130_without_traceback(tmp_path):
    """Standard error a terminal (a pseudo-terminal), so the progress bar shows: once it has moved
    the run is under way, and SIGINT then stops it with exit code 130."""
    master, slave = pty.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 100, 0, 0))  # 100 columns for the bar
    proc = cli(
        "landing",
        "--runs",
        "100000",
        "--no-plots",
        "--out",
        "land",
        cwd=tmp_path,
        stdout=subprocess.DEVNULL,
        stderr=slave,
        preexec_fn=_default_sigint,
    )
    os.close(slave)
    seen, deadline = b"", time.monotonic() + 120
    try:
        while b"batch/s" not in seen and time.monotonic() < deadline:  # the progress bar has moved
            if not select.select([master], [], [], 1.0)[0]:
                continue
            try:
                chunk = os.read(master, 4096)
            except OSError:
                break  # the command ended on its own
            if not chunk:
                break
            seen += chunk
        proc.send_signal(signal.SIGINT)
        rest = _read_all(master, 60)
        proc.wait(timeout=60)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()
        pytest.fail("the command did not stop within 60 s of SIGINT")
    finally:
        os.close(master)
    err = (seen + rest).decode(errors="replace").replace("\r\n", "\n")  # a terminal ends lines in CRLF
    assert proc.returncode == EXIT_INTERRUPTED, err
    assert "Traceback" not in err and "KeyboardInterrupt" not in err
    assert err.endswith(
        "\nregistration landing: interrupted; nothing was written (no earlier outputs in land)\n"
    )
    assert not (tmp_path / "land").exists()


@pytest.mark.parametrize(
    "command", [["schema"], ["schema", "--json"], ["simulate", "--steps", "20", "--no-plots"]]
)
def test_a_closed_pipe_stops_quietly(tmp_path, command):
    """Before: BrokenPipeError tracebacks (e.g. `registration schema | head -1`)."""
    read_end, write_end = os.pipe()
    os.close(read_end)  # the reader is gone before the first line
    proc = cli(*command, cwd=tmp_path, stdout=write_end, stderr=subprocess.PIPE)
    os.close(write_end)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == EXIT_BROKEN_PIPE
    assert b"Traceback" not in err and b"BrokenPipe" not in err and b"Exception ignored" not in err
