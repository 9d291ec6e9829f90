"""Stone Soup detections -> this package's plots, sensors and navigation tables.

Each detection's model pose (``translation_offset``: the sensor's world position, m;
``rotation_offset``: its orientation (roll, pitch, yaw), rad) gives its platform's navigation at
the detection time: the sensor position moved back along the lever arm, the attitude relative to
the local ENU there (:meth:`registration.interop.world.LocalFrame.navigation`). A 2-D model's
position has no height: world z = 0 is used.
"""

from __future__ import annotations

import datetime
from typing import Iterable

import numpy as np
from stonesoup.types.detection import Clutter

from registration.fleet.data.tables import CHANNELS, NAV_COLUMNS, read_table
from registration.interop.convert import MODEL_CHANNELS, measured_plot, model_kind, model_pose
from registration.interop.requires import STONESOUP_VERSION
from registration.interop.world import LocalFrame

__all__ = ["STONESOUP_VERSION", "detections_to_tables"]

#: Two sensors of one platform at one instant must imply the same navigation within these: latitude
#: and longitude (rad; 2e-10 rad is about 1 mm), attitude (rad), altitude (m).
SAME_NAV_POSITION, SAME_NAV_ANGLE, SAME_NAV_M = 2e-10, 1e-7, 1e-3


def _target_of(detection, key: str):
    tid = detection.metadata.get(key)
    if tid is None and getattr(detection, "groundtruth_path", None) is not None:
        tid = detection.groundtruth_path.id
    return tid


def _collect(detections: Iterable, sensor_key: str, target_key: str) -> list:
    """(sensor id, target id, detection) of every detection that is not clutter, checked."""
    rows = []
    for k, det in enumerate(detections):
        if isinstance(det, Clutter):
            continue
        sensor = det.metadata.get(sensor_key)
        if sensor is None:
            raise ValueError(
                f"detection {k} at {det.timestamp}: no metadata[{sensor_key!r}] naming its sensor"
            )
        model_kind(det.measurement_model, sensor)
        model_pose(det.measurement_model, sensor)
        target = _target_of(det, target_key)
        if target is None:
            raise ValueError(
                f"sensor {sensor!r}: detection {k} at {det.timestamp} has no target id "
                f"(metadata[{target_key!r}] or a ground-truth path)"
            )
        rows.append((str(sensor), str(target), det))
    if not rows:
        raise ValueError("detections: nothing to convert (no detections, or clutter only)")
    return rows


def _sensor_info(sensors, wanted: list) -> dict:
    """sensor id -> (platform id, lever (3,) m, prior columns) from an optional sensors table."""
    if sensors is None:
        return {s: (s, np.zeros(3), {}) for s in wanted}
    st = read_table("sensors", sensors, ("sensor", "platform"))
    ids, platforms = list(st.ids("sensor")), st.ids("platform")
    lever = np.stack([st.floats(f"lever_{a}", default=0.0) for a in "xyz"], axis=1)
    priors = {c: st.floats(c) for c in st.columns if c.startswith("prior_")}
    missing = [s for s in wanted if s not in ids]
    if missing:
        raise ValueError(f"sensors: detections of sensor(s) {missing}, but the sensors table lists {ids}")
    return {
        s: (
            str(platforms[ids.index(s)]),
            lever[ids.index(s)],
            {c: v[ids.index(s)] for c, v in priors.items()},
        )
        for s in wanted
    }


