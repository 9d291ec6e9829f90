"""``registration import asterix|nmea``: a recording in a real format becomes the fleet tables.

Each importer (:mod:`registration.io.asterix`, :mod:`registration.io.nmea`) turns its inputs into
the fleet tables in their file form (degrees, metres; the columns of docs/reference/fleet-files.md), a table
of
the records it set aside and a summary. This command writes them into ``--out`` by the standard
names, so that ``registration fleet register --tables OUT`` registers them next:

- ``plots``, ``navigation``, ``sensors``, ``platforms``, ``reference`` (``.csv`` or ``.parquet``,
  ``--format``; a table the recording gave no row for is not written);
- ``rejected.csv``: what was set aside and why (file, where in it, reason);
- ``import_summary.json``: counts, time span, and what the format adds (scan periods, vessels).

The folder is published whole: a failed or interrupted import leaves ``--out`` as it was.
"""

from __future__ import annotations

import argparse
import datetime as dt
import sys
import textwrap
from pathlib import Path
from typing import TYPE_CHECKING

from registration.cli.errors import EXIT_CODES_EPILOG, CommandError, prepare_out, writing
from registration.cli.options import HelpFormatter
from registration.cli.staging import staged_outputs

if TYPE_CHECKING:  # imported when the command runs: `registration --help` loads no importer
    from registration.io.imports import ImportResult

__all__ = [
    "HELP",
    "CAT021_EDITIONS",
    "CAT001_EDITIONS",
    "CAT002_EDITIONS",
    "EDITION_OPTIONS",
    "LIMIT_OPTIONS",
    "add_arguments",
    "run",
]

#: The CAT021 editions ``--cat021-edition`` takes (registration.io.asterix.SUPPORTED_EDITIONS[21]).
CAT021_EDITIONS = ("0.23", "0.24", "0.25", "0.26", "2.1", "2.2", "2.3", "2.4", "2.5", "2.6", "2.7")
#: The CAT001 and CAT002 editions ``--cat001-edition``, ``--cat002-edition`` take (SUPPORTED_EDITIONS).
CAT001_EDITIONS = ("1.1", "1.2", "1.3", "1.4")
CAT002_EDITIONS = ("1.0", "1.1", "1.2")
#: Category -> the ``--catNNN-edition`` option's attribute name.
EDITION_OPTIONS = {21: "cat021_edition", 1: "cat001_edition", 2: "cat002_edition"}
#: The bounds of an ASTERIX import given as options (keyword arguments of ``import_asterix``).
LIMIT_OPTIONS = ("max_bytes", "max_records", "max_rejected_rows")
#: The framings ``--framing`` takes (registration.io.asterix.capture.detect.FRAMING_NAMES, and 'final').
FRAMINGS = ("auto", "netto", "gps", "rff", "ioss", "final", "ioss_seq", "oradis", "hdlc")

HELP = (
    "import a recording (ASTERIX, NMEA 0183 with AIS) as the fleet tables that "
    "'fleet register --tables' reads"
)
ASTERIX_HELP = (
    "ASTERIX radar plots (CAT048, CAT001), service messages (CAT034, CAT002) and ADS-B reports "
    "(CAT021) from raw recordings or pcap/pcapng captures, gzip-compressed or not, into plots, "
    "navigation (one row per site), sensors, platforms and reference tables"
)
NMEA_HELP = (
    "an NMEA 0183 bridge log (GGA/RMC/GNS, ZDA, HDT/THS, $PASHR, TTM, !AIVDM) into the platform's "
    "navigation, the ARPA radar's plots (with sensor-local track ids), the AIS vessels as the reference "
    "table, and the sensors and platforms tables"
)


def _date(text: str) -> dt.date:
    try:
        return dt.date.fromisoformat(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a date YYYY-MM-DD (UTC), got {text!r}") from None


def _prior(text: str) -> float:
    if text.strip().lower() in ("free", "inf", ""):
        return float("inf")
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected a sigma in degrees >= 0 or 'free', got {text!r}"
        ) from None
    if not value >= 0:
        raise argparse.ArgumentTypeError(f"expected a sigma in degrees >= 0 or 'free', got {text!r}")
    return value


def _common(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "inputs", nargs="+", type=Path, metavar="INPUT", help="the recording's files, in time order"
    )
    p.add_argument(
        "--out",
        type=Path,
        required=True,
        metavar="DIR",
        help="folder for the tables, rejected.csv and import_summary.json (created if missing)",
    )
    p.add_argument(
        "--date",
        type=_date,
        default=None,
        metavar="YYYY-MM-DD",
        help="UTC date of the recording's first time of day (default: from the recording, else "
        "times count from its first midnight)",
    )
    p.add_argument("--format", choices=("csv", "parquet"), default="csv", help="file format of the tables")


