"""``registration simulate``: the two-ship scenario of
Wang et al. 2011 end to end, with a report and plots."""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from registration.cli.errors import (
    add_allow_inconsistent,
    consistency_gate,
    consistency_line,
    prepare_out,
    writing,
)
from registration.cli.options import add_no_plots, add_out, add_seed
from registration.cli.staging import staged_outputs
from registration.io.files.jsonfile import write_json
from registration.online import DEFAULT_LINEARIZATION, LINEARIZATIONS, Q_MODES, T_VARIANTS

HELP = (
    "simulate the two-ship scenario of Wang et al. 2011, register online, and compare with the paper's "
    "Table 1"
)

DEFAULT_MOTION = "2,8,5,12"


def add_scenario_arguments(p: argparse.ArgumentParser) -> None:
    """Options shared by `simulate` and `montecarlo`: the paper scenario and the filter settings."""
    p.add_argument(
        "--angle-sigma-deg",
        type=float,
        default=0.5,
        metavar="DEG",
        help="bearing and elevation noise standard deviation, deg (the paper's value)",
    )
    p.add_argument(
        "--range-sigma-m",
        type=float,
        default=50.0,
        metavar="M",
        help="range noise standard deviation, m (the paper's value)",
    )
    p.add_argument(
        "--steps",
        type=int,
        default=300,
        metavar="N",
        help="synchronous measurement pairs, one per second (the paper's count)",
    )
    p.add_argument(
        "--ship-motion",
        nargs="?",
        const=DEFAULT_MOTION,
        default=None,
        metavar="PITCH_DEG,PITCH_S,ROLL_DEG,ROLL_S",
        help="let both ships pitch and roll sinusoidally: amplitudes in deg (below 45), periods in s "
        f"(no value: {DEFAULT_MOTION}); default: level ships, as in the paper",
    )
    p.add_argument(
        "--linearization",
        choices=list(LINEARIZATIONS),
        default=DEFAULT_LINEARIZATION,
        help="where the filter linearises the model: paper = at the raw measurements (as printed), "
        "relinearized = at the corrected measurements (extended Kalman filter), "
        "fitted = at the most probable noise-free plots",
    )
    p.add_argument(
        "--q-mode",
        choices=list(Q_MODES),
        default="fixed",
        help="the filter's process noise Q: fixed (a small constant Q per step) or adaptive "
        "(the sample covariance of the last 20 estimates, the fixed Q as a floor; eqs. 21-22)",
    )
    p.add_argument(
        "--t-variant",
        choices=list(T_VARIANTS),
        default="standard",
        help="the filter's ENU->ECEF rotation T: standard (orthonormal) or paper (eq. 4 as printed); "
        "the data are always simulated with the standard T",
    )


def check_scenario_arguments(args: argparse.Namespace) -> None:
    """Reject out-of-range scenario options before any work (ValueError naming the option)."""
    if not 0 < args.angle_sigma_deg < 20:
        raise ValueError(
            f"--angle-sigma-deg: expected a value in (0, 20) degrees, got {args.angle_sigma_deg}"
        )
    if not 0 < args.range_sigma_m < 1e6:
        raise ValueError(f"--range-sigma-m: expected a value in (0, 1e6) m, got {args.range_sigma_m}")
    if args.steps < 2:
        raise ValueError(f"--steps: expected at least 2 measurement pairs, got {args.steps}")
    if args.seed < 0:
        raise ValueError(f"--seed: expected an integer >= 0, got {args.seed}")
    parse_motion(args.ship_motion)


def add_arguments(p: argparse.ArgumentParser) -> None:
    add_seed(p, 0)
    add_scenario_arguments(p)
    add_out(p, "simulate")
    add_no_plots(p)
    p.add_argument(
        "--export",
        type=Path,
        default=None,
        metavar="FILE",
        help="also write the simulated data as FILE (.csv or .parquet; the format `registration register` "
        "reads, see `registration schema`); default: not written",
    )
    add_allow_inconsistent(p)


