"""CAT063 sensor status messages (EUROCONTROL ASTERIX Category 063, editions 1.6 and 1.7) carrying
the estimates of a registration, one record per sensor: what a tracker of the ARTAS class reads to
correct a radar's plots.

Items written (field reference number in brackets):

- I063/010 [1] data source identifier: SAC/SIC of the registration service;
- I063/015 [2] service identification (one octet);
- I063/030 [3] time of message, s since midnight UTC, LSB 1/128 s;
- I063/050 [4] sensor identifier: SAC/SIC of the radar;
- I063/060 [5] sensor configuration and status, first octet: CON (0 operational, 1 degraded,
  2 initialisation, 3 not connected), PSR/SSR/MDS/ADS/MLT NOGO bits;
- I063/070 [6] time stamping bias, ms, LSB 1 ms, signed;
- I063/080 [7] SSR / Mode S range gain (LSB 1e-5, signed) and range bias (NM, LSB 1/128, signed);
- I063/081 [8] SSR / Mode S azimuth bias, degrees, LSB 360/2^16, signed;
- I063/090 [9] PSR range gain and bias, as I063/080;
- I063/091 [10] PSR azimuth bias, as I063/081.

An item is written only when its value is known (not None, finite). Values are this package's
error convention (docs/reference/conventions.md): the error as estimated, reported minus true, so a plot is
corrected by subtracting it: time bias = reported minus true plot time; range error = bias + gain x
true range; azimuth error = bias. Inside, SI units and radians; the item units (ms, NM, degrees)
only here, at the edge. Each value is rounded to the nearest LSB; a value outside what the item
can hold is a ValueError naming the sensor and the item.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TypeGuard

from registration.io.asterix.encode.blocks import data_blocks, fspec, signed_item, unsigned_item
from registration.io.asterix.tables.sites import PSR_SUFFIX

__all__ = ["CAT063_EDITIONS", "NM_M", "SensorStatus", "encode_cat063", "estimates_cat063", "status_record"]

#: The editions whose layout of these items this encoder writes (identical for the items used).
CAT063_EDITIONS = ("1.6", "1.7")
#: One international nautical mile, m.
NM_M = 1852.0
_AZIMUTH_LSB_RAD = 2.0 * math.pi / 65536.0
_RANGE_BIAS_LSB_M = NM_M / 128.0
_GAIN_LSB = 1e-5
_TIME_BIAS_LSB_S = 1e-3
_CON = {"operational": 0, "degraded": 1, "initialisation": 2, "not_connected": 3}


@dataclass(frozen=True, kw_only=True)
class SensorStatus:
    """The status of one sensor at one time, SI units and radians (None: not estimated, the item
    is left out). ``name`` is used in error messages only."""

    name: str
    sac: int
    sic: int
    time_of_day_s: float  # s since midnight UTC
    state: str = "operational"  # operational, degraded, initialisation, not_connected
    time_bias_s: float | None = None  # reported minus true plot time, s
    ssr_range_gain: float | None = None  # dimensionless
    ssr_range_bias_m: float | None = None  # m
    ssr_azimuth_bias_rad: float | None = None  # rad
    psr_range_gain: float | None = None
    psr_range_bias_m: float | None = None
    psr_azimuth_bias_rad: float | None = None
    psr_nogo: bool = False
    ssr_nogo: bool = False


def _known(value: float | None) -> TypeGuard[float]:
    return value is not None and math.isfinite(value)


def _quantum(value: float, lsb: float, bits: int, what: str) -> bytes:
    raw = signed_item(round(value / lsb), bits, what)
    return raw.to_bytes(bits // 8, "big")


def _gain_and_bias(status: SensorStatus, gain: float | None, bias_m: float | None, item: str) -> bytes:
    """I063/080 or I063/090: both subfields are written; an unknown one is sent as 0."""
    g = gain if _known(gain) else 0.0
    b = bias_m if _known(bias_m) else 0.0
    return _quantum(g, _GAIN_LSB, 16, f"{status.name}: {item} range gain") + _quantum(
        b, _RANGE_BIAS_LSB_M, 16, f"{status.name}: {item} range bias (m)"
    )


def status_record(status: SensorStatus, sac: int, sic: int, service_id: int = 1) -> bytes:
    """One CAT063 record (FSPEC and items) for ``status``, sent by the service ``sac``/``sic``."""
    name = status.name
    items: dict[int, bytes] = {
        1: bytes([unsigned_item(sac, 8, "I063/010 SAC"), unsigned_item(sic, 8, "I063/010 SIC")]),
        2: bytes([unsigned_item(service_id, 8, "I063/015")]),
        3: unsigned_item(round(status.time_of_day_s * 128.0) % (86400 * 128), 24, "I063/030").to_bytes(
            3, "big"
        ),
        4: bytes(
            [
                unsigned_item(status.sac, 8, f"{name}: I063/050 SAC"),
                unsigned_item(status.sic, 8, f"{name}: SIC"),
            ]
        ),
    }
    if status.state not in _CON:
        raise ValueError(f"{name}: state {status.state!r} is not one of {sorted(_CON)}")
    items[5] = bytes([_CON[status.state] << 6 | int(status.psr_nogo) << 5 | int(status.ssr_nogo) << 4])
    if _known(status.time_bias_s):
        items[6] = _quantum(status.time_bias_s, _TIME_BIAS_LSB_S, 16, f"{name}: I063/070 time bias (s)")
    if _known(status.ssr_range_gain) or _known(status.ssr_range_bias_m):
        items[7] = _gain_and_bias(status, status.ssr_range_gain, status.ssr_range_bias_m, "I063/080 SSR")
    if _known(status.ssr_azimuth_bias_rad):
        items[8] = _quantum(
            status.ssr_azimuth_bias_rad, _AZIMUTH_LSB_RAD, 16, f"{name}: I063/081 azimuth bias"
        )
    if _known(status.psr_range_gain) or _known(status.psr_range_bias_m):
        items[9] = _gain_and_bias(status, status.psr_range_gain, status.psr_range_bias_m, "I063/090 PSR")
    if _known(status.psr_azimuth_bias_rad):
        items[10] = _quantum(
            status.psr_azimuth_bias_rad, _AZIMUTH_LSB_RAD, 16, f"{name}: I063/091 azimuth bias"
        )
    return fspec(items) + b"".join(items[k] for k in sorted(items))


def encode_cat063(statuses: Sequence[SensorStatus], sac: int, sic: int, service_id: int = 1) -> bytes:
    """CAT063 data blocks holding one record per status, sent by the service ``sac``/``sic``."""
    return data_blocks(63, [status_record(s, sac, sic, service_id) for s in statuses])


def estimates_cat063(
    estimates: Mapping[str, Mapping[str, float]],
    sources: Mapping[str, tuple[int, int]],
    time_of_day_s: float,
    service: tuple[int, int],
    silent: frozenset[str] = frozenset(),
) -> bytes:
    """CAT063 data blocks, one record per sensor of ``sources`` (sensor -> SAC/SIC) with its
    estimates (``estimates``: sensor -> state -> value, SI: ``range_bias``, ``range_gain``,
    ``bearing_bias``, ``time_bias``; those of ``<sensor>.psr``, its PSR channel, in I063/090 and
    091) at ``time_of_day_s`` (s since midnight UTC); ``silent`` sensors are reported ``not
    connected``, the others operational. ``service``: the SAC/SIC of the sender."""
    statuses = []
    for name, (sac, sic) in sources.items():
        v = estimates.get(name, {})
        psr = estimates.get(name + PSR_SUFFIX, {})  # its PSR channel, when it is a sensor of its own
        statuses.append(
            SensorStatus(
                name=name,
                sac=sac,
                sic=sic,
                time_of_day_s=time_of_day_s % 86400.0,
                state="not_connected" if name in silent else "operational",
                time_bias_s=v.get("time_bias"),
                ssr_range_gain=v.get("range_gain"),
                ssr_range_bias_m=v.get("range_bias"),
                ssr_azimuth_bias_rad=v.get("bearing_bias"),
                psr_range_gain=psr.get("range_gain"),
                psr_range_bias_m=psr.get("range_bias"),
                psr_azimuth_bias_rad=psr.get("bearing_bias"),
            )
        )
    return encode_cat063(statuses, *service)
