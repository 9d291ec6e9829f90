"""Ctrl-C and SIGTERM held back while a run's outputs are being published.

Publication is a few renames (:func:`registration.io.output.outfolder.publish`); stopped in the
middle, ``--out`` would hold some new files and some old ones until the next run completes the
move. :func:`deferred_signals` holds SIGINT and SIGTERM for those renames, then acts on them:
SIGINT raises :class:`InterruptedAfterPublishing` (a ``KeyboardInterrupt`` that says the outputs
are whole, so the message printed can tell the truth), SIGTERM is raised again with the handler
that was there before. A SIGKILL cannot be held; the marker left in ``--out`` covers it.

For the crash tests, the environment variable ``REGISTRATION_PUBLISH_HOOK=SIGNAL:STEP`` (e.g.
``KILL:2``, ``INT:0``) makes the process send itself ``SIGNAL`` just before rename number ``STEP``
of a publication (:func:`publication_step`); unset, it does nothing.
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
from collections.abc import Iterator

__all__ = ["InterruptedAfterPublishing", "deferred_signals", "publication_step", "HOOK_ENV"]

#: The test hook: ``SIGNAL:STEP`` (signal name without ``SIG``, rename number from 0).
HOOK_ENV = "REGISTRATION_PUBLISH_HOOK"
_HELD = (signal.SIGINT, signal.SIGTERM)


class InterruptedAfterPublishing(KeyboardInterrupt):
    """Ctrl-C arrived while the outputs were being published: they were published whole first."""


@contextlib.contextmanager
def deferred_signals() -> Iterator[None]:
    """Hold SIGINT and SIGTERM for the block (in the main thread; elsewhere signals cannot arrive),
    then act on what arrived: SIGINT raises :class:`InterruptedAfterPublishing`, SIGTERM is sent
    again to the handler that was there before."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    received: list[int] = []

    def hold(signum, frame) -> None:
        received.append(signum)

    previous = {s: signal.signal(s, hold) for s in _HELD}
    try:
        yield
    finally:
        for s, before in previous.items():
            signal.signal(s, before if before is not None else signal.SIG_DFL)
    if signal.SIGTERM in received:
        signal.raise_signal(signal.SIGTERM)
    if signal.SIGINT in received and previous[signal.SIGINT] is signal.default_int_handler:
        raise InterruptedAfterPublishing
    handler = previous[signal.SIGINT]
    if signal.SIGINT in received and callable(handler) and handler is not signal.default_int_handler:
        handler(signal.SIGINT, None)


def publication_step(step: int) -> None:
    """The crash-test hook, called before rename ``step`` of a publication: with
    ``REGISTRATION_PUBLISH_HOOK=SIGNAL:STEP`` set and ``STEP == step``, send ``SIGNAL`` to this
    process. Does nothing otherwise."""
    hook = os.environ.get(HOOK_ENV)
    if not hook:
        return
    name, _, at = hook.partition(":")
    if at.strip() == str(step):
        os.kill(os.getpid(), getattr(signal, "SIG" + name.strip().upper()))
