"""CAT021 ADS-B reports -> the fleet reference file (``time_s``, ``target``, ``lat_deg``,
``lon_deg``, ``alt_m``, ``sigma_m``, ``sigma_up_m``).

* target: I021/080 target address as 6 uppercase hex digits, as the CAT048 plots' I048/220.
* time: I021/071 (time of applicability for position), else I021/073 (time of message reception
  for position), else I021/077 (time of report transmission); I021/030 in editions 0.2x.
* position: I021/131 (high resolution), else I021/130, WGS-84; ``alt_m``: I021/140 geometric height
  x 6.25 ft x 0.3048 m/ft, above the WGS-84 ellipsoid.
* ``sigma_m``, ``sigma_up_m``: the horizontal sigma (per axis, east and north) and the vertical
  one, from the position quality (:func:`adsb_sigma_m`).
* set aside, first reason first: no address, no time item, time of 24 h or more, TST, SIM, RAB
  (editions 2.x: I021/040; 0.2x: I021/040 too), no position, a position out of range, no
  quality (no I021/090 or no NACp in it; NACp 12-15 reserved), NACp below 7 (NUCp below 6),
  no geometric height.

The EPU (estimated position uncertainty, NACp) is a 95 % bound on the horizontal position
error. For a circular Gaussian of sigma s per axis the radius holding 95 % is
s sqrt(-2 ln 0.05) = 2.4477 s, so ``sigma_m`` = EPU / 2.4477. The vertical sigma ``sigma_up_m`` is
the 95 % bound of GVA (I021/090, 1: 150 m, 2: 45 m) over 1.96 when given, else twice the
horizontal one (GNSS vertical errors run about twice the horizontal per axis) (docs/howto/import-asterix.md).
"""

from __future__ import annotations

import math

import numpy as np

from registration.io.asterix.decode.decode21 import FLIGHT_LEVEL_LSB_FL, FOOT_M, HEIGHT_LSB_FT
from registration.io.asterix.tables.plots48 import format_ids
from registration.io.asterix.tables.verdicts import Verdicts

__all__ = [
    "NACP_EPU_M",
    "NUCP_EPU_M",
    "GVA_BOUND_M",
    "CIRCULAR_95",
    "adsb_sigma_m",
    "reference_verdicts",
    "reference_columns",
]

_NM = 1852.0
#: NACp -> horizontal EPU, 95 % (m) (RTCA DO-260B); NACp below 7 is set aside.
NACP_EPU_M = {7: 0.1 * _NM, 8: 0.05 * _NM, 9: 30.0, 10: 10.0, 11: 3.0}
#: NUCp (editions 0.2x) -> its 95 % horizontal accuracy bound (m) (DO-260); below 6 is set aside.
NUCP_EPU_M = {6: 0.1 * _NM, 7: 0.05 * _NM, 8: 10.0, 9: 3.0}
#: GVA -> 95 % vertical bound (m).
GVA_BOUND_M = {1: 150.0, 2: 45.0}
#: sqrt(-2 ln 0.05): the 95 % radius of a circular Gaussian, in sigmas per axis.
CIRCULAR_95 = math.sqrt(-2.0 * math.log(0.05))
_GAUSS_95 = 1.959964


def adsb_sigma_m(epu_m: np.ndarray, gva: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(horizontal sigma per axis, east and north; vertical sigma, along the local up), both m, of
    ADS-B positions of horizontal 95 % bound ``epu_m`` (m) and GVA ``gva`` (0 or 3: not stated):
    EPU / 2.4477, and GVA bound / 1.96, else 2 EPU / 2.4477."""
    horizontal = np.asarray(epu_m, dtype=float) / CIRCULAR_95
    gva = np.asarray(gva)
    vertical = np.where(
        gva == 1, GVA_BOUND_M[1] / _GAUSS_95, np.where(gva == 2, GVA_BOUND_M[2] / _GAUSS_95, 2.0 * horizontal)
    )
    return horizontal, vertical


def _lookup(table: dict, values: np.ndarray) -> np.ndarray:
    out = np.full(values.shape, np.nan)
    for k, v in table.items():
        out[values == k] = v
    return out


def reference_verdicts(f: dict, old_edition: bool) -> tuple[Verdicts, np.ndarray]:
    """(why each CAT021 record is set aside, its horizontal EPU in m: NaN where unknown)."""
    v = Verdicts(f["sac"].size)
    v.rule(~f["has_080"], "no_address", "no I021/080 (target address)")
    v.rule(
        f["time_item"] == "",
        "missing_item",
        "no time item (" + ("I021/030" if old_edition else "I021/071, I021/073 or I021/077") + ")",
    )
    v.rule(f["tod"] >= 86400 * 128, "bad_time", "time of day is 24 h or more")
    v.rule(f["tst"] == 1, "test_target", "test target (I021/040 TST)")
    v.rule(f["sim"] == 1, "simulated", "simulated target (I021/040 SIM)")
    v.rule(f["rab"] == 1, "field_monitor", "report from a field monitor (I021/040 RAB)")
    v.rule(~f["has_position"], "no_position", "no WGS-84 position (I021/130, I021/131)")
    v.rule(
        (np.abs(f["lat_deg"]) > 90) | (np.abs(f["lon_deg"]) > 180),
        "bad_position",
        "latitude beyond +-90 deg or longitude beyond +-180 deg",
    )
    if old_edition:
        v.rule(~f["has_nucp"], "no_quality", "no I021/090 (NUCp)")
        epu = _lookup(NUCP_EPU_M, f["nucp"])
        low = f["has_nucp"] & (f["nucp"] < 6)
        v.rule(low, "low_nacp", format_ids(f["nucp"], "NUCp %d is below 6"))
    else:
        v.rule(~f["has_nacp"], "no_quality", "no NACp (I021/090 absent or without its first extension)")
        v.rule(f["nacp"] > 11, "no_quality", format_ids(f["nacp"], "NACp %d is reserved"))
        epu = _lookup(NACP_EPU_M, f["nacp"])
        low = f["has_nacp"] & (f["nacp"] < 7)
        v.rule(low, "low_nacp", format_ids(f["nacp"], "NACp %d is below 7 (EPU of 0.3 NM or more)"))
    v.rule(~f["has_140"], "no_geometric_height", "no I021/140 (geometric height)")
    return v, epu


def reference_columns(f: dict, time_s: np.ndarray, epu_m: np.ndarray) -> dict:
    """The reference file columns of records (all; select the kept ones after), and
    ``pressure_alt_m``: the I021/145 flight level as a pressure altitude (1/4 FL x 30.48 m; NaN
    where absent), for the relation of flight levels to heights (not written)."""
    horizontal, vertical = adsb_sigma_m(epu_m, np.where(f["has_gva"], f["gva"], 0))
    return {
        "time_s": time_s,
        "target": format_ids(f["address"], "%06X"),
        "lat_deg": f["lat_deg"],
        "lon_deg": f["lon_deg"],
        "alt_m": f["height"] * (HEIGHT_LSB_FT * FOOT_M),
        "sigma_m": horizontal,
        "sigma_up_m": vertical,
        "pressure_alt_m": np.where(
            f["has_145"], f["flight_level"] * (FLIGHT_LEVEL_LSB_FL * 100.0 * FOOT_M), np.nan
        ),
    }
