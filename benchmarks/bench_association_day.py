#!/usr/bin/env python3
"""An imported ATC day registered by partitions: plots without target ids associated out of core.

Run from a checkout::

    python3 benchmarks/bench_association_day.py                      # 24 h, 40 aircraft an hour
    python3 benchmarks/bench_association_day.py --hours 2 --cache /tmp/atcday
    python3 benchmarks/bench_association_day.py --tiny              # minutes: does it still run?

The recording: hour after hour of held-out ATC traffic (``tests/io/asterix/atc.py``: the same three
radars' errors all day, other aircraft every hour; Mode S with ADS-B, Mode A/C, primary-only
aircraft; flight levels in ISA + 12 K and QNH 1025 hPa; 3 % of the SSR replies missed, so those
plots are primary-only), encoded by libasterix as one CAT048/CAT021/CAT034 file and imported with
``registration import asterix``. The plots without a target id (the primary-only ones) are at least
8 % of the plots with the default mix.

Runs, each ``python -m registration fleet register`` in its own process tree (peak resident memory
of every process, ``VmHWM``, as ``bench_archive_workers.py`` reads it):

* ``day``: the whole import with ``--memory-limit`` (default 2GiB): the run chooses the partitions
  and associates them one by one (``--workers N``: on a local Dask cluster). Printed: plots, the
  share without id, wall time, peak memory.
* ``first_hours`` (``--compare-hours``, default 2): the first hours cut out of the import,
  registered in memory and with ``--partition-s`` (default 1800 s): the labels (associations.csv
  against labelled_plots/) and the estimates in units of the in-memory sigma.

The requirement (printed, not asserted): the day in at most 2 GiB and 15 min; the first hours with
the same labels and estimates within 0.1 sigma.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
from bench_archive_workers import measure
from common import add_arguments, write

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
DATE = "2024-05-01"
#: Records an import of the day may decode (a day of three radars with ADS-B is about 4 million).
MAX_RECORDS = 20_000_000
#: ISA + 12 K, QNH 1025 hPa: the flight levels' atmosphere.
ATMOSPHERE = (12.0, 102500.0)


def _hour(k: int, aircraft: int, duration: float) -> tuple[bytes, int, object]:
    """(raw ASTERIX of hour ``k``, plots, SITES frame)."""
    from tests.io.asterix.atc import RadarModel, atc_truth, encode_atc

    with_adsb, mode_s, transponder = int(0.6 * aircraft), int(0.7 * aircraft), int(0.88 * aircraft)
    s = atc_truth(
        seed=3000 + k,
        duration_s=duration,
        t0=3600.0 * k,
        n_aircraft=aircraft,
        errors_seed=7,
        flight_levels=ATMOSPHERE,
        model=RadarModel(missed_ssr=0.03),
        mix=(with_adsb, mode_s, transponder),
    )
    s.plots["address"] = s.plots["address"] + 0x10000 * k  # other aircraft every hour
    s.plots["mode_a"] = np.where(s.plots["mode_a"] >= 0, (s.plots["mode_a"] + 0o100 * k) % 0o10000, -1)
    s.adsb["address"] = s.adsb["address"] + 0x10000 * k
    rec = encode_atc(s.plots, s.adsb, s.sites, s.date, s.scans)
    return rec.raw(), len(s.plots["time_s"]), s.sites


def recording(folder: Path, hours: float, aircraft: int, cache: Path | None) -> tuple[Path, Path, int]:
    """The day's recording (raw ASTERIX), its SITES.csv and its plots; hours kept in ``cache``."""
    where = cache or folder
    where.mkdir(parents=True, exist_ok=True)
    pieces, n = [], 0
    for k in range(int(np.ceil(hours))):
        duration = min(3600.0, hours * 3600.0 - k * 3600.0)
        path = where / f"hour{k:02d}_{aircraft}ac_{duration:g}s.ast"
        counts = path.with_suffix(".json")
        if not (path.exists() and counts.exists()):
            raw, plots, sites = _hour(k, aircraft, duration)
            path.write_bytes(raw)
            counts.write_text(json.dumps({"plots": plots}))
            sites.to_csv(where / "SITES.csv", index=False)
        pieces.append(path.read_bytes())
        n += json.loads(counts.read_text())["plots"]
    out = folder / "day.ast"
    out.write_bytes(b"".join(pieces))
    return out, where / "SITES.csv", n


def imported(folder: Path, ast: Path, sites: Path) -> Path:
    out = folder / "imported"
    cmd = [sys.executable, "-m", "registration", "import", "asterix", str(ast), "--sites", str(sites)]
    cmd += ["--max-records", str(MAX_RECORDS)]  # a day is more than the default bound of an import
    done = subprocess.run(
        [*cmd, "--out", str(out), "--date", DATE], check=True, capture_output=True, text=True
    )
    if "(max_" in done.stderr:  # a bound of the import reached (the command warns)
        raise SystemExit(f"the day's import is not whole:\n{done.stderr}")
    return out


