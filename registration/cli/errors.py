"""Exit codes and error reporting shared by every ``registration`` sub-command.

Every failure the user can cause or meet (a bad option, an unreadable input, an unwritable output,
Ctrl-C, a closed pipe) ends with at most one line on standard error (at most :data:`MAX_MESSAGE`
characters: a longer message names a file holding the whole) and one of these exit codes;
``REGISTRATION_DEBUG=1`` in the environment adds the Python traceback.

====  ==========================================================================================
code  meaning
====  ==========================================================================================
0     success
1     ``register --validate-only``: some rows are bad (listed on standard output)
2     bad input: an invalid option or value, an input that cannot be read, an output that cannot
      be written (the message names the option or the path)
3     the run finished and wrote its outputs, but its normalised innovations (a fleet run: its
      residuals) grossly contradict the model (the consistency gate; see
      :mod:`registration.core.consistency`);
      ``--allow-inconsistent`` accepts such a run with exit code 0
4     internal numerical error: a computation failed in a way the checks did not foresee (for
      example a matrix that cannot be inverted); not a fault of the input as such. Please report
      it with the traceback that ``REGISTRATION_DEBUG=1`` shows
130   interrupted (Ctrl-C); --out is left as it was (a new one is not left behind)
141   standard output was closed early (e.g. piped into ``head``): the command stops quietly,
      like a program ended by SIGPIPE (128 + 13)
143   terminated (SIGTERM, 128 + 15): temporary folders removed, --out left as it was
====  ==========================================================================================
"""

from __future__ import annotations

import argparse
import os
import re
import sys
import tempfile
import traceback
from contextlib import contextmanager
from pathlib import Path

__all__ = [
    "EXIT_OK",
    "EXIT_BAD_ROWS",
    "EXIT_BAD_INPUT",
    "EXIT_INCONSISTENT",
    "EXIT_NUMERICAL",
    "EXIT_INTERRUPTED",
    "EXIT_BROKEN_PIPE",
    "EXIT_TERMINATED",
    "DEBUG_ENV",
    "EXIT_CODES_EPILOG",
    "MAX_MESSAGE",
    "short_message",
    "CODE_OPTIONS",
    "exit_codes_epilog",
    "CommandError",
    "os_error_message",
    "writing",
    "prepare_out",
    "add_allow_inconsistent",
    "consistency_line",
    "consistency_gate",
    "interrupt_message",
    "is_numerical",
    "numerical_message",
    "run_guarded",
]

EXIT_OK = 0
EXIT_BAD_ROWS = 1
EXIT_BAD_INPUT = 2
EXIT_INCONSISTENT = 3
EXIT_NUMERICAL = 4
EXIT_INTERRUPTED = 130
EXIT_BROKEN_PIPE = 141
EXIT_TERMINATED = 143

#: Set this environment variable to 1 to see the traceback behind an error message.
DEBUG_ENV = "REGISTRATION_DEBUG"

#: The exit-code table as shown at the end of ``--help``.
EXIT_CODES_EPILOG = f"""exit codes:
  {EXIT_OK:<4} success
  {EXIT_BAD_ROWS:<4} register --validate-only: some rows are bad
  {EXIT_BAD_INPUT:<4} bad input: an invalid option or value, an unreadable input, an unwritable output
  {EXIT_INCONSISTENT:<4} the run's consistency check (normalised innovations, or residuals for a fleet
       run) says the data grossly contradict the model (outputs written; --allow-inconsistent
       accepts the run)
  {EXIT_NUMERICAL:<4} internal numerical error (e.g. a matrix that cannot be inverted): not bad input; please
       report it with the traceback {DEBUG_ENV}=1 shows
  {EXIT_INTERRUPTED:<4} interrupted (Ctrl-C)
  {EXIT_BROKEN_PIPE:<4} standard output closed early (e.g. piped into head)
  {EXIT_TERMINATED:<4} terminated (SIGTERM): temporary folders removed, outputs not half-written
{DEBUG_ENV}=1 in the environment shows the traceback behind an error message."""
#: Exit codes only some commands can give, with the option (its argparse dest) of those that can.
CODE_OPTIONS = {EXIT_BAD_ROWS: "validate_only", EXIT_INCONSISTENT: "allow_inconsistent"}


def exit_codes_epilog(leave_out=()) -> str:
    """:data:`EXIT_CODES_EPILOG` without the entries of the codes in ``leave_out`` (a command's own table)."""
    lines, skip = [], False
    for line in EXIT_CODES_EPILOG.splitlines():
        code = line[2:].split(" ", 1)[0]
        if line.startswith("  ") and code.isdigit():  # an entry; its continuation lines are indented further
            skip = int(code) in leave_out
        elif not line.startswith("   "):
            skip = False
        if not skip:
            lines.append(line)
    return "\n".join(lines)


