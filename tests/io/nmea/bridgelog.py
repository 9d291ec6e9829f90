"""A simulated bridge log, encoded only by independent encoders: pynmea2 builds every NMEA sentence
(with its checksum) and pyais (``encode_dict``, ``TagBlock.create_str``) every AIS sentence and tag
block. The reader under test never writes a line of it.

What the log holds (``BridgeLogConfig`` in truth.py sets it): 10 Hz ``$PASHR``, 1 Hz GGA, RMC, HDT
and ZDA of the own ship (moving, yawing, pitching, rolling); TTM of ``n_vessels`` vessels once a
radar scan, with a known range bias, bearing bias, clock offset and noise; AIS of ``n_ais`` of
them (class A messages 1 and 3, class B message 18; latencies up to ``latency_max_s`` between the
report's second and its reception time; a few reports without a second), static messages 5 and
24, the own ship's ``!AIVDO``. Usage::

    log = simulate_bridge_log(BridgeLogConfig(seed=3, range_bias_m=80.0))
    path = log.write(tmp_path / "bridge.nmea")
    sensors = log.write_sensors(tmp_path / "SENSORS.csv")   # or log.sensors, the DataFrame
    log.errors           # {"RADAR:range_bias": 80.0, "RADAR:bearing_bias": rad, "RADAR:time_bias": s, ...}
    log.track_mmsi       # TTM track -> MMSI of the vessels on AIS (the association to expect)
    log.truth            # the geometry; log.plots, log.reports: what was measured and reported

The platform is ``OWN``, the radar ``RADAR`` (talker ``RA``). On one ship, a heading error and a
bearing bias are determined only as their sum unless the heading is held (``prior_heading_deg``
0) or another sensor separates them; the log's heading error is 0 by default.
"""

from __future__ import annotations

import datetime as dt
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd
import pynmea2

from tests.io.nmea import encode
from tests.io.nmea.truth import BridgeLogConfig, Truth, make_truth

__all__ = ["BridgeLog", "BridgeLogConfig", "simulate_bridge_log", "OWN_MMSI", "PLATFORM", "SENSOR"]

OWN_MMSI = "244999999"
PLATFORM = "OWN"
SENSOR = "RADAR"
UNITS = {"N": 1852.0, "K": 1000.0, "S": 1609.344}


@dataclass
class BridgeLog:
    """The log's ``lines`` (without line ends), its ``truth``, the ``sensors`` table to import it
    with, ``plots`` (one row per TTM: true and measured values) and ``reports`` (one row per AIS
    position report of another vessel)."""

    config: BridgeLogConfig
    truth: Truth
    lines: list[str]
    sensors: pd.DataFrame
    plots: pd.DataFrame
    reports: pd.DataFrame
    track_mmsi: dict = field(default_factory=dict)

    def write(self, path) -> Path:
        """The log as a file (CRLF line ends, as NMEA talkers send them)."""
        path = Path(path)
        path.write_text("\r\n".join(self.lines) + "\r\n")
        return path

    def write_sensors(self, path) -> Path:
        """The sensors table (with its talker column) as a CSV file, for ``registration import nmea
        --sensors``."""
        path = Path(path)
        self.sensors.to_csv(path, index=False)
        return path

    @property
    def errors(self) -> dict[str, float]:
        """The simulated errors by state name: range bias (m),
        bearing bias (rad), time bias (s), heading error (rad)."""
        c = self.config
        return {
            f"{SENSOR}:range_bias": c.range_bias_m,
            f"{SENSOR}:bearing_bias": c.bearing_bias_rad,
            f"{SENSOR}:time_bias": c.clock_offset_s,
            f"{PLATFORM}:heading_error": c.heading_error_rad,
        }


class _Lines:
    """Lines with their emission times (unix s), sorted at the end; ``stamp`` adds a logger prefix."""

    def __init__(self, config: BridgeLogConfig, midnight_unix: float):
        self.items: list[tuple[float, int, str]] = []
        self.config, self.midnight = config, midnight_unix

    def add(self, t: float, line: str) -> None:
        self.items.append((self.midnight + t, len(self.items), line))

    def lines(self) -> list[str]:
        out = []
        for unix, _, line in sorted(self.items):
            if self.config.reception_stamp == "prefix-iso":
                stamp = dt.datetime.fromtimestamp(unix, dt.timezone.utc).isoformat(timespec="milliseconds")
                line = stamp.replace("+00:00", "Z") + " " + line
            elif self.config.reception_stamp == "prefix-unix":
                line = f"{unix:.3f} {line}"
            out.append(line)
        return out