def parse_motion(text: str | None):
    """``PITCH_DEG,PITCH_S,ROLL_DEG,ROLL_S`` -> ShipMotion (radians, seconds); None -> None (level ships)."""
    from registration.online.scenario import ShipMotion

    if text is None:
        return None
    expected = (
        f"--ship-motion: expected PITCH_DEG,PITCH_S,ROLL_DEG,ROLL_S (e.g. {DEFAULT_MOTION}), got {text!r}"
    )
    try:
        pd, ps, rd, rs = (float(v) for v in text.split(","))
    except ValueError as exc:
        raise ValueError(expected) from exc
    if not (0 <= pd < 45 and 0 <= rd < 45 and 0 < ps < np.inf and 0 < rs < np.inf):
        raise ValueError(expected + ": amplitudes in [0, 45) deg and periods > 0 s")
    return ShipMotion(np.radians(pd), ps, np.radians(rd), rs)


def _fmt(v: float) -> str:
    return f"{v:10.2f}"


def table1_lines(stats: dict, paper: dict, noise_free: dict | None = None) -> list[str]:
    head = "X_A - X_B (m)  paper before  ours before  paper after  ours after"
    if noise_free is not None:
        head += "  | noise off: before       after"
    lines = [head]
    for stat in ("max", "mean", "std"):
        for i, axis in enumerate("XYZ"):
            line = (
                f"  {stat:>4} {axis}     {_fmt(paper['before'][stat][i])}  {_fmt(stats['before'][stat][i])}  "
                f"{_fmt(paper['after'][stat][i])}  {_fmt(stats['after'][stat][i])}"
            )
            if noise_free is not None:
                line += (
                    f"  |        {_fmt(noise_free['before'][stat][i])}  {_fmt(noise_free['after'][stat][i])}"
                )
            lines.append(line)
    return lines


def estimate_lines(rows: list[dict]) -> list[str]:
    """The console table of the two-ship estimate rows (``registration.online.estimate_rows``):
    state, estimate, σ (one standard deviation, as in summary.json), truth, unit (deg or m), status."""
    lines = [f"  {'state':<14}{'estimate':>12}{'σ':>10}{'truth':>10}  unit  status"]
    for r in rows:
        k = np.degrees(1.0) if r["unit"] == "rad" else 1.0
        unit = "deg" if r["unit"] == "rad" else "m"
        truth = "" if r["truth"] is None else f"{r['truth'] * k:10.4g}"
        mark = (
            ""
            if r["status"] in ("identifiable", "identifiable combination")
            else "   <- not a converged estimate"
        )
        lines.append(
            f"  {r['name']:<14}{r['estimate'] * k:12.4g}{r['sigma'] * k:10.3g}{truth:>10}  {unit:<4}  "
            f"{r['status']}{mark}"
        )
    return lines


def _check(args: argparse.Namespace) -> None:
    """Every option checked and the output places prepared before the simulation starts."""
    check_scenario_arguments(args)
    if args.export is not None:
        from registration.io.files.tablefile import file_format

        try:
            file_format(args.export)
        except ValueError as exc:
            raise ValueError(f"--export: {exc}") from exc
        if args.export.is_dir():
            raise ValueError(
                f"--export: {args.export} is a folder; expected a file name ending in .csv or .parquet"
            )
        prepare_out(args.export.parent)
    prepare_out(args.out)


def _print_report(args, scenario, result, stats, noise_free, rows) -> None:
    """The report on standard output: scenario line, Table 1, estimates, observability, consistency."""
    from registration.online.scenario import PAPER_TABLE1

    print(
        f"Paper scenario (Wang et al. 2011, section 4): {args.steps} pairs at 1 s, seed {args.seed}, "
        f"angle noise {args.angle_sigma_deg} deg, range noise {args.range_sigma_m} m, "
        f"ships {'level (paper)' if args.ship_motion is None else 'pitching/rolling ' + args.ship_motion}; "
        f"linearization {args.linearization}, Q {args.q_mode}, T {args.t_variant}"
    )
    print()
    print("Table 1 (paper) beside this run. Ours uses our own target trajectory (the paper's came from a")
    print("simulator we do not have), so only magnitudes are comparable; with 0.5 deg angle noise the")
    print("difference spreads by hundreds of metres, so the paper's 'after' figures are not reachable.")
    print("The last two columns rerun the same scenario with the noise switched off (same filter settings).")
    for line in table1_lines(stats, PAPER_TABLE1, noise_free):
        print(line)
    print()
    print("Final estimates (deg or m) with σ (one standard deviation), against the truth of the simulation:")
    for line in estimate_lines(rows):
        print(line)
    print()
    print("Observability:")
    for line in result.observability.lines():
        print(line)
    print("\n" + consistency_line(result.consistency))