def _sensors_table(rows: list, info: dict) -> dict:
    """The sensors table: noise sigmas from the models (one noise per sensor), platform, lever arm."""
    sigma, kinds = {}, {}
    for sensor, _, det in rows:
        model = det.measurement_model
        kind = type(model)
        cov = np.asarray(model.covar(), dtype=float)
        s = np.full(3, np.nan)
        d = np.sqrt(np.diag(cov))
        s[:2] = (d[-1], d[-2])  # range is last, bearing before it, in both models
        if MODEL_CHANNELS[kind][2]:
            s[2] = d[0]
        if sensor not in sigma:
            sigma[sensor], kinds[sensor] = s, kind
        elif kinds[sensor] is not kind or not np.allclose(sigma[sensor], s, rtol=1e-9, equal_nan=True):
            raise ValueError(
                f"sensor {sensor!r}: its detections carry different models or noise "
                f"({kinds[sensor].__name__} {sigma[sensor].tolist()} vs {kind.__name__} {s.tolist()})"
            )
    ids = list(sigma)
    out = {"sensor": np.array(ids), "platform": np.array([info[s][0] for s in ids])}
    for k, c in enumerate(CHANNELS):
        out[f"sigma_{c}"] = np.array([sigma[s][k] for s in ids])
    for k, a in enumerate("xyz"):
        out[f"lever_{a}"] = np.array([info[s][1][k] for s in ids])
    for c in sorted({c for s in ids for c in info[s][2]}):
        out[c] = np.array([info[s][2].get(c, np.inf) for s in ids])
    return out


def _navigation_table(platform: np.ndarray, time: np.ndarray, nav: np.ndarray, sensor: np.ndarray) -> dict:
    """One navigation row per (platform, time); sensors of one platform at one instant must agree."""
    order = np.lexsort((time, platform))
    keep: list[int] = []
    for i in order:
        if keep and platform[keep[-1]] == platform[i] and time[keep[-1]] == time[i]:
            j = keep[-1]
            diff = np.abs(nav[i] - nav[j])
            diff[3] = abs(float((nav[i, 3] - nav[j, 3] + np.pi) % (2 * np.pi) - np.pi))
            if diff[:2].max() > SAME_NAV_POSITION or diff[2] > SAME_NAV_M or diff[3:].max() > SAME_NAV_ANGLE:
                raise ValueError(
                    f"platform {platform[i]!r} at {time[i]} s: sensors {sensor[j]!r} and {sensor[i]!r} "
                    f"imply different navigation (lever arms or orientations disagree): "
                    f"{nav[j].tolist()} vs {nav[i].tolist()}"
                )
            continue
        keep.append(i)
    rows = np.array(keep, dtype=int)
    return {
        "platform": platform[rows],
        "time": time[rows],
        **{c: nav[rows, k] for k, c in enumerate(NAV_COLUMNS)},
    }


def detections_to_tables(
    detections: Iterable,
    frame: LocalFrame,
    sensors=None,
    epoch: datetime.datetime | None = None,
    *,
    sensor_key: str = "sensor",
    target_key: str = "target",
) -> dict:
    """The ``plots``, ``sensors`` and ``navigation`` tables (dicts of numpy columns, SI units,
    radians) of Stone Soup detections, and the ``epoch`` their times count from (default: the
    earliest detection).

    ``detection.metadata[sensor_key]`` names the sensor; the target is ``metadata[target_key]``
    or the ground-truth path's id; clutter is left out. ``sensors`` (optional, a sensors table)
    gives each sensor's platform and lever arm (default: a platform per sensor, no lever arm)
    and is copied with its ``prior_*`` columns; the noise sigmas come from the models. Pass the
    result to ``registration.fleet.build_problem(plots, sensors, navigation)``.
    """
    rows = _collect(detections, sensor_key, target_key)
    sensor_ids = list(dict.fromkeys(r[0] for r in rows))
    info = _sensor_info(sensors, sensor_ids)
    epoch = min(det.timestamp for _, _, det in rows) if epoch is None else epoch
    time = np.array([(det.timestamp - epoch).total_seconds() for _, _, det in rows])
    sensor = np.array([r[0] for r in rows])
    plot = np.stack([measured_plot(det, s) for s, _, det in rows])
    poses = [model_pose(det.measurement_model, s) for s, _, det in rows]
    lever = np.stack([info[s][1] for s in sensor])
    nav = frame.navigation(np.stack([p for p, _ in poses]), np.stack([o for _, o in poses]), lever)
    platform = np.array([info[s][0] for s in sensor])
    plots = {
        "time": time,
        "sensor": sensor,
        "target": np.array([r[1] for r in rows]),
        **{c: plot[:, k] for k, c in enumerate(CHANNELS)},
    }
    return {
        "plots": plots,
        "sensors": _sensors_table(rows, info),
        "navigation": _navigation_table(platform, time, nav, sensor),
        "epoch": epoch,
    }
