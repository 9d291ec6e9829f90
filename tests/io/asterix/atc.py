"""An air-traffic scenario for the acceptance of the ASTERIX reader: three shore radars with range
bias, range gain, azimuth bias and clock offset, aircraft on straight tracks, ADS-B for most of
them (Mode S), some Mode A/C only, some primary only; encoded in real ASTERIX by libasterix.

* :func:`encode_atc` builds the encoded recording from a truth scenario given as arrays (per plot:
  time as stamped, radar, range, bearing, kind 'mode_s' | 'mode_a' | 'primary', address, Mode 3/A
  code; per ADS-B report: time, address, latitude, longitude, geometric height, NACp; per radar
  its antenna scans for the CAT034 messages).
* :func:`atc_truth` simulates such arrays (geometry through registration.core.frames) with known
  errors (:attr:`AtcTruth.truth`, in the fleet's state names and SI units).

``python -m tests.io.asterix.atc FOLDER`` writes the recording (raw, pcap) and SITES.csv.
"""

from __future__ import annotations

import datetime as dt
import sys
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from tests.io.asterix.atc_model import RadarModel, apply_model
from tests.io.asterix.encode import (
    cat021_record,
    cat034_record,
    cat048_record,
    encode_recording,
    service_messages,
)

__all__ = ["AtcTruth", "RadarModel", "atc_truth", "encode_atc", "CENTRE_DEG", "RADAR_LAYOUT"]

CENTRE_DEG = (45.0, 5.0)
#: name -> (sac, sic, east m, north m, antenna height m, scan period s, sigma range m, sigma bearing deg)
RADAR_LAYOUT = {
    "R1": (30, 1, -60e3, 0.0, 150.0, 4.0, 30.0, 0.08),
    "R2": (30, 2, 60e3, 20e3, 90.0, 5.0, 40.0, 0.10),
    "R3": (30, 3, 0.0, 80e3, 300.0, 6.0, 25.0, 0.07),
}
ADSB_SOURCE = (40, 1)
_FT = 0.3048
#: ``fl_raw`` of a plot without a flight level.
NO_FL = -(1 << 20)
#: The geoid undulation (m) of the scenario's area: the ellipsoid height of mean sea level.
GEOID_M = 48.0


@dataclass
class AtcTruth:
    """The arrays :func:`encode_atc` takes, the SITES table, the scans, and the true errors
    (``truth``: 'R1:range_bias' m, 'R1:bearing_bias' rad, 'R1:range_gain', 'R1:time_bias' s, ...,
    at the start; ``steps``: state -> (time s as stamped, size SI) of a state that steps)."""

    plots: dict
    adsb: dict
    sites: pd.DataFrame
    scans: dict
    truth: dict
    date: dt.date
    steps: dict = field(default_factory=dict)

    def truth_in(self, name: str, start_s: float, end_s: float) -> float:
        """The true value (SI) of state ``name`` over ``[start_s, end_s)`` (stamped time); NaN when
        it steps inside the span."""
        value = self.truth[name]
        if name in self.steps:
            t, size = self.steps[name]
            if start_s < t < end_s:
                return float("nan")
            value += size if start_s >= t else 0.0
        return value


