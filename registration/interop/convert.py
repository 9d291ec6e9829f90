"""Stone Soup detections <-> this package's plots, sensors and navigation tables.

Supported measurement models: ``CartesianToElevationBearingRange`` (a 3-D radar: range, bearing,
elevation) and ``CartesianToBearingRange`` (a 2-D radar: range, bearing). Measurement vectors are
in Stone Soup's order, ``(elevation, bearing, range)`` and ``(bearing, range)``, with Stone Soup's
bearing counter-clockwise from the body x axis: ``bearing_ss = -bearing_deck``. Poses follow
:mod:`registration.interop.world`. Detections carry ``metadata["sensor"]`` (and ``"target"``,
``"platform"``); time in the tables is seconds since ``epoch``.

Stone Soup's 2-D model works in the world's x-y plane: it ignores height and measures horizontal
range. It equals this package's 2-D radar (slant range in the deck frame) only for a level sensor
and a target at the sensor's height in world coordinates; the conversion keeps the values as they
are and says so, it does not invent an elevation.
"""

from __future__ import annotations

import datetime

import numpy as np
from stonesoup.models.measurement.nonlinear import CartesianToBearingRange, CartesianToElevationBearingRange
from stonesoup.platform import FixedPlatform
from stonesoup.sensor.radar import RadarElevationBearingRange
from stonesoup.types.angle import Bearing, Elevation
from stonesoup.types.array import CovarianceMatrix, StateVector
from stonesoup.types.detection import Detection
from stonesoup.types.state import State

from registration.core.angles import wrap_angle
from registration.fleet.data.navigation import navigation_at, platform_navigation
from registration.fleet.data.tables import CHANNELS, read_table
from registration.interop.requires import STONESOUP_VERSION
from registration.interop.world import LocalFrame

__all__ = [
    "EPOCH",
    "MODEL_CHANNELS",
    "POSITION_MAPPING",
    "STONESOUP_VERSION",
    "measurement_model",
    "model_kind",
    "model_pose",
    "measured_plot",
    "ss_covariance",
    "ss_vector",
    "tables_to_detections",
    "mounted_radar",
]

#: Default time origin of the tables (seconds since this instant, naive UTC).
EPOCH = datetime.datetime(2000, 1, 1)
#: Channels (range, bearing, elevation) that each supported model measures.
MODEL_CHANNELS = {
    CartesianToElevationBearingRange: (True, True, True),
    CartesianToBearingRange: (True, True, False),
}
#: Position indices of Stone Soup's constant-velocity state (x, vx, y, vy, z, vz).
POSITION_MAPPING = (0, 2, 4)


def model_kind(model, sensor) -> type:
    """The supported model class of ``model``; ValueError naming the sensor and the model otherwise."""
    for kind in MODEL_CHANNELS:
        if type(model) is kind:
            return kind
    raise ValueError(
        f"sensor {sensor!r}: measurement model {type(model).__name__} is not supported "
        f"(supported: {', '.join(k.__name__ for k in MODEL_CHANNELS)})"
    )


def model_pose(model, sensor) -> tuple[np.ndarray, np.ndarray]:
    """The sensor's world position (3,) m (a 2-D model's height is 0) and Stone Soup orientation (3,)
    rad held by ``model``. ValueError naming the sensor for a model without pose, or with the
    all-zero pose that Stone Soup fills in when the sensor has no platform position and orientation."""
    t, o = model.translation_offset, model.rotation_offset
    if t is None or o is None:
        raise ValueError(
            f"sensor {sensor!r}: its {type(model).__name__} has no translation_offset/rotation_offset "
            "(the platform lacks position or orientation)"
        )
    t, o = np.asarray(t, dtype=float).ravel(), np.asarray(o, dtype=float).ravel()
    if not (np.any(t) or np.any(o)):
        raise ValueError(
            f"sensor {sensor!r}: its {type(model).__name__} has the default pose (position 0, orientation "
            "0), which Stone Soup gives a sensor whose platform lacks position and orientation"
        )
    p = np.zeros(3)
    p[: min(3, t.size)] = t[:3]
    return p, o[:3]


def ss_vector(kind: type, plot) -> StateVector:
    """Stone Soup measurement vector of a plot (range m, deck bearing rad, elevation rad)."""
    r, q, e = (float(v) for v in plot)
    if kind is CartesianToElevationBearingRange:
        return StateVector([Elevation(e), Bearing(-q), r])
    return StateVector([Bearing(-q), r])


def ss_covariance(kind: type, cov_plot: np.ndarray) -> np.ndarray:
    """A (3, 3) covariance in plot order (range, bearing, elevation) in Stone Soup's measurement order."""
    rows = (
        [[0, 0, 1], [0, -1, 0], [1, 0, 0]]
        if kind is CartesianToElevationBearingRange
        else [[0, -1, 0], [1, 0, 0]]
    )
    M = np.array(rows, dtype=float)
    return M @ cov_plot @ M.T


def measured_plot(detection, sensor) -> np.ndarray:
    """(range m, deck bearing rad, elevation rad; NaN if not measured) of a detection."""
    kind = model_kind(detection.measurement_model, sensor)
    z = np.asarray(detection.state_vector, dtype=float).ravel()
    if kind is CartesianToElevationBearingRange:
        return np.array([z[2], float(wrap_angle(-z[1])), z[0]])
    return np.array([z[1], float(wrap_angle(-z[0])), np.nan])


