#!/usr/bin/env python3
"""Throughput and peak memory of ``registration register`` on large recorded files.

Run from a checkout (the package installed, editable or not)::

    python3 benchmarks/bench_register.py                       # 10^5 and 10^6 rows
    python3 benchmarks/bench_register.py --rows 100000 300000 --json results.json
    python3 benchmarks/bench_register.py --rows 3000000 --cases csv csv-plots   # plots on and off

Input: the paper scenario (300 synchronous pairs at 1 s, seed 0) tiled until the wanted number of
rows, time shifted so it keeps increasing, with a little extra noise per row (1 m in range, 0.001 deg
in the angles) so that the copies differ, written once per size as CSV and as Parquet (row groups
of 100,000). Each measurement runs in a fresh worker process that imports the package, records
its resident set size (RSS, ``/proc/self/status`` VmRSS), resets the peak mark (``clear_refs``), runs
:func:`registration.recorded.run_register` exactly as the CLI does (no progress bar; no plots except
in the ``*-plots`` cases, which draw the three PNGs as the CLI does by default) and reports the
wall time and its peak RSS during the run (VmHWM; ``ru_maxrss`` where /proc is missing, which also
counts the pre-exec image). "Above baseline" subtracts the RSS after the
imports (numpy, pandas, pyarrow, casadi, the compiled generated code), which does not depend on
the input. Rows per second count input rows over the whole command: both passes (filter, then the
information matrix at the final estimate), validation, the input hash, the output writing.

For comparison the in-memory API :func:`registration.online.register` is measured on the smaller
sizes: it keeps every step's covariance (K x 12 x 12 doubles, 1.15 kB per row), so its memory
grows with the input, which is exactly what the streaming runner avoids (blocks of
``--chunk-rows`` rows, default 20,000).

The cases of one size run interleaved (common.interleave; ``--repeat`` rounds, default 1, times
are medians). Figures: benchmarks/results/register.json; ``--tiny``: 600 rows.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from common import ROOT, Timed, add_arguments, interleave, median, write

WORKER = r"""
import json, resource, sys, time
from pathlib import Path
mode, path, out, extra = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3]), json.loads(sys.argv[4])


def status(key):
    try:
        for line in open("/proc/self/status"):
            if line.startswith(key + ":"):
                return int(line.split()[1]) / 1024  # kB -> MiB
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


import numpy, pandas, pyarrow, pyarrow.parquet, pyarrow.csv  # noqa: F401  (baseline)
from registration import _codegen as _loader
from registration.online import RegistrationConfig, register
from registration.recorded import RunOptions, read_table, run_register
for name in ("kalman_step_paper_standard", "pseudo_measurement_standard"):
    _loader.get(name)
base = status("VmRSS")
try:  # reset the peak-RSS mark (VmHWM) so the peak below is that of the run alone
    with open("/proc/self/clear_refs", "w") as f:
        f.write("5")
except OSError:
    pass
t0 = time.perf_counter()
if mode == "stream":
    opts = RunOptions(out=out, progress=False, log=lambda m: None, **{"plots": False, **extra})
    summary = run_register([path], opts)
    rows = summary["rows"]["read"]
else:
    result = register(read_table(path))
    rows = len(result.time)
