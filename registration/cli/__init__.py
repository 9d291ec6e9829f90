"""``registration`` command line: one sub-command per module of this package."""

from __future__ import annotations

import argparse
import importlib
import sys

#: sub-command name -> module of registration.cli (listed in the order shown in --help)
COMMANDS = {
    "simulate": "simulate",
    "montecarlo": "montecarlo",
    "fuse": "fuse",
    "landing": "landing",
    "schema": "schema",
    "register": "register",
}


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="registration",
        description="Register and fuse radar measurements across moving ships (SI units inside; _deg options at the edge).",
    )
    sub = parser.add_subparsers(dest="command", required=True)
    for name, module in COMMANDS.items():
        try:
            mod = importlib.import_module(f"registration.cli.{module}")
        except ModuleNotFoundError as exc:
            if exc.name == f"registration.cli.{module}":
                continue  # capability not built yet
            raise
        p = sub.add_parser(name, help=mod.HELP, description=mod.HELP)
        mod.add_arguments(p)
        p.set_defaults(_run=mod.run)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return int(args._run(args) or 0)
    except ValueError as exc:  # bad input: a clear message, not a traceback
        print(f"registration {args.command}: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
