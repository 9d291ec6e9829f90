"""What the live service sends on: CAT063 sensor status messages carrying the current estimates,
and the radars' CAT048 plots corrected by them (docs/reference/corrected-plots.md).

Both take the estimates of a sensor by state name (SI: rad, m, 1, s; this package's convention,
reported minus true): ``range_bias``, ``range_gain``, ``bearing_bias`` (the azimuth bias) and
``time_bias``; a state not estimated is left out of CAT063 and not corrected.
"""

from __future__ import annotations

from typing import Mapping

from registration.io.asterix.encode.cat063 import estimates_cat063

__all__ = ["cat063_message", "plot_corrections"]

#: The CAT063 message of a set of estimates (one definition, with ``fleet register --cat063``).
cat063_message = estimates_cat063


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
