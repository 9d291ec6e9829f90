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

from registration.cli.simulate import add_scenario_arguments, parse_motion

HELP = "Monte Carlo over seeds: RMSE of the identifiable estimates vs the filter's 2σ and the Cramér-Rao bound, and NEES"

def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--runs", type=int, default=100, help="number of Monte Carlo runs (default 100)")
    p.add_argument("--seed", type=int, default=0, help="first seed; run i uses seed + i (default 0)")
    add_scenario_arguments(p)
    p.add_argument("--include-weak", action="store_true",
                   help="also show states that are only weakly observable (flagged; never part of the NEES)")
    p.add_argument("--sum", action="append", default=[], metavar="NAME+NAME",
                   help="also show a sum of two states, e.g. dC_a+dq_a (flagged unless identifiable; repeatable)")
    p.add_argument("--out", type=Path, default=Path("out/montecarlo"), help="output folder (default out/montecarlo)")
    p.add_argument("--no-plot", action="store_true", help="skip the PNG")


def run(args: argparse.Namespace) -> int:
    from registration.online.montecarlo import parse_sum, run_montecarlo
    from registration.online import RegistrationConfig

    if args.runs < 2:
        raise ValueError(f"--runs: expected at least 2 runs, got {args.runs}")
    if not 0 < args.angle_sigma_deg < 20:
        raise ValueError("--angle-sigma-deg: expected a value in (0, 20) degrees")
    if not args.range_sigma_m > 0:
        raise ValueError("--range-sigma-m: expected a value > 0 m")
    if args.steps < 2:
        raise ValueError("--steps: expected at least 2 measurement pairs")
    sums = [parse_sum(s) for s in args.sum]
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
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    summary = result.to_json()
    summary["command"] = {k: (str(v) if isinstance(v, Path) else v) for k, v in vars(args).items() if not k.startswith("_")}
    (out / "montecarlo.json").write_text(json.dumps(summary, indent=1) + "\n")
    written = [out / "montecarlo.json"]
    if not args.no_plot:
        result.plot(out / "montecarlo.png")
        written.append(out / "montecarlo.png")
    print("wrote " + ", ".join(str(p) for p in written))
    return 0