def cut(tables: Path, folder: Path, hours: float) -> Path:
    """The first ``hours`` of the imported tables (plots and references by time)."""
    import pandas as pd

    folder.mkdir(parents=True, exist_ok=True)
    plots = pd.read_csv(tables / "plots.csv", dtype={"target": str}, keep_default_na=False)
    end = plots["time_s"].min() + hours * 3600.0
    plots[plots["time_s"] < end].to_csv(folder / "plots.csv", index=False)
    refs = pd.read_csv(tables / "reference.csv", dtype={"target": str}, keep_default_na=False)
    refs[refs["time_s"] < end + 60.0].to_csv(folder / "reference.csv", index=False)
    for name in ("navigation", "sensors", "platforms"):
        (folder / f"{name}.csv").write_bytes((tables / f"{name}.csv").read_bytes())
    return folder


def _labels(out_memory: Path, out_parts: Path) -> dict:
    import pandas as pd

    by_time = ["time_s", "sensor"]
    memory = pd.read_csv(out_memory / "associations.csv", dtype={"target": str}, keep_default_na=False)
    memory = memory[memory["target"] != ""].sort_values(by_time, kind="stable")
    parts = pd.read_parquet(out_parts / "labelled_plots").sort_values(by_time, kind="stable")
    same = len(memory) == len(parts) and bool(
        np.array_equal(memory["time_s"].to_numpy(), parts["time_s"].to_numpy())
        and np.array_equal(memory["target"].to_numpy(), parts["target"].to_numpy())
    )
    return {"labelled_in_memory": len(memory), "labelled_by_parts": len(parts), "same_labels": same}


def first_hours(folder: Path, tables: Path, hours: float, partition_s: float) -> dict:
    small = cut(tables, folder / "first", hours)
    mem = measure("first_memory", small, folder / "first_memory", [])
    parts = measure("first_parts", small, folder / "first_parts", ["--partition-s", f"{partition_s:g}"])
    sigma = mem["sigma"]
    live = sigma > 0
    dz = np.abs(parts["estimate"][live] - mem["estimate"][live]) / sigma[live]
    return {
        "hours": hours,
        "memory": {k: mem[k] for k in ("seconds", "peak_mib", "iterations")},
        "parts": {k: parts[k] for k in ("seconds", "peak_mib", "iterations", "partitions")},
        "max_estimate_difference_sigma": float(dz.max()),
        **_labels(folder / "first_memory", folder / "first_parts"),
    }


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--hours", type=float, default=24.0)
    ap.add_argument("--aircraft", type=int, default=40, help="aircraft per hour")
    ap.add_argument("--memory-limit", default="2GiB")
    ap.add_argument("--workers", type=int, help="the day's run on a local Dask cluster of N workers")
    ap.add_argument("--compare-hours", type=float, default=2.0)
    ap.add_argument("--partition-s", type=float, default=1800.0, help="of the first hours' run by parts")
    ap.add_argument("--cache", type=Path, help="keep the hourly recordings here and reuse them")
    ap.add_argument("--work", type=Path, help="work folder (default: a temporary one)")
    add_arguments(ap)
    args = ap.parse_args(argv)
    if args.tiny:
        args.hours, args.aircraft, args.compare_hours, args.partition_s = 0.05, 6, 0.05, 90.0
    import tempfile

    with tempfile.TemporaryDirectory(prefix="bench-association-day-") as temp:
        folder = args.work or Path(temp)
        folder.mkdir(parents=True, exist_ok=True)
        t = time.perf_counter()
        ast, sites, n_sim = recording(folder, args.hours, args.aircraft, args.cache)
        tables = imported(folder, ast, sites)
        prepared = time.perf_counter() - t
        import pandas as pd

        target = pd.read_csv(tables / "plots.csv", usecols=["target"], dtype=str, keep_default_na=False)
        n, without = len(target), int((target["target"] == "").sum())
        extra = ["--memory-limit", args.memory_limit]
        day = measure(
            "day", tables, folder / "day", extra + (["--workers", str(args.workers)] if args.workers else [])
        )
        summary = json.loads((folder / "day" / "summary.json").read_text())
        figures = {
            "plots": n,
            "plots_without_id": without,
            "share_without_id": without / n,
            "prepared_seconds": prepared,
            "day": {
                k: day[k] for k in ("seconds", "peak_mib", "processes", "partitions", "partition_s", "said")
            },
            "association": summary.get("association"),
            "first_hours": first_hours(folder, tables, args.compare_hours, args.partition_s),
        }
    how = f"by {day['partitions']} partitions" if day["partitions"] else "in memory (it fits)"
    print(
        f"{n} plots, {100 * without / n:.1f} % without id: registered {how} in {day['seconds']:.0f} s, "
        f"peak {day['peak_mib']:.0f} MiB (limit {args.memory_limit}; aim: 2 GiB and 15 min)"
    )
    f = figures["first_hours"]
    print(
        f"first {f['hours']:g} h: same labels {f['same_labels']} ({f['labelled_in_memory']} / "
        f"{f['labelled_by_parts']} plots labelled), estimates within "
        f"{f['max_estimate_difference_sigma']:.3g} sigma of the run in memory (aim 0.1); "
        f"in memory {f['memory']['seconds']:.0f} s, by parts {f['parts']['seconds']:.0f} s"
    )
    sizes = {"hours": args.hours, "aircraft": args.aircraft, "workers": args.workers}
    write("association_day", args, sizes, figures)
    return figures


if __name__ == "__main__":
    main()