def _navigation(truth: Truth, out: _Lines, rng) -> None:
    c = truth.config
    n = int(round(c.duration_s * c.attitude_rate_hz))
    t = truth.t0 + np.arange(n) / c.attitude_rate_hz
    o = truth.own(t)
    heading = np.degrees(o["heading"] + c.heading_error_rad)
    for k in range(n):
        out.add(t[k], encode.pashr(t[k], heading[k], np.degrees(o["roll"][k]), np.degrees(o["pitch"][k])))
    for s in np.arange(np.ceil(truth.t0), truth.t0 + c.duration_s):
        o = truth.own(s)
        lat, lon = float(o["lat"]), float(o["lon"])
        day = truth.day + dt.timedelta(days=int(s // 86400))
        sog, cog = f"{float(o['speed']) / 1852.0 * 3600.0:.1f}", f"{np.degrees(float(o['course'])):.1f}"
        out.add(s, encode.gga(s, lat, lon, c.antenna_msl_m, f"{c.geoid_separation_m:.2f}"))
        out.add(s, encode.rmc(s, lat, lon, day, "A", sog, cog))
        out.add(s, encode.hdt(np.degrees(float(o["heading"]) + c.heading_error_rad)))
        out.add(s, encode.zda(s, day))
        if c.extra_sentences:
            out.add(s, str(pynmea2.VTG("GP", "VTG", (cog, "T", "", "M", sog, "N", "", "K", "D"))))
            for part in range(3):
                sats = [f"{(4 * part + j) % 32 + 1:02d},45,{(30 * j) % 360:03d},40" for j in range(4)]
                out.add(
                    s,
                    str(
                        pynmea2.GSV(
                            "GP", "GSV", tuple(["3", str(part + 1), "12"] + ",".join(sats).split(","))
                        )
                    ),
                )


def _ttm(truth: Truth, out: _Lines, rng) -> pd.DataFrame:
    c = truth.config
    rows = []
    scans = np.arange(
        truth.t0, truth.t0 + c.duration_s - c.scan_period_s - c.clock_offset_s - 1.0, c.scan_period_s
    )
    units = list(UNITS)
    for k, v in enumerate(truth.vessels):
        t = scans + v.phase_s
        r, q = truth.radar(k, t)
        r_m = r + c.range_bias_m + rng.normal(0, c.sigma_range_m, t.size)
        q_m = q + c.bearing_bias_rad + rng.normal(0, c.sigma_bearing_rad, t.size)
        t_rep = np.round(t + c.clock_offset_s, 2)  # as the sentence gives it
        for j in range(t.size):
            ref = c.bearing_reference if c.bearing_reference != "mixed" else "RT"[int(rng.integers(2))]
            unit = c.distance_unit if c.distance_unit != "mixed" else units[int(rng.integers(3))]
            b = q_m[j] + (truth.reported_heading(t_rep[j]) if ref == "T" else 0.0)
            out.add(
                t[j] + 0.1,
                encode.ttm(
                    v.track, f"{r_m[j] / UNITS[unit]:.5f}", float(np.degrees(b)), ref, unit, "T", t_rep[j]
                ),
            )
            rows.append((t[j], t_rep[j], str(v.track), v.mmsi, r[j], q[j], r_m[j], q_m[j], ref, unit))
    return pd.DataFrame(
        rows,
        columns=[
            "time_true",
            "time_reported",
            "track",
            "mmsi",
            "range_true",
            "bearing_true",
            "range_measured",
            "bearing_measured",
            "reference",
            "unit",
        ],
    )


def _ais_line(out: _Lines, sentences: list[str], recv: float, midnight: float) -> None:
    for s in sentences:
        out.add(recv, (encode.tag(midnight + recv) + s) if out.config.reception_stamp == "tagblock" else s)


def _ais(truth: Truth, out: _Lines, rng, midnight: float) -> pd.DataFrame:
    c = truth.config
    rows, seq = [], 0
    end = truth.t0 + c.duration_s - c.latency_max_s - 1.0
    for k, v in enumerate(truth.vessels):
        if v.mmsi is None:
            continue
        for n, t in enumerate(np.arange(np.ceil(truth.t0) + int(rng.integers(v.period_s)), end, v.period_s)):
            p = truth.vessel(k, t)
            noise = rng.normal(0.0, c.ais_noise_m[0 if v.accuracy else 1], 2)
            lat_noisy, lon_noisy = truth.offset(p["lat"], p["lon"], noise[0], noise[1])
            second = int(t % 60) if rng.random() >= c.unavailable_second_fraction else 60
            kind = 18 if v.ais_class == "B" else (1 if n % 2 == 0 else 3)
            data = {
                "msg_type": kind,
                "mmsi": int(v.mmsi),
                "lat": float(np.degrees(lat_noisy)),
                "lon": float(np.degrees(lon_noisy)),
                "speed": round(float(p["speed"]) * 3600 / 1852, 1),
                "course": round(float(np.degrees(p["course"])), 1),
                "heading": int(np.degrees(p["course"])) % 360,
                "second": second,
                "accuracy": v.accuracy,
            }
            recv = t + rng.uniform(0, c.latency_max_s)
            _ais_line(out, encode.ais(data), recv, midnight)
            rows.append(
                (
                    v.mmsi,
                    t,
                    recv,
                    second,
                    float(p["lat"]),
                    float(p["lon"]),
                    float(lat_noisy),
                    float(lon_noisy),
                    kind,
                    v.accuracy,
                    float(p["speed"]),
                )
            )
        for t in np.arange(truth.t0 + 5.0 + k, end, c.static_period_s):
            seq = (seq + 1) % 10
            if v.ais_class == "A":
                static = [
                    {
                        "msg_type": 5,
                        "mmsi": int(v.mmsi),
                        "shipname": v.name,
                        "callsign": f"CALL{k}",
                        "to_bow": 80,
                        "to_stern": 20,
                        "to_port": 8,
                        "to_starboard": 8,
                    }
                ]
            else:
                static = [
                    {"msg_type": 24, "mmsi": int(v.mmsi), "partno": 0, "shipname": v.name},
                    {"msg_type": 24, "mmsi": int(v.mmsi), "partno": 1, "callsign": f"CALL{k}"},
                ]
            for d in static:
                _ais_line(out, encode.ais(d, seq_id=seq), t, midnight)
    own = truth.own
    for t in np.arange(np.ceil(truth.t0) + 1.0, end, c.vdo_period_s):
        o = own(t)
        data = {
            "msg_type": 1,
            "mmsi": int(OWN_MMSI),
            "lat": float(np.degrees(o["lat"])),
            "lon": float(np.degrees(o["lon"])),
            "speed": round(float(o["speed"]) * 3600 / 1852, 1),
            "course": round(float(np.degrees(o["course"])), 1),
            "second": int(t % 60),
            "accuracy": True,
        }
        _ais_line(out, encode.ais(data, own=True), t + 0.2, midnight)
    return pd.DataFrame(
        rows,
        columns=[
            "mmsi",
            "time_true",
            "time_received",
            "second",
            "lat",
            "lon",
            "lat_reported",
            "lon_reported",
            "msg_type",
            "accuracy",
            "speed",
        ],
    )


def sensors_table(config: BridgeLogConfig) -> pd.DataFrame:
    """The sensors table of the log's radar (talker RA), fleet file columns plus ``talker``; its
    biases and time bias estimated without prior (empty cells)."""
    x, y, z = config.lever_arm_m
    return pd.DataFrame(
        {
            "sensor": [SENSOR],
            "platform": [PLATFORM],
            "talker": ["RA"],
            "sigma_range_m": [config.sigma_range_m],
            "sigma_bearing_deg": [float(np.degrees(config.sigma_bearing_rad))],
            "prior_range_bias_m": [np.nan],
            "prior_bearing_bias_deg": [np.nan],
            "lever_x_m": [x],
            "lever_y_m": [y],
            "lever_z_m": [z],
            "prior_time_bias_s": [np.nan],
        }
    )


def simulate_bridge_log(config: BridgeLogConfig | None = None) -> BridgeLog:
    """The simulated bridge log of ``config`` (default :class:`BridgeLogConfig`)."""
    config = config or BridgeLogConfig()
    truth = make_truth(config)
    rng = np.random.default_rng(config.seed + 1000)
    midnight = dt.datetime.combine(truth.day, dt.time(0), tzinfo=dt.timezone.utc).timestamp()
    out = _Lines(config, midnight)
    _navigation(truth, out, rng)
    plots = _ttm(truth, out, rng)
    reports = _ais(truth, out, rng, midnight)
    track_mmsi = {str(v.track): v.mmsi for v in truth.vessels if v.mmsi}
    return BridgeLog(config, truth, out.lines(), sensors_table(config), plots, reports, track_mmsi)
