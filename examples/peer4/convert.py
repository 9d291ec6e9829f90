"""Convert the peer4-radar data to the long-form tables of registration.fleet.

The data are the MATLAB files of the repository github.com/zyj030513/registration- (commit
c9c3fa69), which accompanies a 2021 IEEE Transactions on Signal Processing paper on the spatial
registration of netted radars: Monte Carlo runs ``Data_for_4_Sensors_<k>.mat`` and the true
track ``Trace_AEW_WGS.mat``. They are read from the folder in ``$PEER4_DATA`` (default: the
project's shared copy next to the checkout).

The data: four fixed sites, one sensor each, every sensor measuring the same single target every
2 s (``Time_Meas`` = 1, 3, ..., 997 s). Per sample: ``Tar_R`` slant range (m), ``Tar_Theta``
azimuth (rad, from east, counter-clockwise), ``Tar_Phi`` elevation (rad); the noise sigmas
``Range_Error``, ``Theta_Error``, ``Phi_Error``; the site ``Sensor_B``, ``Sensor_L`` (rad),
``Sensor_H`` (m) and a zero ``Sensor_Attitude``, so each sensor frame is the local ENU frame.

Conventions mapped to ours (docs/reference/conventions.md):

* a site is a platform with heading 0 (bow = north), pitch 0, roll 0, so deck = ENU;
* bearing q (from north, clockwise) = pi/2 - azimuth: a bias b in azimuth is -b in bearing;
* elevation and range as they are; measured = true + bias + noise in both.
* Sensor 4 is used for azimuth and elevation only, as in the peer's study (its file also has a
  range; it is left out).
* The sites' attitudes are held fixed at zero (prior sigma 0): the study's model has sensor biases
  only, and on a level site a heading error could not be told from the bearing bias anyway.
* Their ellipsoid has f = 1/298.257 (WGS-84: 1/298.257223563). Our WGS-84 site positions from
  the files' (B, L, H) differ from the files' ``Sensor_Posi`` by 1.6 cm (:func:`site_offsets`),
  2e-7 rad at the 60-86 km ranges: nothing next to the 1 deg, 100 m noise.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import scipy.io

DATA = Path(
    os.environ.get("PEER4_DATA", Path(__file__).resolve().parents[3] / "shared" / "external" / "peer4-radar")
)
SENSORS = ("S1", "S2", "S3", "S4")
ANGLE_ONLY = "S4"
#: The true biases of the README (same in every run), in the peer's convention: azimuth and
#: elevation in degrees, range in metres.
TRUE_BIASES_PEER = {
    "S1": (5.0, 5.0, 3000.0),
    "S2": (-5.0, -5.0, -3000.0),
    "S3": (5.0, 5.0, 3000.0),
    "S4": (-5.0, -5.0, -3000.0),
}
TRUTH_STEP_S = 0.01


def run_path(run: int) -> Path:
    return DATA / f"Data_for_4_Sensors_{run}.mat"


def _samples(mat: dict, k: int):
    return mat[f"Sensor{k + 1}_data"]


def true_state() -> dict:
    """The true biases in registration.fleet's state names and convention (rad, m)."""
    out = {}
    for sid, (az, el, r) in TRUE_BIASES_PEER.items():
        out[f"{sid}:bearing_bias"] = -np.radians(az)
        out[f"{sid}:elevation_bias"] = np.radians(el)
        if sid != ANGLE_ONLY:
            out[f"{sid}:range_bias"] = r
        for what in ("heading", "pitch", "roll"):
            out[f"{sid}-site:{what}_error"] = 0.0
    return out