def encode_atc(plots: dict, adsb: dict, sites: pd.DataFrame, date: dt.date, scans: dict | None = None):
    """The recording (:class:`~tests.io.asterix.encode.Recording`) of the truth arrays.

    ``plots``: ``time_s`` (as the radar stamps it, s since midnight of ``date``), ``radar`` (a
    SITES sensor), ``range_m``, ``bearing_deg``, ``kind``, ``address`` (Mode S), ``mode_a`` (an
    int, octal digits, for 'mode_a' plots; -1: none). ``adsb``: ``time_s``, ``address``,
    ``lat_deg``, ``lon_deg``, ``height_m`` (geometric, above the ellipsoid), ``nacp``, optional
    ``gva``. ``scans``: radar -> (first north marker time as stamped, period s, sectors, end time):
    its CAT034 north markers and sector crossings."""
    src = {r.sensor: (int(r.sac), int(r.sic)) for r in sites.itertuples()}
    messages = []
    for k in range(len(plots["time_s"])):
        sac, sic = src[plots["radar"][k]]
        t, kind = float(plots["time_s"][k]), plots["kind"][k]
        rho = int(round(plots["range_m"][k] / 1852.0 * 256))
        theta = int(round(plots["bearing_deg"][k] / 360.0 * 65536)) % 65536
        kw = (
            {"typ": 5, "address": int(plots["address"][k])}
            if kind == "mode_s"
            else {"typ": 2, "mode_a": int(plots["mode_a"][k])}
            if kind == "mode_a"
            else {"typ": 1}
        )
        if "fl_raw" in plots and plots["fl_raw"][k] != NO_FL:
            kw["fl_raw"] = int(plots["fl_raw"][k])
        messages.append((t, 48, sac, sic, cat048_record("1.32", sac, sic, t, rho, theta, **kw)))
    for radar, (t0, period, sectors, t1) in (scans or {}).items():
        sac, sic = src[radar]
        for t, what, sector in service_messages(sac, sic, t0, t1, period, sectors):
            messages.append(
                (
                    t,
                    34,
                    sac,
                    sic,
                    cat034_record(
                        "1.29",
                        sac,
                        sic,
                        1 if what == "north" else 2,
                        t,
                        sector,
                        period if what == "north" else None,
                    ),
                )
            )
    gva = adsb.get("gva", np.full(len(adsb["time_s"]), 2))
    for k in range(len(adsb["time_s"])):
        t = float(adsb["time_s"][k])
        rec = cat021_record(
            "2.6",
            *ADSB_SOURCE,
            t,
            address=int(adsb["address"][k]),
            lat_deg=float(adsb["lat_deg"][k]),
            lon_deg=float(adsb["lon_deg"][k]),
            height_ft_raw=int(round(adsb["height_m"][k] / _FT / 6.25)),
            nacp=int(adsb["nacp"][k]),
            gva=int(gva[k]),
            fl_raw=int(adsb["fl_raw"][k]) if "fl_raw" in adsb else None,
        )
        messages.append((t, 21, *ADSB_SOURCE, rec))
    return encode_recording(messages, date)


def _geometry():
    from registration.core.frames import enu2ecef_rotation, geodetic2ecef

    lat0, lon0 = np.radians(CENTRE_DEG)
    return geodetic2ecef(lat0, lon0, 0.0)[0], enu2ecef_rotation(lat0, lon0)[0]


def _to_geodetic(p_ecef: np.ndarray):
    from registration.core.frames import ecef2geodetic

    lat, lon, alt = ecef2geodetic(p_ecef)
    return np.degrees(lat), np.degrees(lon), alt


def _sites(origin, R) -> tuple[pd.DataFrame, dict]:
    rows, ecef = [], {}
    for name, (sac, sic, e, n, h, _, sr, sb) in RADAR_LAYOUT.items():
        lat, lon, _ = _to_geodetic(origin + R @ np.array([e, n, 0.0]))
        from registration.core.frames import geodetic2ecef

        ecef[name] = geodetic2ecef(np.radians(lat[0]), np.radians(lon[0]), h)[0]
        rows.append((name, sac, sic, lat[0], lon[0], h, sr, sb, np.nan, np.nan))
    columns = [
        "sensor",
        "sac",
        "sic",
        "lat_deg",
        "lon_deg",
        "alt_m",
        "sigma_range_m",
        "sigma_bearing_deg",
        "prior_range_gain",
        "prior_time_bias_s",
    ]
    return pd.DataFrame(rows, columns=columns), ecef


def _aircraft(rng, n: int, duration: float):
    """(start ENU (n, 3) m, velocity ENU (n, 3) m/s) of straight tracks crossing the area."""
    heading = rng.uniform(0, 2 * np.pi, n)
    speed = rng.uniform(140.0, 240.0, n)
    mid = rng.uniform(-70e3, 70e3, (n, 2)) + [0.0, 30e3]
    v = np.stack([speed * np.sin(heading), speed * np.cos(heading), rng.uniform(-5, 5, n)], axis=1)
    start = np.column_stack([mid, rng.uniform(3000.0, 11000.0, n)]) - v * duration / 2
    return start, v


