#!/usr/bin/env python3
"""Speed of the Monte Carlo evaluation: the run-by-run path the package used before (kept here as
the baseline) against the batch ``run_montecarlo``, with ``register()`` over the same rows as the
reference.

Run from a checkout (the package installed, editable or not)::

    python3 benchmarks/bench_montecarlo.py                    # 1000 runs; the baseline at 100 runs
    python3 benchmarks/bench_montecarlo.py --legacy-runs 1000 --json bench_montecarlo.json

Contenders, median of ``--repeat`` rounds interleaved in alternating order (common.interleave)
after one warm-up, ratios the median of the rounds' ratios, all in one process (figures:
benchmarks/results/montecarlo.json; ``--tiny``: 4 runs):

1. ``run by run``: the previous implementation, copied below (``legacy_*``): per seed, the paper
   scenario with its per-step dead reckoning, ``register()`` and the Cramér-Rao bound, then the
   same statistics (:func:`registration.online.montecarlo.summarise_runs`).
2. ``batch``: :func:`registration.online.montecarlo.run_montecarlo` (tracks once, every run's
   filter in one compiled call), at the baseline's number of runs and at ``--runs``.
3. ``register()`` over the same number of rows (the batch's rows of all runs end to end, times
   renumbered): the reference the batch is measured against.
4. End to end: ``python -m registration montecarlo --runs N --no-plot`` as a subprocess (start-up,
   imports, SciPy for the chi-square intervals, JSON output), and ``python -c pass`` for scale.

Before timing, the baseline's and the batch's results are compared field by field: equal bit for
bit except the Cramér-Rao bound, which the baseline averaged over R identical copies (its
rounding is the difference, printed). Aim: the end-to-end command within 3x one ``register()``
call over the same rows; the script says whether it is met. Timings are noisy on a shared
machine: compare the ratios, measured in the same run.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from common import add_arguments, interleave, median, paired_ratio, summary, write

from registration import _codegen
from registration.core.angles import wrap_angle
from registration.online import RegistrationConfig, register
from registration.online.contract import DATA_COLUMNS, N_STATE, ROW_COLUMNS, STATE_NAMES
from registration.online.crlb import crlb_from_information, crlb_information
from registration.online.montecarlo import collect_runs, run_montecarlo, summarise_runs
from registration.online.scenario import Scenario, paper_scenarios

AIM_RATIO = 3.0
SHIPS = {
    "a": dict(lat0=np.radians(20.0), lon0=np.radians(115.0), course=np.radians(150.0), speed=12.0),
    "b": dict(lat0=np.radians(20.0), lon0=np.radians(115.5), course=np.radians(330.0), speed=8.0),
}


# --------------------------------------------------------------------------- the previous path (baseline)
def legacy_dead_reckon(lat0, lon0, alt, course, speed, dt, substeps=10):
    """The previous per-step integration, verbatim."""
    radii = _codegen.get("radii_of_curvature")
    k = len(course)
    lat, lon = np.empty(k), np.empty(k)
    la, lo = float(lat0), float(lon0)
    h = dt / substeps
    for i in range(k):
        lat[i], lon[i] = la, lo
        M, N = radii(la)[0][0]
        for _ in range(substeps):
            la += speed[i] * np.cos(course[i]) * h / (M + alt[i])
            lo += speed[i] * np.sin(course[i]) * h / ((N + alt[i]) * np.cos(la))
    return lat, lon


def legacy_paper_scenario(seed: int, n_steps: int = 300, dt: float = 1.0) -> Scenario:
    """The previous ``paper_scenario`` with its defaults (level ships, standard T), one seed."""
    rng = np.random.default_rng(seed)
    t = np.arange(n_steps) * dt
    deg = np.where(
        t < 60,
        240.0,
        np.where(t < 150, 240.0 + 2.0 * (t - 60), np.where(t < 210, 420.0, 420.0 - 2.0 * (t - 210))),
    )
    M, N = _codegen.get("radii_of_curvature")(np.radians(20.0))[0][0]
    tgt_alt = np.linspace(2000.0, 4000.0, n_steps)
    tgt_lat, tgt_lon = legacy_dead_reckon(
        np.radians(20.0) + 45_000.0 / (M + 2000.0),
        np.radians(115.25),
        tgt_alt,
        np.radians(np.mod(deg, 360.0)),
        200.0 * np.ones(n_steps),
        dt,
    )
    p_target = _codegen.get("geodetic2ecef")(tgt_lat, tgt_lon, tgt_alt)[0]
    err = {
        "heading": np.radians(0.1),
        "level": np.radians(0.03),
        "bias": [1000.0, np.radians(0.5), np.radians(0.5)],
    }
    sigmas = np.array([50.0, np.radians(0.5), np.radians(0.5)])
    data, truth = {"time": t}, {}
    for p, ship in SHIPS.items():
        ones = np.ones(n_steps)
        alt, heading, level = 20.0 * ones, ship["course"] * ones, np.zeros(n_steps)
        lat, lon = legacy_dead_reckon(ship["lat0"], ship["lon0"], alt, heading, ship["speed"] * ones, dt)
        plot = _codegen.get("ecef2plot_standard")(p_target, lat, lon, alt, heading, level, level)[0]
        measured = plot + err["bias"] + rng.normal(size=(n_steps, 3)) * sigmas
        data.update(
            {
                f"{p}_lat": lat,
                f"{p}_lon": lon,
                f"{p}_alt": alt,
                f"{p}_heading": wrap_angle(heading + err["heading"]),
                f"{p}_pitch": level + err["level"],
                f"{p}_roll": level + err["level"],
                f"{p}_range": measured[:, 0],
                f"{p}_bearing": wrap_angle(measured[:, 1]),
                f"{p}_elevation": measured[:, 2],
            }
        )
        truth.update({f"{p}_heading": heading, f"{p}_pitch": level, f"{p}_roll": level, f"{p}_plot": plot})
    truth_state = np.array([err["heading"], err["level"], err["level"], *err["bias"]] * 2)
    return Scenario(
        data=data,
        truth_state=truth_state,
        truth=truth,
        sigma0=np.tile(sigmas, 2),
        description={"seed": seed, "t_variant": "standard"},
    )


def legacy_collect_runs(runs: int, seed0: int, config: RegistrationConfig) -> dict:
    """The previous collection loop: scenario, register() and the bound per seed."""
    out: dict = {"status_counts": {n: {} for n in STATE_NAMES}, "combo_counts": {}, "config": config}
    for r in range(runs):
        sc = legacy_paper_scenario(seed0 + r)
        res = register(sc.data, config)
        if r == 0:
            k = len(res.time)
            out.update(
                time=res.time,
                description={},
                err=np.empty((runs, k, N_STATE)),
                P=np.empty((runs, k, N_STATE, N_STATE)),
                nis=np.empty((runs, k)),
                crlb=np.zeros((k, N_STATE, N_STATE)),
            )
        out["err"][r] = res.estimates - sc.truth_state
        out["P"][r] = res.covariances
        out["nis"][r] = res.nis
        out["crlb"] += crlb_from_information(crlb_information(sc), config.prior_sigma)
        for name, status in res.observability.status.items():
            out["status_counts"][name][status] = out["status_counts"][name].get(status, 0) + 1
        for comb in res.identifiable_combinations():
            pair = tuple(STATE_NAMES[i] for i in sorted(comb["indices"]))
            out["combo_counts"][pair] = out["combo_counts"].get(pair, 0) + 1
    out["crlb"] = out["crlb"] / runs
    return out


# --------------------------------------------------------------------------- helpers
def compare(old, new) -> dict:
    """Largest relative difference per array field of two MonteCarloResults (0.0: bit for bit)."""
    out = {}
    for name in ("rmse", "mean_error", "filter_sigma", "filter_two_sigma_mean", "crlb_sigma", "nees", "nis"):
        a, b = getattr(old, name), getattr(new, name)
        out[name] = float(np.max(np.abs(a - b) / np.maximum(np.abs(a), 1e-300)))
    out["counts_equal"] = (
        old.status_counts == new.status_counts and old.combination_counts == new.combination_counts
    )
    out["quantities_equal"] = [q.name for q in old.quantities] == [q.name for q in new.quantities]
    return out


def rows_data(runs: int, seed0: int) -> dict:
    """The batch's rows of ``runs`` runs end to end as one data set (times renumbered)."""
    rows = paper_scenarios(range(seed0, seed0 + runs)).rows.reshape(-1, len(ROW_COLUMNS))
    data = {c: np.ascontiguousarray(rows[:, j]) for j, c in enumerate(DATA_COLUMNS[1:])}
    data["time"] = np.arange(len(rows), dtype=float)
    return data


