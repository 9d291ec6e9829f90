#!/usr/bin/env python3
"""The table of docs/background/association.md: association + registration of plots without target ids on
simulated fleets with known truth, printed as markdown.

Run from a checkout::

    python3 benchmarks/association_table.py                  # 3 runs per row, 300 s each
    python3 benchmarks/association_table.py --runs 1 --duration 120
    python3 benchmarks/association_table.py --table robust   # the fleets of the robust association

``--table robust`` runs the fleets of :mod:`registration.fleet.association.simulated.fleets` instead (the
issue's rolling fleet with a passive sensor, with and without 5 % clutter, another sensor mix, the
extended errors, a bridge log with AIS, an ATC recording with Mode S, Mode A and primary plots), one
row per fleet and draw, against the registration of all real plots with their true ids (the AIS
vessels' plots for the bridge log): wrong joins (labels that are not the plot's target), clutter
associated, real plots unassociated, the largest |estimate - truth| / sigma over the identifiable
states and sums, the largest sigma ratio to the ids run, the chi-square mean against its 99.9 % band.

Each row is one simulated case of :func:`registration.fleet.association_scenario` (the default
fleet's five radars: three 3-D, two 2-D, all asynchronous), run ``--runs`` times with different
random draws (targets, biases' signs, noise, misses, clutter). Per run: the plots are associated and
registered by :func:`associate_and_register`, and the same real plots (without the clutter) are
registered with their true target ids as the reference. Columns (mean over the runs, worst run in
brackets where it matters):

* error: share of the real plots given a label that stands for another target (each label stands
  for the true target of most of its plots);
* unassoc.: share of the real plots left unassociated; clutter in: share of the clutter plots given
  a label; labels/target: labels per true target (1 = no target split in pieces);
* passes: association passes (all runs converged unless marked);
* bias vs ids: the largest difference between the association's estimate and the true-id
  registration's, over all states, in units of the true-id registration's sigma;
* bias vs truth: the largest |estimate - truth| / sigma of the association's registration;
* time: seconds of the association + registration, and of the true-id registration (the two
  interleaved, common.interleave).

The table's lines go to benchmarks/results/association_table.json (``--table robust``:
association_table_robust.json); ``--tiny``: three short rows (robust: two fleets at a tenth of
their length, the ATC recording left out), to check the script works.
"""

from __future__ import annotations

import argparse

import numpy as np
from common import add_arguments, interleave, write

from registration.fleet import (
    associate_and_register,
    association_scenario,
    association_scores,
    build_problem,
    solve_batch,
)
from registration.fleet.association.simulated.fleets import (
    atc_fleet,
    registration_scores,
    rolling_fleet,
    vessel_fleet,
)

#: The robust table's fleets: name -> function of the seed returning (simulation, references, ids run plots).
MIX = {
    "A-ESM": ("A", (np.nan, np.radians(0.25), np.radians(0.3)), 1.0, 0.1, (1.0, 4.0, 25.0)),
    "A-2D": ("A", (30.0, np.radians(0.2), np.nan), 2.5, 0.77, (0.0, 12.0, 20.0)),
    "B-3D": ("B", (25.0, np.radians(0.15), np.radians(0.2)), 2.0, 1.21, (0.0, 10.0, 22.0)),
    "S-3D": ("S", (30.0, np.radians(0.1), np.radians(0.15)), 4.0, 2.33, (0.0, 0.0, 10.0)),
    "S-2D": ("S", (40.0, np.radians(0.1), np.nan), 5.0, 3.46, (0.0, 0.0, 12.0)),
}


