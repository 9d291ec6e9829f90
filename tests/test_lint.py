"""Lint and types, as CI runs them: ruff (pycodestyle, pyflakes, import order, 110 columns) and the
ruff formatter on the whole tree, mypy on registration/ (configuration in pyproject.toml). Each
test fails with the tool's own report, so the fix is the tool's first line."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _run(*command: str) -> subprocess.CompletedProcess:
    return subprocess.run(command, cwd=ROOT, capture_output=True, text=True, timeout=600)


def _ruff() -> str:
    found = shutil.which("ruff")
    if found is None:
        pytest.skip("ruff is not installed (it is in the test extra: pip install -e '.[test]')")
    return found


def test_ruff_finds_nothing():
    done = _run(_ruff(), "check", "--no-cache", ".")
    assert done.returncode == 0, done.stdout + done.stderr


def test_the_tree_is_formatted():
    done = _run(_ruff(), "format", "--check", "--no-cache", ".")
    assert done.returncode == 0, done.stdout + done.stderr


def test_mypy_finds_nothing_in_the_package():
    """mypy keeps its incremental cache where it does when run by hand (.mypy_cache, ignored by
    git): a first run checks the whole package (about 22 s of CPU), a run after small changes
    re-checks what they touch (about 3 s)."""
    pytest.importorskip("mypy", reason="mypy is in the test extra: pip install -e '.[test]'")
    done = _run(sys.executable, "-m", "mypy")
    assert done.returncode == 0, done.stdout + done.stderr
