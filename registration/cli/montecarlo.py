"""``registration montecarlo``: RMSE of the identifiable estimates against the filter's sigma and the CRLB.

Runs the paper scenario with seeds SEED .. SEED + RUNS - 1 (:mod:`registration.montecarlo`),
prints the final-step table (RMSE, filter sigma and 2-sigma, sqrt(CRLB), bias per identifiable
quantity, in deg or m) with the average NEES against its 95 % chi-square interval, and writes
``montecarlo.json`` and ``montecarlo.png`` into ``--out``.

The data are always simulated with the standard (orthonormal) T; ``--t-variant paper`` changes
only the filter's model, so the run shows what the paper's eq. (4) costs.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np

from registration.cli.errors import add_allow_inconsistent, consistency_gate, consistency_line, prepare_out, writing
from registration.cli.options import add_no_plots, add_out, add_seed
from registration.cli.simulate import add_scenario_arguments, check_scenario_arguments, parse_motion

HELP = "Monte Carlo over seeds: RMSE of the identifiable estimates vs the filter's 2σ and the Cramér-Rao bound, and NEES"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--runs", type=int, default=100, metavar="N", help="number of Monte Carlo runs (at least 2)")
    add_seed(p, 0, "first random seed; run i uses seed + i")
    add_scenario_arguments(p)
    p.add_argument("--include-weak", action="store_true",
                   help="also show states that are only weakly observable (flagged; never part of the NEES)")
    p.add_argument("--sum", action="append", default=[], metavar="NAME+NAME",
                   help="also show a sum of two states, e.g. dC_a+dq_a (deg or m; flagged unless identifiable; "
                        "repeatable); default: none")
    add_out(p, "montecarlo", "montecarlo.json and montecarlo.png")
    add_no_plots(p, old_spelling="--no-plot")
    add_allow_inconsistent(p)


def pooled_consistency(result):
    """The consistency report of every run's NIS pooled: mean over runs and steps, runs x steps samples of 3 dof."""
    from registration.core.consistency import ConsistencyReport

    nis = np.asarray(result.nis, dtype=float)
    return ConsistencyReport.from_mean(float(np.mean(nis)), result.runs * nis.size, 3, "NIS")


def run(args: argparse.Namespace) -> int:
    from registration.online import RegistrationConfig
    from registration.online.montecarlo import parse_sum, run_montecarlo

    if args.runs < 2:
        raise ValueError(f"--runs: expected at least 2 runs, got {args.runs}")
    check_scenario_arguments(args)
    try:
        sums = [parse_sum(s) for s in args.sum]
    except ValueError as exc:
        raise ValueError(f"--sum: {exc}") from exc
    out = prepare_out(args.out)
    angle = float(np.radians(args.angle_sigma_deg))
    config = RegistrationConfig(
        sigma0=(args.range_sigma_m, angle, angle) * 2, q_mode=args.q_mode,
        linearization=args.linearization, t_variant=args.t_variant,
    )
    result = run_montecarlo(
        args.runs, args.seed, config, include_weak=args.include_weak, extra_sums=sums, progress=True,
        angle_sigma=angle, range_sigma=args.range_sigma_m, n_steps=args.steps,
        ship_motion=parse_motion(args.ship_motion), t_variant="standard",
    )
    print(result.table())
    consistency = pooled_consistency(result)
    print(consistency_line(consistency))
    summary = result.to_json()
    summary["consistency"] = consistency.to_json()
    summary["command"] = {k: (str(v) if isinstance(v, Path) else v) for k, v in vars(args).items() if not k.startswith("_")}
    written = [out / "montecarlo.json"]
    with writing(written[0]):
        written[0].write_text(json.dumps(summary, indent=1) + "\n")
    if not args.no_plots:
        with writing(out / "montecarlo.png"):
            result.plot(out / "montecarlo.png")
        written.append(out / "montecarlo.png")
    print("wrote " + ", ".join(str(p) for p in written))
    return consistency_gate("registration montecarlo", consistency, args.allow_inconsistent)
