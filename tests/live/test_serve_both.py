"""``registration serve`` with radar sites and a ship's bridge at once: the sample ATC recording
(written by libasterix) and a bridge log of the same hour (pynmea2, pyais) replayed together at 40
times their pace to the service's two inputs. Every plot of both is counted as each import counts
it, none arrives after its epoch (the ship's plots wait for their tracks to be named: the radars'
must wait with them), and every bias of the three radars and of the ship's radar ends within 3.5
sigma of the truth."""

from __future__ import annotations

import datetime as dt
import json
import math
import re
import subprocess
import sys
import time

import pytest

from registration.io.asterix import import_asterix
from registration.io.nmea import import_nmea
from tests.io.nmea.bridgelog import PLATFORM, BridgeLogConfig, simulate_bridge_log
from tests.live.running import SAMPLES, serving

pytest.importorskip("asterix")

SPEED = "40"
#: The sample recording's hour: 10:00 UTC on 2024-05-01.
START = dt.datetime(2024, 5, 1, 10, 0, 0, tzinfo=dt.timezone.utc)


#: Seconds between starting the two replays and their common start (``--start-at``): each
#: process's start-up (an interpreter, numpy, the recording's first piece) is behind it.
START_AFTER_S = 5.0


def _replay(path, port: int, start_at: float) -> subprocess.Popen:
    """A replay of ``path`` to ``port`` whose first datagram is due at ``start_at`` (Unix s). The
    two replays keep in step however late either process starts: at 40 times the pace, a start one
    and a half seconds apart had put the radars a minute of data behind the ship, whose plots then
    closed the epochs the radars' plots were still to come for (late plots, on a loaded machine)."""
    cmd = [sys.executable, "-m", "registration", "replay", str(path), "--to", f"udp://127.0.0.1:{port}"]
    cmd += ["--speed", SPEED, "--start-at", f"{start_at:.3f}"]
    return subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)


def _settled(svc, plots: int, lines: int, timeout_s: float = 90.0) -> dict:
    """The status once both inputs are imported and estimated and nothing moved for 3 s."""
    deadline = time.monotonic() + timeout_s
    seen, since = None, time.monotonic()
    while time.monotonic() < deadline:
        s = svc.get("/api/status")
        key = (s["ingest"]["plots"], s["nmea"], s["epochs"], s["ingest"]["backlog_plots"])
        if key != seen:
            seen, since = key, time.monotonic()
        done = (
            s["ingest"]["plots"] >= plots
            and s["nmea"]["lines"] >= lines
            and s["ingest"]["backlog_plots"] == 0
        )
        if done and time.monotonic() - since >= 3.0:
            return s
        time.sleep(0.25)
    return svc.get("/api/status")


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("both")
    log = simulate_bridge_log(BridgeLogConfig(seed=31, start_utc=START, duration_s=300.0))
    nmea_path = log.write(tmp / "bridge.nmea")
    sensors = log.write_sensors(tmp / "SENSORS.csv")
    atc = import_asterix(SAMPLES / "atc.pcap.gz", SAMPLES / "SITES.csv")
    ship = import_nmea(nmea_path, PLATFORM, sensors)
    lines = sum(1 for line in nmea_path.read_bytes().split(b"\n") if line.strip())
    inputs = ("--sites", str(SAMPLES / "SITES.csv"), "--asterix", "udp://127.0.0.1:0")
    inputs += ("--nmea", "udp://127.0.0.1:0", "--platform", PLATFORM, "--sensors", str(sensors))
    with serving("--date", "2024-05-01", inputs=inputs) as svc:
        nmea_port = int(re.search(r"nmea udp://127\.0\.0\.1:(\d+)", svc.line).group(1))
        start_at = time.time() + START_AFTER_S
        replays = [
            _replay(SAMPLES / "atc.pcap.gz", svc.input_port, start_at),
            _replay(nmea_path, nmea_port, start_at),
        ]
        for r in replays:
            assert r.wait(120) == 0, r.stderr.read() if r.stderr else ""
        status = _settled(svc, len(atc.plots), lines)
        estimates = svc.get("/api/estimates")
        stopped = svc.stop()
    return dict(log=log, atc=atc, ship=ship, lines=lines, status=status, estimates=estimates, stopped=stopped)


def test_both_inputs_are_counted_as_their_imports_count(run):
    s = run["status"]
    assert s["ingest"]["plots"] == len(run["atc"].plots)
    assert s["nmea"]["lines"] == run["lines"] and s["nmea"]["plots"] == len(run["ship"].plots)
    per_sensor = {x["sensor"]: x["plots"] for x in s["sensors"]}
    assert set(per_sensor) == {"R1", "R2", "R3", "RADAR"}
    assert per_sensor["RADAR"] == len(run["ship"].plots)
    assert run["stopped"][0] == 0, run["stopped"][2]


def test_no_plot_arrives_after_its_epoch(run):
    s = run["status"]
    assert s["ingest"]["late_plots"] == 0, s["ingest"]
    assert s["nmea"]["tracks_associated"] == sum(1 for v in run["log"].truth.vessels if v.mmsi), s["nmea"]


def test_every_bias_of_radars_and_ship_ends_within_3_5_sigma(run):
    rows = {f"{r['object']}:{r['state']}": r for r in run["estimates"]["estimates"]}
    truth = json.loads((SAMPLES / "truth.json").read_text())["asterix"]
    degrees = {"bearing_bias": math.degrees(1.0)}
    cfg = run["log"].config
    truth_si = dict(truth)
    truth_si.update(
        {
            "RADAR:range_bias": cfg.range_bias_m,
            "RADAR:bearing_bias": cfg.bearing_bias_rad,
            "RADAR:time_bias": cfg.clock_offset_s,
        }
    )
    for name, value in truth_si.items():
        row = rows[name]
        assert row["status"] == "identifiable", row
        z = (row["estimate"] - value * degrees.get(name.split(":")[1], 1.0)) / row["sigma"]
        assert abs(z) < 3.5, (name, row, value)