def measurement_model(
    frame: LocalFrame,
    navigation,
    lever_deck,
    sigma,
    sensor="sensor",
    *,
    mapping=POSITION_MAPPING,
    ndim_state: int = 6,
):
    """The Stone Soup model of a sensor at one navigation row (lat, lon, alt, heading, pitch, roll;
    rad, m) with lever arm ``lever_deck`` (m) and noise ``sigma`` = (range m, bearing rad,
    elevation rad; NaN = not measured). ValueError naming the sensor for other channel sets."""
    sigma = np.asarray(sigma, dtype=float)
    channels = tuple(bool(v) for v in np.isfinite(sigma))
    kind = next((k for k, c in MODEL_CHANNELS.items() if c == channels), None)
    if kind is None:
        measured = [c for c, m in zip(CHANNELS, channels) if m]
        raise ValueError(
            f"sensor {sensor!r} measures {measured}: Stone Soup models exist here for range+bearing "
            "(CartesianToBearingRange) and range+bearing+elevation (CartesianToElevationBearingRange) only"
        )
    p_world, orientation = frame.sensor_pose(navigation, lever_deck)
    cov = np.diag(np.nan_to_num(sigma) ** 2)
    mapping = tuple(mapping)[: 3 if kind is CartesianToElevationBearingRange else 2]
    return kind(
        ndim_state=ndim_state,
        mapping=mapping,
        noise_covar=CovarianceMatrix(ss_covariance(kind, cov)),
        translation_offset=StateVector(p_world[0]),
        rotation_offset=StateVector(orientation[0]),
    )


def mounted_radar(frame: LocalFrame, navigation, lever_deck, sigma, *, ndim_state: int = 6):
    """A Stone Soup ``FixedPlatform`` at one navigation row with a ``RadarElevationBearingRange``
    mounted at ``lever_deck`` (m, deck frame). Returns (platform, radar).

    Stone Soup does not rotate a fixed platform's mounting offset with its orientation, so the
    offset is given in world axes (the lever arm turned by the platform's attitude)."""
    nav = np.asarray(navigation, dtype=float).reshape(1, 6)
    p_nav, orientation = frame.sensor_pose(nav)
    p_sensor, _ = frame.sensor_pose(nav, lever_deck)
    state = np.zeros(ndim_state)
    state[list(POSITION_MAPPING)] = p_nav[0]
    sigma = np.asarray(sigma, dtype=float)
    cov = ss_covariance(CartesianToElevationBearingRange, np.diag(sigma**2))
    radar = RadarElevationBearingRange(
        ndim_state=ndim_state,
        position_mapping=POSITION_MAPPING,
        noise_covar=CovarianceMatrix(cov),
        mounting_offset=StateVector(p_sensor[0] - p_nav[0]),
    )
    platform = FixedPlatform(
        states=[State(StateVector(state))],
        position_mapping=POSITION_MAPPING,
        orientation=StateVector(orientation[0]),
        sensors=[radar],
    )
    return platform, radar


def tables_to_detections(
    plots,
    sensors,
    navigation,
    frame: LocalFrame,
    epoch: datetime.datetime = EPOCH,
    *,
    mapping=POSITION_MAPPING,
    ndim_state: int = 6,
) -> list:
    """Stone Soup ``Detection`` objects (time order) of a plots table, each with the measurement
    model of its sensor at the plot time (navigation interpolated as in :mod:`registration.fleet`).

    Tables as for ``registration.fleet.build_problem`` (SI units, radians). ValueError naming the
    sensor for a sensor without a Stone Soup model, and the row for a plot lacking a channel."""
    pt = read_table("plots", plots, ("time", "sensor", "target"))
    st = read_table("sensors", sensors, ("sensor", "platform"))
    sensor_ids = [str(s) for s in st.ids("sensor")]
    platform_of = dict(zip(sensor_ids, (str(p) for p in st.ids("platform"))))
    sigma = np.stack([st.floats(f"sigma_{c}", default=np.nan) for c in CHANNELS], axis=1)
    lever = np.stack([st.floats(f"lever_{a}", default=0.0) for a in "xyz"], axis=1)
    platform_ids = list(dict.fromkeys(platform_of.values()))
    tracks = platform_navigation(read_table("navigation", navigation, ("platform",)), platform_ids)
    sid, time = pt.ids("sensor"), pt.floats("time")
    unknown = np.flatnonzero(~np.isin(sid, sensor_ids))
    if unknown.size:
        raise pt.error(int(unknown[0]), f"sensor {sid[unknown[0]]!r} is not in the sensors table")
    s_index = np.array([sensor_ids.index(s) for s in sid], dtype=int)
    p_index = np.array([platform_ids.index(platform_of[s]) for s in sid], dtype=int)
    nav = navigation_at(tracks, platform_ids, p_index, time, lambda i: f"plots row {i} (sensor {sid[i]!r})")
    values = np.stack([pt.floats(c, default=np.nan) for c in CHANNELS], axis=1)
    targets = pt.ids("target")
    out = []
    for i in np.argsort(time, kind="stable"):
        s = s_index[i]
        model = measurement_model(
            frame, nav[i], lever[s], sigma[s], sensor_ids[s], mapping=mapping, ndim_state=ndim_state
        )
        wanted = np.array(MODEL_CHANNELS[type(model)])
        if not np.isfinite(values[i, wanted]).all():
            raise pt.error(
                int(i),
                f"sensor {sensor_ids[s]!r}: a {type(model).__name__} detection needs "
                f"{[c for c, w in zip(CHANNELS, wanted) if w]}, got {values[i].tolist()}",
            )
        out.append(
            Detection(
                ss_vector(type(model), values[i]),
                timestamp=epoch + datetime.timedelta(seconds=float(time[i])),
                measurement_model=model,
                metadata={
                    "sensor": sensor_ids[s],
                    "target": str(targets[i]),
                    "platform": platform_of[sensor_ids[s]],
                },
            )
        )
    return out
