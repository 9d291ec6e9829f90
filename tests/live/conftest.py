"""Fixtures of the live page's browser tests: one headless Chromium per test module (started only
when a test asks for it) and a fresh page, in a fresh context at 1280x800, for each test.

While Playwright's sync API runs it holds an asyncio event loop as the main thread's running loop:
``asyncio.run`` in the main thread fails until the browser closes. Hence one browser per module, not
per session (a later module's ``asyncio.run`` would fail), and a service under test that uses asyncio
must run its loop in a thread of its own."""

from __future__ import annotations

import pytest

from tests.live.browser import LAUNCH_ARGS, VIEWPORT, chromium_path, why_no_browser


@pytest.fixture(scope="module")
def chromium_browser():
    """The system Chromium under Playwright; the test skips, saying why, where there is none."""
    reason = why_no_browser()
    if reason:
        pytest.skip(reason)
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=chromium_path(), args=LAUNCH_ARGS)
        yield browser
        browser.close()


@pytest.fixture
def browser_page(chromium_browser):
    """A Playwright page of its own (fresh cookies, cache and storage), closed after the test."""
    context = chromium_browser.new_context(viewport=VIEWPORT)
    page = context.new_page()
    page.set_default_timeout(5000)
    yield page
    context.close()
