"""The options every ``registration`` sub-command spells the same way, and the help layout.

Each option's help states its unit; :class:`HelpFormatter` appends the default, so a default is
written in one place only (the ``add_argument`` call).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

__all__ = ["HelpFormatter", "add_out", "add_no_plots", "add_seed", "add_dask", "check_dask", "OUT_ROOT"]

#: ``--out`` defaults to OUT_ROOT/<command> (relative to the working folder).
OUT_ROOT = Path("out")


class HelpFormatter(argparse.RawDescriptionHelpFormatter, argparse.ArgumentDefaultsHelpFormatter):
    """Appends ``(default: X)`` to an option's help, except for on/off flags, options whose default
    is None (their help says what happens without them) and help texts that already state a default.
    Description and epilog are printed as written (wrap them with :func:`textwrap.fill`)."""

    def _get_help_string(self, action: argparse.Action) -> str:
        text = action.help or ""
        default = action.default
        if (
            not action.option_strings
            or default is None
            or isinstance(default, bool)
            or (isinstance(default, list) and not default)
            or default is argparse.SUPPRESS
            or "default" in text.lower()
        ):
            return text
        return text + (
            " (default: %(default).6g)" if isinstance(default, float) else " (default: %(default)s)"
        )


def add_out(p: argparse.ArgumentParser, command: str, what: str = "summary.json and the PNG plots") -> None:
    """``--out DIR``, default ``out/<command>``; the folder is created."""
    p.add_argument(
        "--out",
        type=Path,
        default=OUT_ROOT / command,
        metavar="DIR",
        help=f"output folder for {what} (created if missing)",
    )


class _DeprecatedFlag(argparse.Action):
    """A hidden old spelling of a flag: sets the same destination and warns once on standard error."""

    def __init__(self, option_strings, dest, new: str, **kwargs):
        super().__init__(
            option_strings, dest, nargs=0, default=argparse.SUPPRESS, help=argparse.SUPPRESS, **kwargs
        )
        self.new = new

    def __call__(self, parser, namespace, values, option_string=None):
        print(f"{parser.prog}: warning: {option_string} is deprecated; use {self.new}", file=sys.stderr)
        setattr(namespace, self.dest, True)


def add_no_plots(p: argparse.ArgumentParser, old_spelling: str | None = None) -> None:
    """``--no-plots`` (skip the PNG files); ``old_spelling`` is accepted, hidden, with a warning."""
    p.add_argument("--no-plots", action="store_true", help="skip the PNG plots")
    if old_spelling:
        p.add_argument(old_spelling, dest="no_plots", action=_DeprecatedFlag, new="--no-plots")


def add_seed(
    p: argparse.ArgumentParser, default: int, what: str = "random seed of the measurement noise"
) -> None:
    """``--seed N`` (an integer)."""
    p.add_argument("--seed", type=int, default=default, metavar="N", help=what)


def add_dask(p: argparse.ArgumentParser, chunks: str) -> None:
    """``--scheduler ADDRESS`` and ``--workers N``: run the ``chunks`` on a dask cluster (optional extra)."""
    g = p.add_argument_group('parallel and distributed runs (needs dask: pip install "dask[distributed]")')
    g.add_argument(
        "--scheduler",
        default=None,
        metavar="ADDRESS",
        help=f"run the {chunks} on the dask.distributed scheduler at ADDRESS, e.g. tcp://host:8786 "
        "(default: in this process)",
    )
    g.add_argument(
        "--workers",
        type=int,
        default=None,
        metavar="N",
        help=f"run the {chunks} on a local dask cluster of N worker processes, one thread each "
        "(default: in this process)",
    )


def check_dask(args: argparse.Namespace) -> None:
    """Reject bad ``--scheduler``/``--workers`` values, or a missing dask, before any work (ValueError)."""
    if args.workers is not None and args.workers < 1:
        raise ValueError(f"--workers: expected at least 1 worker, got {args.workers}")
    if args.scheduler and args.workers:
        raise ValueError("--scheduler, --workers: give one or the other")
    if args.scheduler or args.workers:
        from registration.core.parallel import require_distributed

        try:
            require_distributed()
        except ImportError as exc:
            raise ValueError(f"--{'scheduler' if args.scheduler else 'workers'}: {exc}") from None
