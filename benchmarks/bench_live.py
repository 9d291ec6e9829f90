#!/usr/bin/env python3
"""The live service (``registration serve``) under load: ingest rate, how far its estimates lag
the data at 20 times real time, memory over a day of data, and its estimates against the batch
run's on the same recordings.

Run from a checkout::

    python3 benchmarks/bench_live.py           # a day of data; the live-against-batch comparison
    python3 benchmarks/bench_live.py --tiny    # seconds: checks the script runs

The recordings are the sample's (``examples/recordings/atc.pcap.gz``, written by libasterix: 300 s
of three radars and ADS-B), and held-out ATC simulations written by libasterix
(``tests/io/asterix/atc.py``) for the comparison with ``fleet register``. A day of data is the
sample repeated, each repetition's CAT048 time of day moved on by the sample's length with
``correct_cat048`` (a time correction; nothing else changes; the CAT021 and CAT034 copies are
duplicates, counted and set aside). Parts:

1. **ingest**: the repeated recording sent by ``registration replay --speed max``; the service's
   count of datagrams against those sent (no drops) and the plots it imports per second of wall
   time, beside the replay's own rate;
2. **lag at 20x**: the sample replayed at 20x; ``/api/status`` polled every 50 ms; the lag is the
   data time sent minus the data time the service shows, in wall seconds;
3. **memory**: the service's resident memory at 1 h, 12 h and 24 h of data time, a day of held-out
   ATC traffic (``atc_truth``: the same three radars' errors all day, other aircraft every hour,
   across midnight, written by libasterix; about 45 s of encoding per hour, kept with ``--cache``)
   replayed at 150x, with the plots the estimator found late and the alarms it raised (none is
   due: nothing changes);
4. **live against batch**: per held-out seed, each live estimate's distance to ``fleet register``'s
   in batch σ, and the ratio of the σ.
"""

from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from common import ROOT, add_arguments, write

from registration.io.asterix.encode import PlotCorrection, correct_cat048
from tests.io.asterix.containers import pcap_bytes, udp_frame
from tests.live.running import datagrams, serving

SAMPLES = ROOT / "examples" / "recordings"
SAMPLE_S = 300.0
SOURCES = [(30, 1), (30, 2), (30, 3)]
#: The service's answers are rebuilt every 0.25 s: no time is measured finer than that.
POLL_RESOLUTION_S = 0.25
#: The day of the memory part starts at 12:00 UTC: it crosses midnight.
DAY_START_S = 43200.0


def _day(folder: Path, repeats: int) -> tuple[Path, int, int]:
    """The sample repeated, CAT048 times moved on: (pcap, datagrams, CAT048 plots expected)."""
    base = datagrams(SAMPLES / "atc.pcap.gz")
    frames, times = [], []
    for k in range(repeats):
        shift = {s: PlotCorrection(time_bias_s=-k * SAMPLE_S) for s in SOURCES}
        for j, d in enumerate(base):
            frames.append(udp_frame(correct_cat048(d, shift).data if k else d))  # CAT048 records only
            times.append(1714557600.0 + k * SAMPLE_S + j * SAMPLE_S / len(base))
    path = folder / "day.pcap"
    path.write_bytes(pcap_bytes(frames, times))
    return path, len(frames), 3692 * repeats