dt = time.perf_counter() - t0
peak = status("VmHWM")
print(json.dumps({"rows": rows, "seconds": dt, "baseline_mib": base, "peak_mib": peak}))
"""


def make_inputs(n_rows: int, folder: Path) -> dict:
    """CSV and Parquet files of n_rows tiled scenario rows, written piece by piece."""
    import numpy as np
    import pyarrow as pa
    import pyarrow.csv as pacsv
    import pyarrow.parquet as pq

    from registration.online.scenario import paper_scenario
    from registration.recorded import to_file_frame

    base = to_file_frame(paper_scenario(n_steps=300, seed=0).data)
    piece_copies = 334  # ~100,000 rows per piece
    paths = {"csv": folder / f"in_{n_rows}.csv", "parquet": folder / f"in_{n_rows}.parquet"}
    writer_pq = None
    with open(paths["csv"], "wb") as fcsv:
        done, k = 0, 0
        while done < n_rows:
            reps = min(piece_copies, -(-(n_rows - done) // len(base)))
            piece = base.loc[np.tile(np.arange(len(base)), reps)].reset_index(drop=True)
            piece["time_s"] = piece["time_s"] + np.repeat(np.arange(k, k + reps) * 300.0, len(base))
            piece = piece.iloc[: n_rows - done].copy()
            # a little independent noise per row, so the copies are not identical (Parquet would
            # otherwise compress the tiles away and the figures would not be those of real logs)
            rng = np.random.default_rng(k)
            for c in ("a_range_m", "b_range_m"):
                piece[c] = piece[c] + rng.normal(0.0, 1.0, len(piece))
            for c in ("a_bearing_deg", "b_bearing_deg", "a_elevation_deg", "b_elevation_deg"):
                piece[c] = piece[c] + rng.normal(0.0, 1e-3, len(piece))
            table = pa.Table.from_pandas(piece, preserve_index=False)
            pacsv.write_csv(table, fcsv, write_options=pacsv.WriteOptions(include_header=done == 0))
            if writer_pq is None:
                writer_pq = pq.ParquetWriter(str(paths["parquet"]), table.schema)
            writer_pq.write_table(table, row_group_size=100_000)
            done += len(piece)
            k += reps
    writer_pq.close()
    return paths


def measure(mode: str, path: Path, out: Path, extra: dict) -> dict:
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    proc = subprocess.run(
        [sys.executable, "-c", WORKER, mode, str(path), str(out), json.dumps(extra)],
        capture_output=True,
        text=True,
        env=env,
    )
    if proc.returncode != 0:
        raise RuntimeError(proc.stderr[-3000:])
    return json.loads(proc.stdout.strip().splitlines()[-1])


def run_case(mode: str, path: Path, out: Path, extra: dict):
    """A contender: one worker process (its own timing and peak memory, as common.Timed)."""

    def run() -> Timed:
        ck = extra.get("checkpoint")
        if ck and Path(ck).exists():
            Path(ck).unlink()
        r = measure(mode, path, out, extra)
        return Timed(r["seconds"], r)

    return run


#: name -> (input format, RunOptions fields); "{ckpt}" is replaced by a checkpoint path
CASES = {
    "csv": ("csv", {"out_format": "csv"}),
    "parquet": ("parquet", {"out_format": "parquet"}),
    "csv-checkpoint": ("csv", {"out_format": "csv", "checkpoint": "{ckpt}", "checkpoint_every": 100_000}),
    "csv-one-pass": ("csv", {"out_format": "csv", "observability": "filter"}),
    "csv-plots": ("csv", {"out_format": "csv", "plots": True}),
}


def _label(fmt: str, extra: dict) -> str:
    return (
        f"stream {fmt} in -> {extra['out_format']} out"
        + (", checkpoint every 1e5" if extra.get("checkpoint") else "")
        + (", one pass (observability=filter)" if extra.get("observability") == "filter" else "")
        + (", with plots" if extra.get("plots") else "")
    )


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rows", type=int, nargs="+", default=[100_000, 1_000_000], help="input sizes, rows")
    ap.add_argument(
        "--cases",
        nargs="+",
        choices=list(CASES),
        default=list(CASES),
        help="which runs to measure (default: all)",
    )
    ap.add_argument(
        "--api-max-rows", type=int, default=300_000, help="largest size also run through the in-memory API"
    )
    ap.add_argument("--repeat", type=int, default=1, help="interleaved rounds of the cases per size")
    add_arguments(ap)
    args = ap.parse_args(argv)
    if args.tiny:  # two cases and the API: each is a fresh process
        args.rows, args.repeat, args.cases = [600], 1, ["csv", "parquet"]
    results = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        for n in args.rows:
            t = time.perf_counter()
            paths = make_inputs(n, tmp)
            sizes = {k: p.stat().st_size / 2**20 for k, p in paths.items()}
            print(
                f"# {n} rows: CSV {sizes['csv']:.0f} MiB, Parquet {sizes['parquet']:.0f} MiB (written in "
                f"{time.perf_counter() - t:.1f} s)",
                flush=True,
            )
            cases = [("stream", *CASES[name]) for name in args.cases]
            if n <= args.api_max_rows:
                cases.append(("api", "csv", {}))
            contenders = {}
            for mode, fmt, extra in cases:
                extra = {k: (str(tmp / "bench.ckpt") if v == "{ckpt}" else v) for k, v in extra.items()}
                label = "API register (in memory)" if mode == "api" else _label(fmt, extra)
                contenders[label] = run_case(mode, paths[fmt], tmp / f"out_{n}_{len(contenders)}", extra)
            times, values = interleave(contenders, args.repeat, warmup=0)
            for label, r in values.items():
                fmt = "parquet" if "parquet in" in label else "csv"
                r.update({"case": label, "input_mib": sizes[fmt], "seconds": median(times[label])})
                r["rounds_seconds"] = times[label]
                results.append(r)
                print(
                    f"{n:>9} rows  {label:<58} {r['rows'] / r['seconds']:>9.0f} rows/s  {r['seconds']:7.2f} "
                    "s  "
                    f"peak RSS {r['peak_mib']:7.0f} MiB ({r['peak_mib'] - r['baseline_mib']:6.0f} above "
                    "baseline)",
                    flush=True,
                )
    write("register", args, {"rows": args.rows, "cases": args.cases, "repeat": args.repeat}, results)
    return 0


if __name__ == "__main__":
    sys.exit(main())