def _radar_plots(name, p_site, R_enu_site, track, t0, duration, errors, rng) -> list:
    """Per (aircraft, scan): (aircraft, stamped time, range, bearing, true bearing) of radar ``name``."""
    _, _, _, _, _, period, sr, sb = RADAR_LAYOUT[name]
    phase = errors["phase"]
    out = []
    for j in range(track.shape[0]):
        for n in range(int(duration // period) + 1):
            t = t0 + phase + n * period
            for _ in range(3):  # the antenna points at the aircraft (near north it may not converge)
                u = R_enu_site.T @ (track[j](t) - p_site)
                bearing = np.degrees(np.arctan2(u[0], u[1])) % 360.0
                t = t0 + phase + (n + bearing / 360.0) * period
            if t > t0 + duration:
                continue
            u = R_enu_site.T @ (track[j](t) - p_site)  # the aircraft where it is at the time stamped
            bearing = np.degrees(np.arctan2(u[0], u[1])) % 360.0
            r = np.linalg.norm(u)
            meas_r = (1 + errors["range_gain"]) * r + errors["range_bias"] + rng.normal(0, sr)
            meas_b = (bearing + np.degrees(errors["bearing_bias"]) + rng.normal(0, sb)) % 360.0
            if r < 250e3:
                out.append((j, t + errors["time_bias"], meas_r, meas_b, bearing))
    return out


def atc_truth(
    seed: int = 0,
    duration_s: float = 600.0,
    t0: float = 36000.0,
    n_aircraft: int = 20,
    date: dt.date = dt.date(2024, 5, 1),
    errors_seed: int | None = None,
    flight_levels: tuple[float, float] | None = None,
    overfly: tuple[str, float, float] | None = None,
    model: RadarModel | None = None,
    mix: tuple[int, int, int] = (12, 14, 17),
    adsb_period_s: float = 1.0,
) -> AtcTruth:
    """A simulated scenario; aircraft 0-13 are Mode S (0-11 with ADS-B at 1 Hz, NACp 8-10), 14-16
    Mode A/C only, the rest primary only (``mix``: the first aircraft without ADS-B, without Mode S,
    without transponder; ``adsb_period_s``: the ADS-B reports' interval). Errors of random sign:
    range bias 80-200 m, gain 200-600 ppm, azimuth bias 0.15-0.4 deg, clock offset 0.3-1.0 s, drawn
    from ``seed`` or, when given, from ``errors_seed`` (the same radars' errors under other
    traffic). ``flight_levels`` (temperature offset K, QNH Pa): the Mode S and Mode A/C plots carry
    I048/090 and the ADS-B reports I021/145, the pressure altitude of the aircraft's height above
    mean sea level (:data:`GEOID_M` below its ellipsoid height) in that atmosphere
    (registration.core.atmosphere), in 25 ft steps (Mode S, ADS-B) or 100 ft (Mode A/C); the plots'
    ``true_height_m`` then holds the aircraft's ellipsoid height where each plot saw it. ``overfly``
    (radar, miss m, height m): the first Mode A/C aircraft (14) passes that radar at the middle of
    the recording, ``miss`` from it horizontally, at that height (ENU up of the scenario's centre)
    with its drawn speed, heading and climb rate (nothing else changes: the same draws). ``model``:
    the further terms of tests/io/asterix/atc_model.py (PSR channels' biases, missed SSR replies,
    eccentricity, a bias step), drawn from generators of their own: without it the scenario is as it
    was."""
    from registration.core.frames import enu2ecef_rotation

    rng = np.random.default_rng(seed)
    origin, R = _geometry()
    sites, site_ecef = _sites(origin, R)
    start, v = _aircraft(rng, n_aircraft, duration_s)
    if overfly is not None:
        radar, miss, height = overfly
        across = np.array([v[14, 1], -v[14, 0]]) / np.hypot(v[14, 0], v[14, 1])
        mid = np.array([*(np.array(RADAR_LAYOUT[radar][2:4]) + miss * across), height])
        start[14] = mid - v[14] * duration_s / 2
    tracks = [lambda t, j=j: origin + R @ (start[j] + v[j] * (t - t0)) for j in range(n_aircraft)]
    tracks = np.array(tracks, dtype=object)
    truth, plots, scans = {}, [], {}
    erng = rng if errors_seed is None else np.random.default_rng(errors_seed)
    sign = lambda: erng.choice([-1.0, 1.0])  # noqa: E731
    for name, site in zip(RADAR_LAYOUT, sites.itertuples()):
        errors = {
            "range_bias": sign() * erng.uniform(80, 200),
            "range_gain": sign() * erng.uniform(200e-6, 600e-6),
            "bearing_bias": np.radians(sign() * erng.uniform(0.15, 0.4)),
            "time_bias": sign() * erng.uniform(0.3, 1.0),
            "phase": erng.uniform(0, RADAR_LAYOUT[name][5]),
        }
        truth.update(
            {f"{name}:{k}": errors[k] for k in ("range_bias", "range_gain", "bearing_bias", "time_bias")}
        )
        R_site = enu2ecef_rotation(np.radians(site.lat_deg), np.radians(site.lon_deg))[0]
        for j, t, r, b, b_true in _radar_plots(
            name, site_ecef[name], R_site, tracks, t0, duration_s, errors, rng
        ):
            plots.append((t, name, r, b, j, b_true))
        period = RADAR_LAYOUT[name][5]
        scans[name] = (
            t0 + errors["phase"] + errors["time_bias"],
            period,
            8,
            t0 + duration_s + errors["time_bias"],
        )
    j = np.array([p[4] for p in plots])
    kind = np.where(j < mix[1], "mode_s", np.where(j < mix[2], "mode_a", "primary"))
    address = 0x400000 + 0x1234 * j
    plot_arrays = {
        "time_s": np.array([p[0] for p in plots]),
        "radar": np.array([p[1] for p in plots]),
        "range_m": np.array([p[2] for p in plots]),
        "bearing_deg": np.array([p[3] for p in plots]),
        "kind": kind,
        "address": address,
        "mode_a": np.where(kind == "mode_a", 0o4000 + 0o11 * j, -1),
        "aircraft": j,
    }
    steps = {}
    if model is not None:
        true_bearing = np.array([p[5] for p in plots])
        steps = apply_model(
            plot_arrays, true_bearing, truth, model, seed, seed if errors_seed is None else errors_seed
        )
        kind = plot_arrays["kind"]
    adsb = _adsb(rng, tracks, t0, duration_s, mix[0], adsb_period_s)
    if flight_levels is not None:
        seen = plot_arrays["time_s"] - np.array([truth[f"{r}:time_bias"] for r in plot_arrays["radar"]])
        height = np.array([_to_geodetic(tracks[a](t))[2][0] for a, t in zip(j, seen)])
        step = np.where(kind == "mode_s", 1, 4)  # in 1/4 FL: 25 ft, 100 ft
        raw = _fl_raw(height, flight_levels, step)
        plot_arrays["fl_raw"] = np.where(kind == "primary", NO_FL, raw)
        plot_arrays["true_height_m"] = height  # ellipsoid height where the plot saw it (not encoded)
        adsb["fl_raw"] = _fl_raw(adsb["true_height_m"], flight_levels, 1)
    return AtcTruth(plot_arrays, adsb, sites, scans, truth, date, steps)


def _fl_raw(height_m: np.ndarray, flight_levels: tuple[float, float], step: int) -> np.ndarray:
    """The flight level in 1/4 FL, rounded to ``step`` of them, of ellipsoid heights ``height_m``."""
    from registration.core.atmosphere import height2pressure_altitude

    hp = height2pressure_altitude(np.asarray(height_m) - GEOID_M, *flight_levels)
    return (np.round(hp / (_FT * 25.0) / step) * step).astype(np.int64)


def _adsb(rng, tracks, t0: float, duration_s: float, n: int, period_s: float) -> dict:
    rows = []
    nacp_of = {8: 92.6, 9: 30.0, 10: 10.0}
    for j in range(n):
        nacp = int(rng.choice([8, 9, 10]))
        sigma_h = nacp_of[nacp] / 2.4477
        for t in np.arange(t0 + rng.uniform(0, 1), t0 + duration_s, period_s):
            p = tracks[j](t)
            lat, lon, h = _to_geodetic(p)
            north, east = rng.normal(0, sigma_h, 2)
            rows.append(
                (
                    t,
                    0x400000 + 0x1234 * j,
                    lat[0] + np.degrees(north / 6.371e6),
                    lon[0] + np.degrees(east / (6.371e6 * np.cos(np.radians(lat[0])))),
                    h[0] + rng.normal(0, min(2 * sigma_h, 20.0)),
                    nacp,
                    h[0],
                )
            )
    a = list(zip(*rows))
    return {
        "time_s": np.array(a[0]),
        "address": np.array(a[1]),
        "lat_deg": np.array(a[2]),
        "lon_deg": np.array(a[3]),
        "height_m": np.array(a[4]),
        "nacp": np.array(a[5]),
        "true_height_m": np.array(a[6]),
    }


if __name__ == "__main__":
    folder = Path(sys.argv[1] if len(sys.argv) > 1 else "atc")
    folder.mkdir(parents=True, exist_ok=True)
    s = atc_truth()
    rec = encode_atc(s.plots, s.adsb, s.sites, s.date, s.scans)
    (folder / "atc.ast").write_bytes(rec.raw())
    (folder / "atc.pcap").write_bytes(rec.pcap())
    s.sites.to_csv(folder / "SITES.csv", index=False)
    pd.Series(s.truth).to_csv(folder / "truth.csv", header=["value_si"])
    print(f"{len(s.plots['time_s'])} plots, {len(s.adsb['time_s'])} ADS-B reports -> {folder}")
