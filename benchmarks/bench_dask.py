"""Monte Carlo of the paper scenario, 1000 runs: in this process against a local dask cluster of
1 and 2 worker processes (chunks of 100 seeds), wall-clock times in s and their ratios, and a
check that every run gives the same statistics bit for bit.

    python benchmarks/bench_dask.py [--runs 1000] [--chunk-runs 100] [--steps 300]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from registration.core.parallel import dask_client
from registration.online.distributed import run_montecarlo_chunked


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--runs", type=int, default=1000)
    p.add_argument("--chunk-runs", type=int, default=100)
    p.add_argument("--steps", type=int, default=300)
    a = p.parse_args()
    kw = dict(chunk_runs=a.chunk_runs, n_steps=a.steps)
    t0 = time.perf_counter()
    ref = run_montecarlo_chunked(a.runs, 0, **kw)
    times = {"in-process": time.perf_counter() - t0}
    for workers in (1, 2):
        t0 = time.perf_counter()
        with dask_client(workers=workers) as client:
            started = time.perf_counter()
            res = run_montecarlo_chunked(a.runs, 0, client=client, **kw)
            times[f"{workers} worker(s), compute"] = time.perf_counter() - started
        times[f"{workers} worker(s), with cluster start/stop"] = time.perf_counter() - t0
        same = all(
            np.array_equal(getattr(ref, k), getattr(res, k))
            for k in ("rmse", "crlb_sigma", "filter_sigma", "nees", "nis")
        )
        assert same, f"{workers} workers: statistics differ from the in-process run"
    print(f"Monte Carlo: {a.runs} runs x {a.steps} steps, chunks of {a.chunk_runs} runs")
    base = times["in-process"]
    for name, t in times.items():
        print(f"  {name:38s} {t:7.2f} s   x{t / base:5.2f} of in-process")
    print("  statistics identical bit for bit in all three")


if __name__ == "__main__":
    main()