class CommandError(Exception):
    """An error the user can fix; ``main`` prints its message as one line and exits with ``code``."""

    def __init__(self, message: str, code: int = EXIT_BAD_INPUT):
        super().__init__(message)
        self.code = code


def os_error_message(exc: OSError) -> str:
    """``PATH: reason`` for an operating-system error, e.g. ``data.csv: No such file or directory``."""
    reason = exc.strerror or str(exc) or type(exc).__name__
    if exc.filename is None:
        return reason
    target = os.fsdecode(exc.filename)
    if exc.filename2 is not None:
        target += f" -> {os.fsdecode(exc.filename2)}"
    return f"{target}: {reason}"


@contextmanager
def writing(path):
    """Turn an operating-system error inside the block into ``CommandError('cannot write PATH: reason')``.

    PATH is the file the error names, else ``path``.
    """
    try:
        yield
    except BrokenPipeError:
        raise
    except OSError as exc:
        target = os.fsdecode(exc.filename) if exc.filename is not None else path
        raise CommandError(f"cannot write {target}: {exc.strerror or exc}") from exc


def prepare_out(out) -> Path:
    """Check that the output folder ``out`` can be created (with its parents) and written in.

    Called before the work starts, so an unusable ``--out`` fails at once with exit code 2. The
    folders made for the check are removed again: the run creates ``out`` when it publishes its
    outputs, so a run that fails aimed at a new folder leaves none behind.
    """
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise CommandError(f"cannot use {out} as the output folder: it exists and is not a folder (--out)")
    created = [p for p in (out, *out.parents) if not p.exists()]  # deepest first
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise CommandError(f"cannot create the output folder {out}: {exc.strerror or exc} (--out)") from exc
    try:
        with tempfile.TemporaryFile(dir=out):
            pass
    except OSError as exc:
        raise CommandError(f"cannot write in the output folder {out}: {exc.strerror or exc} (--out)") from exc
    finally:
        for folder in created:
            try:
                folder.rmdir()
            except OSError:
                break
    return out


def add_allow_inconsistent(p: argparse.ArgumentParser) -> None:
    """The ``--allow-inconsistent`` flag of every command that runs the consistency gate."""
    p.add_argument(
        "--allow-inconsistent",
        action="store_true",
        help="exit 0 even when the normalised innovations grossly contradict the model "
        f"(otherwise exit code {EXIT_INCONSISTENT} after writing the outputs)",
    )


def consistency_line(report) -> str:
    """The report line every command with a consistency gate prints on standard output: the figures
    and the verdict. A failed gate's likely causes are left to :func:`consistency_gate`, on
    standard error, so they are printed once."""
    text = report.message()
    if not report.ok:
        text = text.split("; the data do not fit the model")[0]
    return f"consistency: {text}"


def consistency_gate(prog: str, report, allow: bool) -> int:
    """The exit code of a run with a :class:`~registration.core.consistency.ConsistencyReport`.

    Call it after the outputs are written. A grossly inconsistent run gives :data:`EXIT_INCONSISTENT`
    with the report (and its likely causes) on standard error, unless ``allow``: then a warning and 0.
    """
    if report.ok:
        return EXIT_OK
    if allow:
        print(
            f"{prog}: warning: inconsistent run accepted (--allow-inconsistent): {report.message()}",
            file=sys.stderr,
        )
        return EXIT_OK
    verdict, _, causes = report.message().partition(" Likely causes: ")
    print(  # on lines of at most MAX_MESSAGE characters
        f"{prog}: error: {verdict} Give --allow-inconsistent to accept the run (exit code "
        f"{EXIT_INCONSISTENT}).",
        file=sys.stderr,
    )
    if causes:
        print(f"Likely causes: {causes}", file=sys.stderr)
    return EXIT_INCONSISTENT


def interrupt_message(prog: str, args: argparse.Namespace | None) -> str:
    """What Ctrl-C prints: where it stopped and, for a run with ``--checkpoint FILE``, how to resume.

    Called once the run has unwound, so ``--out`` holds what it held before the run (a new one
    is gone again): the message says whether there were earlier outputs."""
    checkpoint = getattr(args, "checkpoint", None)
    if checkpoint:
        return f"{prog}: interrupted; rerun the same command to resume from its checkpoint {checkpoint}"
    out = getattr(args, "out", None)
    if not out:
        return f"{prog}: interrupted"
    if Path(out).is_dir() and any(Path(out).iterdir()):
        return f"{prog}: interrupted; nothing was written: {out} keeps what it held before"
    return f"{prog}: interrupted; nothing was written (no earlier outputs in {out})"