def load_run(run: int) -> dict:
    """The tables (plots, sensors, navigation, platforms) of one Monte Carlo run."""
    mat = scipy.io.loadmat(run_path(run), squeeze_me=True, struct_as_record=False)
    plots = {k: [] for k in ("time", "sensor", "target", "range", "bearing", "elevation")}
    sensors = {k: [] for k in ("sensor", "platform", "sigma_range", "sigma_bearing", "sigma_elevation")}
    navigation = {k: [] for k in ("platform", "time", "lat", "lon", "alt", "heading", "pitch", "roll")}
    for k, sid in enumerate(SENSORS):
        samples = _samples(mat, k)
        first = samples[0]
        if np.any(np.asarray(first.Sensor_Attitude) != 0):
            raise ValueError(
                f"{run_path(run)}: sensor {k + 1} has a non-zero attitude; the conversion assumes ENU"
            )
        n = len(samples)
        plots["time"].append(np.array([s.Time_Meas for s in samples], dtype=float))
        plots["sensor"] += [sid] * n
        plots["target"] += [f"target-{int(s.Tar_Num)}" for s in samples]
        plots["range"].append(
            np.full(n, np.nan) if sid == ANGLE_ONLY else np.array([s.Tar_R for s in samples])
        )
        plots["bearing"].append(np.pi / 2 - np.array([s.Tar_Theta for s in samples]))
        plots["elevation"].append(np.array([s.Tar_Phi for s in samples]))
        sensors["sensor"].append(sid)
        sensors["platform"].append(f"{sid}-site")
        sensors["sigma_range"].append(np.nan if sid == ANGLE_ONLY else float(first.Range_Error))
        sensors["sigma_bearing"].append(float(first.Theta_Error))
        sensors["sigma_elevation"].append(float(first.Phi_Error))
        for key, value in (
            ("platform", f"{sid}-site"),
            ("time", 0.0),
            ("lat", first.Sensor_B),
            ("lon", first.Sensor_L),
            ("alt", first.Sensor_H),
            ("heading", 0.0),
            ("pitch", 0.0),
            ("roll", 0.0),
        ):
            navigation[key].append(value)
    plots = {
        k: (np.concatenate(v) if k in ("time", "range", "bearing", "elevation") else np.array(v))
        for k, v in plots.items()
    }
    plots["bearing"] = np.angle(np.exp(1j * plots["bearing"]))  # to (-pi, pi]
    platforms = {"platform": np.array(navigation["platform"])}
    for what in ("heading", "pitch", "roll"):
        platforms[f"prior_{what}"] = np.zeros(len(SENSORS))
    return {
        "plots": plots,
        "sensors": {k: np.array(v) for k, v in sensors.items()},
        "navigation": {k: np.array(v) for k, v in navigation.items()},
        "platforms": platforms,
    }


def truth_track() -> tuple[np.ndarray, np.ndarray]:
    """(t (K,) s, p_ecef (K, 3) m) of the true target; column k (1-based) is at k * 0.01 s."""
    mat = scipy.io.loadmat(DATA / "Trace_AEW_WGS.mat", squeeze_me=True)
    p = np.asarray(mat["Trace_AEW_WGS"], dtype=float).T
    step = float(mat["Ts"])
    if abs(step - TRUTH_STEP_S) > 1e-12:
        raise ValueError(f"truth step {step} s, expected {TRUTH_STEP_S} s")
    return step * np.arange(1, p.shape[0] + 1), p


def truth_at(times: np.ndarray) -> np.ndarray:
    """True target ECEF (m) at sample times that fall on the truth grid."""
    t, p = truth_track()
    k = np.round(np.asarray(times) / TRUTH_STEP_S).astype(int) - 1
    if np.any(np.abs(t[k] - times) > 1e-9):
        raise ValueError("sample times off the truth grid")
    return p[k]


def site_offsets(run: int = 1) -> np.ndarray:
    """(4,) metres between our WGS-84 site positions (from B, L, H) and the files' Sensor_Posi."""
    from registration import _codegen

    mat = scipy.io.loadmat(run_path(run), squeeze_me=True, struct_as_record=False)
    out = []
    for k in range(len(SENSORS)):
        s = _samples(mat, k)[0]
        p = _codegen.get("geodetic2ecef")(s.Sensor_B, s.Sensor_L, s.Sensor_H)[0][0]
        out.append(float(np.linalg.norm(p - np.asarray(s.Sensor_Posi, dtype=float))))
    return np.array(out)
