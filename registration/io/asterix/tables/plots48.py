"""CAT048 target reports -> plots of the fleet plots file (``time_s``, ``sensor``, ``target``,
``range_m``, ``bearing_deg``; no elevation: a surveillance radar does not measure it).

* sensor: I048/010 SAC/SIC looked up in SITES; not there: set aside (``unknown_sac_sic``).
* time: I048/140 placed on the time axis (:mod:`registration.io.asterix.tables.timeofday`).
* range: I048/040 RHO (1/256 NM, slant range) x 1852 m/NM (exact); bearing: THETA (360/2^16 deg,
  clockwise from north, 0 <= bearing < 360).
* target: the I048/220 aircraft address as 6 uppercase hex digits ("4CA1F3"); else a valid
  Mode 3/A code (I048/070: V = 0 validated, G = 0 not garbled; L, smoothed, is fine) as "A" and 4
  octal digits ("A4521"), except the shared codes of :data:`SHARED_MODE_A` which name no aircraft;
  else no id (''): primary-only plots and the rest.
* set aside, first reason first: no I048/010, I048/140 or I048/040 (``missing_item``), time of
  day of 24 h or more (``bad_time``), SAC/SIC not in SITES, TST (``test_target``), SIM
  (``simulated``), RAB (``field_monitor``), TYP 0 (``no_detection``), RHO 0 (``zero_range``).
"""

from __future__ import annotations

import numpy as np

from registration.io.asterix.decode.decode48 import FLIGHT_LEVEL_LSB_FL, RHO_LSB_NM, THETA_LSB_DEG
from registration.io.asterix.tables.verdicts import Verdicts

__all__ = [
    "NM_M",
    "FL_M",
    "pressure_altitude_m",
    "SHARED_MODE_A",
    "format_ids",
    "unknown_source_texts",
    "target_ids",
    "plot_verdicts",
    "plot_columns",
    "file_kinds",
]

#: The international nautical mile (m), exact.
NM_M = 1852.0
#: A flight level: 100 ft of pressure altitude (m).
FL_M = 30.48
#: Mode 3/A codes shared by many aircraft (conspicuity, VFR, emergency, radio failure, unlawful
#: interference): they give no id.
SHARED_MODE_A = frozenset(int(code, 8) for code in ("1000", "1200", "2000", "7000", "7500", "7600", "7700"))


def format_ids(values: np.ndarray, fmt: str) -> np.ndarray:
    """Each integer formatted with ``fmt`` (e.g. "%06X"), through the unique values (few)."""
    if values.size == 0:
        return np.zeros(0, dtype=object)
    unique, inverse = np.unique(values, return_inverse=True)
    return np.array([fmt % int(v) for v in unique], dtype=object)[inverse.ravel()]


def unknown_source_texts(sac: np.ndarray, sic: np.ndarray, mask: np.ndarray) -> np.ndarray:
    """'SAC/SIC a/b is not in SITES' where ``mask``, '' elsewhere (N,)."""
    out = np.full(sac.size, "", dtype=object)
    pairs = sac[mask] * 256 + sic[mask]
    if pairs.size:
        unique, inverse = np.unique(pairs, return_inverse=True)
        texts = np.array(
            [f"SAC/SIC {p >> 8}/{p & 0xFF} is not in SITES" for p in unique.tolist()], dtype=object
        )
        out[mask] = texts[inverse.ravel()]
    return out


def target_ids(f: dict) -> tuple[np.ndarray, np.ndarray]:
    """(target id per record, kind per record: 'mode_s', 'mode_a' or 'none') from the fields of
    :func:`~registration.io.asterix.decode.decode48.decode048`."""
    n = f["address"].size
    ids = np.full(n, "", dtype=object)
    kind = np.full(n, "none", dtype=object)
    mode_a = f["has_070"] & (f["m3a_v"] == 0) & (f["m3a_g"] == 0) & ~np.isin(f["m3a"], list(SHARED_MODE_A))
    ids[mode_a], kind[mode_a] = format_ids(f["m3a"][mode_a], "A%04o"), "mode_a"
    mode_s = f["has_220"]
    ids[mode_s], kind[mode_s] = format_ids(f["address"][mode_s], "%06X"), "mode_s"
    return ids, kind


def pressure_altitude_m(f: dict) -> np.ndarray:
    """(N,) the pressure altitude (m) of each record's flight level (I048/090 or I001/090: 1/4 FL x
    30.48 m), NaN where the item is absent, not validated (V) or garbled (G)."""
    valid = f["has_090"] & (f["mc_v"] == 0) & (f["mc_g"] == 0)
    return np.where(valid, f["mode_c"] * (FLIGHT_LEVEL_LSB_FL * FL_M), np.nan)


def plot_verdicts(f: dict, sensor: np.ndarray) -> Verdicts:
    """Why each CAT048 record is set aside (''  when kept); ``sensor`` (N,) index of its SITES row
    (-1: SAC/SIC not in SITES)."""
    v = Verdicts(f["sac"].size)
    for item, what in (
        ("010", "data source identifier"),
        ("140", "time of day"),
        ("040", "measured position"),
    ):
        v.rule(~f[f"has_{item}"], "missing_item", f"no I048/{item} ({what})")
    v.rule(f["tod"] >= 86400 * 128, "bad_time", "I048/140 time of day is 24 h or more")
    v.rule(sensor < 0, "unknown_sac_sic", unknown_source_texts(f["sac"], f["sic"], sensor < 0))
    v.rule(f["tst"] == 1, "test_target", "test target (I048/020 TST)")
    v.rule(f["sim"] == 1, "simulated", "simulated target (I048/020 SIM)")
    v.rule(f["rab"] == 1, "field_monitor", "report from a field monitor (I048/020 RAB)")
    v.rule(f["has_020"] & (f["typ"] == 0), "no_detection", "I048/020 TYP 0: no detection")
    v.rule(f["rho"] == 0, "zero_range", "I048/040 RHO is 0 (a plot at the radar)")
    return v


def plot_columns(f: dict, time_s: np.ndarray, sensor_name: np.ndarray) -> dict:
    """The plots file columns of records (all of them; select the kept ones after): ``time_s``,
    ``sensor``, ``target``, ``range_m``, ``bearing_deg``, ``kind`` ('mode_s', 'mode_a', 'none') and
    ``primary`` (I048/020 TYP 1: a primary-only plot) and ``pressure_alt_m``
    (:func:`pressure_altitude_m`)."""
    ids, kind = target_ids(f)
    return {
        "time_s": time_s,
        "sensor": sensor_name,
        "target": ids,
        "range_m": f["rho"] * (RHO_LSB_NM * NM_M),
        "bearing_deg": f["theta"] * THETA_LSB_DEG,
        "kind": kind,
        "primary": f["has_020"] & (f["typ"] == 1),
        "pressure_alt_m": pressure_altitude_m(f),
    }


def file_kinds(kind: np.ndarray, primary: np.ndarray) -> np.ndarray:
    """The plots file's ``kind`` column: 'mode_s' or 'mode_a' (the id's kind), else 'primary' for a
    primary-only plot, else 'other' (a secondary plot without a usable id)."""
    kind = np.asarray(kind, dtype=object)
    return np.where(kind != "none", kind, np.where(np.asarray(primary, dtype=bool), "primary", "other"))