#: What `registration simulate` writes into --out (the outputs of an earlier run there are replaced whole).
SIMULATE_OUTPUTS = frozenset({"summary.json", "tracks.png", "differences.png", "estimates.png"})


def _write(path: Path, args, scenario, config, result, stats, noise_free, rows) -> list[Path]:
    """summary.json and the plots, into the run folder ``path``; the paths written."""
    from registration.online.scenario import PAPER_TABLE1

    summary = {
        "scenario": scenario.description,
        "config": config.to_json(),
        "before": stats["before"],
        "after": stats["after"],
        "noise_free": noise_free,
        "paper_table1": PAPER_TABLE1,
        "estimates": rows,
        "observability": result.observability.to_json(),
        "mean_nis": float(np.mean(result.nis)),
        "consistency": result.consistency.to_json(),
    }
    written = [path / "summary.json"]
    with writing(written[0]):
        write_json(written[0], summary)
    if not args.no_plots:
        from registration.online.plots import plot_differences, plot_estimates, plot_tracks

        for name, draw in (
            ("tracks.png", lambda p: plot_tracks(scenario.data, scenario.truth, p)),
            ("differences.png", lambda p: plot_differences(result, p)),
            ("estimates.png", lambda p: plot_estimates(result, scenario.truth_state, p)),
        ):
            with writing(path / name):
                written.append(draw(path / name))
    return written


def _export(scenario, path: Path) -> Path:
    """The simulated data as ``path`` (--export), written after the --out outputs are published."""
    from registration.recorded.reading.formats import write_table

    with writing(path):
        return write_table(scenario.data, path)


def run(args: argparse.Namespace) -> int:
    """Simulate, register, print the report; publish summary.json and the plots into --out whole
    (an earlier run's outputs there are replaced only once all are written; a failure leaves them
    as they were). The --export file may lie outside --out, so it is not part of that publication:
    it is written after it, and a failure there (exit 2) leaves --out holding this run's outputs."""
    from registration.online import RegistrationConfig, register
    from registration.online.scenario import paper_scenario

    _check(args)
    motion = parse_motion(args.ship_motion)
    scenario = paper_scenario(
        seed=args.seed,
        angle_sigma=np.radians(args.angle_sigma_deg),
        range_sigma=args.range_sigma_m,
        n_steps=args.steps,
        ship_motion=motion,
        t_variant="standard",
    )
    config = RegistrationConfig(
        sigma0=tuple(scenario.sigma0),
        q_mode=args.q_mode,
        linearization=args.linearization,
        t_variant=args.t_variant,
    )
    result = register(scenario.data, config, progress=True)
    stats = result.statistics()
    # The same run with the noise switched off: what the systematic errors alone produce.
    quiet = paper_scenario(
        seed=args.seed,
        angle_sigma=0.0,
        range_sigma=0.0,
        n_steps=args.steps,
        ship_motion=motion,
        t_variant="standard",
    )
    noise_free = register(quiet.data, config).statistics()
    rows = result.estimate_rows(scenario.truth_state)
    _print_report(args, scenario, result, stats, noise_free, rows)
    with staged_outputs(args.out, "registration simulate", SIMULATE_OUTPUTS) as folder:
        written = [
            folder.final(p)
            for p in _write(folder.path, args, scenario, config, result, stats, noise_free, rows)
        ]
    if args.export is not None:
        written.append(_export(scenario, args.export))
    print("\nwrote " + ", ".join(str(p) for p in written))
    return consistency_gate("registration simulate", result.consistency, args.allow_inconsistent)
