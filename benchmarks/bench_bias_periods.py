#!/usr/bin/env python3
"""Cost of ``fleet register --bias-period-s``: the static run against the same run with two periods.

Run from a checkout::

    python3 benchmarks/bench_bias_periods.py              # the built-in fleet over 1200 s
    python3 benchmarks/bench_bias_periods.py --duration 600 --repeats 5 --json out.json
    python3 benchmarks/bench_bias_periods.py --tiny       # seconds: does it still run?

Problem: ``fleet simulate``'s built-in fleet (three ships, a shore site, six sensors, five targets)
written as CSV tables once. Contenders, interleaved over ``--repeats`` rounds (common.interleave;
figures are medians, the ratio the median of the rounds' ratios), each the whole command in this
process (read, register, print, write; ``--no-plots``):

* ``static``: ``fleet register --tables DIR``;
* ``periods``: the same with ``--bias-period-s`` half the duration (two periods): the static solve,
  then one solve per period started from its estimate, the change tests and the two more files.

The target (docs/background/bias-periods.md): ``periods`` at most twice ``static``. Figures:
benchmarks/results/bias_periods.json.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import tempfile
from pathlib import Path

from common import add_arguments, interleave, median, paired_ratio, summary, write

from registration.cli import main

#: The ratio the option must stay within (two periods against the static run).
TARGET_RATIO = 2.0


def _run(args: list[str]) -> int:
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        code = main(args)
    if code != 0:
        raise RuntimeError(f"{' '.join(args)}: exit {code}")
    return code


def main_(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_arguments(parser)
    parser.add_argument("--duration", type=float, default=1200.0, help="simulated seconds (default 1200)")
    parser.add_argument("--repeats", type=int, default=5, help="interleaved rounds (default 5)")
    args = parser.parse_args(argv)
    duration, repeats = (120.0, 1) if args.tiny else (args.duration, args.repeats)
    with tempfile.TemporaryDirectory() as tmp:
        tables = Path(tmp) / "tables"
        _run(["fleet", "simulate", "--out", str(tables), "--duration-s", f"{duration:g}", "--no-plots"])
        base = ["fleet", "register", "--tables", str(tables), "--no-plots"]
        period = duration / 2
        contenders = {
            "static": lambda: _run([*base, "--out", str(Path(tmp) / "static")]),
            "periods": lambda: _run(
                [*base, "--out", str(Path(tmp) / "periods"), "--bias-period-s", f"{period:g}"]
            ),
        }
        times, _ = interleave(contenders, repeats)
    ratio = paired_ratio(times, "periods", "static")
    print(f"built-in fleet, {duration:g} s of plots; periods of {period:g} s (2); {repeats} rounds")
    for name, t in times.items():
        print(f"  {name:8s} median {median(t):7.3f} s   best {min(t):7.3f} s")
    verdict = "within" if ratio <= TARGET_RATIO else "ABOVE"
    print(f"ratio periods / static: {ratio:.2f} ({verdict} the target of {TARGET_RATIO:g})")
    write(
        "bias_periods",
        args,
        {"duration_s": duration, "period_s": period, "periods": 2, "repeats": repeats},
        {"seconds": summary(times), "ratio_periods_over_static": ratio, "target_ratio": TARGET_RATIO},
    )


if __name__ == "__main__":
    main_()
