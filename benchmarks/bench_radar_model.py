#!/usr/bin/env python3
"""The radar error model's combined acceptance at full size: every effect in one recording.

Run from a checkout::

    python3 benchmarks/bench_radar_model.py                  # 20 aircraft, 3600 s, seeds 42-44
    python3 benchmarks/bench_radar_model.py --seeds 45 --duration 1800 --json out.json
    python3 benchmarks/bench_radar_model.py --tiny           # seconds: does it still run?

Per seed, tests/io/asterix/radar_model.py: the ATC simulator's recording, encoded by libasterix as
a dual-feed pcap (every datagram on LAN A and LAN B), with each radar's primary channel with biases
of its own and 15 % of the SSR plots primary-only, R2's azimuth eccentricity, a 0.1 deg step of
R3's azimuth bias at the middle period boundary, flight levels of ISA + 12 K and QNH 1025 hPa.
``import asterix`` then ``fleet register --bias-period-s 600`` with SITES ``psr_channel own`` and
a free ``prior_eccentricity_deg`` for every radar; then, with the plain SITES and no periods, the
diagnostics. Printed and written (benchmarks/results/radar_model.json): per state kind the worst
|z| over the periods and seeds (the acceptance: at most 3.5), the changes found (the acceptance:
R3's bearing bias at the step, and its primary channel's, nothing else), the diagnostics' findings
of the plain run, the exit codes and the seconds of each stage (the machine shared and loaded).
"""

from __future__ import annotations

import argparse
import contextlib
import io
import tempfile
import time
from pathlib import Path

from common import add_arguments, write

from tests.io.asterix.radar_model import make_run, period_z, register, state_kind, summary_of

Z_LIMIT = 3.5


def _quiet(fn, *args, **kwargs):
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        return fn(*args, **kwargs)


def _one(folder: Path, seed: int, size: dict) -> dict:
    """The figures of one seed."""
    import pandas as pd

    t0 = time.perf_counter()
    run = make_run(folder, seed, **size)
    t1 = time.perf_counter()
    code_import, code, out = _quiet(register, run, True, "--bias-period-s", f"{size['period_s']:g}")
    t2 = time.perf_counter()
    plain_import, plain_code, plain_out = _quiet(register, run, False, "--allow-inconsistent")
    t3 = time.perf_counter()
    z = period_z(run, out) if code == 0 else None
    worst = {}
    if z is not None:
        z["kind"] = [state_kind(o, s) for o, s in zip(z["object"], z["state"])]
        for kind, rows in z.groupby("kind"):
            r = rows.loc[rows["z"].abs().idxmax()]
            worst[kind] = {
                "z": float(r["z"]),
                "state": f"{r['object']}:{r['state']}",
                "period": r["period_start_s"],
            }
    changes = pd.read_csv(out / "changes.csv") if code == 0 else pd.DataFrame()
    findings = (
        summary_of(plain_out).get("diagnostics", {}).get("findings", []) if plain_code in (0, 3) else []
    )
    association = summary_of(out)["inputs"].get("association", {}) if code == 0 else {}
    return {
        "seed": seed,
        "plots": int(len(run.truth.plots["time_s"])),
        "adsb_reports": int(len(run.truth.adsb["time_s"])),
        "step_s": run.step_s,
        "exit_codes": {
            "import": code_import,
            "register": code,
            "plain_import": plain_import,
            "plain": plain_code,
        },
        "states_checked": 0 if z is None else int(len(z)),
        "worst_z": worst,
        "changes": [
            {"state": f"{c.object}:{c.state}", "time_s": c.time_s, "size": c.after - c.before, "z": c.z}
            for c in changes.itertuples()
        ],
        "psr_plots_associated": {
            s: v.get("associated", 0)
            for s, v in association.get("by_sensor", {}).items()
            if s.endswith(".psr")
        },
        "psr_plots_unassociated": {
            s: v.get("unassociated", 0)
            for s, v in association.get("by_sensor", {}).items()
            if s.endswith(".psr")
        },
        "diagnostics": [
            {k: f[k] for k in ("sensor", "test", "channel", "what", "size", "unit", "z", "hint")}
            for f in findings
        ],
        "seconds": {
            "simulate_encode": t1 - t0,
            "import_register_periods": t2 - t1,
            "import_register_plain": t3 - t2,
        },
    }


def main_(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_arguments(parser)
    parser.add_argument("--seeds", type=int, nargs="+", default=[42, 43, 44], help="seeds (default 42 43 44)")
    parser.add_argument("--duration", type=float, default=3600.0, help="seconds of traffic (default 3600)")
    args = parser.parse_args(argv)
    if args.tiny:
        seeds = args.seeds[:1]
        size = {
            "periods": 3,
            "period_s": 60.0,
            "step_boundary": 2,
            "n_aircraft": 8,
            "mix": (4, 5, 7),
            "adsb_period_s": 2.0,
        }
    else:
        seeds = args.seeds
        periods = int(round(args.duration / 600.0))
        size = {"periods": periods, "period_s": 600.0, "step_boundary": periods // 2, "n_aircraft": 20}
    runs = []
    with tempfile.TemporaryDirectory() as tmp:
        for seed in seeds:
            r = _one(Path(tmp) / f"seed{seed}", seed, size)
            runs.append(r)
            print(
                f"seed {seed}: {r['plots']} plots, {r['adsb_reports']} ADS-B reports; "
                f"exit codes {r['exit_codes']}; {r['states_checked']} period states checked; seconds "
                + ", ".join(f"{k} {v:.1f}" for k, v in r["seconds"].items())
            )
            print(
                f"  PSR plots associated {r['psr_plots_associated']}, "
                f"unassociated {r['psr_plots_unassociated']}"
            )
            for c in r["changes"]:
                print(f"  change: {c['state']} at {c['time_s']:g} s, {c['size']:+.4f} (z {c['z']:+.1f})")
            for f in r["diagnostics"]:
                print(
                    f"  plain diagnostics: {f['sensor']}: {f['what']} {f['size']:+.4g} {f['unit']} "
                    f"(z {f['z']:+.1f}): {f['hint']}"
                )
    kinds = sorted({k for r in runs for k in r["worst_z"]})
    worst = {}
    for k in kinds:
        zs = [
            (abs(r["worst_z"][k]["z"]), r["seed"], r["worst_z"][k]["state"])
            for r in runs
            if k in r["worst_z"]
        ]
        z, seed, state = max(zs)
        worst[k] = {"abs_z": z, "seed": seed, "state": state}
    print(f"worst |z| per state kind over seeds {seeds} (acceptance: <= {Z_LIMIT}):")
    for k, w in worst.items():
        print(f"  {k:28s} {w['abs_z']:5.2f}   ({w['state']}, seed {w['seed']})")
    write(
        "radar_model",
        args,
        {"seeds": seeds, **{k: v for k, v in size.items()}},
        {"worst_abs_z": worst, "runs": runs},
    )


if __name__ == "__main__":
    main_()
