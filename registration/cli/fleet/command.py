"""``registration fleet``: batch registration of a fleet (any number of platforms and sensors).

``fleet simulate`` runs the built-in fleet (three ships, a shore site, six sensors, five targets)
and writes its input tables as a working example; ``fleet register`` reads such tables (CSV or
Parquet, degrees and metres; see :mod:`registration.io.fleet.reading.read`) and registers them. Both print
the estimates per sensor and platform, the observability report and the chi-square check, and
write ``estimates.csv``, ``summary.json`` and the plots. See docs/howto/register-a-fleet.md.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from registration.cli.errors import prepare_out, writing
from registration.cli.fleet.options import add_arguments
from registration.cli.fleet.tables import REGISTER_OUTPUTS, opened_tables, write_rejected
from registration.cli.staging import staged_outputs

__all__ = [
    "HELP",
    "REGISTER_OUTPUTS",
    "SIMULATE_OUTPUTS",
    "add_arguments",
    "run",
    "run_register",
    "run_simulate",
]

HELP = (
    "registration of a fleet, in one batch or online: simulate the built-in fleet, or register fleet tables "
    "read from files"
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
    its labels (:mod:`registration.cli.fleet.association`)."""
    from registration.cli.fleet.association import associate

    return associate(tables, window_s, method)


def _write_associations(out: Path, tables, association) -> Path:
    """associations.csv (:func:`registration.cli.fleet.association.write_associations`)."""
    from registration.cli.fleet.association import write_associations

    return write_associations(out, tables, association)


def _run_line(result) -> str:
    if hasattr(result, "history"):
        used = f"{result.n_plots_used} of {result.n_plots_read} plots used"
        return f"online filter: {result.history.time.size} epochs, {used}"
    return f"converged: {result.converged} after {result.iterations} iterations"


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

    from registration.cli.fleet.output import gate, print_report, write_outputs
    from registration.fleet import fleet_scenario
    from registration.fleet.simulation.scenario import DEFAULT_FLEET
    from registration.fleet.simulation.tracks import random_targets
    from registration.io import read_fleet_tables, write_fleet_tables
    from registration.io.fleet.estimates import estimate_rows

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


def run_register(args: argparse.Namespace) -> int:
    """Read the tables, register, print and write the outputs (replacing an earlier run's in
    --out only once all are written); exit 3 on a gross misfit."""
    from registration.cli.fleet.output import gate

    if not (args.window_s >= 0 and args.window_s < float("inf")):
        raise ValueError(f"--window-s: expected a length >= 0 s, got {args.window_s}")
    from registration.cli.fleet.archive import archive_requested, run_archive
    from registration.cli.fleet.periods import check_period_options

    archive = archive_requested(args)
    check_period_options(args, archive)
    if archive:
        if getattr(args, "cat063", None) is not None:
            raise ValueError("--cat063: not with an archive read by parts (--partition-s, --workers)")
        return run_archive(args)
    from registration.cli.fleet.cat063 import cat063_sources, write_cat063

    sources = cat063_sources(args)  # before the solve: a missing summary is found at once
    out = prepare_out(args.out)
    with opened_tables(args, out) as tables:
        with staged_outputs(out, "registration fleet register", REGISTER_OUTPUTS) as folder:
            result, written, t_end = _register_into(folder.path, args, tables)
    finals = [folder.final(p) for p in written]
    if sources is not None:
        finals.append(write_cat063(args.cat063, result, sources, t_end, (25, 200)))
    print("\nwrote " + ", ".join(str(p) for p in finals))
    return gate("registration fleet register", result, args.allow_inconsistent)


def _register_into(path: Path, args: argparse.Namespace, tables):
    """Register the tables, print the report and write the outputs into ``path``: (result, files,
    the time of the last plot used, s)."""
    from registration.cli.fleet.association import association_summary, online_note
    from registration.cli.fleet.diagnostics import kinds_by_row
    from registration.cli.fleet.output import print_report, redundancy_check, write_outputs
    from registration.cli.fleet.periods import (
        change_lines,
        periods_summary,
        solve_bias_periods,
        write_period_outputs,
    )
    from registration.io.fleet.estimates import estimate_rows
    from registration.io.fleet.reading.read import needs_association

    association = None
    if not needs_association(tables.plots):
        problem, result = _solve(tables, args.window_s, args.method)
    else:
        association, problem, result = _associate(tables, args.window_s, args.method)
    redundancy_check(result, problem.n_plots, args.window_s)
    periods = None if args.bias_period_s is None else solve_bias_periods(tables, association, result, args)
    rows = estimate_rows(result)
    header = [
        "Fleet tables " + ", ".join(str(p) for p in tables.paths.values()) + ":",
        problem.lines()[0],
        *([] if association is None else association.lines()[: -len(association.batch.lines())]),
        *([] if association is None else online_note(args.method)),
        _run_line(result),
    ]
    print_report(result, rows, header)
    if periods is not None:
        print("\n".join(change_lines(periods)))
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
    extra = None if periods is None else {"bias_periods": periods_summary(periods)}
    written = write_outputs(
        path, problem, result, rows, inputs, plots=not args.no_plots, extra=extra, kinds=kinds_by_row(tables)
    )
    if periods is not None:
        written += write_period_outputs(path, periods, plots=not args.no_plots)
    if args.on_bad_row == "skip" or tables.rejected:  # stop mode too: plots that cannot be used
        written.append(write_rejected(path, tables.rejected_frame()))
    if association is not None:
        written.append(_write_associations(path, tables, association))
    return result, written, float(np.max(problem.time))


def run(args: argparse.Namespace) -> int:
    return run_simulate(args) if args.action == "simulate" else run_register(args)
