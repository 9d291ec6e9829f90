"""``registration`` command line: one sub-command per module of this package.

A sub-command module defines ``HELP`` (one line), ``add_arguments(parser)`` and ``run(args) -> int``;
optionally ``interrupt_hint(args) -> str | None``, the text Ctrl-C prints (e.g. how to resume).
Errors, exit codes and the consistency gate: :mod:`registration.cli.errors`; every message starts
with the full command (``registration fleet register: error: ...``), and each command's ``--help``
lists the exit codes it can give (:class:`CommandParser`).
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import signal
import sys
import textwrap
import threading
from collections.abc import Iterator

from registration import __version__
from registration.cli.errors import (
    CODE_OPTIONS,
    EXIT_CODES_EPILOG,
    EXIT_TERMINATED,
    exit_codes_epilog,
    run_guarded,
)
from registration.cli.options import HelpFormatter

#: sub-command name -> module of registration.cli (listed in the order shown in --help)
COMMANDS = {
    "simulate": "simulate",
    "montecarlo": "montecarlo",
    "fuse": "fuse",
    "landing": "landing",
    "schema": "schema",
    "register": "register",
    "fleet": "fleet",
    "import": "importing",
    "serve": "serve",
    "replay": "replay",
}


class CommandParser(argparse.ArgumentParser):
    """The parser of a sub-command (and of its own sub-commands, e.g. ``fleet register``): the
    parsed arguments name the full command (``_prog``, e.g. ``registration fleet register``, the
    prefix of every message), and ``--help`` lists only the exit codes the command can give."""

    subcommands = None  # the action of add_subparsers(), if the command has sub-commands

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.set_defaults(_prog=self.prog)  # a nested sub-command's default replaces its parent's

    def add_subparsers(self, **kwargs):
        self.subcommands = super().add_subparsers(**kwargs)
        return self.subcommands

    def optional_codes(self) -> set[int]:
        """The exit codes of :data:`CODE_OPTIONS` this command, or one of its sub-commands, can give."""
        if self.subcommands is not None:
            return set().union(*(p.optional_codes() for p in self.subcommands.choices.values()))
        return {code for code, dest in CODE_OPTIONS.items() if self.get_default(dest) is not None}

    def format_help(self) -> str:
        if self.epilog == EXIT_CODES_EPILOG:
            self.epilog = exit_codes_epilog(set(CODE_OPTIONS) - self.optional_codes())
        return super().format_help()


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="registration",
        description=textwrap.fill(
            "Register and fuse radar measurements across moving ships "
            "(SI units inside; options in degrees end in _deg)."
        ),
        epilog=EXIT_CODES_EPILOG,
        formatter_class=HelpFormatter,
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND", parser_class=CommandParser)
    for name, module in COMMANDS.items():
        try:
            mod = importlib.import_module(f"registration.cli.{module}")
        except ModuleNotFoundError as exc:
            if exc.name == f"registration.cli.{module}":
                continue  # capability not built yet
            raise
        p = sub.add_parser(
            name,
            help=mod.HELP,
            description=textwrap.fill(mod.HELP),
            epilog=EXIT_CODES_EPILOG,
            formatter_class=HelpFormatter,
        )
        mod.add_arguments(p)
        p.set_defaults(_run=mod.run, _hint=getattr(mod, "interrupt_hint", None))
    return parser


def main(argv: list[str] | None = None) -> int:
    """Run the command line ``argv`` (default: ``sys.argv[1:]``); return the exit code (see ``--help``)."""
    argv = sys.argv[1:] if argv is None else list(argv)
    parser = build_parser()
    if not argv:  # no command: the commands, then exit 2 (a command is required)
        parser.print_help(sys.stderr)
        return 2
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help, --version, or an option argparse rejected (its message is printed)
        return exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 2)
    with _terminate_cleanly():
        return run_guarded(args._prog, args._run, args, args._hint)


@contextlib.contextmanager
def _terminate_cleanly() -> Iterator[None]:
    """SIGTERM ends the command by ``SystemExit(EXIT_TERMINATED)`` rather than at once, so that its
    temporary folders (spilled partitions, converted archives: gigabytes on a long run) are
    removed, local Dask workers stopped and no output half-written (publication holds the signal
    until its renames are done). Commands that stop gracefully on SIGTERM (``serve``, ``replay``)
    set their own handler inside. The previous handler comes back afterwards."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def stop(signum, frame) -> None:
        raise SystemExit(EXIT_TERMINATED)

    previous = signal.signal(signal.SIGTERM, stop)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous if previous is not None else signal.SIG_DFL)


if __name__ == "__main__":
    sys.exit(main())
