"""Stone Soup multi-target tracking on a simulated fleet, before and after registration.

The fleet of ``registration.fleet.fleet_scenario`` (three rolling ships, a shore site, five
targets; biased radars and attitude errors) is registered by the batch estimator from all its
plots. The plots of the three 3-D radars become Stone Soup detections
(``tables_to_detections``), and one Stone Soup tracker (extended Kalman filter, global nearest
neighbour, two-point initiation) runs twice: on the raw detections and on the detections
corrected by ``RegisteredDetectionFeeder``. The OSPA distance (Stone Soup's ``OSPAMetric``,
position only) of both runs against the truth is printed and plotted. Each tracker run (about 4 s
for the default 60 s of data) shows a progress bar over its scans on standard error.

Run: ``python docs/examples/stonesoup_tracking.py [out.png]`` (default ``out/stonesoup/ospa.png``).
"""

from __future__ import annotations

import datetime
from itertools import groupby
from pathlib import Path

import numpy as np
from stonesoup.dataassociator.neighbour import GNNWith2DAssignment
from stonesoup.deleter.time import UpdateTimeDeleter
from stonesoup.hypothesiser.distance import DistanceHypothesiser
from stonesoup.initiator.simple import MultiMeasurementInitiator
from stonesoup.measures import Euclidean, Mahalanobis
from stonesoup.metricgenerator.ospametric import OSPAMetric
from stonesoup.models.transition.linear import CombinedLinearGaussianTransitionModel, ConstantVelocity
from stonesoup.predictor.kalman import ExtendedKalmanPredictor
from stonesoup.tracker.simple import MultiTargetTracker
from stonesoup.types.groundtruth import GroundTruthPath, GroundTruthState
from stonesoup.types.state import GaussianState
from stonesoup.updater.kalman import ExtendedKalmanUpdater
from tqdm import tqdm

from registration.fleet import fleet_scenario, solve_batch
from registration.fleet.simulation.scenario import CENTRE
from registration.interop.stonesoup import EPOCH, LocalFrame, RegisteredDetectionFeeder, tables_to_detections

#: The sensors tracked (the 3-D radars; the registration uses every sensor's plots).
TRACKED = ("A-3D", "B-3D", "C-3D")
#: OSPA cut-off distance (m) and order.
OSPA_C, OSPA_P = 2000.0, 1


def scans(detections: list) -> list:
    """(time, set of detections) per distinct timestamp, in time order: a Stone Soup detector."""
    return [(t, set(group)) for t, group in groupby(detections, key=lambda d: d.timestamp)]


def truths(scenario, times: list) -> set:
    """Ground-truth paths of the scenario's targets at the scan times (world = ENU at CENTRE, m)."""
    seconds = np.array([(t - EPOCH).total_seconds() for t in times])
    paths = set()
    for tid, track in scenario.config.targets.items():
        p = track.enu(seconds)
        v = np.gradient(p, seconds, axis=0)
        states = [
            GroundTruthState([p[k, 0], v[k, 0], p[k, 1], v[k, 1], p[k, 2], v[k, 2]], timestamp=t)
            for k, t in enumerate(times)
        ]
        paths.add(GroundTruthPath(states, id=tid))
    return paths


def tracker(detector) -> MultiTargetTracker:
    """A GNN tracker with an extended Kalman filter; each detection carries its own model."""
    transition = CombinedLinearGaussianTransitionModel([ConstantVelocity(5.0)] * 3)
    predictor = ExtendedKalmanPredictor(transition)
    updater = ExtendedKalmanUpdater(measurement_model=None)
    hypothesiser = DistanceHypothesiser(predictor, updater, measure=Mahalanobis(), missed_distance=5.0)
    associator = GNNWith2DAssignment(hypothesiser)
    deleter = UpdateTimeDeleter(datetime.timedelta(seconds=8))
    prior = GaussianState(np.zeros(6), np.diag([0.0, 300.0, 0.0, 300.0, 0.0, 50.0]) ** 2)
    initiator = MultiMeasurementInitiator(prior, deleter, associator, updater, min_points=2)
    return MultiTargetTracker(
        initiator=initiator, deleter=deleter, detector=detector, data_associator=associator, updater=updater
    )


