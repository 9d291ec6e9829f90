#!/usr/bin/env python3
"""Speed of association + registration of plots without target ids, against registration of the
same real plots with their true target ids, both in this run.

Run from a checkout::

    python3 benchmarks/bench_association.py                  # 10 sensors x 20 targets x 1000 s
    python3 benchmarks/bench_association.py --duration 300 --json out.json
    python3 benchmarks/bench_association.py --tiny                   # seconds: does it still run?

Problem: the default fleet's three ships and shore site with ten radars (3-D and 2-D, sampling
once a second at their own time offsets), twenty targets (crossing pairs among them), angle biases
of 2 deg, 10 % missed detections and one clutter plot per scan per sensor on average
(:func:`registration.fleet.association_scenario`). Timed: :func:`associate_and_register` end to
end (checks, tracks per sensor, association passes, the solves between them and the final solve),
and the baseline :func:`build_problem` + :func:`solve_batch` on the real plots with their true
ids, interleaved (``--repeats`` rounds; the ratio is the median of the rounds' ratios). Printed
and written to benchmarks/results/association.json: the times, the share of the association's
time spent in the assignments (``linear_sum_assignment``'s and the compiled tracker's own), the
ratio of the two times, the association's scores against the truth and the largest difference of
the two estimates in units of the baseline's sigma; and, from one more run, the association's time
by stage (``association_stages.py``). The machine's load average is printed too (other work slows
both).
"""

from __future__ import annotations

import argparse
import os

import numpy as np
from association_stages import stage_times
from common import add_arguments, interleave, paired_ratio, summary, write

from registration.fleet import (
    associate_and_register,
    association_scenario,
    association_scores,
    build_problem,
    solve_batch,
)

#: Ten radars: platform, noise sigma (range m, bearing rad, elevation rad; NaN = not measured),
#: period (s), time offset (s), lever arm (m, deck frame).
SENSORS_10 = {
    "A-3D": ("A", (25.0, np.radians(0.15), np.radians(0.2)), 1.0, 0.0, (0.0, 20.0, 25.0)),
    "A-2D": ("A", (40.0, np.radians(0.2), np.nan), 1.0, 0.55, (0.0, -12.0, 18.0)),
    "B-3D": ("B", (30.0, np.radians(0.2), np.radians(0.25)), 1.0, 0.83, (0.0, 15.0, 20.0)),
    "B-2D": ("B", (40.0, np.radians(0.2), np.nan), 1.0, 0.11, (0.0, -10.0, 18.0)),
    "C-3D": ("C", (20.0, np.radians(0.1), np.radians(0.15)), 1.0, 0.21, (0.0, 25.0, 30.0)),
    "C-2D": ("C", (40.0, np.radians(0.25), np.nan), 1.0, 0.62, (0.0, -30.0, 22.0)),
    "C-3Db": ("C", (30.0, np.radians(0.15), np.radians(0.2)), 1.0, 0.74, (0.0, 5.0, 28.0)),
    "S-2D": ("S", (30.0, np.radians(0.1), np.nan), 1.0, 0.47, (0.0, 0.0, 10.0)),
    "S-3D": ("S", (30.0, np.radians(0.1), np.radians(0.1)), 1.0, 0.93, (0.0, 5.0, 12.0)),
    "S-3Db": ("S", (25.0, np.radians(0.12), np.radians(0.12)), 1.0, 0.36, (0.0, -5.0, 14.0)),
}


def scenario(targets: int = 20, duration_s: float = 1000.0):
    """The benchmark's simulation (module docstring): ``targets`` targets over ``duration_s`` s."""
    return association_scenario(
        targets,
        crossing=True,
        angle_bias=np.radians(2.0),
        p_missed=0.1,
        clutter_per_scan=1.0,
        duration_s=duration_s,
        seed=5,
        sensors=SENSORS_10,
    )


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--duration", type=float, default=1000.0, help="seconds of data")
    parser.add_argument("--targets", type=int, default=20)
    parser.add_argument("--repeats", type=int, default=3, help="rounds of the two, interleaved")
    add_arguments(parser)
    args = parser.parse_args(argv)
    if args.tiny:
        args.duration, args.targets, args.repeats = 60.0, 3, 1

    sim = scenario(args.targets, args.duration)
    sc = sim.scenario
    sizes = {
        "sensors": len(SENSORS_10),
        "targets": args.targets,
        "duration_s": args.duration,
        "plots": int(sim.plots["time"].size),
        "real_plots": int(np.count_nonzero(sim.true_target != "")),
        "repeats": args.repeats,
    }
    out: dict = {"load_average_before": os.getloadavg()}
    cpu: dict[str, list[float]] = {}
    times, values = interleave(
        {
            "association": lambda: associate_and_register(sim.plots, sc.sensors, sc.navigation, sc.platforms),
            "true_ids": lambda: solve_batch(
                build_problem(sim.labelled_plots, sc.sensors, sc.navigation, sc.platforms)
            ),
        },
        args.repeats,
        warmup=0,
        cpu=cpu,
    )
    base, result = values["true_ids"], values["association"]
    out["seconds"] = summary(times)
    out["ratio_over_true_ids"] = paired_ratio(times, "association", "true_ids")
    out["cpu_seconds"] = summary(cpu)
    out["cpu_ratio_over_true_ids"] = paired_ratio(cpu, "association", "true_ids")
    out["assignment_s"] = result.seconds_assignment
    out["assignment_share"] = result.assignment_share
    out["registration_share"] = result.seconds_registration / result.seconds_total
    out["passes"] = result.iterations
    out["join_passes"] = result.join_passes
    out["converged"] = result.converged
    out.update(association_scores(result.labels, sim.true_target))
    free = base.layout.free
    diff = np.abs(result.batch.estimate - base.estimate)[free] / base.sigma[free]
    out["max_estimate_difference_in_sigma"] = float(np.max(diff))
    stages = stage_times(lambda: associate_and_register(sim.plots, sc.sensors, sc.navigation, sc.platforms))
    print("\n".join(stages.lines()))
    out["stage_seconds"] = {"whole": stages.whole, "solves": stages.solves, "total": stages.total}
    out["load_average_after"] = os.getloadavg()
    for key, value in {**sizes, **out}.items():
        print(f"{key:36s} {value}")
    write("association", args, sizes, out)
    return out


if __name__ == "__main__":
    main()