def _fleet(name: str, seed: int, scale: float = 1.0):
    """(simulation, references, plots of the ids run) of one robust-table fleet (durations times
    ``scale``; the ATC recording has its own)."""
    if name == "issue":
        sim, refs = rolling_fleet(seed, duration_s=600.0 * scale), None
    elif name == "issue, 5 % clutter":
        sim, refs = rolling_fleet(seed, duration_s=600.0 * scale, clutter_share=0.05), None
    elif name == "other mix, 5 % clutter":
        sim, refs = (
            rolling_fleet(
                seed,
                duration_s=300.0 * scale,
                n_aircraft=8,
                sensors=MIX,
                clutter_share=0.05,
                angle_bias=np.radians(3.0),
            ),
            None,
        )
    elif name == "issue, time bias + gain, 5 % clutter":
        sim, refs = (
            rolling_fleet(seed, duration_s=300.0 * scale, clutter_share=0.05, time_bias=0.3, range_gain=3e-4),
            None,
        )
    elif name == "bridge log (ARPA + AIS)":
        sim, refs = vessel_fleet(seed, duration_s=600.0 * scale)
        keep = np.isin(sim.true_target, np.unique(refs["target"]))
        ids = {k: v[keep] for k, v in sim.plots.items() if k != "track"}
        return sim, refs, dict(ids, target=sim.true_target[keep])
    else:  # ATC
        sim, refs = atc_fleet(seed)
    real = sim.true_target != ""
    return (
        sim,
        refs,
        dict(
            {k: v[real] for k, v in sim.plots.items() if k not in ("track", "target")},
            target=sim.true_target[real],
        ),
    )


ROBUST = (
    "issue",
    "issue, 5 % clutter",
    "other mix, 5 % clutter",
    "issue, time bias + gain, 5 % clutter",
    "bridge log (ARPA + AIS)",
    "ATC (Mode S, Mode A, primary)",
)


def _both(sim, refs, ids) -> tuple[dict, object, object]:
    """The association's and the true ids' registration, interleaved (common.interleave): the
    seconds of each, the association result and the ids run."""
    sc = sim.scenario
    times, values = interleave(
        {
            "ids": lambda: solve_batch(build_problem(ids, sc.sensors, sc.navigation, sc.platforms, refs)),
            "association": lambda: associate_and_register(
                sim.plots, sc.sensors, sc.navigation, sc.platforms, refs
            ),
        },
        1,
        warmup=0,
    )
    return {k: t[0] for k, t in times.items()}, values["association"], values["ids"]


def robust_row(name: str, seed: int, scale: float = 1.0) -> str:
    sim, refs, ids = _fleet(name, seed, scale)
    sc = sim.scenario
    seconds, result, base = _both(sim, refs, ids)
    t_ids, t_assoc = seconds["ids"], seconds["association"]
    real, lab = sim.true_target != "", result.labels != ""
    # each label stands for the true target of most of its plots (ids given and references by name too)
    wrong = int(round(association_scores(result.labels, sim.true_target)["error_rate"] * real.sum()))
    reg = registration_scores(result.batch, base, sc.truth_state)
    return (
        f"| {name} | {seed} | {int(real.sum())} ({int((~real).sum())}) | {wrong} | "
        f"{int((lab & ~real).sum())} | "
        f"{100 * np.mean(~lab[real]):.1f} % | {result.n_targets} | {reg['vs_truth']:.2f} | "
        f"{reg['sigma_ratio']:.3f} | "
        f"{reg['chi2_mean']:.4f} [{reg['chi2_band'][0]:.3f}, {reg['chi2_band'][1]:.3f}] | "
        f"{'yes' if result.converged else 'no'} | {t_assoc:.1f} / {t_ids:.1f} |"
    )


