"""The combined acceptance of the radar error model, shared by
tests/io/asterix/test_radar_model_acceptance.py and benchmarks/bench_radar_model.py: one recording
of the ATC simulator (tests/io/asterix/atc.py) with every effect at once, encoded by libasterix and
delivered as a dual feed (every datagram on LAN A and LAN B), imported and registered through the
commands.

The effects: each radar's primary channel with range and azimuth biases of its own, a share of the
SSR plots primary-only (the reply missed) beside the aircraft without transponder; an azimuth
eccentricity of R2; a step of R3's azimuth bias at a period boundary; flight levels that are
pressure altitudes of a warm day (ISA + 12 K, QNH 1025 hPa).

With SITES ``psr_channel own`` and a free ``prior_eccentricity_deg`` for every radar,
``fleet register --bias-period-s`` must give every state of every period within its sigmas of the
truth and list the step alone in changes.csv; with the plain SITES (neither column) and no periods,
the diagnostics must name what the model lacks.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from registration.cli import main
from tests.io.asterix.atc import AtcTruth, RadarModel, atc_truth, encode_atc
from tests.io.asterix.containers import two_lans

__all__ = ["DAY", "PERIOD_S", "STEP_DEG", "ECCENTRICITY_DEG", "Run", "make_run", "period_z", "register"]

DAY = (12.0, 102500.0)  # ISA + 12 K, QNH 1025 hPa
PERIOD_S = 600.0
STEP_DEG = 0.1
ECCENTRICITY_DEG = (0.12, -0.08)  # R2's a sin(theta) + b cos(theta)
MISSED_SSR = 0.15
#: The run starts at 10:00 (a period boundary); its plots, stamped by clocks up to 1 s off, stay
#: inside whole periods: t0 1 s after the boundary, 2 s short of the last one.
START_S = 36000.0
#: File unit factor from SI of the state units in estimates_by_period.csv.
FILE_FACTOR = {"deg": float(np.degrees(1.0)), "m": 1.0, "1": 1.0, "s": 1.0}


@dataclass(frozen=True)
class Run:
    """A recording's folder (``ab.pcap``, ``SITES.csv`` with the options, ``SITES_plain.csv``
    without), its truth and the step's time (s, stamped)."""

    folder: Path
    truth: AtcTruth
    step_s: float


def make_run(
    folder: Path,
    seed: int,
    periods: int = 3,
    period_s: float = PERIOD_S,
    step_boundary: int = 2,
    n_aircraft: int = 20,
    mix: tuple[int, int, int] = (12, 14, 17),
    adsb_period_s: float = 1.0,
) -> Run:
    """Simulate ``periods`` periods of ``period_s`` from :data:`START_S`, the step of R3 at the
    ``step_boundary``-th boundary, ``n_aircraft`` of ``mix`` (tests/io/asterix/atc.py); write the
    dual-feed pcap and both SITES files into ``folder``."""
    step_s = START_S + step_boundary * period_s
    model = RadarModel(
        psr_errors=True,
        missed_ssr=MISSED_SSR,
        eccentricity_deg={"R2": ECCENTRICITY_DEG},
        bearing_step=("R3", step_s, STEP_DEG),
    )
    truth = atc_truth(
        seed,
        duration_s=periods * period_s - 3.0,
        t0=START_S + 1.0,
        n_aircraft=n_aircraft,
        mix=mix,
        adsb_period_s=adsb_period_s,
        flight_levels=DAY,
        model=model,
    )
    rec = encode_atc(truth.plots, truth.adsb, truth.sites, truth.date, truth.scans)
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "ab.pcap").write_bytes(two_lans(rec))
    truth.sites.to_csv(folder / "SITES_plain.csv", index=False)
    sites = truth.sites.copy()
    sites["psr_channel"] = "own"
    sites["prior_eccentricity_deg"] = np.inf  # free: no prior
    sites.to_csv(folder / "SITES.csv", index=False)
    return Run(folder, truth, step_s)


def register(run: Run, model: bool, *extra: str) -> tuple[int, int, Path]:
    """Import ``run``'s pcap (with the SITES of the model's options, or the plain ones) and register
    it: (import exit code, register exit code, output folder)."""
    name = "model" if model else "plain"
    sites = run.folder / ("SITES.csv" if model else "SITES_plain.csv")
    tables, out = run.folder / f"tables_{name}", run.folder / f"out_{name}"
    argv = ["import", "asterix", str(run.folder / "ab.pcap"), "--sites", str(sites), "--out", str(tables)]
    code_import = main(argv)
    code = main(["fleet", "register", "--tables", str(tables), "--out", str(out), "--no-plots", *extra])
    return code_import, code, out


def period_z(run: Run, out: Path) -> pd.DataFrame:
    """estimates_by_period.csv's states whose truth is known, with ``truth`` (file units) and
    ``z`` = (estimate - truth) / sigma; states not determined (sigma infinite) or fixed left out."""
    rows = pd.read_csv(out / "estimates_by_period.csv")
    names = rows["object"] + ":" + rows["state"]
    known = names.isin(list(run.truth.truth))
    rows = rows[known & np.isfinite(rows["sigma"]) & (rows["sigma"] > 0)].copy()
    rows["truth"] = [
        run.truth.truth_in(f"{r.object}:{r.state}", r.period_start_s, r.period_end_s) * FILE_FACTOR[r.unit]
        for r in rows.itertuples()
    ]
    rows["z"] = (rows["estimate"] - rows["truth"]) / rows["sigma"]
    return rows


def state_kind(obj: str, state: str) -> str:
    """The kind of a state for the figures: 'radar:range_bias', 'psr:bearing_bias', ..."""
    return ("psr:" if obj.endswith(".psr") else "radar:") + state


def summary_of(out: Path) -> dict:
    return json.loads((out / "summary.json").read_text())