def run(
    detector, truth: set, desc: str = "tracking", scans_total: int | None = None
) -> tuple[list, np.ndarray, int]:
    """Track ``detector``'s scans (a progress bar ``desc`` over ``scans_total`` of them); the times
    and OSPA distance (m) at each scan time, and the number of tracks."""
    tracks = set()
    for _, current in tqdm(tracker(detector), desc=desc, total=scans_total, unit="scan"):
        tracks |= current
    metric = OSPAMetric(c=OSPA_C, p=OSPA_P, measure=Euclidean(mapping=[0, 2, 4]))
    states, ids = OSPAMetric.extract_states(tracks, True)
    truth_states, truth_ids = OSPAMetric.extract_states(truth, True)
    result = metric.compute_over_time(states, ids, truth_states, truth_ids)
    return (
        [m.timestamp for m in result.value],
        np.array([m.value for m in result.value], dtype=float),
        len(tracks),
    )


def plot(times_raw, ospa_raw, times_reg, ospa_reg, png: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(8, 4))
    for times, ospa, label in ((times_raw, ospa_raw, "raw detections"), (times_reg, ospa_reg, "registered")):
        t = [(s - EPOCH).total_seconds() for s in times]
        ax.plot(t, ospa, label=f"{label} (mean {np.mean(ospa):.0f} m)")
    ax.set_xlabel("time (s)")
    ax.set_ylabel(f"OSPA (m, c = {OSPA_C:.0f} m, p = {OSPA_P})")
    ax.set_title("Stone Soup GNN/EKF tracker on the fleet's 3-D radars")
    ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=100)
    plt.close(fig)


def main(png: str | None = "out/stonesoup/ospa.png", seed: int = 0, duration_s: float = 60.0) -> dict:
    """Run both trackers; returns the mean OSPA (m) of the raw and the registered run, and the PNG path."""
    scenario = fleet_scenario(seed, duration_s=duration_s)
    result = solve_batch(scenario.problem())
    frame = LocalFrame(*CENTRE)  # the scenario's ENU origin, so the truth is already in world coordinates
    keep = np.isin(scenario.plots["sensor"], TRACKED)
    plots = {k: v[keep] for k, v in scenario.plots.items()}
    raw = scans(tables_to_detections(plots, scenario.sensors, scenario.navigation, frame))
    truth = truths(scenario, [t for t, _ in raw])
    corrected = RegisteredDetectionFeeder(reader=raw, result=result, sensors=scenario.sensors, frame=frame)
    t_raw, ospa_raw, n_raw = run(raw, truth, "tracking raw detections", len(raw))
    t_reg, ospa_reg, n_reg = run(corrected, truth, "tracking registered detections", len(raw))
    metrics = {
        "raw": float(np.mean(ospa_raw)),
        "registered": float(np.mean(ospa_reg)),
        "tracks_raw": n_raw,
        "tracks_registered": n_reg,
        "targets": len(truth),
        "png": png,
    }
    print(
        f"mean OSPA over {len(raw)} scans: raw {metrics['raw']:.1f} m ({n_raw} tracks), "
        f"registered {metrics['registered']:.1f} m ({n_reg} tracks); {len(truth)} targets"
    )
    if png:
        Path(png).parent.mkdir(parents=True, exist_ok=True)
        plot(t_raw, ospa_raw, t_reg, ospa_reg, png)
        print(f"wrote {png}")
    return metrics


if __name__ == "__main__":
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("png", nargs="?", default="out/stonesoup/ospa.png", help="the OSPA figure to write")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--duration", type=float, default=60.0, help="seconds of data")
    args = parser.parse_args()
    main(args.png, args.seed, args.duration)
