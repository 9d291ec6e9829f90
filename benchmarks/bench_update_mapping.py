#!/usr/bin/env python3
"""Speed of ``OnlineRegistrar.update(row)`` by the form of the row: the contract's array against
the mappings users try first, as ratios measured in one run.

Run from a checkout (the package installed, editable or not)::

    python3 benchmarks/bench_update_mapping.py               # 300 rows, best of 7 rounds
    python3 benchmarks/bench_update_mapping.py --rows 3000 --repeat 11

Rows: the paper scenario's (``paper_scenario(seed)``, tiled to ``--rows``), default configuration
(``fitted``, fixed Q). Contenders, one fresh registrar each, every row through ``update()``, best
of ``--repeat`` interleaved rounds after one warm-up:

1. ``array``: the (18,) float64 array in contract order (the baseline);
2. ``dict of floats``: ``{"a_lat": ..., ..., "b_elevation": ...}`` with Python floats;
3. ``dict of numpy scalars``: the same with ``numpy.float64`` values (``data[c][i]``);
4. ``dict with time``: a data-contract record, ``time`` included (ignored by ``update()``);
5. ``pandas Series``: the rows of ``DataFrame.iterrows()``.

Before timing, every form's estimates, covariances, innovations, S and NIS are checked equal to
the array's bit for bit. Aim: each mapping within 2x the array (printed: met or not). Timings
are noisy on a shared machine: compare the ratios, measured in the same run.
"""

from __future__ import annotations

import argparse
import sys
import time

import numpy as np

from registration.online import OnlineRegistrar, RegistrationConfig
from registration.online.contract import DATA_COLUMNS, ROW_COLUMNS
from registration.online.scenario import paper_scenario

AIM_RATIO = 2.0
BASELINE = "array"


def row_forms(n_rows: int, seed: int) -> dict:
    """The same ``n_rows`` rows in every form, keyed by the contender's name."""
    base = paper_scenario(seed).data
    reps = -(-n_rows // len(base["time"]))
    data = {c: np.tile(np.asarray(base[c], dtype=np.float64), reps)[:n_rows] for c in ROW_COLUMNS}
    data["time"] = np.arange(n_rows, dtype=np.float64)
    rows = np.ascontiguousarray(np.stack([data[c] for c in ROW_COLUMNS], axis=1))
    forms = {
        BASELINE: list(rows),
        "dict of floats": [{c: float(data[c][i]) for c in ROW_COLUMNS} for i in range(n_rows)],
        "dict of numpy scalars": [{c: data[c][i] for c in ROW_COLUMNS} for i in range(n_rows)],
        "dict with time": [{c: float(data[c][i]) for c in DATA_COLUMNS} for i in range(n_rows)],
    }
    try:
        import pandas as pd
    except ImportError:
        return forms
    frame = pd.DataFrame({c: data[c] for c in DATA_COLUMNS})
    forms["pandas Series"] = [r for _, r in frame.iterrows()]
    return forms


def run(config: RegistrationConfig, rows: list) -> list[dict]:
    """Every row through one fresh registrar's ``update()``; the results."""
    reg = OnlineRegistrar(config)
    update = reg.update
    return [update(r) for r in rows]


def check_identical(config: RegistrationConfig, forms: dict) -> None:
    """Every form gives the array's results bit for bit (else SystemExit)."""
    ref = run(config, forms[BASELINE])
    for name, rows in forms.items():
        for i, (a, b) in enumerate(zip(ref, run(config, rows))):
            for key in a:
                if not np.array_equal(np.asarray(a[key]), np.asarray(b[key])):
                    raise SystemExit(f"{name}: row {i}, {key} differs from the array form's")


def measure(config: RegistrationConfig, forms: dict, rounds: int) -> dict:
    """Best seconds per row of each form over ``rounds`` interleaved rounds (after one warm-up)."""
    times = {name: [] for name in forms}
    for name, rows in forms.items():
        run(config, rows)
    for _ in range(rounds):
        for name, rows in forms.items():
            t0 = time.perf_counter()
            run(config, rows)
            times[name].append((time.perf_counter() - t0) / len(rows))
    return {name: min(t) for name, t in times.items()}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rows", type=int, default=300, help="rows per contender (default 300)")
    ap.add_argument("--repeat", type=int, default=7, help="timed rounds; the best is kept (default 7)")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    config = RegistrationConfig()
    forms = row_forms(args.rows, args.seed)
    check_identical(config, forms)
    best = measure(config, forms, args.repeat)
    print(
        f"OnlineRegistrar.update(), {args.rows} rows, linearization {config.linearization}, best of {args.repeat} "
        "interleaved rounds; every form's results equal the array's bit for bit"
    )
    print(f"  {'row form':<24}{'us/row':>9}{'/ array':>10}")
    for name, sec in best.items():
        ratio = sec / best[BASELINE]
        mark = (
            ""
            if name == BASELINE
            else ("  (aim <= 2x: met)" if ratio <= AIM_RATIO else "  (aim <= 2x: NOT met)")
        )
        print(f"  {name:<24}{sec * 1e6:9.2f}{ratio:9.2f}x{mark}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