def is_numerical(exc: BaseException) -> bool:
    """True for a numerical failure (ArithmeticError, numpy's LinAlgError, which is a ValueError):
    an internal error, reported with :data:`EXIT_NUMERICAL`, not as bad input."""
    if isinstance(exc, ArithmeticError):
        return True
    np = sys.modules.get("numpy")
    return np is not None and isinstance(exc, np.linalg.LinAlgError)


def numerical_message(exc: BaseException) -> str:
    """The one line of an internal numerical error: what failed, and how to report it."""
    what = str(exc) or type(exc).__name__
    return (
        f"internal numerical error ({type(exc).__name__}): {what}. This is not a fault of the input as such; "
        f"please report it, with the traceback that {DEBUG_ENV}=1 shows (exit code {EXIT_NUMERICAL})"
    )


def _after_publishing(exc: BaseException) -> bool:
    """Ctrl-C held back while the outputs were published, so they are whole (not a lost run)."""
    signals = sys.modules.get("registration.io.output.signals")
    return signals is not None and isinstance(exc, signals.InterruptedAfterPublishing)


def _debug() -> bool:
    return os.environ.get(DEBUG_ENV, "").strip() not in ("", "0")


#: The longest error line printed (characters); a longer message (a list of every excluded target)
#: is cut, and the whole of it written to a file the line names.
MAX_MESSAGE = 300


def short_message(line: str) -> str:
    """``line`` if at most :data:`MAX_MESSAGE` characters long (a path counted as a word), else its
    start (cut after a ``;`` or ``,`` where one is near) and the name of a file holding the whole.
    The file is a new one in the system's temporary folder, so a failed run leaves --out as it was."""
    paths = sum(len(m) - 4 for m in re.findall(r"(?:[A-Za-z]:)?[/\\][^\s:'\",;()]+", line))
    if len(line) - paths <= MAX_MESSAGE:
        return line  # the paths it names are counted as one word: their length is not the message's
    fd, name = tempfile.mkstemp(prefix="registration-error-", suffix=".txt")
    with os.fdopen(fd, "w") as f:
        f.write(line + "\n")
    tail = f" ... (the whole message, {len(line)} characters: {name})"
    head = line[: max(MAX_MESSAGE - len(tail), 40) + paths]
    cut = max(head.rfind("; "), head.rfind(", "))
    return (head[:cut] if cut > len(head) // 2 else head) + tail


def _fail(prog: str, message: str, code: int) -> int:
    if _debug():
        traceback.print_exc()
    print(short_message(f"{prog}: error: {message}"), file=sys.stderr)
    return code


def _silence_stdout() -> None:
    """Point standard output at the null device so the interpreter's final flush cannot fail again."""
    try:
        fd = sys.stdout.fileno()
    except (AttributeError, OSError, ValueError):
        return  # not a real file (captured output): nothing left to flush
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, fd)
    os.close(devnull)


def run_guarded(prog: str, run, args: argparse.Namespace, hint=None) -> int:
    """``run(args)`` with every expected failure turned into one line on standard error and an exit code.

    ``hint(args)``, if given, may return the text Ctrl-C prints (e.g. how to resume); None falls
    back to :func:`interrupt_message`. Other exceptions are bugs and keep their traceback.
    """
    try:
        return int(run(args) or 0)
    except BrokenPipeError:
        _silence_stdout()
        return EXIT_BROKEN_PIPE
    except KeyboardInterrupt as exc:
        if _debug():
            traceback.print_exc()
        if _after_publishing(exc):
            out = getattr(args, "out", None)
            text = f"{prog}: interrupted once the outputs were published: {out} holds this run's outputs"
        else:
            text = (hint(args) if hint else None) or interrupt_message(prog, args)
        # on a line of its own: a progress bar may have left the cursor at the end of its line
        print("\n" + text, file=sys.stderr)
        return EXIT_INTERRUPTED
    except CommandError as exc:
        return _fail(prog, str(exc), exc.code)
    except OSError as exc:
        return _fail(prog, os_error_message(exc), EXIT_BAD_INPUT)
    except (ArithmeticError, ValueError) as exc:  # numpy's LinAlgError is a ValueError
        if is_numerical(exc):
            return _fail(prog, numerical_message(exc), EXIT_NUMERICAL)
        return _fail(prog, str(exc), EXIT_BAD_INPUT)
