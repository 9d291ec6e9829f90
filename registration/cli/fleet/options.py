"""The options of ``registration fleet simulate`` and ``fleet register``: :func:`add_arguments`.
The input-table options' help comes from the fleet files' schemas
(:func:`registration.io.fleet.schema.option_help`), so the help, the reader and
docs/reference/fleet-tables.md say the same."""

from __future__ import annotations

import argparse
import textwrap
from pathlib import Path

from registration.cli.errors import EXIT_CODES_EPILOG, add_allow_inconsistent
from registration.cli.options import HelpFormatter, add_no_plots, add_out, add_seed
from registration.io.fleet.folder import TABLE_NAMES
from registration.io.fleet.schemadoc import option_help

__all__ = ["REGISTER_HELP", "SIMULATE_HELP", "add_arguments"]

SIMULATE_HELP = (
    "simulate the built-in fleet (3 ships, a shore site, 6 sensors, 5 targets), register it (in one "
    "batch, or online with --method online), and write its input tables as a working example for "
    "`fleet register`"
)
REGISTER_HELP = (
    "register a fleet from plots, navigation and sensors tables (CSV or Parquet, degrees and metres; "
    "see docs/reference/fleet-files.md)"
)

#: The options of `fleet simulate` after --seed, --method, --out and --no-plots: (flag, type, default,
#: metavar, help); type None: a choice of the file format.
_SIMULATE = (
    (
        "--duration-s",
        float,
        300.0,
        "S",
        "length of the simulated recording, s (targets leaving a sensor's coverage are not plotted)",
    ),
    (
        "--targets",
        int,
        None,
        "N",
        "N random targets circling in the area, the first a reference target (default: the built-in five)",
    ),
)
#: Its extended sensor errors, in their own group (each estimated without prior).
_EXTENDED = (
    (
        "--range-gain-ppm",
        "PPM",
        "give every sensor with range a range gain of +-PPM (random signs), estimated without prior",
    ),
    (
        "--time-bias-s",
        "S",
        "give every sensor a time bias (reported - true plot time) of +-S s, estimated without prior",
    ),
    (
        "--position-error-m",
        "M",
        "give every sensor a position error (stated - true) of +-M m per east, "
        "north and up axis, estimated without prior",
    ),
)


def _parser(sub, name: str, text: str) -> argparse.ArgumentParser:
    return sub.add_parser(
        name,
        help=text,
        description=textwrap.fill(text),
        epilog=EXIT_CODES_EPILOG,
        formatter_class=HelpFormatter,
    )


def _add_method(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--method",
        choices=("batch", "online"),
        default="batch",
        help="batch: maximum likelihood over all plots at once; online: the filter, one update per "
        "window of plots, with the estimates over time in history.csv (docs/background/fleet-online.md); "
        "plots without "
        "target ids are first associated by the batch, then filtered with the labels it gave",
    )


def _add_simulate(sim: argparse.ArgumentParser) -> None:
    add_seed(sim, 0)
    _add_method(sim)
    add_out(sim, "fleet-simulate", "the input tables, estimates.csv, summary.json and the PNG plots")
    add_no_plots(sim)
    sim.add_argument(
        "--format", choices=("csv", "parquet"), default="csv", help="file format of the tables written"
    )
    for flag, kind, default, metavar, text in _SIMULATE:
        sim.add_argument(flag, type=kind, default=default, metavar=metavar, help=text)
    errors = sim.add_argument_group("extended sensor errors (default: none, and not modelled)")
    for flag, metavar, text in _EXTENDED:
        errors.add_argument(flag, type=float, default=None, metavar=metavar, help=text)
    add_allow_inconsistent(sim)


def _add_tables(reg: argparse.ArgumentParser) -> None:
    """--tables DIR and one option per table, whose help is the table's schema."""
    files = reg.add_argument_group(
        "input tables (.csv or .parquet): --tables DIR, or --plots, --navigation and "
        "--sensors (each overriding the folder's file)"
    )
    files.add_argument(
        "--tables",
        type=Path,
        default=None,
        metavar="DIR",
        help=f"a folder holding the tables by their standard names ({', '.join(TABLE_NAMES)}; .csv or "
        ".parquet), as 'registration import' writes them",
    )
    for name in TABLE_NAMES:
        files.add_argument(f"--{name}", type=Path, default=None, metavar="FILE", help=option_help(name))


def _add_register(reg: argparse.ArgumentParser) -> None:
    from registration.cli.fleet.archive import add_archive_arguments
    from registration.cli.fleet.periods import add_period_argument

    _add_tables(reg)
    reg.add_argument(
        "--cat063",
        type=Path,
        metavar="FILE.ast",
        help="also write the estimates as ASTERIX CAT063 sensor status messages (one record per radar, "
        "SAC/SIC 25/200 as sender; the radars' SAC/SIC from the import_summary.json of --tables DIR)",
    )
    reg.add_argument(
        "--window-s",
        type=float,
        default=20.0,
        metavar="S",
        help="length of the windows each target track is cut into, s (0: one per instant); the "
        "online filter updates once per window",
    )
    _add_method(reg)
    add_period_argument(reg)
    reg.add_argument(
        "--on-bad-row",
        choices=["stop", "skip"],
        default="stop",
        help="stop at the first bad row of the plots (then the reference) file, or skip: set bad rows "
        "aside in rejected.csv (file, row, column, reason_code, reason) and register the rest",
    )
    add_out(reg, "fleet-register", "estimates.csv, summary.json and the PNG plots")
    add_no_plots(reg)
    add_allow_inconsistent(reg)
    add_archive_arguments(reg)


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The actions of ``registration fleet``: ``simulate`` and ``register``, with their options."""
    sub = p.add_subparsers(dest="action", required=True, metavar="ACTION")
    _add_simulate(_parser(sub, "simulate", SIMULATE_HELP))
    _add_register(_parser(sub, "register", REGISTER_HELP))
