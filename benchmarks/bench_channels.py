#!/usr/bin/env python3
"""Cost of the azimuth eccentricity and the PSR channel in the batch solver, and their long Monte Carlo.

Run from a checkout::

    python3 benchmarks/bench_channels.py                     # 1800 s of the ATC scenario, 7 rounds
    python3 benchmarks/bench_channels.py --montecarlo 200    # and 200 seeds of the Monte Carlo

Requirement checked (printed, never asserted: timings depend on the machine and its load): "the
PSR and eccentricity states cost at most LIMIT (1.2) times the run without them on the same data".

Data: :func:`registration.fleet.simulation.channels.atc_channel_scenario` (three radar sites, five
aircraft, R1 with an azimuth eccentricity, a random half of R2's plots primary-only with biases of
their own), seed 3, ``--duration`` seconds. The same plots are registered four ways, timed
interleaved (:func:`common.interleave`: rounds in alternating order, ratios the median of the
rounds' ratios):

* ``plain``: the three-error model as before: no ``prior_eccentricity`` or ``channel_of`` column,
  R2.psr's plots given to R2 (one sensor, as an import without ``psr_channel``);
* ``channels``: the same with the eccentricity (free on R1, held at 0 on the others) and R2.psr a
  channel of R2;
* ``extended``: ``plain`` with the extended errors (range gain, time bias, position error; no
  prior) on every sensor: the model a real ATC registration runs;
* ``extended+channels``: both.

The ratios of the requirement are ``channels / plain`` and ``extended+channels / extended``.

``--montecarlo N`` runs N seeds (from 20000) of the 150 s scenario of
tests/fleet/test_channels_montecarlo.py and applies [0.8, 1.25] to RMSE / sqrt(CRLB) of each new
state alone (R1's eccentricity terms, R2.psr's biases), with the mean NEES in its 95 % band.
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
from common import add_arguments, interleave, machine, paired_ratio, summary, write

from registration.core.consistency import nees_interval
from registration.fleet import build_problem, solve_batch
from registration.fleet.simulation.channels import atc_channel_scenario

LIMIT = 1.2
SEED = 3
NEW_STATES = (
    "R1:eccentricity_sin",
    "R1:eccentricity_cos",
    "R2.psr:range_bias",
    "R2.psr:bearing_bias",
    "R2.psr:elevation_bias",
)
EXTENDED_COLUMNS = ("prior_range_gain", "prior_time_bias", "prior_position")


def problems(duration_s: float) -> dict:
    """The four problems of the module docstring, on the same plots."""
    sc = atc_channel_scenario(SEED, duration_s=duration_s)
    new = ("prior_eccentricity", "channel_of")
    plain_sensors = {k: v[:-1] for k, v in sc.sensors.items() if k not in new}  # R2.psr is the last row
    plain_plots = dict(sc.plots, sensor=np.where(sc.plots["sensor"] == "R2.psr", "R2", sc.plots["sensor"]))

    def extended(sensors: dict) -> dict:
        n = sensors["sensor"].size
        return dict(sensors, **{c: np.full(n, np.inf) for c in EXTENDED_COLUMNS})

    args = (sc.navigation, sc.platforms, sc.references)
    return {
        "plain": build_problem(plain_plots, plain_sensors, *args),
        "channels": build_problem(sc.plots, sc.sensors, *args),
        "extended": build_problem(plain_plots, extended(plain_sensors), *args),
        "extended+channels": build_problem(sc.plots, extended(sc.sensors), *args),
    }


def montecarlo(runs: int, duration_s: float = 150.0) -> dict:
    """RMSE / sqrt(CRLB) per new state and the mean NEES over ``runs`` seeds (module docstring)."""
    est, tru, sig, nees = [], [], [], []
    layout = None
    t0 = time.perf_counter()
    for seed in range(20000, 20000 + runs):
        sc = atc_channel_scenario(seed, duration_s=duration_s)
        result = solve_batch(sc.problem())
        layout = result.layout if layout is None else layout
        e = result.estimate - sc.truth_vector(layout)
        used = layout.free[np.isfinite(result.sigma[layout.free])]
        nees.append(float(e[used] @ np.linalg.solve(result.covariance[np.ix_(used, used)], e[used])))
        est.append(result.estimate)
        tru.append(sc.truth_vector(layout))
        sig.append(result.sigma)
    assert layout is not None
    err, sig_a = np.array(est) - np.array(tru), np.array(sig)
    ratios = {}
    for name in NEW_STATES:
        i = layout.index(name)
        ratios[name] = float(np.sqrt(np.mean(err[:, i] ** 2) / np.mean(sig_a[:, i] ** 2)))
    dof = int(layout.free.size)
    lo, hi = nees_interval(runs, dof, 0.95)
    return {
        "runs": runs,
        "duration_s": duration_s,
        "seconds": time.perf_counter() - t0,
        "ratios": ratios,
        "ratios_in_band": all(0.8 <= r <= 1.25 for r in ratios.values()),
        "mean_nees": float(np.mean(nees)),
        "nees_dof": dof,
        "nees_band": [lo, hi],
        "nees_in_band": bool(lo <= np.mean(nees) <= hi),
    }


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--duration", type=float, default=1800.0, help="seconds of the scenario")
    parser.add_argument("--repeats", type=int, default=7, help="timed rounds (alternating order)")
    parser.add_argument(
        "--montecarlo", type=int, default=0, metavar="N", help="and N seeds of the Monte Carlo"
    )
    add_arguments(parser)
    args = parser.parse_args(argv)
    if args.tiny:
        args.duration, args.repeats, args.montecarlo = 60.0, 1, min(args.montecarlo, 2)
    print(
        f"OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS')}, load {os.getloadavg()}", flush=True
    )
    probs = problems(args.duration)
    results = {}

    def contender(name):
        def run():
            results[name] = solve_batch(probs[name])
            return results[name].converged

        return run

    cpu: dict[str, list[float]] = {}
    times, converged = interleave({name: contender(name) for name in probs}, args.repeats, cpu=cpu)
    figures: dict = {
        "plots": {name: int(p.n_plots) for name, p in probs.items()},
        "states": {name: int(p.layout.n) for name, p in probs.items()},
        "converged": converged,
        "iterations": {name: int(r.iterations) for name, r in results.items()},
        "seconds": summary(times),
        "cpu_seconds": summary(cpu),
        "ratios": {
            "channels/plain": paired_ratio(times, "channels", "plain"),
            "extended+channels/extended": paired_ratio(times, "extended+channels", "extended"),
        },
        "cpu_ratios": {
            "channels/plain": paired_ratio(cpu, "channels", "plain"),
            "extended+channels/extended": paired_ratio(cpu, "extended+channels", "extended"),
        },
        "limit": LIMIT,
        "load_average_after": machine()["load_average"],
        "openblas_num_threads": os.environ.get("OPENBLAS_NUM_THREADS"),
    }
    for name, s in figures["seconds"].items():
        print(
            f"{name:20s} {figures['plots'][name]:6d} plots {figures['states'][name]:3d} states  "
            f"median {s['median']:.3f} s  best {s['best']:.3f} s  "
            f"(cpu median {figures['cpu_seconds'][name]['median']:.3f} s)  "
            f"iterations {figures['iterations'][name]}"
        )
    for name, r in figures["ratios"].items():
        print(
            f"ratio {name:28s} {r:.3f}  ({'within' if r <= LIMIT else 'ABOVE'} the limit {LIMIT}; "
            f"cpu {figures['cpu_ratios'][name]:.3f})"
        )
    if args.montecarlo:
        mc = montecarlo(args.montecarlo)
        figures["montecarlo"] = mc
        print(
            f"Monte Carlo, {mc['runs']} runs: mean NEES {mc['mean_nees']:.2f} over {mc['nees_dof']} states, "
            f"band [{mc['nees_band'][0]:.2f}, {mc['nees_band'][1]:.2f}]"
        )
        for name, r in mc["ratios"].items():
            print(
                f"  {name:24s} RMSE/sqrt(CRLB) {r:.3f}{'' if 0.8 <= r <= 1.25 else '  OUTSIDE [0.8, 1.25]'}"
            )
    write("channels", args, {"duration_s": args.duration, "repeats": args.repeats, "seed": SEED}, figures)
    return figures


if __name__ == "__main__":
    main()