def robust_table(seeds, names=ROBUST, scale: float = 1.0) -> list[str]:
    lines = [
        "| fleet | seed | real plots (clutter) | wrong joins | clutter in | unassoc. | targets | "
        "max \\|est − truth\\|/σ | σ ratio vs ids | χ² mean [99.9 % band] | converged | time (s): assoc. / "
        "ids |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    print("\n".join(lines), flush=True)
    for name in names:
        for seed in seeds:
            lines.append(robust_row(name, seed, scale))
            print(lines[-1], flush=True)
    return lines


#: Rows: targets, crossing pairs, angle bias (deg), share of missed detections, clutter plots per scan.
CASES = [
    (5, False, 2.0, 0.0, 0.0),
    (5, False, 2.0, 0.1, 1.0),
    (5, False, 5.0, 0.1, 1.0),
    (5, True, 2.0, 0.1, 1.0),
    (5, True, 5.0, 0.1, 1.0),
    (20, False, 2.0, 0.1, 1.0),
    (20, False, 5.0, 0.1, 1.0),
    (20, True, 2.0, 0.1, 1.0),
    (20, True, 5.0, 0.1, 1.0),
    (20, True, 5.0, 0.1, 5.0),
]


def run_case(
    n_targets: int,
    crossing: bool,
    bias_deg: float,
    p_missed: float,
    clutter: float,
    seed: int,
    duration_s: float,
) -> dict:
    """One run: the scores, the estimates against the true-id registration and the truth, the times."""
    sim = association_scenario(
        n_targets,
        crossing=crossing,
        angle_bias=np.radians(bias_deg),
        p_missed=p_missed,
        clutter_per_scan=clutter,
        duration_s=duration_s,
        seed=seed,
    )
    sc = sim.scenario
    seconds, result, base = _both(sim, None, sim.labelled_plots)
    free = base.layout.free
    truth = sc.truth_vector(base.layout)
    est = result.batch.estimate
    return {
        **association_scores(result.labels, sim.true_target),
        "passes": result.iterations,
        "converged": result.converged,
        "seconds": seconds["association"],
        "seconds_ids": seconds["ids"],
        "vs_ids": float(np.max(np.abs(est - base.estimate)[free] / base.sigma[free])),
        "vs_truth": float(np.max(np.abs(est - truth)[free] / result.batch.sigma[free])),
        "plots": int(sim.plots["time"].size),
        "clutter": int(np.count_nonzero(sim.true_target == "")),
    }


def _row(case, runs: list[dict]) -> str:
    n, crossing, bias, missed, clutter = case
    mean = {k: float(np.mean([r[k] for r in runs])) for k in runs[0] if k != "converged"}
    worst = {k: float(np.max([r[k] for r in runs])) for k in runs[0] if k != "converged"}
    conv = "" if all(r["converged"] for r in runs) else " (not all converged)"
    return (
        f"| {n} | {'yes' if crossing else 'no'} | {bias:g} | {100 * missed:g} % | {clutter:g} | "
        f"{mean['plots']:.0f} ({mean['clutter']:.0f}) | {100 * mean['error_rate']:.2f} % "
        f"({100 * worst['error_rate']:.2f} %) | "
        f"{100 * mean['unassociated_rate']:.1f} % ({100 * worst['unassociated_rate']:.1f} %) | "
        f"{100 * mean['clutter_associated']:.2f} % | {mean['labels_per_target']:.2f} | "
        f"{mean['passes']:.1f}{conv} | "
        f"{mean['vs_ids']:.2f} ({worst['vs_ids']:.2f}) | {mean['vs_truth']:.2f} ({worst['vs_truth']:.2f}) | "
        f"{mean['seconds']:.1f} / {mean['seconds_ids']:.1f} |"
    )


def main(argv=None) -> list[str]:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, default=3, help="runs per row (random draws)")
    parser.add_argument("--duration", type=float, default=300.0, help="seconds of data per run")
    parser.add_argument(
        "--table",
        choices=("scenario", "robust"),
        default="scenario",
        help="scenario: the association_scenario rows; robust: the fleets of the robust association",
    )
    parser.add_argument(
        "--seeds", type=int, nargs="*", default=[101, 102], help="draws of each robust-table fleet"
    )
    add_arguments(parser)
    args = parser.parse_args(argv)
    cases, names, scale = CASES, ROBUST, 1.0
    if args.tiny:  # a few rows, short: does it still run?
        args.runs, args.duration, args.seeds = 1, 30.0, args.seeds[:1]
        cases, names, scale = [CASES[1], CASES[3], CASES[5]], ROBUST[:1] + ROBUST[4:5], 0.1
    if args.table == "robust":
        lines = robust_table(args.seeds, names, scale)
        write("association_table_robust", args, {"seeds": args.seeds, "fleets": list(names)}, lines)
        return lines
    lines = [
        f"{args.runs} runs of {args.duration:g} s per row; mean (worst run)",
        "",
        "| targets | crossing | angle bias (deg) | missed | clutter / scan | plots (clutter) | error | "
        "unassoc. | "
        "clutter in | labels / target | passes | bias vs ids (σ) | bias vs truth (σ) | time (s): assoc. / "
        "ids |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    print("\n".join(lines), flush=True)
    for case in cases:
        runs = [run_case(*case, seed=seed, duration_s=args.duration) for seed in range(args.runs)]
        lines.append(_row(case, runs))
        print(lines[-1], flush=True)
    write("association_table", args, {"runs": args.runs, "duration_s": args.duration}, lines)
    return lines


if __name__ == "__main__":
    main()
