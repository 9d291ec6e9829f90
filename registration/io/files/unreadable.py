"""The one error for a file that cannot be read: one line naming the file, what could not be done
and why (:func:`read_error`), for every reader (table files, recordings, captures, logs)."""

from __future__ import annotations

__all__ = ["one_line", "read_error"]


def one_line(exc: BaseException) -> str:
    """An error's text on one line: an operating-system error's ``strerror`` (without the file
    name the message already gives), else its text with all whitespace runs made one space (its
    type's name when it has no text)."""
    if isinstance(exc, OSError) and exc.strerror:
        return exc.strerror
    return " ".join(str(exc).split()) or type(exc).__name__


def read_error(
    path, exc: BaseException, doing: str = "cannot be read", error: type[Exception] = ValueError
) -> Exception:
    """The error to raise (``from exc``) when file ``path`` cannot be read: an ``error`` (a
    ValueError, or a subclass such as a reader's own) with the message ``PATH: DOING: REASON``,
    REASON :func:`one_line` of ``exc``; e.g. ``raise read_error(path, exc, "cannot read it as CSV")
    from exc``."""
    return error(f"{path}: {doing}: {one_line(exc)}")
