#!/usr/bin/env python3
"""Memory and time of the partitioned batch solver on Parquet archives against the in-memory
``solve_batch``, each run in its own subprocess (peak resident memory: ``ru_maxrss`` of that process).

Run from a checkout::

    python3 benchmarks/bench_archive.py                       # 80 000 plots, then 10^6 plots
    python3 benchmarks/bench_archive.py --sizes 80000 --json out.json

Problems: the 8 sensors of ``bench_fleet.py`` (three ships, a shore site; 1 Hz each), ten targets;
``80000``: bench_fleet's own problem (its ten targets, 1000 s, navigation at 10 Hz); larger sizes:
ten random targets circling in the area (``random_targets``, they stay in coverage) over as many
seconds as the plots need, navigation at ``--nav-hz`` (80 Hz: 3 * 10^6 navigation rows for 10^6
plots). The tables are written with ``write_fleet_tables`` as Parquet, then the plots and the
navigation rewritten sorted by time (navigation: by platform, then time) in row groups of
ROW_GROUP rows, as an archive would be laid out.

Runs (each a fresh process):

* ``batch``: ``read_fleet_tables`` + ``solve_batch`` (today's in-memory path; only for sizes up to
  ``--batch-max``);
* ``cached``: ``solve_batch_partitioned`` on the Parquet folder, every partition's design kept in
  memory (the speed path when the archive fits);
* ``bounded``: the same with no partition kept (memory bounded by a partition: each pass reads
  and builds every partition again).

Printed per run: wall time of the solve (s; reading included), peak RSS (MiB), iterations, and
the largest relative difference of the estimates and sigmas from the ``batch`` run of the same
size; then the ratios (time and memory) against ``batch`` in the same invocation.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

ROW_GROUP = 100_000
HERE = Path(__file__).resolve().parent


def prepare(folder: Path, plots: int, nav_hz: float) -> dict:
    """Simulate about ``plots`` plots and write them as a Parquet archive in ``folder``."""
    import pyarrow.parquet as pq

    sys.path.insert(0, str(HERE))
    from bench_fleet import CONFIG

    from registration.fleet import fleet_scenario
    from registration.fleet.simulation.tracks import random_targets
    from registration.io import write_fleet_tables

    if plots <= 80_000:
        sc = fleet_scenario(3, duration_s=plots / 80.0, config=CONFIG)
    else:
        config = replace(CONFIG, targets=random_targets(10, 7), reference_target="T1")
        sc = fleet_scenario(3, duration_s=plots / 80.0, config=config, nav_rate_hz=nav_hz)
    write_fleet_tables(folder, sc.plots, sc.navigation, sc.sensors, sc.platforms, sc.references, fmt="parquet")
    for name, keys in (("plots", [("time_s", "ascending")]),
                       ("navigation", [("platform", "ascending"), ("time_s", "ascending")])):
        table = pq.read_table(folder / f"{name}.parquet").sort_by(keys)
        pq.write_table(table, folder / f"{name}.parquet", row_group_size=ROW_GROUP)
    return {"plots": int(sc.plots["time"].size), "navigation_rows": int(sc.navigation["time"].size)}


def run(mode: str, folder: Path, partition_s: float, out: Path) -> None:
    """One measured run (in this process): writes its figures and estimate to ``out``."""
    from registration.fleet.batch.archive import ParquetSource
    from registration.fleet.batch.partitioned import solve_batch_partitioned
    from registration.io.fleet.cells import FILE_COLUMNS

    t = time.perf_counter()
    if mode == "batch":
        from registration.fleet import solve_batch
        from registration.io import read_fleet_tables

        names = ("plots", "navigation", "sensors", "platforms", "reference")
        problem = read_fleet_tables(*(folder / f"{n}.parquet" for n in names)).problem()
        t_solve = time.perf_counter()
        result = solve_batch(problem)
        solve_seconds = time.perf_counter() - t_solve
    else:
        solve_seconds = None
        source = ParquetSource(folder, FILE_COLUMNS)
        result = solve_batch_partitioned(source, partition_s=partition_s, cache=10**6 if mode == "cached" else 0)
    seconds = time.perf_counter() - t
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    np.savez(out.with_suffix(".npz"), estimate=result.estimate, sigma=result.sigma)
    out.write_text(json.dumps({"seconds": seconds, "peak_mib": rss, "iterations": int(result.iterations),
                               "solve_seconds": solve_seconds}))


def measure(mode: str, folder: Path, partition_s: float, work: Path) -> dict:
    out = work / f"{mode}-{folder.name}.json"
    subprocess.run([sys.executable, __file__, "--run", mode, "--folder", str(folder), "--partition-s",
                    str(partition_s), "--out", str(out)], check=True)
    figures = json.loads(out.read_text())
    with np.load(out.with_suffix(".npz")) as data:
        figures["estimate"], figures["sigma"] = data["estimate"], data["sigma"]
    return figures


def relative(a: np.ndarray, b: np.ndarray) -> float:
    fin = np.isfinite(b) & (b != 0)
    return float(np.max(np.abs(a[fin] - b[fin]) / np.abs(b[fin]))) if fin.any() else 0.0


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[80_000, 1_000_000], help="plots per problem")
    parser.add_argument("--nav-hz", type=float, default=80.0, help="ship navigation rate for sizes above 80 000")
    parser.add_argument("--partition-s", type=float, default=200.0, help="partition length, s")
    parser.add_argument("--batch-max", type=int, default=400_000, help="largest size also run in memory")
    parser.add_argument("--json", help="write the figures to this file")
    parser.add_argument("--run", help=argparse.SUPPRESS)
    parser.add_argument("--folder", help=argparse.SUPPRESS)
    parser.add_argument("--out", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.run:
        run(args.run, Path(args.folder), args.partition_s, Path(args.out))
        return {}
    report = {"load": os.getloadavg(), "partition_s": args.partition_s, "sizes": {}}
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        for size in args.sizes:
            folder = work / f"archive-{size}"
            folder.mkdir()
            info = prepare(folder, size, args.nav_hz)
            modes = ["batch", "cached", "bounded"] if size <= args.batch_max else ["bounded"]
            runs = {m: measure(m, folder, args.partition_s, work) for m in modes}
            base = runs.get("batch")
            print(f"{info['plots']} plots, {info['navigation_rows']} navigation rows, load {os.getloadavg()[0]:.1f}")
            for m, r in runs.items():
                line = f"  {m:8s} {r['seconds']:8.2f} s {r['peak_mib']:8.0f} MiB peak  {r['iterations']} iterations"
                if r.get("solve_seconds") is not None:
                    line += f" (reading {r['seconds'] - r['solve_seconds']:.2f} s, solve_batch {r['solve_seconds']:.2f} s)"
                if base is not None and m != "batch":
                    r["estimate_rel"] = relative(r["estimate"], base["estimate"])
                    r["sigma_rel"] = relative(r["sigma"], base["sigma"])
                    r["time_ratio"] = r["seconds"] / base["seconds"]
                    r["memory_ratio"] = r["peak_mib"] / base["peak_mib"]
                    r["solve_ratio"] = r["seconds"] / base["solve_seconds"]
                    line += (f"  x{r['time_ratio']:.2f} time (x{r['solve_ratio']:.2f} of solve_batch alone), x{r['memory_ratio']:.2f} memory of batch; estimates "
                             f"{r['estimate_rel']:.1e}, sigmas {r['sigma_rel']:.1e} relative")
                print(line, flush=True)
            report["sizes"][size] = {**info, **{m: {k: v for k, v in r.items() if k not in ("estimate", "sigma")}
                                                for m, r in runs.items()}}
    if args.json:
        Path(args.json).write_text(json.dumps(report, indent=2))
    return report


if __name__ == "__main__":
    main()
