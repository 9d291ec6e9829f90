#!/usr/bin/env python3
"""Memory of every process and wall time of ``fleet register --tables DIR`` on Dask workers against
the same run in process, on a Parquet archive as pandas writes it (the plots in one row group, not
in time order; the navigation in row groups of 2^20 rows).

Run from a checkout::

    python3 benchmarks/bench_archive_workers.py                 # 10^6 plots, 2 workers
    python3 benchmarks/bench_archive_workers.py --plots 200000 --json out.json

The archive: the 8 sensors of ``bench_fleet.py`` (three ships, a shore site), ten random targets,
navigation at 80 Hz (3 navigation rows per plot), written by ``write_fleet_tables`` as Parquet and
left as written. Runs (each ``python -m registration fleet register ... --no-plots`` in its own
process tree, one after the other):

* ``in_process``: ``--partition-s P`` (default 600 s);
* ``workers``: the same with ``--workers N`` (default 2), a local Dask cluster;
* ``limit``: ``--memory-limit L`` (default 1GiB) without ``--partition-s``: the run chooses the
  partitioning by itself.

Peak resident memory per process: ``VmHWM`` of every process of the run's tree (the command, the
Dask nannies and workers), read from ``/proc/PID/status`` every POLL_S seconds while the run lives
(VmHWM only grows, so the last reading is the process's peak up to POLL_S before it ended; not
``ru_maxrss``, which a child inherits from its parent). Printed: wall time, the largest peak of
each role, the time ratio ``workers / in_process``, and the largest relative difference of the
estimates (estimates.csv) from the in-process run's. ``--tiny``: 4000 plots, 20 s partitions (its
``limit`` run fits in memory: 0 partitions).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from dataclasses import replace
from pathlib import Path

import numpy as np
from common import add_arguments, write

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
#: Seconds between two readings of the processes' peaks.
POLL_S = 0.2


def prepare(folder: Path, plots: int) -> dict:
    """Simulate about ``plots`` plots and write the archive as ``write_fleet_tables`` writes it."""
    import pyarrow.parquet as pq

    sys.path.insert(0, str(HERE))
    from bench_fleet import CONFIG

    from registration.fleet import fleet_scenario
    from registration.fleet.simulation.tracks import random_targets
    from registration.io import write_fleet_tables

    config = replace(CONFIG, targets=random_targets(10, 7), reference_target="T1")
    sc = fleet_scenario(3, duration_s=plots / 80.0, config=config, nav_rate_hz=80.0)
    write_fleet_tables(
        folder, sc.plots, sc.navigation, sc.sensors, sc.platforms, sc.references, fmt="parquet"
    )
    meta = {n: pq.ParquetFile(folder / f"{n}.parquet").metadata for n in ("plots", "navigation")}
    return {
        "plots": meta["plots"].num_rows,
        "navigation_rows": meta["navigation"].num_rows,
        "plots_row_groups": meta["plots"].num_row_groups,
        "navigation_row_groups": meta["navigation"].num_row_groups,
        "plots_in_time_order": bool(np.all(np.diff(sc.plots["time"]) >= 0)),
    }


def _tree(root: int) -> list[int]:
    """``root`` and its descendants (from /proc/PID/task/*/children)."""
    out, todo = [], [root]
    while todo:
        pid = todo.pop()
        out.append(pid)
        try:
            for task in os.listdir(f"/proc/{pid}/task"):
                with open(f"/proc/{pid}/task/{task}/children") as f:
                    todo += [int(c) for c in f.read().split()]
        except OSError:
            pass
    return out


def _status(pid: int) -> tuple[float | None, str]:
    """(VmHWM in MiB, the command line) of a process (None: gone or no VmHWM)."""
    try:
        with open(f"/proc/{pid}/status") as f:
            hwm = next((int(line.split()[1]) / 1024 for line in f if line.startswith("VmHWM:")), None)
        with open(f"/proc/{pid}/cmdline", "rb") as f:
            cmd = f.read().replace(b"\0", b" ").decode(errors="replace")
    except OSError:
        return None, ""
    return hwm, cmd


def _role(pid: int, root: int, cmd: str) -> str:
    if pid == root:
        return "command"
    if "resource_tracker" in cmd:
        return "resource tracker"
    if "multiprocessing" in cmd or "spawn_main" in cmd or "forkserver" in cmd:
        return "worker"
    return "other"


def measure(name: str, folder: Path, out: Path, extra: list[str]) -> dict:
    """One run of ``fleet register`` with the peaks of every process of its tree (module docstring)."""
    cmd = [sys.executable, "-m", "registration", "fleet", "register", "--tables", str(folder)]
    cmd += ["--out", str(out), "--no-plots", *extra]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(HERE.parent), os.environ.get("PYTHONPATH", "")]))
    t = time.perf_counter()
    log = open(out.parent / f"{name}.log", "w")
    proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, env=env)
    peaks: dict[int, tuple[float, str]] = {}
    while proc.poll() is None:
        for pid in _tree(proc.pid):
            hwm, line = _status(pid)
            if hwm is not None:
                peaks[pid] = (max(hwm, peaks.get(pid, (0.0, ""))[0]), line or peaks.get(pid, (0, ""))[1])
        time.sleep(POLL_S)
    seconds = time.perf_counter() - t
    log.close()
    text = (out.parent / f"{name}.log").read_text()
    if proc.returncode not in (0, 3):
        raise RuntimeError(f"{name}: exit {proc.returncode}\n{text[-3000:]}")
    processes = [
        {"pid": pid, "role": _role(pid, proc.pid, line), "peak_mib": round(hwm, 1)}
        for pid, (hwm, line) in sorted(peaks.items())
    ]
    import pandas as pd

    est = pd.read_csv(out / "estimates.csv").set_index(["object", "state"])
    summary = json.loads((out / "summary.json").read_text())
    return {
        "seconds": seconds,
        "processes": processes,
        "peak_mib": max(p["peak_mib"] for p in processes),
        "partitions": summary.get("partitions", 0),  # 0: registered in memory
        "partition_s": summary.get("partition_s") or 0.0,
        "iterations": summary["iterations"],
        "said": [line for line in text.splitlines() if "partitions of" in line or "by partitions" in line],
        "estimate": est["estimate"].to_numpy(),
        "sigma": est["sigma"].to_numpy(),
    }


def relative(a: np.ndarray, b: np.ndarray) -> float:
    scale = np.maximum(np.abs(b), 1e-300)
    fin = np.isfinite(a) & np.isfinite(b)
    return float(np.max(np.abs(a[fin] - b[fin]) / scale[fin])) if fin.any() else 0.0


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--plots", type=int, default=1_000_000, help="plots in the archive (about)")
    parser.add_argument("--workers", type=int, default=2, help="Dask worker processes")
    parser.add_argument("--partition-s", type=float, default=600.0, help="partition length, s")
    parser.add_argument("--memory-limit", default="1GiB", help="the limit of the 'limit' run")
    parser.add_argument(
        "--modes",
        nargs="+",
        choices=("in_process", "workers", "limit"),
        default=["in_process", "workers", "limit"],
    )
    parser.add_argument("--archive", help="keep the prepared archive in this folder and reuse it")
    add_arguments(parser)
    args = parser.parse_args(argv)
    if args.tiny:
        args.plots, args.partition_s = 4000, 20.0
    report: dict = {"load_before": os.getloadavg(), "runs": {}}
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        folder = Path(args.archive) / f"plots-{args.plots}" if args.archive else work / "archive"
        info_file = folder / "info.json"
        if info_file.exists():
            info = json.loads(info_file.read_text())
        else:
            folder.mkdir(parents=True, exist_ok=True)
            info = prepare(folder, args.plots)
            info_file.write_text(json.dumps(info))
        report["archive"] = info
        print(
            f"{info['plots']} plots in {info['plots_row_groups']} row group(s) (in time order: "
            f"{info['plots_in_time_order']}), {info['navigation_rows']} navigation rows in "
            f"{info['navigation_row_groups']}; load {os.getloadavg()[0]:.1f}",
            flush=True,
        )
        extras = {
            "in_process": ["--partition-s", str(args.partition_s)],
            "workers": ["--partition-s", str(args.partition_s), "--workers", str(args.workers)],
            "limit": ["--memory-limit", args.memory_limit],
        }
        runs = {}
        for m in args.modes:
            runs[m] = measure(m, folder, work / f"out-{m}", extras[m])
            r = runs[m]
            roles: dict[str, float] = {}
            for p in r["processes"]:
                roles[p["role"]] = max(roles.get(p["role"], 0.0), p["peak_mib"])
            print(
                f"  {m:10s} {r['seconds']:8.1f} s  {r['partitions']} partitions of {r['partition_s']:g} s  "
                + ", ".join(f"{k} {v:.0f} MiB" for k, v in sorted(roles.items()))
                + f" (largest of {len(r['processes'])} processes)",
                flush=True,
            )
            for line in r["said"]:
                print(f"      said: {line}")
        base = runs.get("in_process")
        for m, r in runs.items():
            if base is not None and m != "in_process":
                r["estimate_rel"] = relative(r["estimate"], base["estimate"])
                r["sigma_rel"] = relative(r["sigma"], base["sigma"])
                r["time_ratio"] = r["seconds"] / base["seconds"]
                print(
                    f"  {m}: x{r['time_ratio']:.2f} the in-process time; estimates {r['estimate_rel']:.1e}, "
                    f"sigmas {r['sigma_rel']:.1e} relative to the in-process run's"
                )
        report["runs"] = {
            m: {k: v for k, v in r.items() if k not in ("estimate", "sigma")} for m, r in runs.items()
        }
    report["load_after"] = os.getloadavg()
    write(
        "archive_workers",
        args,
        {"plots": args.plots, "workers": args.workers, "partition_s": args.partition_s},
        report,
    )
    return report


if __name__ == "__main__":
    main()
