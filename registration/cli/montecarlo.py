"""``registration montecarlo``: RMSE of the identifiable estimates against the filter's sigma and the CRLB.

Runs the paper scenario with seeds SEED .. SEED + RUNS - 1 (:mod:`registration.montecarlo`),
prints the final-step table (RMSE, filter sigma and 2-sigma, sqrt(CRLB), bias per identifiable
quantity, in deg or m) with the average NEES against its 95 % chi-square interval, and writes
``montecarlo.json`` and ``montecarlo.png`` into ``--out`` (replacing an earlier run's outputs there
only once all are written, see :mod:`registration.cli.staging`).

``--workers N`` or ``--scheduler ADDRESS`` runs the seeds in chunks of ``--chunk-runs`` on a dask
cluster (the statistics are the same, bit for bit, as in this process). ``--sweep NAME=V1,V2,...``
runs the Monte Carlo at every value of one scenario option as one job and writes ``sweep.csv``
(or ``.parquet``) and ``sweep.png`` instead.

The data are always simulated with the standard (orthonormal) T; ``--t-variant paper`` changes
only the filter's model, so the run shows what the paper's eq. (4) costs.
"""

from __future__ import annotations

import argparse
import copy
from pathlib import Path

import numpy as np

from registration.cli.errors import (
    add_allow_inconsistent,
    consistency_gate,
    consistency_line,
    prepare_out,
    writing,
)
from registration.cli.options import add_dask, add_no_plots, add_out, add_seed, check_dask
from registration.cli.simulate import add_scenario_arguments, check_scenario_arguments, parse_motion
from registration.cli.staging import staged_outputs
from registration.io.files.jsonfile import write_json
from registration.online.distributed import DEFAULT_CHUNK_RUNS

#: --sweep NAME -> the type of its values (the scenario options of the same name)
SWEEPABLE = {"angle-sigma-deg": float, "range-sigma-m": float, "steps": int}

#: What `registration montecarlo` writes into --out, with or without --sweep: a run replaces every
#: one of these an earlier run left (a sweep replaces montecarlo.json too), so --out holds one run.
MONTECARLO_OUTPUTS = frozenset(
    {"montecarlo.json", "montecarlo.png", "sweep.csv", "sweep.parquet", "sweep.png"}
)

HELP = (
    "Monte Carlo over seeds: RMSE of the identifiable estimates vs the filter's 2σ and the Cramér-Rao "
    "bound, and NEES"
)


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--runs", type=int, default=100, metavar="N", help="number of Monte Carlo runs (at least 2)"
    )
    add_seed(p, 0, "first random seed; run i uses seed + i")
    add_scenario_arguments(p)
    p.add_argument(
        "--include-weak",
        action="store_true",
        help="also show states that are only weakly observable (flagged; never part of the NEES)",
    )
    p.add_argument(
        "--sum",
        action="append",
        default=[],
        metavar="NAME+NAME",
        help="also show a sum of two states, e.g. dC_a+dq_a (deg or m; flagged unless identifiable; "
        "repeatable); default: none",
    )
    add_out(p, "montecarlo", "montecarlo.json and montecarlo.png (with --sweep: sweep.csv and sweep.png)")
    add_no_plots(p, old_spelling="--no-plot")
    add_allow_inconsistent(p)
    p.add_argument(
        "--sweep",
        default=None,
        metavar="NAME=V1,V2,...",
        help="run the Monte Carlo at each value of one scenario option, NAME one of "
        f"{', '.join(SWEEPABLE)} (values in the unit the name states); default: no sweep",
    )
    p.add_argument("--format", choices=["csv", "parquet"], default="csv", help="format of the --sweep table")
    add_dask(p, "chunks of seeds")
    p.add_argument(
        "--chunk-runs",
        type=int,
        default=DEFAULT_CHUNK_RUNS,
        metavar="N",
        help="runs (consecutive seeds) per chunk of work; the results do not depend on it",
    )


def parse_sweep(text: str) -> tuple[str, list]:
    """``"angle-sigma-deg=0.1,0.2"`` -> ``("angle-sigma-deg", [0.1, 0.2])`` (ValueError naming --sweep)."""
    name, sep, values = str(text).partition("=")
    name = name.strip().removeprefix("--")
    if not sep or name not in SWEEPABLE:
        raise ValueError(
            f"--sweep: expected NAME=V1,V2,... with NAME one of {', '.join(SWEEPABLE)}, got {text!r}"
        )
    kind = SWEEPABLE[name]
    try:
        parsed = [kind(v) for v in values.split(",") if v.strip()]
    except ValueError as exc:
        raise ValueError(
            f"--sweep: {name}: expected {kind.__name__} values separated by commas, got {values!r}"
        ) from exc
    if not parsed or len(set(parsed)) != len(parsed):
        raise ValueError(f"--sweep: {name}: expected distinct values separated by commas, got {values!r}")
    return name, parsed


def pooled_consistency(result):
    """The consistency report of every run's NIS pooled:
    mean over runs and steps, runs x steps samples of 3 dof."""
    from registration.core.consistency import ConsistencyReport

    nis = np.asarray(result.nis, dtype=float)
    return ConsistencyReport.from_mean(float(np.mean(nis)), result.runs * nis.size, 3, "NIS")


