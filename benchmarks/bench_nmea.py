#!/usr/bin/env python3
"""Speed of the NMEA 0183 + AIS import (``registration.io.nmea.import_nmea``) on one hour of a bridge log.

Run from a checkout (the package installed, pynmea2 and pyais present)::

    python3 benchmarks/bench_nmea.py                 # one hour, 20 tracked targets, ~150 000 lines
    python3 benchmarks/bench_nmea.py --duration-s 600 --repeat 5

The log comes from the test generator (``tests/io/nmea/bridgelog.py``, encoded by pynmea2 and
pyais): 10 Hz ``$PASHR``; 1 Hz GGA, RMC, HDT, ZDA, VTG and three GSV; one TTM per target and
second (an ARPA's output rate) for 20 targets; AIS of 16 of them in NMEA 4.10 tag blocks (class A
every 2-10 s, class B every 30 s, static messages every minute) and the own ship's ``!AIVDO``.
It is written once into a temporary folder. Then, interleaved ``--repeat`` times in alternating
order (common.interleave), the wall time of:

* ``import_nmea``: the whole import (read, checksums, fields, clock, navigation, plots, AIS via
  pyais, summary);
* ``pynmea2.parse`` baseline: pynmea2 parsing every line on its own (the tag block stripped; AIS
  sentences are not pynmea2's and count as parse errors), nothing more: the cost of one Python
  object per line, before any table is built.

Printed: lines, best and median seconds, lines per second, the median of the rounds' ratios.
The aim: at most 10 s for the hour. Figures: benchmarks/results/nmea.json.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import pynmea2
from common import add_arguments, interleave, median, paired_ratio, summary, write

from registration.io.nmea import import_nmea
from tests.io.nmea.bridgelog import PLATFORM, BridgeLogConfig, simulate_bridge_log  # the tests' generator


def _baseline(path: Path) -> int:
    """pynmea2.parse of every line; returns the number it parsed."""
    ok = 0
    with open(path, encoding="latin-1") as f:
        for line in f:
            line = line.strip()
            if line.startswith("\\"):
                line = line[line.find("\\", 1) + 1 :]
            try:
                pynmea2.parse(line, check=True)
                ok += 1
            except (pynmea2.ParseError, pynmea2.ChecksumError, pynmea2.SentenceTypeError, ValueError):
                pass
    return ok


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--duration-s", type=float, default=3600.0, help="log length (s), default 3600")
    ap.add_argument("--repeat", type=int, default=3, help="runs of each case, alternated (default 3)")
    ap.add_argument("--progress", action="store_true", help="show the import's progress bar")
    add_arguments(ap)
    args = ap.parse_args(argv)
    if args.tiny:
        args.duration_s, args.repeat = 30.0, 1
    config = BridgeLogConfig(
        seed=1, duration_s=args.duration_s, n_vessels=20, n_ais=16, scan_period_s=1.0, extra_sentences=True
    )
    t = time.perf_counter()
    log = simulate_bridge_log(config)
    with tempfile.TemporaryDirectory() as folder:
        path = log.write(Path(folder) / "bridge.nmea")
        n = len(log.lines)
        print(
            f"log: {n} lines, {path.stat().st_size / 1e6:.1f} MB, {args.duration_s:g} s "
            f"(generated in {time.perf_counter() - t:.1f} s)"
        )
        times, values = interleave(
            {
                "import_nmea": lambda: import_nmea(path, PLATFORM, log.sensors, progress=args.progress),
                "pynmea2.parse baseline": lambda: _baseline(path),
            },
            args.repeat,
            warmup=0,
        )
    result = values["import_nmea"]
    print(
        f"imported: {len(result.navigation)} navigation rows, {len(result.plots)} plots, "
        f"{len(result.reference)} reference positions, {len(result.rejected)} lines set aside"
    )
    for name, ts in times.items():
        print(
            f"  {name:24s} best {min(ts):6.2f} s  median {median(ts):6.2f} s  {n / median(ts):9.0f} lines/s"
        )
    ratio = paired_ratio(times, "import_nmea", "pynmea2.parse baseline")
    met = median(times["import_nmea"]) <= 10.0 * args.duration_s / 3600.0
    print(f"import / baseline: {ratio:.2f} (aim: the hour in at most 10 s: {'met' if met else 'NOT met'})")
    figures = {
        "seconds": summary(times),
        "lines_per_s": {name: n / median(ts) for name, ts in times.items()},
        "import_over_baseline": ratio,
    }
    write("nmea", args, {"duration_s": args.duration_s, "lines": n, "repeat": args.repeat}, figures)


if __name__ == "__main__":
    main()
