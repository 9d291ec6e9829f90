"""The two-ship data contract of registration.online (synchronous pairs of plots, columns ``time``,
``a_lat`` ... ``b_elevation``) as the fleet's long-form tables, for comparing the two estimators."""

from __future__ import annotations

import numpy as np

NAV = ("lat", "lon", "alt", "heading", "pitch", "roll")
PLOT = ("range", "bearing", "elevation")
#: The online filter's state names -> the fleet's, in the filter's order.
STATE_MAP = {
    "dC_a": "a:heading_error",
    "dphi_a": "a:pitch_error",
    "dtheta_a": "a:roll_error",
    "dr_a": "a-radar:range_bias",
    "dq_a": "a-radar:bearing_bias",
    "de_a": "a-radar:elevation_bias",
    "dC_b": "b:heading_error",
    "dphi_b": "b:pitch_error",
    "dtheta_b": "b:roll_error",
    "dr_b": "b-radar:range_bias",
    "dq_b": "b-radar:bearing_bias",
    "de_b": "b-radar:elevation_bias",
}


def fleet_tables(data: dict, sigma0, prior_sigma) -> dict:
    """Tables for build_problem from the two-ship ``data``; noise ``sigma0`` (6,) and the filter's
    ``prior_sigma`` (12,) in its state order."""
    t = np.asarray(data["time"], dtype=float)
    n = t.size
    names = list(STATE_MAP)
    prior = dict(zip(names, prior_sigma))
    navigation = {"platform": np.repeat(["a", "b"], n), "time": np.r_[t, t]}
    for c in NAV:
        navigation[c] = np.r_[data[f"a_{c}"], data[f"b_{c}"]]
    plots = {
        "time": np.r_[t, t],
        "sensor": np.repeat(["a-radar", "b-radar"], n),
        "target": np.full(2 * n, "T"),
    }
    for c in PLOT:
        plots[c] = np.r_[data[f"a_{c}"], data[f"b_{c}"]]
    platforms = {"platform": np.array(["a", "b"])}
    for what, key in (("heading", "dC"), ("pitch", "dphi"), ("roll", "dtheta")):
        platforms[f"prior_{what}"] = np.array([prior[f"{key}_a"], prior[f"{key}_b"]])
    sensors = {"sensor": np.array(["a-radar", "b-radar"]), "platform": np.array(["a", "b"])}
    for k, (c, key) in enumerate(zip(PLOT, ("dr", "dq", "de"))):
        sensors[f"sigma_{c}"] = np.array([sigma0[k], sigma0[3 + k]])
        sensors[f"prior_{c}"] = np.array([prior[f"{key}_a"], prior[f"{key}_b"]])
    return {"plots": plots, "sensors": sensors, "navigation": navigation, "platforms": platforms}
