#!/usr/bin/env python3
"""Speed of ``OnlineRegistrar.update(row)`` by the form of the row: the contract's array against
the mappings users try first, as ratios measured in one run.

Run from a checkout (the package installed, editable or not)::

    python3 benchmarks/bench_update_mapping.py               # 300 rows, 7 rounds
    python3 benchmarks/bench_update_mapping.py --rows 3000 --repeat 11

Rows: the paper scenario's (``paper_scenario(seed)``, tiled to ``--rows``), default configuration
(``fitted``, fixed Q). Contenders, one fresh registrar each, every row through ``update()``,
median of ``--repeat`` rounds interleaved in alternating order (common.interleave) after one
warm-up, ratios the median of the rounds' ratios (figures: benchmarks/results/update_mapping.json):

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

import numpy as np
from common import add_arguments, interleave, median, paired_ratio, write

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
    """Seconds per row of each form in each of ``rounds`` interleaved rounds (after one warm-up)."""
    times, _ = interleave({name: (lambda r=rows: run(config, r)) for name, rows in forms.items()}, rounds)
    return {name: [x / len(forms[name]) for x in t] for name, t in times.items()}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rows", type=int, default=300, help="rows per contender (default 300)")
    ap.add_argument("--repeat", type=int, default=7, help="timed rounds, interleaved (default 7)")
    ap.add_argument("--seed", type=int, default=0)
    add_arguments(ap)
    args = ap.parse_args(argv)
    if args.tiny:
        args.rows, args.repeat = 30, 1
    config = RegistrationConfig()
    forms = row_forms(args.rows, args.seed)
    check_identical(config, forms)
    times = measure(config, forms, args.repeat)
    print(
        f"OnlineRegistrar.update(), {args.rows} rows, linearization {config.linearization}, median of "
        f"{args.repeat} interleaved rounds; every form's results equal the array's bit for bit"
    )
    print(f"  {'row form':<24}{'us/row':>9}{'/ array':>10}")
    figures = {}
    for name, t in times.items():
        ratio = paired_ratio(times, name, BASELINE)
        mark = (
            ""
            if name == BASELINE
            else ("  (aim <= 2x: met)" if ratio <= AIM_RATIO else "  (aim <= 2x: NOT met)")
        )
        print(f"  {name:<24}{median(t) * 1e6:9.2f}{ratio:9.2f}x{mark}")
        figures[name] = {"us_per_row": median(t) * 1e6, "over_array": ratio}
    write("update_mapping", args, {"rows": args.rows, "repeat": args.repeat}, figures)
    return 0


if __name__ == "__main__":
    sys.exit(main())
