"""What every benchmark shares: the checkout's package first on the path, the ``--tiny`` and
``--json`` options, interleaved timing of contenders with the median of their paired ratios, and
the JSON file of figures that ``python -m benchmarks.tables`` turns into the tables of
docs/results.md.

Interleaving: the contenders of one benchmark run in rounds, A B C then C B A, and so on, and a
ratio is the median over the rounds of A's time over B's in the same round. A slow phase of a
shared machine then hits both sides of a ratio alike instead of one side's whole series.

The JSON of a full run goes to ``benchmarks/results/NAME.json`` (committed: the docs' tables come
from it); a ``--tiny`` run (seconds, small sizes, figures meaningless: the test suite's check that
the script still runs) writes only where ``--json`` says.
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import statistics
import sys
import time
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import NamedTuple

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
RESULTS = HERE / "results"

# The checkout's registration, not an installed copy, for every script that imports this module.
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

__all__ = [
    "RESULTS",
    "Timed",
    "ROOT",
    "add_arguments",
    "interleave",
    "machine",
    "median",
    "paired_ratio",
    "summary",
    "write",
]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """``--tiny`` and ``--json FILE`` on a benchmark's parser."""
    parser.add_argument(
        "--tiny",
        action="store_true",
        help="a run of seconds on small sizes, to check the script works (figures meaningless)",
    )
    parser.add_argument(
        "--json",
        metavar="FILE",
        help="write the figures here (default: benchmarks/results/NAME.json, none with --tiny)",
    )


class Timed(NamedTuple):
    """What a contender that times itself (e.g. a C program with clock_gettime) returns."""

    seconds: float
    value: object


def interleave(
    contenders: Mapping[str, Callable[[], object]],
    repeats: int,
    warmup: int = 1,
    cpu: dict[str, list[float]] | None = None,
) -> tuple[dict[str, list[float]], dict[str, object]]:
    """Wall seconds of each contender per round, the rounds in alternating order (A B, B A, ...),
    after ``warmup`` untimed calls of each; and the value each returned last. A contender that
    returns :class:`Timed` gives its own seconds and value. ``cpu``, if given, receives the
    process CPU seconds of each round too (all threads: less sensitive to other processes than
    the wall time, but BLAS threads count more than once)."""
    names = list(contenders)
    values: dict[str, object] = {}
    for _ in range(warmup):
        for name in names:
            value = contenders[name]()
            values[name] = value.value if isinstance(value, Timed) else value
    times: dict[str, list[float]] = {name: [] for name in names}
    for k in range(repeats):
        for name in names if k % 2 == 0 else names[::-1]:
            t0, c0 = time.perf_counter(), time.process_time()
            value = contenders[name]()
            seconds = time.perf_counter() - t0
            if cpu is not None:
                cpu.setdefault(name, []).append(time.process_time() - c0)
            if isinstance(value, Timed):
                seconds, value = value
            times[name].append(seconds)
            values[name] = value
    return times, values


def median(values: Sequence[float]) -> float:
    return float(statistics.median(values))


def paired_ratio(times: Mapping[str, Sequence[float]], a: str, b: str) -> float:
    """Median over the rounds of a's time over b's time in the same round."""
    return median([x / y for x, y in zip(times[a], times[b], strict=True)])


def summary(times: Mapping[str, Sequence[float]], per: float = 1.0) -> dict[str, dict[str, object]]:
    """Median and best seconds of each contender (divided by ``per``, e.g. the rows), and all
    of its rounds."""
    return {
        name: {"median": median(t) / per, "best": min(t) / per, "rounds": [x / per for x in t]}
        for name, t in times.items()
    }


def machine() -> dict[str, object]:
    """Where and under what load the figures were measured."""
    import numpy as np

    return {
        "node": platform.node(),
        "platform": platform.platform(),
        "processor": platform.processor() or platform.machine(),
        "cpus": os.cpu_count(),
        "python": platform.python_version(),
        "numpy": np.__version__,
        "load_average": list(os.getloadavg()),
    }


def _plain(value: object) -> object:
    """numpy scalars and arrays, paths and tuples as JSON."""
    if hasattr(value, "tolist"):
        return value.tolist()
    return str(value)


def write(name: str, args: argparse.Namespace, sizes: Mapping[str, object], figures: object) -> Path | None:
    """The run's figures as JSON: benchmarks/results/NAME.json for a full run, ``--json`` if given."""
    path = Path(args.json) if args.json else (None if args.tiny else RESULTS / f"{name}.json")
    if path is None:
        return None
    doc = {
        "benchmark": name,
        "date": datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC"),
        "machine": machine(),
        "tiny": bool(args.tiny),
        "sizes": dict(sizes),
        "figures": figures,
    }
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(doc, indent=1, default=_plain, allow_nan=True) + "\n")
    print(f"figures written to {path}")
    return path
