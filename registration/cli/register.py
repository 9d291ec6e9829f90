"""``registration register``: register recorded files (CSV/Parquet), streaming and resumable.

Exit codes (:mod:`registration.cli.errors`): 0 success; 1 ``--validate-only`` found bad rows; 2 bad
input (an unreadable or empty file, a bad row in stop mode, every row rejected, a damaged
checkpoint, an unusable ``--out``); 3 the run finished and was published, but its mean NIS is
more than 10 x its expectation (the likely causes are printed; ``--allow-inconsistent`` accepts it).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from registration.cli.errors import (
    EXIT_BAD_INPUT,
    EXIT_BAD_ROWS,
    EXIT_OK,
    add_allow_inconsistent,
    consistency_gate,
    consistency_line,
)
from registration.cli.options import add_dask, add_no_plots, add_out, check_dask
from registration.online import DEFAULT_LINEARIZATION, LINEARIZATIONS

HELP = (
    "register recorded data: a synchronous table or two per-radar plot files (+ navigation), CSV or Parquet"
)


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "inputs",
        nargs="+",
        type=Path,
        metavar="INPUT",
        help="one synchronous table, or two per-radar plot files (A then B); see `registration schema`",
    )
    add_out(
        p,
        "register",
        "the estimates, positions, rejected rows, summary.json and plots; a run works in "
        "DIR/partial-<pid>-<token> and, once finished, replaces the outputs of the run before it whole",
    )
    p.add_argument(
        "--nav",
        type=Path,
        action="append",
        default=[],
        metavar="FILE",
        help="navigation file (asynchronous form; repeat for one file per ship; default: none)",
    )
    p.add_argument(
        "--checkpoint",
        type=Path,
        default=None,
        metavar="FILE",
        help="save the run's state to FILE every --checkpoint-every rows; rerunning the same command resumes "
        "(default: no checkpoint)",
    )
    p.add_argument(
        "--checkpoint-every", type=int, default=100_000, metavar="N", help="rows between checkpoints"
    )
    p.add_argument(
        "--chunk-rows", type=int, default=20_000, metavar="N", help="rows read and filtered per block"
    )
    p.add_argument(
        "--on-bad-row",
        choices=["stop", "skip"],
        default="stop",
        help="stop at the first bad row, or skip: set bad rows aside in rejected.csv",
    )
    p.add_argument("--format", choices=["csv", "parquet"], default="csv", help="format of the outputs")
    _add_filter_options(p)
    p.add_argument(
        "--validate-only", action="store_true", help="check every row and report, without estimating"
    )
    add_no_plots(p)
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    add_allow_inconsistent(p)
    p.add_argument(
        "--each",
        action="store_true",
        help="every INPUT is a synchronous table of its own: one registration per file, "
        "into DIR/<file stem>/",
    )
    add_dask(p, "files of --each")
    _add_asynchronous_options(p)


def _add_filter_options(p: argparse.ArgumentParser) -> None:
    """The filter's model and noise: linearisation, process noise, rotation T, radar sigmas, and
    where the information matrix is taken."""
    p.add_argument(
        "--linearization",
        choices=list(LINEARIZATIONS),
        default=DEFAULT_LINEARIZATION,
        help="where the filter linearises the model: paper = at the raw measurements (as printed), "
        "relinearized = at the corrected measurements, fitted = at the most probable noise-free plots",
    )
    p.add_argument(
        "--q-mode",
        choices=["fixed", "adaptive"],
        default="fixed",
        help="the filter's process noise Q: fixed, or adaptive from the last --q-window estimates",
    )
    p.add_argument("--q-window", type=int, default=20, metavar="N", help="estimates in the adaptive-Q window")
    p.add_argument(
        "--t-variant",
        choices=["standard", "paper"],
        default="standard",
        help="the filter's ENU->ECEF rotation T: standard (orthonormal) or paper (as printed)",
    )
    p.add_argument(
        "--sigma",
        default="50,0.5,0.5",
        metavar="R_M,Q_DEG,E_DEG[,R_M,Q_DEG,E_DEG]",
        help="radar noise sigmas: range in m, bearing and elevation in deg; 3 values for both radars or 6 "
        "(A then B)",
    )
    p.add_argument(
        "--observability",
        choices=["final", "filter"],
        default="final",
        help="information matrix at the final estimate (second pass) or as the filter accumulated it",
    )


def _add_asynchronous_options(p: argparse.ArgumentParser) -> None:
    """The pairing of the asynchronous form's two plot files: clock offsets and interpolation."""
    g = p.add_argument_group("asynchronous form (two plot files)")
    g.add_argument(
        "--clock-offset-a",
        type=float,
        default=0.0,
        metavar="S",
        help="radar A's clock offset, s: its clock reads reference time + S",
    )
    g.add_argument(
        "--clock-offset-b",
        type=float,
        default=0.0,
        metavar="S",
        help="radar B's clock offset, s: its clock reads reference time + S",
    )
    g.add_argument(
        "--pair-at", choices=["a", "b"], default="a", help="common instants = this radar's plot times"
    )
    g.add_argument(
        "--interp-degree",
        type=int,
        default=1,
        metavar="N",
        help="degree of the sliding-window fit, 1: linear between neighbours",
    )
    g.add_argument(
        "--max-extrapolation-s",
        type=float,
        default=0.0,
        metavar="S",
        help="largest extrapolation beyond a stream's samples, s",
    )
    g.add_argument(
        "--max-gap-s",
        type=float,
        default=None,
        metavar="S",
        help="widest gap between samples to interpolate across, s (default: 2.5 x the median interval)",
    )


