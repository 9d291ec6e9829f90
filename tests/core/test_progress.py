"""The one rule for progress bars: shown only when asked and standard error is a terminal, first
drawn after PROGRESS_DELAY_S; a silent stand-in otherwise, with the same methods."""

from __future__ import annotations

import io

import registration.core.progress as progress
from registration.core.progress import progress_bar, progress_status, stderr_is_terminal


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_no_bar_unless_asked_and_on_a_terminal(monkeypatch, capsys):
    monkeypatch.setattr(progress, "PROGRESS_DELAY_S", 0.0)
    with progress_bar(True, "captured", total=3) as bar:  # asked, but stderr is no terminal
        bar.update(3)
        progress_status(bar, "status")
        assert bar.disable
    assert capsys.readouterr().err == ""
    terminal = _Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    assert stderr_is_terminal()
    with progress_bar(False, "not asked", total=3) as bar:
        bar.update(3)
        assert bar.disable
    assert terminal.getvalue() == ""
    with progress_bar(True, "shown", total=3, unit="file") as bar:
        bar.update(1)
        progress_status(bar, "the status")
        assert not bar.disable
    assert "shown" in terminal.getvalue() and "the status" in terminal.getvalue()


def test_short_work_draws_nothing_before_the_delay(monkeypatch):
    terminal = _Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    with progress_bar(True, "short", total=3) as bar:  # PROGRESS_DELAY_S (1 s) not reached
        bar.update(3)
        assert not bar.disable
    assert terminal.getvalue().strip() == ""


def test_a_bar_over_an_iterable_yields_its_items(monkeypatch):
    assert list(progress_bar(True, "items", iterable=[1, 2, 3])) == [1, 2, 3]
    monkeypatch.setattr("sys.stderr", _Terminal())
    assert list(progress_bar(True, "items", iterable=range(4))) == [0, 1, 2, 3]


def test_a_stream_without_isatty_is_no_terminal(monkeypatch):
    monkeypatch.setattr("sys.stderr", object())
    assert not stderr_is_terminal()