def build_job(args: argparse.Namespace):
    """The :class:`MonteCarloJob` of the options (checked first)."""
    from registration.online import RegistrationConfig
    from registration.online.distributed import MonteCarloJob
    from registration.online.montecarlo import parse_sum

    if args.runs < 2:
        raise ValueError(f"--runs: expected at least 2 runs, got {args.runs}")
    check_scenario_arguments(args)
    try:
        sums = tuple(parse_sum(s) for s in args.sum)
    except ValueError as exc:
        raise ValueError(f"--sum: {exc}") from exc
    angle = float(np.radians(args.angle_sigma_deg))
    config = RegistrationConfig(
        sigma0=(args.range_sigma_m, angle, angle) * 2,
        q_mode=args.q_mode,
        linearization=args.linearization,
        t_variant=args.t_variant,
    )
    scenario = dict(
        angle_sigma=angle,
        range_sigma=args.range_sigma_m,
        n_steps=args.steps,
        ship_motion=parse_motion(args.ship_motion),
        t_variant="standard",
    )
    return MonteCarloJob(args.runs, args.seed, config, args.include_weak, sums, scenario)


def sweep_jobs(args: argparse.Namespace) -> tuple[str, list, list]:
    """``(name, values, jobs)``: one job per value of ``--sweep`` (every point checked before any work)."""
    name, values = parse_sweep(args.sweep)
    jobs = []
    for v in values:
        point = copy.copy(args)
        setattr(point, name.replace("-", "_"), v)
        try:
            jobs.append(build_job(point))
        except ValueError as exc:
            raise ValueError(f"--sweep: {name}={v}: {exc}") from exc
    return name, values, jobs


def run(args: argparse.Namespace) -> int:
    from registration.core.parallel import dask_client
    from registration.online.distributed import run_montecarlo_jobs

    if args.chunk_runs < 1:
        raise ValueError(f"--chunk-runs: expected at least 1 run per chunk, got {args.chunk_runs}")
    check_dask(args)
    name, values, jobs = sweep_jobs(args) if args.sweep else (None, None, [build_job(args)])
    out = prepare_out(args.out)
    with dask_client(args.scheduler, args.workers) as client:
        results = run_montecarlo_jobs(jobs, client, chunk_runs=args.chunk_runs, progress=True)
    if args.sweep:
        assert name is not None and values is not None  # sweep_jobs names the swept option and its values
        return _write_sweep(args, out, name, values, results)
    result = results[0]
    print(result.table())
    consistency = pooled_consistency(result)
    print(consistency_line(consistency))
    summary = result.to_json()
    summary["consistency"] = consistency.to_json()
    summary["command"] = {
        k: (str(v) if isinstance(v, Path) else v) for k, v in vars(args).items() if not k.startswith("_")
    }
    with staged_outputs(out, "registration montecarlo", MONTECARLO_OUTPUTS) as folder:
        written = [folder.path / "montecarlo.json"]
        with writing(written[0]):
            write_json(written[0], summary, indent=1)
        if not args.no_plots:
            with writing(folder.path / "montecarlo.png"):
                result.plot(folder.path / "montecarlo.png")
            written.append(folder.path / "montecarlo.png")
    print("wrote " + ", ".join(str(folder.final(p)) for p in written))
    return consistency_gate("registration montecarlo", consistency, args.allow_inconsistent)


def _write_sweep(args: argparse.Namespace, out: Path, name: str, values: list, results: list) -> int:
    """The sweep's table and figure, published into ``out``
    whole; exit code of the least consistent grid point."""
    from registration.online.sweep import plot_sweep, sweep_table, write_sweep_table

    table = sweep_table(name, values, results)
    with staged_outputs(out, "registration montecarlo", MONTECARLO_OUTPUTS) as folder:
        with writing(folder.path / f"sweep.{args.format}"):
            written = [write_sweep_table(table, folder.path / "sweep", args.format)]
        if not args.no_plots:
            with writing(folder.path / "sweep.png"):
                plot_sweep(table, folder.path / "sweep.png")
            written.append(folder.path / "sweep.png")
    with_nees = table.drop_duplicates("value")[["value", "nees", "nees_low", "nees_high"]]
    print(f"Monte Carlo sweep over {name}: {len(values)} points x {args.runs} runs")
    print(
        table[["value", "quantity", "unit", "rmse", "filter_sigma", "crlb_sigma", "mean_error"]].to_string(
            index=False, float_format=lambda x: f"{x:.4g}"
        )
    )
    print(with_nees.to_string(index=False, float_format=lambda x: f"{x:.4g}"))
    reports = [pooled_consistency(r) for r in results]
    for v, rep in zip(values, reports):
        print(f"{name}={v}: " + consistency_line(rep))
    print("wrote " + ", ".join(str(folder.final(p)) for p in written))
    worst = next((r for r in reports if not r.ok), reports[0])
    return consistency_gate("registration montecarlo", worst, args.allow_inconsistent)
