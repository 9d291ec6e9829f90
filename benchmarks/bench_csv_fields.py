#!/usr/bin/env python3
"""Cost of counting each CSV line's fields (registration.io.files.csvrows) against pandas' own read.

Run from a checkout (the package installed)::

    python3 benchmarks/bench_csv_fields.py                  # 10^6 rows of each file
    python3 benchmarks/bench_csv_fields.py --rows 200000 --repeat 5

Two files are written once into a temporary folder: a fleet plots file (``time_s``, quoted
``sensor`` and ``target`` ids, ``range_m``, ``bearing_deg``, ``elevation_deg``; about 65 bytes per
row) and a recorded synchronous table (19 numeric columns, about 245 bytes per row). For each,
interleaved in alternating order (common.interleave), best and median of ``--repeat`` runs of the
process CPU time (less sensitive than the wall time to other work on the machine), ratios the
median of the rounds' ratios (figures: benchmarks/results/csv_fields.json):

* ``pandas chunks``: ``pandas.read_csv(chunksize=20000)``, the reader before the field count;
* ``blocks + field count``: :func:`registration.io.files.csvrows.read_csv_blocks` (4 MiB blocks);
* ``read + field count``: the file read in the same blocks and scanned, without pandas.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np
import pandas as pd
from common import Timed, add_arguments, interleave, median, paired_ratio, summary, write

from registration.io.files.csvrows import BLOCK_BYTES, count_fields, read_csv_blocks
from registration.io.files.tablefile import write_frame


def _files(folder: Path, rows: int) -> dict[str, Path]:
    rng = np.random.default_rng(0)
    plots = pd.DataFrame(
        {
            "time_s": np.arange(rows) * 0.25,
            "sensor": rng.choice(["A-3D", "B-3D", "C-2D"], rows),
            "target": rng.choice([f"T{k}" for k in range(1, 6)], rows),
            "range_m": rng.uniform(1e3, 1e5, rows),
            "bearing_deg": rng.uniform(-180, 180, rows),
            "elevation_deg": np.where(rng.random(rows) < 0.3, np.nan, rng.uniform(-5, 30, rows)),
        }
    )
    table = pd.DataFrame({f"c{k}": rng.normal(size=rows) * 10 ** (k % 5) for k in range(18)})
    table.insert(0, "time_s", np.arange(rows) * 1.0)
    out = {"plots (quoted ids)": folder / "plots.csv", "recorded table (numbers)": folder / "table.csv"}
    write_frame(plots, out["plots (quoted ids)"], "csv")
    write_frame(table, out["recorded table (numbers)"], "csv")
    return out


def _count_only(path: Path) -> int:
    n = 0
    with open(path, "rb") as f:
        while block := f.read(BLOCK_BYTES):  # the blocks cut lines: near enough for a cost
            n += count_fields(block)[0].size
    return n


CASES = {
    "pandas chunks": lambda p: sum(
        len(f) for f in pd.read_csv(p, chunksize=20000, index_col=False, skipinitialspace=True)
    ),
    "blocks + field count": lambda p: sum(len(f) for f in read_csv_blocks(p)),
    "read + field count": _count_only,
}


def _cpu(run, path: Path):
    """A contender timed in process CPU time (less sensitive to other work on the machine)."""

    def timed() -> Timed:
        t = time.process_time()
        value = run(path)
        return Timed(time.process_time() - t, value)

    return timed


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=1_000_000)
    parser.add_argument("--repeat", type=int, default=3)
    add_arguments(parser)
    args = parser.parse_args(argv)
    if args.tiny:
        args.rows, args.repeat = 2000, 1
    figures = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, path in _files(Path(tmp), args.rows).items():
            cpu, _ = interleave({case: _cpu(run, path) for case, run in CASES.items()}, args.repeat, warmup=0)
            size = path.stat().st_size / 2**20
            for case, v in cpu.items():
                print(
                    f"{name}, {args.rows} rows, {size:.0f} MiB: {case}: CPU best {min(v):.3f} s, "
                    f"median {median(v):.3f} s, over pandas chunks "
                    f"{paired_ratio(cpu, case, 'pandas chunks'):.2f}"
                )
            figures[name] = {
                "mib": size,
                "cpu_seconds": summary(cpu),
                "over_pandas_chunks": {case: paired_ratio(cpu, case, "pandas chunks") for case in cpu},
            }
    write("csv_fields", args, {"rows": args.rows, "repeat": args.repeat}, figures)


if __name__ == "__main__":
    main()
