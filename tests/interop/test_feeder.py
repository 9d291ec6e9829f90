"""Detections corrected by a registration result: the values, the covariance, and the refusals."""

from types import SimpleNamespace

import numpy as np
import pytest
from stonesoup.models.measurement.nonlinear import (
    CartesianToBearingRangeRate,
    CartesianToElevationBearingRange,
)
from stonesoup.sensor.radar import RadarElevationBearingRange
from stonesoup.types.detection import Detection
from stonesoup.types.state import State

from registration.fleet import fleet_scenario, solve_batch
from registration.fleet.simulation.scenario import CENTRE
from registration.interop.stonesoup import (
    EPOCH,
    LocalFrame,
    RegisteredDetectionFeeder,
    RegistrationCorrector,
    tables_to_detections,
)

FRAME = LocalFrame(*CENTRE)
RADARS_3D = ("A-3D", "B-3D", "C-3D")


def result_of(names, estimate, covariance=None):
    """The duck type the corrector takes: layout.names, estimate, covariance."""
    n = len(names)
    cov = np.zeros((n, n)) if covariance is None else covariance
    return SimpleNamespace(
        layout=SimpleNamespace(names=tuple(names)), estimate=np.asarray(estimate, float), covariance=cov
    )


def detections_of(scenario, sensors=RADARS_3D):
    keep = np.isin(scenario.plots["sensor"], sensors)
    plots = {k: v[keep] for k, v in scenario.plots.items()}
    return tables_to_detections(plots, scenario.sensors, scenario.navigation, FRAME)


def truth_state(scenario, detection) -> State:
    t = (detection.timestamp - EPOCH).total_seconds()
    p = scenario.config.targets[detection.metadata["target"]].enu(np.array([t]))[0]
    return State(np.array([[p[0]], [0.0], [p[1]], [0.0], [p[2]], [0.0]]))


def error_m(detection, truth: State) -> np.ndarray:
    """|measured - model(truth)| per channel in m (elevation and bearing times the range)."""
    z = np.asarray(detection.state_vector, float).ravel()
    h = np.asarray(detection.measurement_model.function(truth), float).ravel()
    d = z - h
    d[:-1] = np.angle(np.exp(1j * d[:-1])) * h[-1]
    return np.abs(d)


@pytest.fixture(scope="module")
def quiet_fleet():
    """A fleet without measurement noise to speak of, ships level (navigation interpolates exactly)."""
    return fleet_scenario(5, duration_s=30.0, noise_scale=1e-9, ship_motion=False)


def test_the_true_errors_make_detections_fit_stonesoups_model_of_the_true_target(quiet_fleet):
    s = quiet_fleet
    names = list(s.truth_state)
    corrector = RegistrationCorrector(result_of(names, [s.truth_state[n] for n in names]), s.sensors, FRAME)
    detections = detections_of(s)
    raw = np.array([error_m(d, truth_state(s, d)) for d in detections])
    fixed = np.array([error_m(corrector.correct(d), truth_state(s, d)) for d in detections])
    assert raw.max() > 100.0  # the biases and attitude errors are large before correction
    assert fixed.max() < 1e-6


def test_the_added_covariance_is_j_p_jt_of_the_corrected_error(quiet_fleet):
    s = quiet_fleet
    names = list(s.truth_state)
    states = [
        "A:heading_error",
        "A:pitch_error",
        "A:roll_error",
        "A-3D:range_bias",
        "A-3D:bearing_bias",
        "A-3D:elevation_bias",
    ]
    idx = [names.index(n) for n in states]
    rng = np.random.default_rng(11)
    G = rng.normal(size=(6, 6)) * np.array([1e-3, 1e-3, 1e-3, 30.0, 1e-3, 1e-3])
    P = np.zeros((len(names), len(names)))
    P[np.ix_(idx, idx)] = G.T @ G
    x0 = np.array([s.truth_state[n] for n in names])
    det = next(d for d in detections_of(s, ("A-3D",)))
    truth = truth_state(s, det)
    corrected = RegistrationCorrector(result_of(names, x0, P), s.sensors, FRAME).correct(det)
    added = np.asarray(corrected.measurement_model.covar(), float) - np.asarray(
        det.measurement_model.covar(), float
    )

    def error(x):  # corrected measurement minus Stone Soup's model of the true target, by the corrected model
        d = RegistrationCorrector(result_of(names, x), s.sensors, FRAME, registration_noise=False).correct(
            det
        )
        return (
            np.asarray(d.state_vector, float).ravel()
            - np.asarray(d.measurement_model.function(truth), float).ravel()
        )

    J = np.empty((3, 6))
    for k, i in enumerate(idx):
        step = 1.0 if "range" in states[k] else 1e-6
        up, down = x0.copy(), x0.copy()
        up[i] += step
        down[i] -= step
        J[:, k] = (error(up) - error(down)) / (2 * step)
    expected = J @ P[np.ix_(idx, idx)] @ J.T
    np.testing.assert_allclose(added, expected, rtol=1e-5, atol=1e-12 * np.abs(expected).max())
    assert added[2, 2] > 100.0  # the range bias's variance is in it


