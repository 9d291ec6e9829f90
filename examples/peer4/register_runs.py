#!/usr/bin/env python3
"""Register the ten peer4-radar runs with registration.fleet and compare with the known biases.

Run from a checkout::

    python3 examples/peer4/register_runs.py                  # print the tables
    python3 examples/peer4/register_runs.py --json peer4.json

Per run: :func:`registration.fleet.solve_batch` on the converted tables (convert.py), the target
position at each of the 499 synchronous instants as a nuisance (``window_s = 0``: no trajectory
model at all), sites fixed, no priors. Nothing is tuned to these runs: the noise sigmas are the
files' own and the options are the defaults apart from the instant windows the synchronous data
allow. Reported:

* each bias estimate with its sigma (the CRLB at the estimate) against the truth, in the peer's
  convention (azimuth from east counter-clockwise: an azimuth bias is minus our bearing bias);
* the NEES of the 11 biases per run and its mean over the runs against the 95 % interval;
* the RMS disagreement between the three ranging sensors (distance between the ECEF positions
  of their simultaneous plots, over the three pairs) before registration (biases taken as zero)
  and after (plots corrected by the estimates), and each sensor's RMS distance to the true track;
* sensor 4 (angles only): RMS angular distance of its line of sight from the true target.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from convert import ANGLE_ONLY, SENSORS, load_run, site_offsets, true_state, truth_at  # noqa: E402

from registration import _codegen  # noqa: E402
from registration.core.consistency import nees_interval  # noqa: E402
from registration.fleet import BatchOptions, build_problem, solve_batch  # noqa: E402

RANGING = [s for s in SENSORS if s != ANGLE_ONLY]


def plot_positions(tables: dict, sensor: str, biases=(0.0, 0.0, 0.0)) -> tuple[np.ndarray, np.ndarray]:
    """(times, ECEF (K, 3)) of one ranging sensor's plots corrected by ``biases`` (m, rad, rad)."""
    p, nav = tables["plots"], tables["navigation"]
    sel = p["sensor"] == sensor
    k = list(nav["platform"]).index(f"{sensor}-site")
    site = [nav[c][k] for c in ("lat", "lon", "alt", "heading", "pitch", "roll")]
    pos = _codegen.get("fleet_plot2ecef")(
        *site,
        np.zeros(3),
        np.asarray(biases, dtype=float),
        np.zeros(3),
        p["range"][sel],
        p["bearing"][sel],
        p["elevation"][sel],
    )[0]
    return p["time"][sel], pos


def _biases_of(result, sensor: str) -> tuple[float, float, float]:
    names = [f"{sensor}:{c}_bias" for c in ("range", "bearing", "elevation")]
    return tuple(result.value(n) if n in result.layout.names else 0.0 for n in names)


def disagreement(tables: dict, result=None) -> dict:
    """RMS pairwise distance (m) between the ranging sensors' simultaneous positions, and each
    sensor's RMS distance to the truth; corrected by ``result`` when given."""
    pos = {
        s: plot_positions(tables, s, _biases_of(result, s) if result else (0.0, 0.0, 0.0)) for s in RANGING
    }
    t0 = pos[RANGING[0]][0]
    assert all(np.array_equal(pos[s][0], t0) for s in RANGING)
    pairs = [
        np.linalg.norm(pos[a][1] - pos[b][1], axis=1) for i, a in enumerate(RANGING) for b in RANGING[i + 1 :]
    ]
    truth = truth_at(t0)
    return {
        "pairs_rms_m": float(np.sqrt(np.mean(np.concatenate(pairs) ** 2))),
        **{
            f"{s}_to_truth_rms_m": float(np.sqrt(np.mean(np.sum((pos[s][1] - truth) ** 2, axis=1))))
            for s in RANGING
        },
    }


def angle_only_error(tables: dict, result=None) -> float:
    """RMS angle (rad) between sensor 4's corrected line of sight and the true target direction."""
    p, nav = tables["plots"], tables["navigation"]
    sel = p["sensor"] == ANGLE_ONLY
    k = list(nav["platform"]).index(f"{ANGLE_ONLY}-site")
    site = [nav[c][k] for c in ("lat", "lon", "alt", "heading", "pitch", "roll")]
    b = np.array(_biases_of(result, ANGLE_ONLY) if result else (0.0, 0.0, 0.0))
    truth = truth_at(p["time"][sel])
    true_plot = _codegen.get("fleet_residual")(
        truth, *site, np.zeros(3), np.zeros(3), np.zeros(3), 0.0, 0.0, 0.0
    )[2]
    dq = np.angle(np.exp(1j * (p["bearing"][sel] - b[1] - true_plot[:, 1])))
    de = p["elevation"][sel] - b[2] - true_plot[:, 2]
    return float(np.sqrt(np.mean(dq**2 * np.cos(true_plot[:, 2]) ** 2 + de**2)))


