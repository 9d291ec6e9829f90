"""The one-time build of the generated C code (``registration._codegen.build``): announced on
standard error before it starts and reported when it ends (in logs too), a progress bar only on a
terminal, sources compiled one by one, largest first, then linked. Built here from the batch
driver and two tiny sources (well under a second), never the full library."""

from __future__ import annotations

import ctypes
import io
import subprocess

import pytest

from registration import _codegen
from registration._codegen import build, cbackend

SOURCES = [
    ("tiny.c", b"double tiny(double x) { return 2.0 * x; }\n"),
    ("larger.c", b"/* padding */\n" * 200 + b"double larger(double x) { return x + 1.0; }\n"),
]


class Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


@pytest.fixture
def cc():
    cc = _codegen.compiler()
    if cc is None:
        pytest.skip("no C compiler")
    return cc


def _build(cc, tmp_path, monkeypatch, stderr, sources=SOURCES):
    monkeypatch.setattr("sys.stderr", stderr)
    lib = tmp_path / "cache" / "key" / "lib.so"
    build.build_library(cc, cbackend.DRIVERS, sources, lib, cbackend.cflags())
    return lib


def test_the_build_says_so_before_and_after_without_a_bar_in_logs(cc, tmp_path, monkeypatch):
    """Before: 20 s to a minute without a word."""
    log = io.StringIO()
    lib = _build(cc, tmp_path, monkeypatch, log)
    lines = log.getvalue().splitlines()
    assert lines[0] == build.BUILD_MESSAGE.format(folder=tmp_path / "cache")
    assert lines[0].startswith("registration: compiling the generated C code once")
    assert (
        len(lines) == 2 and lines[1].startswith("registration: compiled in ") and "\r" not in log.getvalue()
    )
    loaded = ctypes.CDLL(str(lib))  # linked: every source's function is there
    for name, expected in (("tiny", 3.0), ("larger", 2.5)):
        f = getattr(loaded, name)
        f.restype, f.argtypes = ctypes.c_double, [ctypes.c_double]
        assert f(1.5) == expected


def test_a_terminal_gets_a_progress_bar_over_the_files(cc, tmp_path, monkeypatch):
    terminal = Terminal()
    _build(cc, tmp_path, monkeypatch, terminal)
    text = terminal.getvalue()
    assert text.startswith("registration: compiling the generated C code once")
    assert "\rcompiling 0/4 files:   0%|" in text  # drawn at once (later updates are throttled to 0.1 s)
    assert (
        text.splitlines()[-1].split("\r")[-1].startswith("registration: compiled in ")
    )  # the bar cleared first


def test_sources_are_compiled_one_by_one_largest_first_then_linked(cc, tmp_path, monkeypatch):
    calls = []
    real = subprocess.run

    def record(argv, **kwargs):
        calls.append(argv)
        return real(argv, **kwargs)

    monkeypatch.setattr(build.subprocess, "run", record)
    monkeypatch.setattr(build, "build_workers", lambda: 1)  # one at a time: the order is the submission order
    _build(cc, tmp_path, monkeypatch, io.StringIO())
    compiled = [argv[argv.index("-c") + 1].rsplit("/", 1)[-1] for argv in calls if "-c" in argv]
    assert compiled == ["_tracker.c", "_batch.c", "larger.c", "tiny.c"]  # by size, the drivers largest here
    assert "-shared" in calls[-1] and "-c" not in calls[-1]


def test_a_failed_compilation_names_the_error_and_publishes_nothing(cc, tmp_path, monkeypatch):
    with pytest.raises(_codegen.ArtifactError, match="C compilation failed"):
        _build(cc, tmp_path, monkeypatch, io.StringIO(), [("broken.c", b"this is not C\n")])
    assert not (tmp_path / "cache" / "key" / "lib.so").exists()
    assert list((tmp_path / "cache" / "key").iterdir()) == []  # its temporary folder is gone too


def test_build_workers_is_the_cpus_this_process_may_use():
    assert build.build_workers() >= 1
