"""Monte Carlo of the paper scenario, 1000 runs: in this process against a local dask cluster of
1 and 2 worker processes (chunks of 100 seeds), wall-clock times in s and their ratios, and a
check that every run gives the same statistics bit for bit.

    python benchmarks/bench_dask.py [--runs 1000] [--chunk-runs 100] [--steps 300] [--repeat 1]
    python benchmarks/bench_dask.py --tiny          # seconds: does it still run?

The three contenders run interleaved in alternating order (common.interleave), ``--repeat``
rounds; the cluster's start and stop are timed with it, the compute alone is printed beside.
Figures: benchmarks/results/dask.json.
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from common import add_arguments, interleave, median, paired_ratio, write

from registration.core.parallel import dask_client
from registration.online.distributed import run_montecarlo_chunked


def main(argv=None) -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--runs", type=int, default=1000)
    p.add_argument("--chunk-runs", type=int, default=100)
    p.add_argument("--steps", type=int, default=300)
    p.add_argument("--repeat", type=int, default=1, help="interleaved rounds")
    add_arguments(p)
    a = p.parse_args(argv)
    if a.tiny:
        a.runs, a.chunk_runs, a.steps, a.repeat = 8, 4, 30, 1
    kw = dict(chunk_runs=a.chunk_runs, n_steps=a.steps)
    compute: dict[str, list[float]] = {"1 worker(s)": [], "2 worker(s)": []}

    def on_cluster(workers: int):
        def run():
            with dask_client(workers=workers) as client:
                started = time.perf_counter()
                res = run_montecarlo_chunked(a.runs, 0, client=client, **kw)
                compute[f"{workers} worker(s)"].append(time.perf_counter() - started)
            return res

        return run

    times, values = interleave(
        {
            "in-process": lambda: run_montecarlo_chunked(a.runs, 0, **kw),
            "1 worker(s)": on_cluster(1),
            "2 worker(s)": on_cluster(2),
        },
        a.repeat,
        warmup=0,
    )
    ref = values["in-process"]
    for name in ("1 worker(s)", "2 worker(s)"):
        same = all(
            np.array_equal(getattr(ref, k), getattr(values[name], k))
            for k in ("rmse", "crlb_sigma", "filter_sigma", "nees", "nis")
        )
        assert same, f"{name}: statistics differ from the in-process run"
    print(f"Monte Carlo: {a.runs} runs x {a.steps} steps, chunks of {a.chunk_runs} runs")
    figures = {"seconds": {}, "over_in_process": {}, "compute_seconds": {}}
    for name, t in times.items():
        ratio = paired_ratio(times, name, "in-process")
        figures["seconds"][name], figures["over_in_process"][name] = median(t), ratio
        note = f" (compute {median(compute[name]):.2f} s)" if name in compute else ""
        print(f"  {name:38s} {median(t):7.2f} s   x{ratio:5.2f} of in-process{note}")
        if name in compute:
            figures["compute_seconds"][name] = median(compute[name])
    print("  statistics identical bit for bit in all three")
    write(
        "dask", a, {"runs": a.runs, "chunk_runs": a.chunk_runs, "steps": a.steps, "repeat": a.repeat}, figures
    )


if __name__ == "__main__":
    main()
