"""``registration fleet``: batch registration of a fleet (any number of platforms and sensors).

``fleet simulate`` runs the built-in fleet (three ships, a shore site, six sensors, five targets)
and writes its input tables as a working example; ``fleet register`` reads such tables (CSV or
Parquet, degrees and metres; see :mod:`registration.io.fleet.read`) and registers them. Both print
the estimates per sensor and platform, the observability report and the chi-square check, and
write ``estimates.csv``, ``summary.json`` and the plots. See docs/fleet.md.
"""

from __future__ import annotations

import argparse
import textwrap
from pathlib import Path

import numpy as np

from registration.cli.errors import EXIT_CODES_EPILOG, add_allow_inconsistent, prepare_out, writing
from registration.cli.options import HelpFormatter, add_no_plots, add_out, add_seed
from registration.cli.staging import staged_outputs

HELP = (
    "registration of a fleet, in one batch or online: simulate the built-in fleet, or register fleet tables read "
    "from files"
)

SIMULATE_HELP = (
    "simulate the built-in fleet (3 ships, a shore site, 6 sensors, 5 targets), register it (in one "
    "batch, or online with --method online), and write its input tables as a working example for "
    "`fleet register`"
)
REGISTER_HELP = (
    "register a fleet from plots, navigation and sensors tables (CSV or Parquet, degrees and metres; "
    "see docs/fleet.md)"
)


