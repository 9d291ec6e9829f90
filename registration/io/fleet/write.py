"""Fleet tables written as files: the long-form tables of :mod:`registration.fleet.data.tables` (SI
units, radians) as CSV or Parquet in the file units of :mod:`registration.io.fleet.reading.read` (degrees,
metres, seconds), so that :func:`~registration.io.fleet.reading.read.read_fleet_tables` reads them back."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from registration.core.frames import ecef2geodetic
from registration.io.fleet.reading.read import FILE_COLUMNS

__all__ = ["write_fleet_tables"]


def _file_frame(name: str, table):
    """A table (SI, radians) -> DataFrame of the file columns present; inf priors written empty."""
    import pandas as pd

    table = {str(k): np.asarray(v) for k, v in dict(table).items()}
    if name == "reference" and "x" in table and "lat" not in table:
        lat, lon, alt = ecef2geodetic(np.stack([table.pop(c) for c in "xyz"], axis=1))
        table.update(lat=lat, lon=lon, alt=alt)
    out = {}
    for column, key, unit, _, _ in FILE_COLUMNS[name]:
        if key not in table:
            continue
        v = table[key]
        if unit == "id":
            out[column] = v.astype(str)
            continue
        v = np.asarray(v, dtype=np.float64)
        if column.startswith("prior_"):
            v = np.where(np.isinf(v), np.nan, v)
        out[column] = np.degrees(v) if unit == "deg" else v
    return pd.DataFrame(out)


def write_fleet_tables(
    folder, plots, navigation, sensors, platforms=None, references=None, fmt: str = "csv", targets=None
) -> list[Path]:
    """Write the tables (SI units, radians; as :func:`build_problem` takes them) as files in
    ``folder``: ``plots``, ``navigation``, ``sensors``, ``platforms`` (if given) and ``reference``
    (if given; ECEF positions are written as lat/lon/alt) and ``targets`` (if given) with suffix
    ``.csv`` or ``.parquet`` (``fmt``), through the one folder writer
    (:func:`~registration.io.files.tablefile.write_tables`: CSV floats as their shortest round-trip
    text). Returns the paths."""
    from registration.io.files.tablefile import write_tables

    tables = {
        "plots": plots,
        "navigation": navigation,
        "sensors": sensors,
        "platforms": platforms,
        "reference": references,
        "targets": targets,
    }
    frames = {name: _file_frame(name, table) for name, table in tables.items() if table is not None}
    return list(write_tables(Path(folder), frames, fmt).values())
