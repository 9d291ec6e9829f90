"""A cheap look at the inputs before the filter runs: angle columns that seem to hold radians.

A column named ``*_deg`` is read as degrees. Radians in it register without any error, only
with wrong results, so before the filter starts the first :data:`SAMPLE_ROWS` rows of every input
file are read and, when at least :data:`MIN_VALUES` values of a column are numbers, these rules
give a warning naming the file and the column:

* a compass angle (``bearing_deg``, ``heading_deg``): every value lies within +-2 pi (6.28) and
  not all are 0: the range of radians, while degrees normally span far more;
* a ship's position (``lat_deg`` with ``lon_deg``): every latitude lies within +-pi/2 (1.57) and
  every longitude within +-2 pi: radians, unless the ship sails within 1.6 deg of 0 N, 0 E.

Elevation, pitch and roll are not checked: a few degrees are normal for them. The consistency
gate after the run (the mean NIS against its chi-square band) catches those too.
"""

from __future__ import annotations

import math

import numpy as np

from registration.recorded.reading.formats import iter_frames
from registration.recorded.reading.rowcheck import Layout

__all__ = ["SAMPLE_ROWS", "MIN_VALUES", "angle_unit_warnings"]

#: Rows read from the start of each file for the check.
SAMPLE_ROWS = 10_000
#: Fewest numeric values a column needs for a warning.
MIN_VALUES = 100
_COMPASS = ("bearing", "heading")


def _max_abs(frame, name: str) -> tuple[float, int] | None:
    """max |value| (file units) over the numeric values of column ``name`` and their count (None: too few)."""
    import pandas as pd

    if name not in frame:
        return None
    v = np.asarray(pd.to_numeric(frame[name], errors="coerce"), dtype=float)
    v = v[np.isfinite(v)]
    return (float(np.max(np.abs(v))), len(v)) if len(v) >= MIN_VALUES else None


def angle_unit_warnings(path, layout: Layout, sample_rows: int = SAMPLE_ROWS) -> list[str]:
    """Warnings for the ``*_deg`` columns of ``path`` (read as ``layout``) whose values look like radians."""
    first = next(iter_frames(path, layout.columns, sample_rows), None)
    if first is None:
        return []
    frame, out = first[1], []
    peaks = {f: _max_abs(frame, f.file_name) for f in layout.fields if f.unit == "deg"}
    for f, peak in peaks.items():
        if f.kind in _COMPASS and peak is not None and 0 < peak[0] <= 2 * math.pi:
            out.append(
                f"{path}: column {f.file_name!r} is in degrees by its name, but its first {peak[1]} values "
                f"all lie within +-{peak[0]:.3g} (radians lie within +-6.28): radians? (if they are degrees, "
                f"the {f.kind} stays within {peak[0]:.3g} deg of 0 and this warning can be ignored)"
            )
    for lat in (f for f in peaks if f.kind == "lat"):
        lon = next((f for f in peaks if f.kind == "lon" and f.prefix == lat.prefix), None)
        if lon is None:
            continue
        a, b = peaks[lat], peaks.get(lon)
        if (
            a is not None
            and b is not None
            and 0 < max(a[0], b[0])
            and a[0] <= math.pi / 2
            and b[0] <= 2 * math.pi
        ):
            out.append(
                f"{path}: columns {lat.file_name!r} and {lon.file_name!r} are in degrees by their names, but "
                f"their first {min(a[1], b[1])} values all lie within +-{a[0]:.3g} and +-{b[0]:.3g}: "
                "radians? (if they are degrees, the ship sails within 1.6 deg of 0 N, 0 E and this warning "
                "can be ignored)"
            )
    return out