def add_arguments(p: argparse.ArgumentParser) -> None:
    sub = p.add_subparsers(dest="action", required=True, metavar="ACTION")
    sim = sub.add_parser(
        "simulate",
        help=SIMULATE_HELP,
        description=textwrap.fill(SIMULATE_HELP),
        epilog=EXIT_CODES_EPILOG,
        formatter_class=HelpFormatter,
    )
    add_seed(sim, 0)
    _add_method(sim)
    add_out(sim, "fleet-simulate", "the input tables, estimates.csv, summary.json and the PNG plots")
    add_no_plots(sim)
    sim.add_argument(
        "--format", choices=("csv", "parquet"), default="csv", help="file format of the tables written"
    )
    sim.add_argument(
        "--duration-s",
        type=float,
        default=300.0,
        metavar="S",
        help="length of the simulated recording, s (targets leaving a sensor's coverage are not plotted)",
    )
    sim.add_argument(
        "--targets",
        type=int,
        default=None,
        metavar="N",
        help="N random targets circling in the area, the first a reference target (default: the built-in "
        "five)",
    )
    errors = sim.add_argument_group("extended sensor errors (default: none, and not modelled)")
    errors.add_argument(
        "--range-gain-ppm",
        type=float,
        default=None,
        metavar="PPM",
        help="give every sensor with range a range gain of +-PPM (random signs), estimated without prior",
    )
    errors.add_argument(
        "--time-bias-s",
        type=float,
        default=None,
        metavar="S",
        help="give every sensor a time bias (reported - true plot time) of +-S s, estimated without prior",
    )
    errors.add_argument(
        "--position-error-m",
        type=float,
        default=None,
        metavar="M",
        help="give every sensor a position error (stated - true) of +-M m per east, north and up axis, "
        "estimated without prior",
    )
    add_allow_inconsistent(sim)
    reg = sub.add_parser(
        "register",
        help=REGISTER_HELP,
        description=textwrap.fill(REGISTER_HELP),
        epilog=EXIT_CODES_EPILOG,
        formatter_class=HelpFormatter,
    )
    files = reg.add_argument_group(
        "input tables (.csv or .parquet): --tables DIR, or --plots, --navigation and "
        "--sensors (each overriding the folder's file)"
    )
    files.add_argument(
        "--tables",
        type=Path,
        default=None,
        metavar="DIR",
        help="a folder holding the tables by their standard names (plots, navigation, sensors, "
        "platforms, reference, targets; .csv or .parquet), as 'registration import' writes them",
    )
    files.add_argument(
        "--plots",
        type=Path,
        default=None,
        metavar="FILE",
        help="time_s, sensor, target and/or track, range_m, bearing_deg, elevation_deg (empty cell: not "
        "measured); plots without a target id (no column, or empty cells) are associated to the "
        "targets with ids, the reference targets and each other, jointly with the registration; "
        "track: a sensor-local track id (associations.csv)",
    )
    files.add_argument(
        "--navigation",
        type=Path,
        default=None,
        metavar="FILE",
        help="time_s, platform, lat_deg, lon_deg, alt_m, heading_deg, pitch_deg, roll_deg "
        "(one row for a fixed site)",
    )
    files.add_argument(
        "--sensors",
        type=Path,
        default=None,
        metavar="FILE",
        help="sensor, platform, sigma_range_m, sigma_bearing_deg, sigma_elevation_deg; optional "
        "prior_range_bias_m, prior_bearing_bias_deg, prior_elevation_bias_deg (0 = fixed), "
        "lever_x_m, lever_y_m, lever_z_m; optional extended errors, each modelled only when its "
        "column is there: prior_range_gain (dimensionless), prior_time_bias_s, prior_position_m "
        "(empty or inf: no prior)",
    )
    files.add_argument(
        "--platforms",
        type=Path,
        default=None,
        metavar="FILE",
        help="platform, prior_heading_deg, prior_pitch_deg, prior_roll_deg (0 = fixed); default: no priors",
    )
    files.add_argument(
        "--reference",
        type=Path,
        default=None,
        metavar="FILE",
        help="time_s, target, lat_deg, lon_deg, alt_m (or x_m, y_m, z_m), optional sigma_m "
        "(m per axis; horizontal with sigma_up_m) and sigma_up_m (m, vertical): known target "
        "positions; default: none",
    )
    files.add_argument(
        "--targets",
        type=Path,
        default=None,
        metavar="FILE",
        help="target, optional name, surface_alt_m (m above WGS-84) and sigma_surface_m: targets that "
        "move on a surface of known height, such as ships on the sea; default: none",
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
    reg.add_argument(
        "--on-bad-row",
        choices=["stop", "skip"],
        default="stop",
        help="stop at the first bad row of the plots (then the reference) file, or skip: set bad rows aside in "
        "rejected.csv (file, row, column, reason_code, reason) and register the rest",
    )
    add_out(reg, "fleet-register", "estimates.csv, summary.json and the PNG plots")
    add_no_plots(reg)
    add_allow_inconsistent(reg)
    from registration.cli.fleet_archive import add_archive_arguments

    add_archive_arguments(reg)


def _add_method(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--method",
        choices=("batch", "online"),
        default="batch",
        help="batch: maximum likelihood over all plots at once; online: the filter, one update per "
        "window of plots, with the estimates over time in history.csv (docs/fleet-online.md); plots without "
        "target ids are first associated by the batch, then filtered with the labels it gave",
    )


def _inputs(tables, problem, window_s: float) -> dict:
    return {
        "files": {k: str(v) for k, v in tables.paths.items()},
        "rows": tables.rows(),
        "window_s": window_s,
        "platforms": list(problem.platform_ids),
        "sensors": list(problem.sensor_ids),
        "targets": list(problem.target_ids),
        "plots_used": problem.n_plots,
        "plots_read": problem.n_input_plots,
    }


def _solve(tables, window_s: float, method: str):
    """(problem, result) of the batch or the online method on the tables."""
    from registration.fleet import BatchOptions, OnlineOptions, register_online, solve_batch

    problem = tables.problem()
    if method == "online":
        return problem, register_online(
            tables.plots,
            tables.sensors,
            tables.navigation,
            tables.platforms,
            tables.references,
            options=OnlineOptions(window_s=window_s),
            targets=tables.targets,
        )
    return problem, solve_batch(
        problem, BatchOptions(window_s=window_s), progress=True
    )  # a bar on a terminal only


def _associate(tables, window_s: float, method: str):
    """Plots without target ids (some or all rows): (association, problem, result) of
    :func:`registration.fleet.associate_and_register`; with --method online, the online filter on
    its labels (:mod:`registration.cli.fleet_association`)."""
    from registration.cli.fleet_association import associate

    return associate(tables, window_s, method)


def _write_associations(out: Path, tables, association) -> Path:
    """associations.csv (:func:`registration.cli.fleet_association.write_associations`)."""
    from registration.cli.fleet_association import write_associations

    return write_associations(out, tables, association)


def _run_line(result) -> str:
    if hasattr(result, "history"):
        return f"online filter: {result.history.time.size} epochs, {result.n_plots_used} of {result.n_plots_read} plots used"
    return f"converged: {result.converged} after {result.iterations} iterations"


#: What `fleet register` writes into --out (the outputs of an earlier run there are replaced whole).
REGISTER_OUTPUTS = frozenset(
    {
        "estimates.csv",
        "history.csv",
        "summary.json",
        "associations.csv",
        "rejected.csv",
        "estimates.png",
        "map.png",
        "residuals.png",
    }
)
#: `fleet simulate` writes its input tables too.
SIMULATE_OUTPUTS = REGISTER_OUTPUTS | {
    f"{t}.{f}"
    for t in ("plots", "navigation", "sensors", "platforms", "reference")
    for f in ("csv", "parquet")
}


def run_simulate(args: argparse.Namespace) -> int:
    """Simulate, write the tables, read them back and register what was written (so `fleet register`
    on these files gives the same numbers)."""
    from dataclasses import replace

    from registration.cli.fleet_output import estimate_rows, gate, print_report, write_outputs
    from registration.fleet import fleet_scenario
    from registration.fleet.simulation.scenario import DEFAULT_FLEET
    from registration.fleet.simulation.tracks import random_targets
    from registration.io import read_fleet_tables, write_fleet_tables

    if args.seed < 0:
        raise ValueError(f"--seed: expected an integer >= 0, got {args.seed}")
    extended = {
        "range_gain": None if args.range_gain_ppm is None else args.range_gain_ppm * 1e-6,
        "time_bias": args.time_bias_s,
        "position_error": args.position_error_m,
    }
    for option, value in (
        ("--range-gain-ppm", args.range_gain_ppm),
        ("--time-bias-s", args.time_bias_s),
        ("--position-error-m", args.position_error_m),
    ):
        if value is not None and not np.isfinite(value):
            raise ValueError(f"{option}: expected a finite number, got {value}")
    if not (10.0 < args.duration_s < float("inf")):
        raise ValueError(f"--duration-s: expected a length > 10 s, got {args.duration_s}")
    if args.targets is not None and args.targets < 1:
        raise ValueError(f"--targets: expected a number of targets >= 1, got {args.targets}")
    config = (
        DEFAULT_FLEET
        if args.targets is None
        else replace(DEFAULT_FLEET, targets=random_targets(args.targets, args.seed), reference_target="T1")
    )
    out = prepare_out(args.out)
    s = fleet_scenario(args.seed, duration_s=args.duration_s, config=config, **extended)
    with staged_outputs(out, "registration fleet simulate", SIMULATE_OUTPUTS) as folder:
        with writing(folder.path):
            tables_written = write_fleet_tables(
                folder.path, s.plots, s.navigation, s.sensors, s.platforms, s.references, args.format
            )
        names = {p.stem: p for p in tables_written}
        tables = read_fleet_tables(
            names["plots"],
            names["navigation"],
            names["sensors"],
            names.get("platforms"),
            names.get("reference"),
        )
        tables.paths = {k: folder.final(v) for k, v in tables.paths.items()}  # where they will be
        problem, result = _solve(tables, 20.0, args.method)
        rows = estimate_rows(result, s.truth_state)
        header = [f"Simulated fleet, seed {args.seed}: " + problem.lines()[0], _run_line(result)]
        print_report(result, rows, header)
        scenario = {k: (float(v) if not isinstance(v, (bool, str)) else v) for k, v in s.description.items()}
        inputs = {**_inputs(tables, problem, 20.0), "method": args.method, "scenario": scenario}
        written = write_outputs(
            folder.path, problem, result, rows, inputs, plots=not args.no_plots, truth=s.truth_state
        )
    print("\nwrote " + ", ".join(str(folder.final(p)) for p in [*tables_written, *written]))
    return gate("registration fleet simulate", result, args.allow_inconsistent)


def _write_rejected(out: Path, frame) -> Path:
    from registration.io.files.tablefile import write_frame

    path = out / "rejected.csv"
    with writing(path):
        write_frame(frame, path, "csv")
    return path


def _table_paths(args: argparse.Namespace) -> dict:
    """The tables' paths: from --tables DIR by their standard names, each overridden by its own option."""
    from registration.io.fleet.folder import REQUIRED_TABLES, TABLE_NAMES, tables_in_folder

    given = {name: getattr(args, name) for name in TABLE_NAMES}
    if args.tables is not None:
        return tables_in_folder(args.tables, given)
    missing = [f"--{n}" for n in REQUIRED_TABLES if given[n] is None]
    if missing:
        raise ValueError(
            f"the arguments {', '.join(missing)} are required (or give --tables DIR, the folder of an import)"
        )
    return given


def _read_tables(args: argparse.Namespace, out: Path):
    """The tables, bad rows stopping the run or set aside (then counted on standard output)."""
    from registration.io import read_fleet_tables
    from registration.io.fleet.rejects import NoValidPlotsError

    paths = _table_paths(args)
    try:
        tables = read_fleet_tables(
            paths["plots"],
            paths["navigation"],
            paths["sensors"],
            paths["platforms"],
            paths["reference"],
            targets=paths["targets"],
            on_bad_row=args.on_bad_row,
        )
    except NoValidPlotsError as exc:
        with staged_outputs(out, "registration fleet register", REGISTER_OUTPUTS) as folder:
            _write_rejected(folder.path, exc.rejected_frame())  # the list of what was wrong is the output
        raise
    if tables.rejected:
        frame = tables.rejected_frame()
        per_file = {
            f: ", ".join(f"{n} {code}" for code, n in g.groupby("reason_code").size().items())
            for f, g in frame.groupby("file")
        }
        print(
            f"set aside {len(frame)} bad rows (in rejected.csv): "
            + "; ".join(f"{f}: {c}" for f, c in per_file.items())
        )
    for note in tables.notes:  # ignored without an error, or suspicious without proof
        print(f"note: {note}")
    return tables


def run_register(args: argparse.Namespace) -> int:
    """Read the tables, register, print and write the outputs (replacing an earlier run's in
    --out only once all are written); exit 3 on a gross misfit."""
    from registration.cli.fleet_output import gate

    if not (args.window_s >= 0 and args.window_s < float("inf")):
        raise ValueError(f"--window-s: expected a length >= 0 s, got {args.window_s}")
    from registration.cli.fleet_archive import archive_requested, run_archive

    if archive_requested(args):
        return run_archive(args)
    out = prepare_out(args.out)
    tables = _read_tables(args, out)
    with staged_outputs(out, "registration fleet register", REGISTER_OUTPUTS) as folder:
        result, written = _register_into(folder.path, args, tables)
    print("\nwrote " + ", ".join(str(folder.final(p)) for p in written))
    return gate("registration fleet register", result, args.allow_inconsistent)


def _register_into(path: Path, args: argparse.Namespace, tables):
    """Register the tables, print the report and write the outputs into ``path``: (result, files)."""
    from registration.cli.fleet_association import association_summary, online_note
    from registration.cli.fleet_output import estimate_rows, print_report, write_outputs
    from registration.io.fleet.read import needs_association

    association = None
    if not needs_association(tables.plots):
        problem, result = _solve(tables, args.window_s, args.method)
    else:
        association, problem, result = _associate(tables, args.window_s, args.method)
    rows = estimate_rows(result)
    header = [
        "Fleet tables " + ", ".join(str(p) for p in tables.paths.values()) + ":",
        problem.lines()[0],
        *([] if association is None else association.lines()[: -len(association.batch.lines())]),
        *([] if association is None else online_note(args.method)),
        _run_line(result),
    ]
    print_report(result, rows, header)
    inputs = {
        **_inputs(tables, problem, args.window_s),
        "method": args.method,
        "on_bad_row": args.on_bad_row,
        "rows_read": tables.rows_read(),
        "rows_rejected": len(tables.rejected),
        "notes": list(tables.notes),
    }
    if association is not None:
        inputs["association"] = association_summary(association, args.method)
    written = write_outputs(path, problem, result, rows, inputs, plots=not args.no_plots)
    if args.on_bad_row == "skip":
        written.append(_write_rejected(path, tables.rejected_frame()))
    if association is not None:
        written.append(_write_associations(path, tables, association))
    return result, written


def run(args: argparse.Namespace) -> int:
    return run_simulate(args) if args.action == "simulate" else run_register(args)
