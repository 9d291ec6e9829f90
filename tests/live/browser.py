"""Headless Chromium for the live page's tests: the distribution's ``chromium`` driven by Playwright
(the PyPI package; never ``playwright install``, never a downloaded browser), plus the checks every
page test wants: no request to any host but the server's, and no console error."""

from __future__ import annotations

import importlib.util
import shutil
from dataclasses import dataclass, field
from typing import Any

# As root on a machine without internet: no sandbox (it needs an unprivileged user), no GPU, and none
# of the background traffic (QUIC, component updates, sync) a fresh profile would start. Playwright
# gives every launch a fresh temporary --user-data-dir and removes it when the browser closes.
LAUNCH_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]
NO_CHROMIUM = "no chromium: install the distribution's chromium package"
NO_PLAYWRIGHT = "no playwright: install the test extra (pip install -e '.[test]')"
VIEWPORT = {"width": 1280, "height": 800}


def chromium_path() -> str | None:
    """The system browser, or None."""
    return shutil.which("chromium")


def why_no_browser() -> str | None:
    """The reason the browser tests cannot run here, or None when they can."""
    if importlib.util.find_spec("playwright") is None:
        return NO_PLAYWRIGHT
    if chromium_path() is None:
        return NO_CHROMIUM
    return None


@dataclass
class PageWatch:
    """What a page did that a test forbids: requests to another host (aborted) and console errors."""

    origin: str
    foreign: list[str] = field(default_factory=list)
    errors: list[str] = field(default_factory=list)


def watch(page: Any, origin: str) -> PageWatch:
    """Abort and record every request of ``page`` not to ``origin`` (``http://127.0.0.1:PORT``), and
    record console errors and uncaught exceptions. Call before ``page.goto``."""
    seen = PageWatch(origin.rstrip("/"))

    def route(r: Any) -> None:
        url = r.request.url
        if url == seen.origin or url.startswith(seen.origin + "/") or url.startswith("data:"):
            r.continue_()
        else:
            seen.foreign.append(url)
            r.abort()

    page.route("**/*", route)
    page.on("console", lambda m: seen.errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: seen.errors.append(f"uncaught: {e}"))
    return seen
