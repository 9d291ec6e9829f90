"""What the live service sends on: CAT063 sensor status messages carrying the current estimates,
and the radars' CAT048 plots corrected by them (docs/reference/corrected-plots.md).

Both take the estimates of a sensor by state name (SI: rad, m, 1, s; this package's convention,
reported minus true): ``range_bias``, ``range_gain``, ``bearing_bias`` (the azimuth bias) and
``time_bias``; a state not estimated is left out of CAT063 and not corrected.
"""

from __future__ import annotations

from typing import Mapping

from registration.io.asterix.encode.cat063 import SensorStatus, encode_cat063
from registration.io.asterix.tables.sites import PSR_SUFFIX

__all__ = ["cat063_message", "plot_corrections"]


def _value(values: Mapping[str, float], name: str) -> float | None:
    return values.get(name)


def cat063_message(
    estimates: Mapping[str, Mapping[str, float]],
    sources: Mapping[str, tuple[int, int]],
    time_of_day_s: float,
    service: tuple[int, int],
    silent: frozenset[str] = frozenset(),
) -> bytes:
    """CAT063 data blocks, one record per sensor of ``sources`` (sensor -> SAC/SIC) with its
    estimates (``estimates``: sensor -> state -> value; those of ``<sensor>.psr``, its PSR channel,
    in I063/090 and 091); ``silent`` sensors are reported ``not
    connected``, the others operational. ``service``: the SAC/SIC of this service."""
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
                time_bias_s=_value(v, "time_bias"),
                ssr_range_gain=_value(v, "range_gain"),
                ssr_range_bias_m=_value(v, "range_bias"),
                ssr_azimuth_bias_rad=_value(v, "bearing_bias"),
                psr_range_gain=_value(psr, "range_gain"),
                psr_range_bias_m=_value(psr, "range_bias"),
                psr_azimuth_bias_rad=_value(psr, "bearing_bias"),
            )
        )
    return encode_cat063(statuses, *service)


def plot_corrections(
    estimates: Mapping[str, Mapping[str, float]], sources: Mapping[str, tuple[int, int]]
) -> dict:
    """SAC/SIC -> :class:`~registration.io.asterix.encode.cat048.PlotCorrection` of each sensor."""
    from registration.io.asterix.encode.cat048 import PlotCorrection

    out = {}
    for name, src in sources.items():
        v = estimates.get(name, {})
        out[src] = PlotCorrection(
            range_bias_m=v.get("range_bias", 0.0),
            range_gain=v.get("range_gain", 0.0),
            azimuth_bias_rad=v.get("bearing_bias", 0.0),
            time_bias_s=v.get("time_bias", 0.0),
        )
    return out
