"""``registration schema``: the columns `registration register` expects, with their units."""

from __future__ import annotations

import argparse
import json

HELP = "print the columns (with units) of the files that `registration register` reads and writes"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--json", action="store_true", help="machine-readable output")


def schema() -> dict:
    """The file forms as a dict: for each form, a list of {column, unit, meaning, required}."""
    from registration.recorded import (
        ESTIMATE_COLUMNS,
        NAV_FIELDS,
        PLOT_FIELDS,
        POSITION_COLUMNS,
        REJECTED_COLUMNS,
        SYNC_FIELDS,
        UNPAIRED_COLUMNS,
    )

    def rows(fields, prefix="", required=True):
        out = []
        for f in fields:
            name = f.file_name if f.kind == "time" or not prefix else f"{prefix}_{f.file_name}"
            out.append({"column": name, "unit": f.unit, "meaning": f.meaning, "required": required})
        return out

    return {
        "synchronous": {
            "description": "one table; each row is one pair of plots of the common target by radar A and "
            "radar B at the same instant, with both ships' navigation and attitude",
            "columns": rows(SYNC_FIELDS),
        },
        "plot_file": {
            "description": "asynchronous form: one file per radar, each with its own timestamps and rate "
            "(give two: radar A's, then radar B's). The columns may carry the radar's prefix (a_range_m) to "
            "say which radar the file belongs to. The ship's navigation may be in the same file (all six "
            "columns, same clock) or in a --nav file.",
            "columns": rows(PLOT_FIELDS) + rows(NAV_FIELDS, required=False),
        },
        "navigation_file": {
            "description": "asynchronous form, --nav FILE: the navigation of one or both ships at its own "
            "rate, on the reference clock; the columns carry the ship's prefix",
            "columns": rows((PLOT_FIELDS[0],))
            + rows(NAV_FIELDS, "a", required=False)
            + rows(NAV_FIELDS, "b", required=False),
        },
        "outputs": {
            "estimates": ESTIMATE_COLUMNS,
            "positions": POSITION_COLUMNS,
            "rejected": REJECTED_COLUMNS,
            "unpaired": UNPAIRED_COLUMNS,
        },
    }


def run(args: argparse.Namespace) -> int:
    s = schema()
    if args.json:
        print(json.dumps(s, indent=2))
        return 0
    print("Files read by `registration register` (CSV or Parquet, chosen by the suffix .csv / .parquet).")
    print("Units are part of the column names; angles in degrees, distances in metres, times in seconds.")
    print("Extra columns are ignored. Rows are numbered from 0 (the CSV header line is not a row).\n")
    for key, title in (
        ("synchronous", "1. Synchronous table (one file)"),
        ("plot_file", "2a. Per-radar plot file (asynchronous form, two files)"),
        ("navigation_file", "2b. Navigation file (asynchronous form, optional, --nav FILE)"),
    ):
        form = s[key]
        print(title)
        print("   " + form["description"])
        for c in form["columns"]:
            opt = "" if c["required"] else "  (optional)"
            print(f"   {c['column']:<20} {c['unit']:<4} {c['meaning']}{opt}")
        print()
    print("Outputs written into --out DIR:")
    print("   estimates.csv|parquet   " + ", ".join(s["outputs"]["estimates"][:6]) + ", ... , nis")
    print("                           (every state and its 1-sigma after each row, degrees or metres)")
    print("   positions.csv|parquet   " + ", ".join(s["outputs"]["positions"]))
    print(
        "                           (corrected ECEF target positions from radar A and B; raw and corrected "
        "A - B)"
    )
    print("   rejected.csv            " + ", ".join(s["outputs"]["rejected"]))
    print("   unpaired.csv            " + ", ".join(s["outputs"]["unpaired"]) + "  (asynchronous form)")
    print("   summary.json, estimates.png, differences.png, tracks.png")
    print(
        "\nExample: registration simulate --export example.csv --out sim && registration register "
        "example.csv --out reg"
    )
    return 0