def parse_sigma(text: str) -> tuple:
    try:
        vals = [float(v) for v in text.split(",")]
    except ValueError as exc:
        raise ValueError(f"--sigma: expected numbers separated by commas, got {text!r}") from exc
    if len(vals) == 3:
        vals = vals * 2
    if len(vals) != 6 or not all(np.isfinite(vals)) or min(vals) <= 0:
        raise ValueError(f"--sigma: expected 3 or 6 positive values (m, deg, deg), got {text!r}")
    return (
        vals[0],
        np.radians(vals[1]),
        np.radians(vals[2]),
        vals[3],
        np.radians(vals[4]),
        np.radians(vals[5]),
    )


def build_options(args: argparse.Namespace):
    from registration.online import RegistrationConfig
    from registration.recorded import PairingOptions, RunOptions

    config = RegistrationConfig(
        sigma0=parse_sigma(args.sigma),
        q_mode=args.q_mode,
        q_window=args.q_window,
        linearization=args.linearization,
        t_variant=args.t_variant,
    )
    pairing = None
    if len(args.inputs) == 2:
        pairing = PairingOptions(
            clock_offset_a=args.clock_offset_a,
            clock_offset_b=args.clock_offset_b,
            pair_at=args.pair_at,
            degree=args.interp_degree,
            max_extrapolation_s=args.max_extrapolation_s,
            max_gap_s=args.max_gap_s,
        )
    return RunOptions(
        out=args.out,
        config=config,
        on_bad_row=args.on_bad_row,
        checkpoint=args.checkpoint,
        checkpoint_every=args.checkpoint_every,
        chunk_rows=args.chunk_rows,
        out_format=args.format,
        observability=args.observability,
        plots=not args.no_plots,
        progress=not args.no_progress,
        nav=list(args.nav),
        pairing=pairing,
    )


def interrupt_hint(args: argparse.Namespace) -> str:
    """What Ctrl-C prints: where the unfinished outputs are and, with a checkpoint, how to resume."""
    if getattr(args, "validate_only", False):
        return "registration register: interrupted"
    if args.checkpoint is None:
        return (
            f"registration register: interrupted; nothing was written: {args.out} holds what it held before "
            "(give --checkpoint FILE to make a long run resumable)"
        )
    return (
        "registration register: interrupted; rerun the same command to resume from its checkpoint "
        f"{args.checkpoint} (the unfinished outputs are in {args.out}/partial-*; {args.out} holds what it "
        "held before)"
    )


def run(args: argparse.Namespace) -> int:
    from registration.cli.simulate import estimate_lines
    from registration.recorded import run_register, summary_consistency, validate_files

    if args.each:
        return run_each(args)
    if args.scheduler or args.workers:
        raise ValueError("--scheduler, --workers: only with --each (one registration per file)")
    options = build_options(args)
    if args.validate_only:
        report = validate_files(args.inputs, options)
        bad = 0
        for path, r in report["files"].items():
            n_bad = r["rows"] - r["accepted"]
            bad += n_bad
            print(
                f"{path} ({r['layout']}): {r['rows']} rows, {r['accepted']} valid, {n_bad} bad "
                f"{r['rejected_by_reason'] or ''}"
            )
        for prob in report["problems"]:
            print(
                f"  {prob['file']}: row {prob['row']}, column {prob['column']!r}: {prob['reason']} "
                f"[{prob['code']}]"
            )
        return EXIT_BAD_ROWS if bad else EXIT_OK

    summary = run_register(args.inputs, options)
    gate = summary_consistency(summary)
    _print_summary(summary, estimate_lines, gate)
    print(
        f"\nwrote {args.out}/ ("
        + ", ".join(Path(v).name for v in summary["outputs"].values())
        + ", summary.json"
        + (", plots" if summary.get("plots") else "")
        + ")"
    )
    return (
        EXIT_OK if gate is None else consistency_gate("registration register", gate, args.allow_inconsistent)
    )


