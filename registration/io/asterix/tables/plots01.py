"""CAT001 target reports -> plots of the fleet plots file, as for CAT048
(:mod:`registration.io.asterix.tables.plots48`): the same columns, the same target id rules (no Mode S
address in CAT001: a valid Mode 3/A code or no id).

* time: I001/141 (truncated, modulo 512 s) made whole by
  :mod:`registration.io.asterix.tables.truncated`, then placed on the time axis.
* range: I001/040 RHO (1/128 NM, slant range) x 1852 m/NM; bearing: THETA (360/2^16 deg).
* set aside, first reason first: a track (I001/020 TYP 1, ``cat001_track``: only plots are
  measurements), no I001/010, I001/141 or I001/040 (``missing_item``), no full time of day
  (``no_full_time``), SAC/SIC not in SITES, TST (``test_target``), SIM (``simulated``), RAB
  (``field_monitor``), SSR/PSR 0 (``no_detection``), RHO 0 (``zero_range``).
"""

from __future__ import annotations

import numpy as np

from registration.io.asterix.decode.decode001 import RHO_LSB_NM, THETA_LSB_DEG
from registration.io.asterix.tables.plots48 import NM_M, pressure_altitude_m, target_ids, unknown_source_texts
from registration.io.asterix.tables.truncated import BASE_NONE
from registration.io.asterix.tables.verdicts import Verdicts

__all__ = ["plot_verdicts01", "plot_columns01"]


def plot_verdicts01(f: dict, sensor: np.ndarray) -> Verdicts:
    """Why each CAT001 record is set aside ('' when kept); ``f`` the fields of
    :func:`~registration.io.asterix.decode.decode001.decode001` with the full time of
    :class:`~registration.io.asterix.tables.truncated.TruncatedClock`; ``sensor`` (N,) index of its
    SITES row (-1: SAC/SIC not in SITES)."""
    v = Verdicts(f["sac"].size)
    v.rule(f["typ"] == 1, "cat001_track", "a CAT001 track (I001/020 TYP 1): only plots are imported")
    for item, what in (
        ("010", "data source identifier"),
        ("141", "truncated time of day"),
        ("040", "measured position"),
    ):
        v.rule(~f[f"has_{item}"], "missing_item", f"no I001/{item} ({what})")
    v.rule(
        f["time_base"] == BASE_NONE,
        "no_full_time",
        "I001/141 is the time of day modulo 512 s and no full time of day came before it in the stream "
        "(a CAT002 message of its radar or a record of any category)",
    )
    v.rule(sensor < 0, "unknown_sac_sic", unknown_source_texts(f["sac"], f["sic"], sensor < 0))
    v.rule(f["tst"] == 1, "test_target", "test target (I001/020 TST)")
    v.rule(f["sim"] == 1, "simulated", "simulated target (I001/020 SIM)")
    v.rule(f["rab"] == 1, "field_monitor", "report from a field monitor (I001/020 RAB)")
    v.rule(f["has_020"] & (f["ssrpsr"] == 0), "no_detection", "I001/020 SSR/PSR 0: no detection")
    v.rule(f["rho"] == 0, "zero_range", "I001/040 RHO is 0 (a plot at the radar)")
    return v


def plot_columns01(f: dict, time_s: np.ndarray, sensor_name: np.ndarray) -> dict:
    """The plots file columns of CAT001 records (all of them; select the kept ones after):
    ``time_s``, ``sensor``, ``target``, ``range_m``, ``bearing_deg``, ``kind`` ('mode_a', 'none'),
    ``primary`` (I001/020 SSR/PSR 1: sole primary detection), ``pressure_alt_m`` (I001/090, as
    :func:`~registration.io.asterix.tables.plots48.pressure_altitude_m`)."""
    ids, kind = target_ids(f)
    return {
        "time_s": time_s,
        "sensor": sensor_name,
        "target": ids,
        "range_m": f["rho"] * (RHO_LSB_NM * NM_M),
        "bearing_deg": f["theta"] * THETA_LSB_DEG,
        "kind": kind,
        "primary": f["has_020"] & (f["ssrpsr"] == 1),
        "pressure_alt_m": pressure_altitude_m(f),
    }
