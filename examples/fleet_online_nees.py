"""NEES of the online fleet filter and of the batch over Monte Carlo runs of the default fleet.

    python3 examples/fleet_online_nees.py [--runs 20] [--duration 200]

Each run draws a new fleet (errors, signs and noise from its seed), registers it with
:func:`registration.fleet.register_online` (from zero, no prior) and with :func:`solve_batch`, and
computes the normalised estimation error squared over the estimated states. Prints the mean NEES of
each against the two-sided 95 % band of a consistent estimator (chi-square, runs x states degrees
of freedom).
"""

from __future__ import annotations

import argparse

import numpy as np

from registration.core.consistency import nees_interval
from registration.fleet import fleet_scenario, register_online, solve_batch


def nees(sc, result) -> float:
    free = result.layout.free
    err = (result.estimate - sc.truth_vector(result.layout))[free]
    return float(err @ np.linalg.solve(result.covariance[np.ix_(free, free)], err))


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, default=20)
    parser.add_argument("--duration", type=float, default=200.0)
    args = parser.parse_args(argv)
    online, batch = [], []
    for seed in range(100, 100 + args.runs):
        sc = fleet_scenario(seed, duration_s=args.duration)
        online.append(
            nees(
                sc,
                register_online(
                    sc.plots, sc.sensors, sc.navigation, sc.platforms, sc.references, residuals=False
                ),
            )
        )
        batch.append(nees(sc, solve_batch(sc.problem())))
    dof = int(sc.problem().layout.free.size)
    lo, hi = nees_interval(args.runs, dof)
    out = {
        "runs": args.runs,
        "states": dof,
        "online": float(np.mean(online)),
        "batch": float(np.mean(batch)),
        "band": (lo, hi),
    }
    print(f"| estimator | mean NEES over {args.runs} runs ({dof} states) | 95 % band |")
    print("|---|---:|---|")
    for name in ("online", "batch"):
        print(f"| {name} | {out[name]:.2f} | [{lo:.2f}, {hi:.2f}] |")
    return out


if __name__ == "__main__":
    main()