def _atc_day(folder: Path, hours: float, cache: Path | None) -> tuple[Path, Path, int, int]:
    """A day of ATC traffic from 12:00 UTC, hour after hour: (pcap, SITES.csv, datagrams, plots)."""
    from tests.io.asterix.atc import atc_truth, encode_atc

    where = cache or folder
    where.mkdir(parents=True, exist_ok=True)
    pieces, n_datagrams, n_plots = [], 0, 0
    for k in range(math.ceil(hours)):
        duration = min(3600.0, hours * 3600.0 - k * 3600.0)
        path = where / f"atc_hour{k:02d}_{duration:g}s.pcap"
        counts = path.with_suffix(".json")
        if not (path.exists() and counts.exists()):
            s = atc_truth(seed=1000 + k, duration_s=duration, t0=DAY_START_S + 3600.0 * k, errors_seed=7)
            # other aircraft every hour: other addresses and Mode 3/A codes
            s.plots["address"] = s.plots["address"] + 0x10000 * k
            s.plots["mode_a"] = np.where(s.plots["mode_a"] >= 0, s.plots["mode_a"] + 0o100 * k, -1)
            s.adsb["address"] = s.adsb["address"] + 0x10000 * k
            path.write_bytes(encode_atc(s.plots, s.adsb, s.sites, s.date, s.scans).pcap())
            counts.write_text(json.dumps({"plots": len(s.plots["time_s"])}))
            s.sites.to_csv(where / "SITES.csv", index=False)
        data = path.read_bytes()
        pieces.append(data if not pieces else data[24:])  # one pcap: the later global headers dropped
        n_datagrams += len(datagrams(path))
        n_plots += json.loads(counts.read_text())["plots"]
    out = folder / "atc_day.pcap"
    out.write_bytes(b"".join(pieces))
    return out, where / "SITES.csv", n_datagrams, n_plots


def _replay(path: Path, port: int, speed: str) -> subprocess.Popen:
    cmd = [sys.executable, "-m", "registration", "replay", str(path), "--to", f"udp://127.0.0.1:{port}"]
    return subprocess.Popen(cmd + ["--speed", speed], stderr=subprocess.PIPE, text=True)


def _until_done(svc, rep: subprocess.Popen, n_datagrams: int, n_plots: int, marks: dict) -> dict:
    """Poll the service until every datagram sent is imported and estimated (or the replay ended,
    nothing waits and nothing moved for 1 s); fills ``marks`` (data hours -> RSS) on the way."""
    t0, t_first, imported, first, last = time.monotonic(), None, None, None, None
    while True:
        s = svc.get("/api/status")
        now = time.monotonic()
        if t_first is None and s["ingest"]["datagrams"]:
            t_first = now
        if first is None and s["data_time_s"] is not None:
            first = s["data_time_s"]
        for mark in marks:
            if marks[mark] is None and first is not None and s["data_time_s"] - first >= mark - SAMPLE_S:
                marks[mark] = s["memory_rss_bytes"]
        if s["ingest"]["datagrams"] >= n_datagrams and s["ingest"]["plots"] >= n_plots:
            imported = imported or now
            if s["ingest"]["backlog_plots"] == 0:
                break
        moved = (s["ingest"], s["epochs"])
        idle = s["ingest"]["waiting_datagrams"] == 0 and s["ingest"]["backlog_plots"] == 0
        if rep.poll() is not None and idle and moved == last:  # replay ended, nothing waits or moved for 1 s
            break
        last = moved if rep.poll() is not None else None
        time.sleep(1.0 if rep.poll() is not None else 0.1)
    t_first = t_first or t0
    return {
        "status": s,
        "import_s": max((imported or now) - t_first, POLL_RESOLUTION_S),
        "estimate_s": max(now - t_first, POLL_RESOLUTION_S),
        "replay": rep.communicate(timeout=60)[1].strip().splitlines()[-1:],
    }


def ingest(folder: Path, hours: float) -> dict:
    """The recording sent at full speed: datagrams lost, import and estimation rates."""
    path, n_datagrams, n_plots = _day(folder, max(int(round(hours * 3600 / SAMPLE_S)), 1))
    with serving("--date", "2024-05-01") as svc:
        done = _until_done(svc, _replay(path, svc.input_port, "max"), n_datagrams, n_plots, {})
        stopped = svc.stop()
    s = done["status"]
    received = s["ingest"]["datagrams"] + s["ingest"]["waiting_datagrams"]
    return {
        "datagrams_sent": n_datagrams,
        "datagrams_received": received,
        "plots": s["ingest"]["plots"],
        "plots_per_s": s["ingest"]["plots"] / done["import_s"],
        "datagrams_per_s": s["ingest"]["datagrams"] / done["import_s"],
        "estimated_plots_per_s": s["ingest"]["plots"] / done["estimate_s"],
        "replay": done["replay"],
        "sigterm_s": stopped[1],
    }


