"""NMEA 0183 TTM (tracked target message) lines corrected by a registration's estimates: what a
tracker reading a radar's ARPA output gets instead of the radar's own, with nothing changed on its
side (docs/reference/corrected-plots.md).

:func:`correct_ttm` rewrites a TTM's distance (field 2, in the unit of field 10: N nautical miles,
K kilometres, S statute miles) and bearing (field 3, degrees, true or relative per field 4) with
this package's error model (docs/reference/conventions.md, errors reported minus true): reported
range = (1 + gain) x true range + range bias, reported bearing = true bearing + azimuth bias, so

    distance = (distance_reported - range_bias) / (1 + gain)    (0 if that is negative)
    bearing = bearing_reported - azimuth_bias                    wrapped to [0, 360) deg

The azimuth bias is the radar's, so it is the same in a relative (from the bow) and a true
bearing (the relative one plus the heading). Each value is written with as many decimals as the
radar wrote (its resolution: a correction is rounded to it), leading zeros kept; every other
character of the line (prefix, tag block, other fields) is unchanged, and the checksum is new.
The TTM is read as the importer reads it (:mod:`registration.io.nmea.ttm`: field positions,
units, the checks of :func:`~registration.io.nmea.ttm.value_problems`); one it would set aside
for a bad checksum, too few fields or a bad distance, unit, bearing, reference or target number
raises ValueError naming the field. A line holding no TTM comes back as it is.
"""

from __future__ import annotations

import math
import re
from typing import Protocol

from registration.io.nmea.fields import numbers, text
from registration.io.nmea.lines import checksums_ok
from registration.io.nmea.ttm import DISTANCE_UNITS_M, TTM_FIELDS, TTM_MIN_FIELDS, value_problems

__all__ = ["RangeAzimuthCorrection", "correct_ttm"]

_PLAIN = re.compile(r"^(\d*)(?:\.(\d*))?$")


class RangeAzimuthCorrection(Protocol):
    """A radar's estimated errors, reported minus true (e.g. a
    :class:`~registration.io.asterix.encode.cat048.PlotCorrection`)."""

    @property
    def range_bias_m(self) -> float: ...  # m

    @property
    def range_gain(self) -> float: ...  # dimensionless

    @property
    def azimuth_bias_rad(self) -> float: ...  # rad


def _sentence(line: str) -> tuple[str, str, str]:
    """(what comes before the sentence, the sentence, the line's end of line characters): the
    sentence starts after the last tag block, else at the first ``$`` or ``!``."""
    body = line.rstrip("\r\n")
    eol = line[len(body) :]
    start = (
        body.rfind("\\") + 1 if "\\" in body else min((body.find(c) for c in "$!" if c in body), default=0)
    )
    return body[:start], body[start:], eol


def _write(value: float, like: str) -> str:
    """``value`` written as the field ``like`` was: its decimals and integer digits (leading zeros)."""
    m = _PLAIN.match(like.strip())
    if m is None:  # an exponent or a sign: the importer reads it, keep 4 decimals
        return f"{value:.4f}"
    whole, frac = m.group(1), m.group(2)
    decimals = len(frac) if frac is not None else 0
    width = (len(whole) if whole.startswith("0") else 0) + (decimals + 1 if frac is not None else 0)
    return f"{value:0{width}.{decimals}f}" if frac is not None else f"{value:0{width}.0f}"


def _checksum(body: str) -> str:
    x = 0
    for ch in body.encode("latin-1"):
        x ^= ch
    return f"{x:02X}"


def _check(c: RangeAzimuthCorrection) -> None:
    values = (c.range_bias_m, c.range_gain, c.azimuth_bias_rad)
    if not all(math.isfinite(v) for v in values) or c.range_gain <= -1.0:
        raise ValueError(
            f"correction: range_bias_m {c.range_bias_m!r} (m), range_gain {c.range_gain!r} (above -1), "
            f"azimuth_bias_rad {c.azimuth_bias_rad!r} (rad) must be finite numbers"
        )


def correct_ttm(line: str, correction: RangeAzimuthCorrection) -> str:
    """``line`` with its TTM's distance and bearing corrected by ``correction`` (see the module's
    text); a line holding no TTM unchanged. ValueError naming the field for a malformed TTM."""
    head, sentence, eol = _sentence(line)
    address = sentence[1:].split(",", 1)[0].split("*", 1)[0]
    if not sentence or address[:1] == "P" or address[2:] != "TTM":
        return line
    has, ok = checksums_ok([sentence])
    if not has[0]:
        raise ValueError(f"TTM without a checksum ('*' and two hex digits at its end): {sentence!r}")
    if not ok[0]:
        raise ValueError(f"TTM checksum {sentence[-2:]!r} does not match the sentence: {sentence!r}")
    fields = sentence[:-3].split(",")
    if len(fields) - 1 < TTM_MIN_FIELDS:
        raise ValueError(
            f"TTM has {len(fields) - 1} fields, at least {TTM_MIN_FIELDS} expected (a truncated sentence?)"
        )
    f = TTM_FIELDS
    distance, bearing = numbers([fields[f["distance"]]]), numbers([fields[f["bearing"]]])
    unit = text([fields[f["unit"]]])
    problem = value_problems([fields[f["number"]]], distance, bearing, unit, text([fields[f["reference"]]]))[
        0
    ]
    if problem:
        named = ", ".join(f"{name} (field {k}) {fields[k]!r}" for name, k in f.items() if k < 11)
        raise ValueError(f"{problem}: {named}")
    _check(correction)
    per_unit_m = DISTANCE_UNITS_M[unit[0]]
    range_m = (float(distance[0]) * per_unit_m - correction.range_bias_m) / (1.0 + correction.range_gain)
    fields[f["distance"]] = _write(max(range_m, 0.0) / per_unit_m, fields[f["distance"]])
    # rounded to the field's decimals first, so that 359.96 written with one decimal becomes 0.0
    b = float(_write(float(bearing[0]) - math.degrees(correction.azimuth_bias_rad), fields[f["bearing"]]))
    fields[f["bearing"]] = _write(b % 360.0, fields[f["bearing"]])
    body = ",".join(fields)
    return f"{head}{body}*{_checksum(body[1:])}{eol}"