def _positive(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected a positive integer, got {text!r}")
    return value


def _ports(text: str) -> list[int]:
    try:
        ports = [int(p) for p in text.split(",") if p.strip()]
    except ValueError:
        ports = []
    if not ports or not all(0 < p < 65536 for p in ports):
        raise argparse.ArgumentTypeError(
            f"expected UDP port numbers 1-65535 separated by commas, got {text!r}"
        )
    return ports


def _asterix_options(ast: argparse.ArgumentParser) -> None:
    """The ASTERIX options beyond the common ones: duplicates, UDP ports, CAT021 edition, the bounds."""
    ast.add_argument(
        "--keep-duplicates",
        action="store_true",
        help="keep records that repeat an earlier one (same category, SAC/SIC, time of day and bytes: "
        "a feed recorded on two LANs, a replayed tail); by default they are set aside as duplicate",
    )
    ast.add_argument(
        "--ports",
        type=_ports,
        default=None,
        metavar="PORT[,PORT...]",
        help="UDP destination ports to read from pcap/pcapng captures (default: all)",
    )
    ast.add_argument(
        "--cat021-edition",
        choices=CAT021_EDITIONS,
        default=None,
        metavar="EDITION",
        help="the CAT021 (ADS-B) edition of the feed: " + ", ".join(CAT021_EDITIONS) + " (0.2x: old "
        "feeds; default: the latest). A feed read in the wrong edition gives records that fail to walk "
        "or lack their address",
    )
    ast.add_argument(
        "--framing",
        choices=FRAMINGS,
        default="auto",
        metavar="NAME",
        help="how a file that is no pcap/pcapng capture wraps its data blocks: auto (default: told by "
        "content), netto (raw data blocks end to end), gps (Croatia Control GPS recording), rff, ioss "
        "(= final), ioss_seq, oradis, hdlc (docs/reference/asterix-framings.md)",
    )
    legacy = ((1, CAT001_EDITIONS, "radar plots"), (2, CAT002_EDITIONS, "service messages"))
    for cat, editions, what in legacy:
        ast.add_argument(
            f"--cat{cat:03d}-edition",
            choices=editions,
            default=None,
            metavar="EDITION",
            help=f"the CAT{cat:03d} ({what}) edition of the feed: {', '.join(editions)} (default: the "
            "latest; the editions share their UAPs)",
        )
    _bounds(ast, ("bytes", "records", "rejected-rows"))


def _bounds(p: argparse.ArgumentParser, names: tuple) -> None:
    """The --max-* options (``names`` of :data:`LIMIT_OPTIONS` with hyphens)."""
    what = {
        "bytes": "the (decompressed) bytes read per input (default 8 GiB); the rest is set aside",
        "records": "the records decoded per input (default 2*10^6, about 0.8 GB); the rest is set aside",
        "rejected-rows": "the rows listed in rejected.csv (default 10^5); the rest is counted in the summary",
    }
    for name in names:
        p.add_argument(
            f"--max-{name}", type=_positive, default=None, metavar="N", help=f"bound on {what[name]}"
        )


def add_arguments(p: argparse.ArgumentParser) -> None:
    from registration.cli import CommandParser  # the parser class that names the full command

    sub = p.add_subparsers(dest="format_name", required=True, metavar="FORMAT", parser_class=CommandParser)
    ast = sub.add_parser(
        "asterix",
        help=ASTERIX_HELP,
        description=textwrap.fill(ASTERIX_HELP),
        epilog=EXIT_CODES_EPILOG,
        formatter_class=HelpFormatter,
    )
    _common(ast)
    ast.add_argument(
        "--sites",
        type=Path,
        required=True,
        metavar="FILE",
        help="sensor, sac, sic, lat_deg, lon_deg, alt_m, sigma_range_m, sigma_bearing_deg; optional "
        "prior columns of the sensors file and prior_heading_deg, prior_pitch_deg, prior_roll_deg "
        "(default 0: a surveyed site)",
    )
    _asterix_options(ast)
    nmea = sub.add_parser(
        "nmea",
        help=NMEA_HELP,
        description=textwrap.fill(NMEA_HELP),
        epilog=EXIT_CODES_EPILOG,
        formatter_class=HelpFormatter,
    )
    _common(nmea)
    nmea.add_argument("--platform", required=True, metavar="NAME", help="the own ship's platform name")
    nmea.add_argument(
        "--sensors",
        type=Path,
        required=True,
        metavar="FILE",
        help="the fleet sensors file of the own ship's sensors, with an optional talker column "
        "(e.g. RA) naming the TTM talker of each",
    )
    _bounds(nmea, ("bytes", "rejected-rows"))
    nmea.add_argument(
        "--keep-duplicates",
        action="store_true",
        help="keep identical sentences with the same time (a feed recorded twice); by default they are "
        "set aside as duplicate",
    )
    nmea.add_argument("--keep-acquiring", action="store_true", help="keep TTM rows of status Q (acquiring)")
    for angle in ("heading", "pitch", "roll"):
        nmea.add_argument(
            f"--prior-{angle}-deg",
            type=_prior,
            default=0.0,
            metavar="SIGMA",
            help=f"prior sigma of the own ship's {angle} error written to platforms.csv, deg; 0 "
            "(default) holds it at 0, 'free' estimates it without prior"
            + (
                " (alone with one radar it is not separable from the radar's bearing bias)"
                if angle == "heading"
                else ""
            ),
        )


def _run_importer(args: argparse.Namespace) -> ImportResult:
    """The import of the chosen format (a bar on a terminal only)."""
    if args.format_name == "asterix":
        from registration.io.asterix import import_asterix, read_sites

        sites = read_sites(args.sites)
        return import_asterix(
            args.inputs,
            sites,
            date=args.date,
            progress=True,
            editions={c: getattr(args, a) for c, a in EDITION_OPTIONS.items() if getattr(args, a)},
            ports=args.ports,
            keep_duplicates=args.keep_duplicates,
            framing=args.framing,
            **{k: getattr(args, k) for k in LIMIT_OPTIONS if getattr(args, k) is not None},
        )
    from registration.io.nmea import import_nmea, read_sensors

    sensors = read_sensors(args.sensors)
    priors = {f"prior_{a}_deg": getattr(args, f"prior_{a}_deg") for a in ("heading", "pitch", "roll")}
    return import_nmea(
        args.inputs,
        args.platform,
        sensors,
        date=args.date,
        keep_acquiring=args.keep_acquiring,
        keep_duplicates=args.keep_duplicates,
        **{k: getattr(args, k) for k in LIMIT_OPTIONS if getattr(args, k, None) is not None},
        progress=True,
        platform_priors=priors,
    )


def flight_level_line(levels: dict) -> str:
    """One line on the flight levels turned into heights (the import summary's ``flight_levels``)."""
    written = levels.get("heights_written", 0)
    rel = levels.get("relation")
    if rel:
        offsets = ", ".join(f"{k} {v:+.0f} m" for k, v in rel["height_minus_pressure_altitude_m"].items())
        return (
            f"flight levels: {written} heights of aircraft without ADS-B, by the relation learned from "
            f"{rel['reports']} ADS-B reports of {rel['aircraft']} aircraft (height minus FL x 100 ft: "
            f"{offsets}; sigma {rel['sigma_m']:.1f} m)"
        )
    offset = levels.get("height_offset")
    if offset:
        return (
            f"flight levels: {written} heights by the ISA, sharing one offset state "
            f"(flight_levels:height_offset, prior sigma {offset['prior_sigma_m']:.0f} m at "
            f"FL{offset['reference_flight_level']:.0f}): no ADS-B report gives both flight level and height"
        )
    return "flight levels: none used (no plot of an aircraft without ADS-B has a valid flight level)"


def run(args: argparse.Namespace) -> int:
    """Import, print the counts, write the folder whole; exit 2 when the input is no recording at all."""
    for path in args.inputs:
        if path.is_dir():
            raise CommandError(f"{path}: a directory; give the recording's files (e.g. {path}/*)")
        if not path.is_file():
            raise CommandError(
                f"{path}: no such file" if not path.exists() else f"{path}: not a regular file"
            )
    from registration.io.imports import IMPORT_FILES  # every file an import may write (both formats)

    out = prepare_out(args.out)
    result = _run_importer(args)
    counts = ", ".join(f"{len(frame)} {name} rows" for name, frame in result.tables.items())
    rejected = result.summary.get("rejected", {})
    total = rejected.get("total", rejected.get("lines", len(result.rejected)))
    print(f"imported {counts}; set aside {total} records (rejected.csv)")
    levels = result.summary.get("flight_levels")
    if levels:
        print(flight_level_line(levels))
    for entry in result.summary.get("files", []):  # a bound reached: the user must know
        for note in entry.get("notes", []) if isinstance(entry, dict) else ():
            if "(max_" in note:
                print(f"warning: {note}", file=sys.stderr)
    with staged_outputs(out, f"registration import {args.format_name}", IMPORT_FILES) as folder:
        with writing(folder.path):
            written = result.write(folder.path, args.format)
    print("wrote " + ", ".join(str(folder.final(p)) for p in written.values()))
    print(f"next: registration fleet register --tables {out} --out DIR")
    return 0