def memory(folder: Path, hours: float, speed: float, cache: Path | None) -> dict:
    """The resident memory at 1 h, 12 h and 24 h of data time, the day replayed at ``speed``."""
    path, sites, n_datagrams, n_plots = _atc_day(folder, hours, cache)
    marks: dict = {h * 3600.0: None for h in (1.0, 12.0, 24.0) if h <= hours}
    with serving("--date", "2024-05-01", sites=sites) as svc:
        done = _until_done(svc, _replay(path, svc.input_port, f"{speed:g}"), n_datagrams, n_plots, marks)
        svc.stop()
    s = done["status"]
    return {
        "rss_bytes_at_data_h": {f"{m / 3600:g}": v for m, v in marks.items()},
        "plots": s["ingest"]["plots"],
        "epochs": s["epochs"],
        "plots_sent": n_plots,
        "late_plots": s["ingest"]["late_plots"],
        "alarms": len(s["alarms"]),
        "alarm_list": s["alarms"][:20],
        "speed": speed,
    }


def lag_at_20x(speed: float = 20.0) -> dict:
    lags = []
    with serving("--date", "2024-05-01") as svc:
        rep = _replay(SAMPLES / "atc.pcap.gz", svc.input_port, f"{speed:g}")
        t0, first = time.monotonic(), None
        while rep.poll() is None:
            s = svc.get("/api/status")
            if s["data_time_s"] is not None:
                if first is None:
                    first, t0 = s["data_time_s"], time.monotonic()
                sent = first + speed * (time.monotonic() - t0)
                lags.append(max(sent - s["data_time_s"], 0.0) / speed)
            time.sleep(0.05)
        svc.stop()
    lags.sort()
    return {
        "polls": len(lags),
        "median_s": lags[len(lags) // 2] if lags else None,
        "max_s": max(lags, default=None),
    }


def against_batch(folder: Path, seeds: list[int], duration_s: float) -> dict:
    import pandas as pd

    from registration.live.estimator import LiveEstimator
    from registration.live.inputs.asterix import AsterixStream
    from tests.io.asterix.atc import atc_truth, encode_atc

    out = {}
    for seed in seeds:
        atc = atc_truth(seed, duration_s=duration_s)
        pcap = folder / f"atc{seed}.pcap"
        pcap.write_bytes(encode_atc(atc.plots, atc.adsb, atc.sites, atc.date, atc.scans).pcap())
        atc.sites.to_csv(folder / "SITES.csv", index=False)
        payloads = datagrams(pcap)
        stream, est = AsterixStream(atc.sites, date=atc.date), LiveEstimator(atc.sites)
        for i in range(0, len(payloads), 300):
            est.feed(stream.decode(payloads[i : i + 300], [1] * len(payloads[i : i + 300])))
        est.flush()
        live = {f"{r['object']}:{r['state']}": r for r in est.rows() if r["status"] == "identifiable"}
        tables, result = folder / f"t{seed}", folder / f"r{seed}"
        run = [sys.executable, "-m", "registration"]
        subprocess.run(
            run
            + ["import", "asterix", str(pcap), "--sites", str(folder / "SITES.csv"), "--out", str(tables)],
            check=True,
            capture_output=True,
        )
        subprocess.run(
            run + ["fleet", "register", "--tables", str(tables), "--out", str(result), "--no-plots"],
            check=True,
            capture_output=True,
        )
        batch = pd.read_csv(result / "estimates.csv")
        z, ratio = [], []
        for row in batch.itertuples():
            key = f"{row.object}:{row.state}"
            if key in live:
                z.append(abs(live[key]["estimate"] - row.estimate) / row.sigma)
                ratio.append(live[key]["sigma"] / row.sigma)
        out[str(seed)] = {
            "max_distance_in_batch_sigma": float(np.max(z)),
            "max_sigma_ratio": float(np.max(ratio)),
            "states": len(z),
        }
        print(
            f"  seed {seed}: {len(z)} states, live within {np.max(z):.2f} batch σ, "
            f"σ ratio at most {np.max(ratio):.2f}"
        )
    return out


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--hours", type=float, default=24.0, help="hours of data, memory part (default 24)")
    ap.add_argument("--memory-speed", type=float, default=150.0, help="its replay speed (default 150)")
    ap.add_argument("--ingest-hours", type=float, default=2.0, help="hours sent at full speed (default 2)")
    ap.add_argument("--cache", type=Path, help="keep the day's hourly recordings here and reuse them")
    ap.add_argument("--seeds", type=int, default=3, help="held-out seeds against the batch run (default 3)")
    ap.add_argument(
        "--parts",
        default="ingest,lag,memory,batch",
        help="which parts to run, comma separated (default all: ingest,lag,memory,batch)",
    )
    add_arguments(ap)
    args = ap.parse_args(argv)
    if args.tiny:
        args.hours, args.seeds, args.ingest_hours, args.memory_speed = 0.02, 1, 0.05, 400.0
    parts = set(args.parts.split(","))
    unknown = parts - {"ingest", "lag", "memory", "batch"}
    if unknown:
        ap.error(f"--parts: unknown {sorted(unknown)}")
    flow = lag = mem = batch = None
    seeds = list(range(101, 101 + args.seeds))
    with tempfile.TemporaryDirectory() as temp:
        folder = Path(temp)
        if "ingest" in parts:
            flow = ingest(folder, args.ingest_hours)
            print(
                f"ingest at full speed: {flow['datagrams_received']} of {flow['datagrams_sent']} datagrams "
                f"received; imported at {flow['plots_per_s']:.0f} plots/s ({flow['datagrams_per_s']:.0f} "
                f"datagrams/s), estimated at {flow['estimated_plots_per_s']:.0f} plots/s; SIGTERM took "
                f"{flow['sigterm_s']:.1f} s; the replay: {' '.join(flow['replay'])}"
            )
        if "lag" in parts:
            lag = lag_at_20x(300.0 if args.tiny else 20.0)
            print(
                f"lag at 20x: median {lag['median_s']:.2f} s, max {lag['max_s']:.2f} s of wall time "
                f"({lag['polls']} polls)"
            )
        if "memory" in parts:
            mem = memory(folder, args.hours, args.memory_speed, args.cache)
            rss = ", ".join(
                f"{h} h {v / 2**20:.0f} MiB" if v else f"{h} h -"
                for h, v in mem["rss_bytes_at_data_h"].items()
            )
            print(
                f"resident memory at data time {rss} ({mem['plots']} of {mem['plots_sent']} plots at "
                f"{mem['speed']:g}x; {mem['late_plots']} late, {mem['alarms']} alarms)"
            )
        if "batch" in parts:
            print("live against fleet register (held-out simulations):")
            batch = against_batch(folder, seeds, 60.0 if args.tiny else 900.0)
    figures = {"ingest": flow, "lag_at_20x": lag, "memory": mem, "against_batch": batch}
    figures = {k: v for k, v in figures.items() if v is not None}
    sizes = {"hours": args.hours, "memory_speed": args.memory_speed, "ingest_hours": args.ingest_hours}
    sizes["parts"] = sorted(parts)
    name = "live" if len(parts) == 4 else "live_" + "_".join(sorted(parts))  # a part: its own results file
    write(name, args, {**sizes, "seeds": seeds}, figures)


if __name__ == "__main__":
    main()