def command(argv: list[str]):
    """A contender: one run of a subprocess."""
    return lambda: subprocess.run(argv, check=True, capture_output=True)


def stages(runs: int, seed0: int, config) -> dict:
    """Seconds of the batch's stages (one pass; the scenario tracks are cached by then)."""
    from registration.online import runs as batch

    out, t = {}, time.perf_counter
    t0 = t()
    sims = paper_scenarios(range(seed0, seed0 + runs))
    out["scenario rows"] = t() - t0
    t0 = t()
    res = batch.filter_runs(config, sims.rows)
    out["filter, all runs (compiled)"] = t() - t0
    t0 = t()
    batch.information_at_estimates(sims.rows, res["x"][:, -1], config.sigma0, config.t_variant)
    out["information at the estimates (compiled)"] = t() - t0
    t0 = t()
    data = collect_runs(runs, seed0, config, False, {})
    out["collect_runs (all of the above + observability reports + bound)"] = t() - t0
    t0 = t()
    summarise_runs(data, seed0)
    out["statistics (summarise_runs)"] = t() - t0
    return out


# --------------------------------------------------------------------------- main
def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument(
        "--runs",
        type=int,
        default=1000,
        help="runs of the batch and of the end-to-end command (default 1000)",
    )
    ap.add_argument(
        "--legacy-runs",
        type=int,
        default=100,
        help="runs of the run-by-run baseline (default 100; it is slow)",
    )
    ap.add_argument(
        "--repeat", type=int, default=3, help="timed rounds per contender, interleaved (default 3)"
    )
    ap.add_argument("--seed", type=int, default=0)
    add_arguments(ap)
    args = ap.parse_args(argv)
    if args.tiny:
        args.runs, args.legacy_runs, args.repeat = 4, 2, 1
    config = RegistrationConfig()
    n_legacy, n_runs, seed = args.legacy_runs, args.runs, args.seed
    print(
        f"backend {_codegen.backend()}, numpy {np.__version__}, {os.cpu_count()} CPUs; paper scenario, 300 "
        "rows per run; "
        f"median of {args.repeat} interleaved rounds"
    )

    old = summarise_runs(legacy_collect_runs(n_legacy, seed, config), seed)
    new = run_montecarlo(n_legacy, seed, config)
    diff = compare(old, new)
    print(f"\nbaseline vs batch, {n_legacy} runs (largest relative difference; 0 = bit for bit):")
    for k, v in diff.items():
        print(f"  {k:<24}{v}")

    data_small, data_big = rows_data(n_legacy, seed), rows_data(n_runs, seed)
    with tempfile.TemporaryDirectory() as tmp:
        cli = [sys.executable, "-m", "registration", "montecarlo", "--runs", str(n_runs), "--no-plot"]
        contenders = {
            f"run by run (before), {n_legacy} runs": lambda: summarise_runs(
                legacy_collect_runs(n_legacy, seed, config), seed
            ),
            f"batch run_montecarlo, {n_legacy} runs": lambda: run_montecarlo(n_legacy, seed, config),
            f"register(), {n_legacy * 300} rows": lambda: register(data_small, config),
            f"batch run_montecarlo, {n_runs} runs": lambda: run_montecarlo(n_runs, seed, config),
            f"register(), {n_runs * 300} rows": lambda: register(data_big, config),
            "command": command([*cli, "--out", tmp]),
            "python -c pass": command([sys.executable, "-c", "pass"]),
        }
        times, _ = interleave(contenders, args.repeat, warmup=0 if args.tiny else 1)
    mid = {label: median(t) for label, t in times.items()}
    labels = list(mid)
    print(f"\n  {'contender':<44}{'seconds':>10}")
    for label, sec in mid.items():
        print(f"  {label:<44}{sec:10.3f}")
    legacy_ratio = paired_ratio(times, labels[0], labels[1])
    small_ratio, big_ratio = (
        paired_ratio(times, labels[1], labels[2]),
        paired_ratio(times, labels[3], labels[4]),
    )
    print(f"\n  batch vs run by run, {n_legacy} runs: {legacy_ratio:.1f}x faster")
    print(
        f"  batch / register() over the same rows: {n_legacy} runs {small_ratio:.2f}x, {n_runs} runs "
        f"{big_ratio:.2f}x"
    )
    cli_s, start_s = mid["command"], mid["python -c pass"]
    cli_ratio = paired_ratio(times, "command", labels[4])
    print(
        f"\nend to end: `registration montecarlo --runs {n_runs} --no-plot` {cli_s:.2f} s (python -c pass: "
        f"{start_s:.2f} s)"
    )
    print(
        f"  = {cli_ratio:.2f}x one register() call over the same {n_runs * 300} rows; aim <= "
        f"{AIM_RATIO:.0f}x: "
        f"{'met' if cli_ratio <= AIM_RATIO else 'NOT met'}"
    )

    parts = stages(n_runs, seed, config)
    print(f"\nstages of the batch, {n_runs} runs (one pass):")
    for k, v in parts.items():
        print(f"  {k:<70}{v:8.3f} s")

    payload = {
        "seconds": summary(times),
        "batch_vs_run_by_run": legacy_ratio,
        "batch_over_register": {str(n_legacy): small_ratio, str(n_runs): big_ratio},
        "cli_seconds": cli_s,
        "python_start_seconds": start_s,
        "cli_over_register": cli_ratio,
        "aim_ratio": AIM_RATIO,
        "stages_seconds": parts,
        "max_relative_difference": diff,
    }
    write("montecarlo", args, {"runs": n_runs, "legacy_runs": n_legacy, "repeat": args.repeat}, payload)
    return 0


if __name__ == "__main__":
    sys.exit(main())