def _print_summary(summary: dict, estimate_lines, gate) -> None:
    """The report on standard output: rows, pairing, X_A - X_B before/after, estimates, observability,
    consistency (``gate``), warnings about the inputs."""
    rows = summary["rows"]
    print(
        f"registration register: {summary['form']} input, {rows['read']} rows read, {rows['accepted']} "
        f"registered, {rows['rejected']} rejected {rows['rejected_by_reason'] or ''}"
    )
    if "pairing" in summary:
        p = summary["pairing"]
        print(
            f"pairing: {p['instants']} instants, {p['paired']} paired ({p['exact']} exact, "
            f"{p['interpolated']} interpolated), {p['unpaired']} unpaired {p['unpaired_reasons'] or ''}"
        )
    print("\nX_A - X_B (m)     before       after")
    for stat in ("max", "mean", "std"):
        for i, axis in enumerate("XYZ"):
            print(
                f"  {stat:>4} {axis}   {summary['before'][stat][i]:10.2f}  {summary['after'][stat][i]:10.2f}"
            )
    print("\nFinal estimates (deg or m) with σ (one standard deviation):")
    for line in estimate_lines(summary["estimates"]):
        print(line)
    obs = summary["observability"]
    print("\nObservability (" + obs["information"] + "):")
    print(
        "  singular values of the prior-scaled information matrix: "
        + " ".join(f"{s:.3g}" for s in obs["singular_values"])
    )
    for t in obs["unobservable"]:
        print(f"  UNOBSERVABLE: {t}")
    for t in obs["weak"]:
        print(f"  weak:         {t}")
    if gate is not None:
        print("\n" + consistency_line(gate))
    for w in summary.get("warnings", []):
        print(f"warning: {w}")


def register_file(task: tuple) -> dict:
    """``(path, RunOptions)`` registered: ``{"file", "summary"}``, or ``{"file", "error"}`` for bad input."""
    from registration.recorded import run_register

    path, options = task
    try:
        return {"file": str(path), "summary": run_register([path], options)}
    except (ValueError, OSError) as exc:
        return {"file": str(path), "error": f"{type(exc).__name__}: {exc}"}


def each_tasks(args: argparse.Namespace) -> list[tuple]:
    """One ``(path, RunOptions)`` per input, its outputs
    in ``--out``/<file stem> (checked before any work)."""
    import dataclasses

    if args.checkpoint is not None or args.nav:
        raise ValueError("--each: every input is a synchronous table; --checkpoint and --nav do not apply")
    stems = [Path(p).stem for p in args.inputs]
    if len(set(stems)) != len(stems):
        dup = sorted({s for s in stems if stems.count(s) > 1})
        raise ValueError(
            f"--each: two inputs share the file stem {dup[0]!r} (their outputs would share a folder)"
        )
    check_dask(args)
    args.inputs = list(args.inputs)
    base = build_options(argparse.Namespace(**{**vars(args), "inputs": args.inputs[:1]}))
    return [
        (Path(p), dataclasses.replace(base, out=Path(args.out) / Path(p).stem, progress=False))
        for p in args.inputs
    ]


def run_each(args: argparse.Namespace) -> int:
    """``--each``: every input registered on its own (on a dask cluster with --workers/--scheduler)."""
    from registration.core.parallel import dask_client, map_chunks
    from registration.recorded import summary_consistency, validate_files

    tasks = each_tasks(args)
    if args.validate_only:
        bad = 0
        for path, options in tasks:
            (r,) = validate_files([path], options)["files"].values()
            bad += r["rows"] - r["accepted"]
            print(
                f"{path} ({r['layout']}): {r['rows']} rows, {r['accepted']} valid, "
                f"{r['rows'] - r['accepted']} bad"
            )
        return EXIT_BAD_ROWS if bad else EXIT_OK
    with dask_client(args.scheduler, args.workers) as client:
        done = map_chunks(register_file, tasks, client, progress=not args.no_progress, desc="files")
    codes = []
    for (path, options), d in zip(tasks, done):
        if "error" in d:
            print(f"{path}: error: {d['error']}")
            codes.append(EXIT_BAD_INPUT)
            continue
        rows, gate = d["summary"]["rows"], summary_consistency(d["summary"])
        print(
            f"{path}: {rows['accepted']} of {rows['read']} rows registered into {options.out}/"
            + ("" if gate is None else "; " + consistency_line(gate))
        )
        codes.append(
            EXIT_OK
            if gate is None
            else consistency_gate(f"registration register {path}", gate, args.allow_inconsistent)
        )
    failed = codes.count(EXIT_BAD_INPUT)
    print(f"registration register --each: {len(tasks) - failed} of {len(tasks)} files registered")
    return max(codes)
