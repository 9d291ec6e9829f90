"""Every ```python block of the README and docs/ runs as written.

A page's blocks run in order in one namespace, as a doctest session would: a later block may use
what an earlier one on the same page made (docs/howto/stonesoup.md reads that way), never what
another page made. Each page runs in a fresh temporary folder that holds ``examples`` (a link to the
repository's examples/), so a block reads the shipped sample data as ``examples/...`` and writes
what it writes there. Figures use matplotlib's Agg backend.

A block that must not run is marked in its fence, ```python no-run (output shown as Python, or a
block that needs a network); :data:`NO_RUN` counts them, so that a new one is a decision seen in
review."""

from __future__ import annotations

import os
import re
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
#: The blocks marked ```python no-run, by page (none now).
NO_RUN: dict[str, int] = {}
#: A fence that opens a Python block, and its info words.
FENCE = re.compile(r"^```python(?P<info>[^\n`]*)\n(?P<code>.*?)^```\s*$", re.M | re.S)


def pages() -> list[Path]:
    return [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]


def blocks(page: Path) -> list[tuple[int, str, bool]]:
    """(line, code, runs) of each ```python block of the page."""
    text = page.read_text(encoding="utf-8")
    out = []
    for m in FENCE.finditer(text):
        info = m.group("info").split()
        out.append((text.count("\n", 0, m.start()) + 1, m.group("code"), "no-run" not in info))
    return out


def _name(page: Path) -> str:
    return page.relative_to(ROOT).as_posix()


PAGES = [p for p in pages() if blocks(p)]


def test_every_python_fence_is_found():
    """The parser sees every fence that opens a Python block (an unclosed one would hide the rest)."""
    for page in pages():
        opened = len(re.findall(r"^```python", page.read_text(encoding="utf-8"), re.M))
        assert len(blocks(page)) == opened, _name(page)
    assert sum(len(blocks(p)) for p in PAGES) >= 13


def test_the_blocks_that_do_not_run_are_counted():
    found = {_name(p): n for p in PAGES if (n := sum(not runs for _, _, runs in blocks(p)))}
    assert found == NO_RUN


@pytest.mark.parametrize("page", PAGES, ids=_name)
def test_the_page_runs(page, tmp_path, monkeypatch):
    import matplotlib

    matplotlib.use("Agg")
    os.symlink(ROOT / "examples", tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    namespace: dict = {"__name__": "__docs__"}
    t0 = time.perf_counter()
    for line, code, runs in blocks(page):
        if runs:
            exec(compile(code, f"{_name(page)}:{line}", "exec"), namespace)  # noqa: S102
    assert time.perf_counter() - t0 < 20.0, "keep the examples on tiny data"
