#!/usr/bin/env python3
"""Memory and time of the partitioned batch solver on Parquet archives against the in-memory
``solve_batch``, each run in its own subprocess (peak resident memory: ``VmHWM`` of that process,
see ``peak_mib``).

Run from a checkout::

    python3 benchmarks/bench_archive.py                       # 80 000 plots, then 10^6 plots
    python3 benchmarks/bench_archive.py --sizes 80000 --json out.json

Problems: the 8 sensors of ``bench_fleet.py`` (three ships, a shore site; 1 Hz each), ten targets;
``80000``: bench_fleet's own problem (its ten targets, 1000 s, navigation at 10 Hz); larger sizes:
ten random targets circling in the area (``random_targets``, they stay in coverage) over as many
seconds as the plots need, navigation at ``--nav-hz`` (80 Hz: 3 * 10^6 navigation rows for 10^6
plots). The tables are written with ``write_fleet_tables`` as Parquet, then the plots and the
navigation rewritten sorted by time (navigation: by platform, then time) in row groups of
ROW_GROUP rows, as an archive would be laid out. Sizes above TILE (10^6) repeat the 10^6 archive
in time (``tile``: the ships sail out of the area after about 40 000 s, so a longer simulation
would thin out), each copy's targets named anew. ``--archives DIR`` keeps the prepared archives
(``DIR/archive-<size>``) for later runs.

Runs (each a fresh process):

* ``batch``: ``read_fleet_tables`` + ``solve_batch`` (today's in-memory path; only for sizes up to
  ``--batch-max``);
* ``cached``: ``solve_batch_partitioned`` on the Parquet folder, every partition's design kept in
  memory (the speed path when the archive fits);
* ``bounded``: the same with no partition kept in memory (memory bounded by a partition): the
  setup pass writes each partition's design to a temporary folder on local disk (the spill cache,
  ``registration.fleet.batch.partitioned.spill``) and the later passes read it from there;
* ``reread`` (only when asked with ``--modes``): no cache at all, each pass reads and builds every
  partition from the Parquet files again (the bounded mode before the spill cache).

Printed per run: wall time of the solve (s; reading included), peak RSS (MiB), iterations, and
the largest relative difference of the estimates and sigmas from the ``batch`` run of the same
size; then the ratios (time and memory) against ``batch`` in the same invocation. The runs of one
size are interleaved (common.interleave, ``--repeat`` rounds, default 1; times are medians, the
time ratio the median of the rounds' ratios). Figures: benchmarks/results/archive.json;
``--tiny``: 1600 plots in 5 s partitions.
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
from common import Timed, add_arguments, interleave, median, paired_ratio, write

ROW_GROUP = 100_000
#: Larger archives are this one repeated in time (tile).
TILE = 1_000_000
HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))  # the checkout's registration, also in the measured subprocesses


def prepare(folder: Path, plots: int, nav_hz: float) -> dict:
    """Simulate about ``plots`` plots and write them as a Parquet archive in ``folder`` (above TILE
    plots: the TILE-plot archive repeated in time, see :func:`tile`)."""
    import pyarrow.parquet as pq

    if plots > TILE:
        base = folder / "tile"
        base.mkdir(parents=True, exist_ok=True)
        info = prepare(base, TILE, nav_hz)
        return tile(base, folder, max(1, round(plots / info["plots"])), nav_hz)

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
    write_fleet_tables(
        folder, sc.plots, sc.navigation, sc.sensors, sc.platforms, sc.references, fmt="parquet"
    )
    for name, keys in (
        ("plots", [("time_s", "ascending")]),
        ("navigation", [("platform", "ascending"), ("time_s", "ascending")]),
    ):
        table = pq.read_table(folder / f"{name}.parquet").sort_by(keys)
        pq.write_table(table, folder / f"{name}.parquet", row_group_size=ROW_GROUP)
    return {"plots": int(sc.plots["time"].size), "navigation_rows": int(sc.navigation["time"].size)}


def tile(base: Path, folder: Path, copies: int, nav_hz: float) -> dict:
    """Write ``copies`` copies of the archive ``base`` one after the other in time into ``folder``
    (copy k: times + k (end of the ships' navigation + one sample), targets renamed ``<id>_k``;
    a fixed site's one navigation row kept once), then remove ``base``. The simulated ships sail out
    of the targets' area after about 40 000 s, so a longer simulation would not keep the plot rate
    (10 h at 80 plots/s): the copies keep it, with the same geometry and noise in every copy."""
    import shutil

    import pyarrow as pa
    import pyarrow.compute as pc
    import pyarrow.parquet as pq

    nav = pq.read_table(base / "navigation.parquet")
    shift = float(pc.max(nav["time_s"]).as_py()) + 1.0 / nav_hz
    counts = {"plots": 0, "navigation_rows": 0}

    def shifted(table, k: int):
        table = table.set_column(
            table.schema.get_field_index("time_s"), "time_s", pc.add(table["time_s"], pa.scalar(k * shift))
        )
        if "target" in table.schema.names:
            table = table.set_column(
                table.schema.get_field_index("target"),
                "target",
                pc.binary_join_element_wise(table["target"].cast(pa.string()), f"_{k}", ""),
            )
        return table

    for name in ("plots", "reference"):
        table = pq.read_table(base / f"{name}.parquet")
        with pq.ParquetWriter(folder / f"{name}.parquet", shifted(table, 0).schema) as writer:
            for k in range(copies):
                writer.write_table(shifted(table, k), row_group_size=ROW_GROUP)
                counts["plots"] += table.num_rows if name == "plots" else 0
    with pq.ParquetWriter(folder / "navigation.parquet", nav.schema) as writer:
        for platform in sorted(set(nav["platform"].to_pylist())):
            rows = nav.filter(pc.equal(nav["platform"], platform))
            for k in range(copies if rows.num_rows > 1 else 1):
                writer.write_table(shifted(rows, k), row_group_size=ROW_GROUP)
                counts["navigation_rows"] += rows.num_rows
    for name in ("sensors", "platforms"):
        shutil.copy(base / f"{name}.parquet", folder / f"{name}.parquet")
    shutil.rmtree(base)
    return counts


def peak_mib() -> float:
    """This process's peak resident memory (MiB): ``VmHWM`` of /proc/self/status where there is one.

    ``ru_maxrss`` alone is not this process's: Linux carries the parent's peak over the fork and
    exec of a subprocess, so a child started by a parent that simulated a large archive reported
    the parent's peak (the 1098 MiB of the first 10^6 measurement). VmHWM belongs to the new process
    image only; where it is missing ``ru_maxrss`` is used."""
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def run(mode: str, folder: Path, partition_s: float, out: Path) -> None:
    """One measured run (in this process): writes its figures and estimate to ``out``."""
    from registration.fleet.batch.partitioned import solve_batch_partitioned
    from registration.io.fleet.archive.parquet import ParquetSource

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
        source = ParquetSource(folder)
        result = solve_batch_partitioned(
            source,
            partition_s=partition_s,
            cache=10**6 if mode == "cached" else 0,
            spill=False if mode == "reread" else None,
        )
    seconds = time.perf_counter() - t
    rss = peak_mib()
    np.savez(out.with_suffix(".npz"), estimate=result.estimate, sigma=result.sigma)
    out.write_text(
        json.dumps(
            {
                "seconds": seconds,
                "peak_mib": rss,
                "iterations": int(result.iterations),
                "solve_seconds": solve_seconds,
            }
        )
    )


def measure(mode: str, folder: Path, partition_s: float, work: Path) -> dict:
    out = work / f"{mode}-{folder.name}.json"
    subprocess.run(
        [
            sys.executable,
            __file__,
            "--run",
            mode,
            "--folder",
            str(folder),
            "--partition-s",
            str(partition_s),
            "--out",
            str(out),
        ],
        check=True,
    )
    figures = json.loads(out.read_text())
    with np.load(out.with_suffix(".npz")) as data:
        figures["estimate"], figures["sigma"] = data["estimate"], data["sigma"]
    return figures


def timed(figures: dict) -> Timed:
    """A run's figures, timed by the run itself (reading and solve, not the process start)."""
    return Timed(figures["seconds"], figures)


def relative(a: np.ndarray, b: np.ndarray) -> float:
    fin = np.isfinite(b) & (b != 0)
    return float(np.max(np.abs(a[fin] - b[fin]) / np.abs(b[fin]))) if fin.any() else 0.0


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[80_000, 1_000_000], help="plots per problem")
    parser.add_argument(
        "--nav-hz", type=float, default=80.0, help="ship navigation rate for sizes above 80 000"
    )
    parser.add_argument("--partition-s", type=float, default=200.0, help="partition length, s")
    parser.add_argument("--batch-max", type=int, default=400_000, help="largest size also run in memory")
    parser.add_argument(
        "--archives",
        help="keep the prepared archives in this folder (archive-<size>/) and reuse "
        "them in later runs (default: a temporary folder, removed)",
    )
    parser.add_argument(
        "--modes",
        nargs="+",
        choices=("batch", "cached", "bounded", "reread"),
        help="runs to make (default: batch, cached, bounded; bounded only above --batch-max)",
    )
    parser.add_argument("--repeat", type=int, default=1, help="interleaved rounds of the runs per size")
    add_arguments(parser)
    parser.add_argument("--run", help=argparse.SUPPRESS)
    parser.add_argument("--folder", help=argparse.SUPPRESS)
    parser.add_argument("--out", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.run:
        run(args.run, Path(args.folder), args.partition_s, Path(args.out))
        return {}
    if args.tiny:  # 20 s of data in 5 s partitions
        args.sizes, args.partition_s, args.repeat = [1600], 5.0, 1
    report = {"load": os.getloadavg(), "partition_s": args.partition_s, "sizes": {}}
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        for size in args.sizes:
            folder = (Path(args.archives) if args.archives else work) / f"archive-{size}"
            info_file = folder / "info.json"
            if info_file.exists():
                info = json.loads(info_file.read_text())
            else:
                folder.mkdir(parents=True, exist_ok=True)
                info = prepare(folder, size, args.nav_hz)
                info_file.write_text(json.dumps(info))
            modes = ["batch", "cached", "bounded"] if size <= args.batch_max else ["bounded"]
            if args.modes:
                modes = [m for m in ("batch", "cached", "bounded", "reread") if m in args.modes]
            contenders = {m: (lambda m=m: timed(measure(m, folder, args.partition_s, work))) for m in modes}
            times, runs = interleave(contenders, args.repeat, warmup=0)
            for m, r in runs.items():
                r["seconds"], r["rounds_seconds"] = median(times[m]), times[m]
            base = runs.get("batch")
            print(
                f"{info['plots']} plots, {info['navigation_rows']} navigation rows, load "
                f"{os.getloadavg()[0]:.1f}"
            )
            for m, r in runs.items():
                line = (
                    f"  {m:8s} {r['seconds']:8.2f} s {r['peak_mib']:8.0f} MiB peak  "
                    f"{r['iterations']} iterations"
                )
                if r.get("solve_seconds") is not None:
                    line += (
                        f" (reading {r['seconds'] - r['solve_seconds']:.2f} s, "
                        f"solve_batch {r['solve_seconds']:.2f} s)"
                    )
                if base is not None and m != "batch":
                    r["estimate_rel"] = relative(r["estimate"], base["estimate"])
                    r["sigma_rel"] = relative(r["sigma"], base["sigma"])
                    r["time_ratio"] = paired_ratio(times, m, "batch")
                    r["memory_ratio"] = r["peak_mib"] / base["peak_mib"]
                    r["solve_ratio"] = r["seconds"] / base["solve_seconds"]
                    line += (
                        f"  x{r['time_ratio']:.2f} time (x{r['solve_ratio']:.2f} of solve_batch alone), "
                        f"x{r['memory_ratio']:.2f} memory of batch; estimates "
                        f"{r['estimate_rel']:.1e}, sigmas {r['sigma_rel']:.1e} relative"
                    )
                print(line, flush=True)
            report["sizes"][size] = {
                **info,
                **{
                    m: {k: v for k, v in r.items() if k not in ("estimate", "sigma")} for m, r in runs.items()
                },
            }
    write("archive", args, {"sizes": args.sizes, "repeat": args.repeat}, report)
    return report


if __name__ == "__main__":
    main()
