"""What the live service sends on: CAT063 sensor status messages carrying the current estimates,
the radars' CAT048 plots corrected by them, and a ship's NMEA lines with its radars' TTM
sentences corrected by them (docs/reference/corrected-plots.md).

Both take the estimates of a sensor by state name (SI: rad, m, 1, s; this package's convention,
reported minus true): ``range_bias``, ``range_gain``, ``bearing_bias`` (the azimuth bias) and
``time_bias``; a state not estimated is left out of CAT063 and not corrected.
"""

from __future__ import annotations

import re
from typing import Mapping, Sequence

from registration.io.asterix.encode.cat063 import estimates_cat063

__all__ = ["cat063_message", "plot_corrections", "ttm_corrections", "corrected_lines"]

_TTM_TALKER = re.compile(r"[$!]([A-Z0-9]{2})TTM,")

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


def ttm_corrections(
    estimates: Mapping[str, Mapping[str, float]], talkers: Mapping[str, str], only: str | None
) -> tuple[dict, object | None]:
    """(TTM talker -> correction of its sensor, the correction of other talkers' TTMs: the ship's
    only sensor's, None when TTMs of other talkers are not the ship's): as the NMEA import assigns
    TTMs to sensors (:func:`~registration.io.nmea.sensors.talker_map`)."""
    from registration.io.asterix.encode.cat048 import PlotCorrection

    def of(sensor: str) -> PlotCorrection:
        v = estimates.get(sensor, {})
        return PlotCorrection(
            range_bias_m=v.get("range_bias", 0.0),
            range_gain=v.get("range_gain", 0.0),
            azimuth_bias_rad=v.get("bearing_bias", 0.0),
        )

    return {t: of(s) for t, s in talkers.items()}, (of(only) if only is not None else None)


def corrected_lines(lines: Sequence[str], by_talker: Mapping[str, object], other: object | None) -> list[str]:
    """``lines`` with each TTM of a known sensor corrected
    (:func:`~registration.io.nmea.correct.correct_ttm`); every other line, and a TTM the import
    would set aside, passed on as it came."""
    from registration.io.nmea.correct import correct_ttm

    out = []
    for line in lines:
        m = _TTM_TALKER.search(line)
        c = by_talker.get(m.group(1), other) if m else None
        if c is not None:
            try:
                line = correct_ttm(line, c)  # type: ignore[arg-type]
            except ValueError:
                pass
        out.append(line)
    return out
