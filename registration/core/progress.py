"""Progress bars of long work: one rule for when a bar shows.

**The rule.** A bar shows on standard error only when the caller asks for one (``enabled``) *and*
standard error is a terminal, and it is first drawn once the work has run
:data:`PROGRESS_DELAY_S` seconds. Otherwise (a pipe, a log file, a test capturing the output, a
notebook) the bar is tqdm's silent stand-in, with the same methods: the work is the same with or
without a bar, and short runs print nothing. Bars are cleared when they close.

:func:`progress_bar` makes a bar (or iterates with one); :func:`progress_status` shows a line of
text beside it. The generated code's build (``registration._codegen``, below this layer) keeps a
bar of its own with the same rule, drawn at once.
"""

from __future__ import annotations

import sys
from typing import Any, Iterable

__all__ = ["PROGRESS_DELAY_S", "progress_bar", "progress_status", "stderr_is_terminal"]

#: Seconds of work before a bar is first drawn (short work draws none).
PROGRESS_DELAY_S = 1.0


def stderr_is_terminal() -> bool:
    """True when standard error is a terminal (False for a pipe, a file, or a stream without a
    file descriptor)."""
    try:
        return bool(sys.stderr.isatty())
    except (AttributeError, ValueError):
        return False


def progress_bar(
    enabled: bool,
    desc: str,
    total: float | None = None,
    unit: str = "it",
    *,
    iterable: Iterable | None = None,
    initial: float = 0,
    unit_scale: bool = False,
) -> Any:
    """A tqdm bar on standard error by the rule of this module (else a silent stand-in): ``desc``
    its label, ``total`` the amount of work in ``unit`` (None: unknown; with ``iterable``, its
    length), ``initial`` the work already done, ``unit_scale`` for k/M prefixes. With ``iterable``,
    iterate over the bar to advance it; else call ``update``. Use it as a context manager (it
    closes with the block)."""
    from tqdm import tqdm

    return tqdm(
        iterable,
        total=total,
        initial=initial,
        desc=desc,
        unit=unit,
        unit_scale=unit_scale,
        file=sys.stderr,
        disable=not (enabled and stderr_is_terminal()),
        leave=False,
        delay=PROGRESS_DELAY_S,
        dynamic_ncols=True,
        mininterval=0.5,
    )


def progress_status(bar: Any, text: str) -> None:
    """Show ``text`` beside a :func:`progress_bar`: at once when the bar has been up for
    :data:`PROGRESS_DELAY_S` seconds, else with its first drawing (a refresh would draw it early)."""
    bar.set_postfix_str(text, refresh=False)
    if not bar.disable and bar.format_dict["elapsed"] >= PROGRESS_DELAY_S:
        bar.refresh()