def test_a_zero_result_passes_detections_through_the_feeder_unchanged_scan_by_scan(quiet_fleet):
    s = quiet_fleet
    names = list(s.truth_state)
    detections = detections_of(s)[:40]
    scans = [(d.timestamp, {d}) for d in detections]
    feeder = RegisteredDetectionFeeder(
        reader=scans, result=result_of(names, np.zeros(len(names))), sensors=s.sensors, frame=FRAME
    )
    out = list(feeder)
    assert [t for t, _ in out] == [t for t, _ in scans]
    for (_, (before,)), (_, after) in zip(scans, out):
        (after,) = after
        assert after is not before and after.metadata == before.metadata
        np.testing.assert_allclose(
            np.asarray(after.state_vector, float), np.asarray(before.state_vector, float), rtol=1e-15
        )
        m0, m1 = before.measurement_model, after.measurement_model
        np.testing.assert_allclose(
            np.asarray(m1.translation_offset, float), np.asarray(m0.translation_offset, float), atol=1e-8
        )
        np.testing.assert_allclose(
            np.asarray(m1.rotation_offset, float), np.asarray(m0.rotation_offset, float), atol=1e-12
        )
        np.testing.assert_array_equal(np.asarray(m1.covar()), np.asarray(m0.covar()))


def test_a_registered_fleet_gives_consistent_corrected_detections():
    s = fleet_scenario(2, duration_s=40.0)
    result = solve_batch(s.problem())
    corrector = RegistrationCorrector(result, s.sensors, FRAME)
    nees_raw, nees = [], []
    for det in detections_of(s):
        truth = truth_state(s, det)
        for d, out in ((det, nees_raw), (corrector.correct(det), nees)):
            v = (
                np.asarray(d.state_vector, float).ravel()
                - np.asarray(d.measurement_model.function(truth), float).ravel()
            )
            v[:2] = np.angle(np.exp(1j * v[:2]))
            out.append(v @ np.linalg.solve(np.asarray(d.measurement_model.covar(), float), v))
    assert np.mean(nees_raw) > 30.0
    assert 2.5 < np.mean(nees) < 3.5  # 3 channels


def test_detections_that_cannot_be_corrected_are_refused_by_name(quiet_fleet):
    s = quiet_fleet
    names = list(s.truth_state)
    det = detections_of(s, ("B-3D",))[0]
    without_b3d = [n for n in names if not n.startswith("B-3D:")]
    feeder = RegisteredDetectionFeeder(
        reader=[(det.timestamp, {det})],
        result=result_of(without_b3d, np.zeros(len(without_b3d))),
        sensors=s.sensors,
        frame=FRAME,
    )
    with pytest.raises(ValueError, match="B-3D.*no state"):
        list(feeder)
    corrector = RegistrationCorrector(result_of(names, np.zeros(len(names))), s.sensors, FRAME)
    other = Detection(
        det.state_vector,
        timestamp=det.timestamp,
        measurement_model=det.measurement_model,
        metadata={"sensor": "Z-9"},
    )
    with pytest.raises(ValueError, match="Z-9"):
        corrector.correct(other)
    rate = CartesianToBearingRangeRate(
        ndim_state=6, mapping=(0, 2, 4), velocity_mapping=(1, 3, 5), noise_covar=np.eye(3)
    )
    with pytest.raises(ValueError, match="B-3D.*CartesianToBearingRangeRate"):
        corrector.correct(Detection(np.zeros((3, 1)), measurement_model=rate, metadata={"sensor": "B-3D"}))
    bare = CartesianToElevationBearingRange(ndim_state=6, mapping=(0, 2, 4), noise_covar=np.eye(3))
    bare.rotation_offset = None
    with pytest.raises(ValueError, match="B-3D.*orientation"):
        corrector.correct(Detection(det.state_vector, measurement_model=bare, metadata={"sensor": "B-3D"}))
    loose = RadarElevationBearingRange(
        ndim_state=6, position_mapping=(0, 2, 4), noise_covar=np.eye(3)
    )  # no platform
    with pytest.raises(ValueError, match="B-3D.*default pose"):
        corrector.correct(
            Detection(
                det.state_vector, measurement_model=loose.measurement_model, metadata={"sensor": "B-3D"}
            )
        )
    cov = np.zeros((len(names), len(names)))
    cov[names.index("B:heading_error"), names.index("B:heading_error")] = np.inf
    with pytest.raises(ValueError, match="B:heading_error"):
        RegistrationCorrector(result_of(names, np.zeros(len(names)), cov), s.sensors, FRAME).correct(det)
    RegistrationCorrector(
        result_of(names, np.zeros(len(names)), cov), s.sensors, FRAME, registration_noise=False
    ).correct(det)


def test_a_live_online_filter_corrects_each_scan_with_what_it_knows_by_then():
    """The feeder reads the filter before every scan: scans fed before any update pass through
    unchanged (zero estimate), scans after the filter has seen 60 s of plots come out corrected
    by its estimate at that time."""
    from registration.fleet import FleetFilter

    s = fleet_scenario(6, duration_s=120.0)
    filt = FleetFilter(s.sensors, s.navigation, s.platforms, s.references)
    detections = detections_of(s, ("A-3D",))
    early = [d for d in detections if (d.timestamp - EPOCH).total_seconds() < 10][:3]
    late = [d for d in detections if (d.timestamp - EPOCH).total_seconds() > 100][:3]
    order = np.argsort(s.plots["time"])
    first = {k: v[order] for k, v in s.plots.items()}
    first = {k: v[first["time"] < 61.0] for k, v in first.items()}

    def scans():
        for d in early:
            yield d.timestamp, {d}
        filt.update(first)  # the filter learns between the scans
        for d in late:
            yield d.timestamp, {d}

    out = [
        next(iter(dets))
        for _, dets in RegisteredDetectionFeeder(reader=scans(), result=filt, sensors=s.sensors, frame=FRAME)
    ]
    bias = filt.estimate[filt.layout.index("A-3D:range_bias")]
    assert abs(bias) > 50.0  # the filter has learned the range bias by the late scans
    for before, after in zip(early + late, out):
        shift = float(after.state_vector[-1] - before.state_vector[-1])
        assert shift == (0.0 if before in early else pytest.approx(-bias, rel=1e-12))