def register_run(run: int, window_s: float = 0.0) -> dict:
    tables = load_run(run)
    result = solve_batch(build_problem(**tables), BatchOptions(window_s=window_s))
    truth = true_state()
    free = result.layout.free
    err = np.array([result.estimate[i] - truth[result.layout.names[i]] for i in free])
    nees = float(err @ np.linalg.solve(result.covariance[np.ix_(free, free)], err))
    return {
        "run": run,
        "converged": result.converged,
        "iterations": result.iterations,
        "chi_square_mean": result.chi_square.mean,
        "chi_square_band": list(result.chi_square.interval),
        "estimates": {
            result.layout.names[i]: [float(result.estimate[i]), float(result.sigma[i])] for i in free
        },
        "nees": nees,
        "n_states": int(free.size),
        "unobservable": [c.text for c in result.observability.unobservable],
        "weak": [c.text for c in result.observability.weak],
        "before": {**disagreement(tables), "S4_angle_rms_rad": angle_only_error(tables)},
        "after": {**disagreement(tables, result), "S4_angle_rms_rad": angle_only_error(tables, result)},
    }


def _peer_units(name: str, value: float) -> float:
    """Our state value in the peer's convention: azimuth = -bearing, degrees; metres."""
    if name.endswith("bearing_bias"):
        return -np.degrees(value)
    return np.degrees(value) if name.endswith("elevation_bias") else value


def summary_lines(runs: list[dict]) -> list[str]:
    truth = true_state()
    names = list(runs[0]["estimates"])
    out = [
        "| bias | truth | mean estimate (10 runs) | RMS error | mean sigma | RMS error / mean sigma |",
        "|---|---|---|---|---|---|",
    ]
    for n in names:
        label = (
            n.replace("bearing_bias", "azimuth bias")
            .replace("elevation_bias", "elevation bias")
            .replace("range_bias", "range bias")
        )
        unit = "m" if n.endswith("range_bias") else "deg"
        est = np.array([_peer_units(n, r["estimates"][n][0]) for r in runs])
        sig = np.array([abs(_peer_units(n, r["estimates"][n][1])) for r in runs])
        tr = _peer_units(n, truth[n])
        rms = float(np.sqrt(np.mean((est - tr) ** 2)))
        out.append(
            f"| {label.replace(':', ' ')} ({unit}) | {tr:+.1f} | {est.mean():+.4f} | {rms:.4f} | "
            f"{sig.mean():.4f} | {rms / sig.mean():.2f} |"
        )
    nees = np.array([r["nees"] for r in runs])
    lo, hi = nees_interval(len(runs), runs[0]["n_states"])
    out.append("")
    out.append(
        f"NEES per run: {', '.join(f'{v:.1f}' for v in nees)}; mean {nees.mean():.2f} for "
        f"{runs[0]['n_states']} states, 95 % interval for the mean of {len(runs)} runs [{lo:.2f}, {hi:.2f}]"
    )
    keys = ["pairs_rms_m", *[f"{s}_to_truth_rms_m" for s in RANGING], "S4_angle_rms_rad"]
    for key in keys:
        b = np.mean([r["before"][key] for r in runs])
        a = np.mean([r["after"][key] for r in runs])
        if key.endswith("rad"):
            out.append(f"{key}: before {np.degrees(b):.3f} deg, after {np.degrees(a):.3f} deg")
        else:
            out.append(f"{key}: before {b:.1f} m, after {a:.1f} m")
    out.append(
        "chi-square (mean squared normalised residual) per run: "
        + ", ".join(f"{r['chi_square_mean']:.3f}" for r in runs)
        + f" (band {runs[0]['chi_square_band'][0]:.3f}"
        f" to {runs[0]['chi_square_band'][1]:.3f})"
    )
    out.append(f"site offsets WGS-84 vs the files' ellipsoid (m): {np.round(site_offsets(), 4).tolist()}")
    return out


def main(argv=None) -> list[dict]:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, nargs="*", default=list(range(1, 11)))
    parser.add_argument(
        "--window-s",
        type=float,
        default=0.0,
        help="target windows (s); 0 (default) = a position per instant, the synchronous data allow it",
    )
    parser.add_argument("--json", help="write every run's figures to this file")
    args = parser.parse_args(argv)
    runs = [register_run(k, args.window_s) for k in args.runs]
    print("\n".join(summary_lines(runs)))
    for r in runs[:1]:
        print("observability of run 1:", r["unobservable"] or "every bias observable", r["weak"] or "")
    if args.json:
        Path(args.json).write_text(json.dumps(runs, indent=2) + "\n")
    return runs


if __name__ == "__main__":
    main()
