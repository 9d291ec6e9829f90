"""Helpers of the NMEA tests: a radar sensors table, a minimal own-ship log, importing hand-made lines."""

from __future__ import annotations

import datetime as dt

import numpy as np
import pandas as pd

from registration.io.nmea import import_nmea
from tests.io.nmea import encode

DAY = dt.date(2024, 5, 1)
LAT, LON = np.radians(43.0), np.radians(7.5)


def radar_sensors(**extra) -> pd.DataFrame:
    """One radar on platform OWN, fleet file columns (and whatever ``extra`` adds)."""
    row = {"sensor": ["RADAR"], "platform": ["OWN"], "sigma_range_m": [15.0], "sigma_bearing_deg": [0.1]}
    row.update({k: [v] for k, v in extra.items()})
    return pd.DataFrame(row)


def navigation_lines(
    t0: float = 43200.0, n: int = 20, heading: float = 30.0, day: dt.date = DAY
) -> list[str]:
    """A minimal own-ship log: 1 Hz GGA and ZDA, 10 Hz $PASHR, a still ship heading ``heading`` deg."""
    out = []
    for k in range(n):
        t = t0 + k
        out += [encode.gga(t, LAT, LON), encode.zda(t, day + dt.timedelta(days=int(t // 86400)))]
        out += [encode.pashr(t + j / 10, heading, 2.0, -1.0) for j in range(10)]
    return out


def import_lines(tmp_path, lines: list[str], sensors=None, name: str = "log.nmea", **kw):
    """Write ``lines`` as a log file and import it for platform OWN."""
    path = tmp_path / name
    path.write_text("\n".join(lines) + "\n")
    return import_nmea(path, "OWN", radar_sensors() if sensors is None else sensors, **kw)


def rejected_lines(result, code: str) -> list[int]:
    """Line numbers set aside with ``code``."""
    r = result.rejected
    return sorted(int(x) for x in r.loc[r["code"] == code, "line"])
