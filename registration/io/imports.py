"""The import contract: what every importer of a recording gives (:class:`ImportResult`).

An importer (ASTERIX: :func:`registration.io.asterix.import_asterix`; NMEA 0183 with AIS:
:func:`registration.io.nmea.import_nmea`) turns a recording into the fleet tables in their file
form (degrees, metres, seconds; the columns of docs/reference/fleet-files.md), the records it set aside (a
rejected ledger's frame, :mod:`registration.io.files.ledger`) and a JSON-able summary.
:meth:`ImportResult.write` writes them into a folder by the standard names, through the one folder
writer (:func:`registration.io.files.tablefile.write_tables`), so that ``registration fleet
register --tables FOLDER`` reads them next.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from registration.io.files.jsonfile import write_json
from registration.io.files.tablefile import write_tables

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["FLEET_TABLES", "ImportResult", "IMPORT_FILES", "REJECTED_FILE", "SUMMARY_FILE"]

#: The fleet tables an import may give, in the order they are written.
FLEET_TABLES = ("plots", "navigation", "sensors", "platforms", "reference", "targets")
#: The files beside the tables: the records set aside and the summary.
REJECTED_FILE, SUMMARY_FILE = "rejected.csv", "import_summary.json"
#: Every file an import may write into a folder (both table formats).
IMPORT_FILES = frozenset(
    {f"{t}.{s}" for t in FLEET_TABLES for s in ("csv", "parquet")} | {REJECTED_FILE, SUMMARY_FILE}
)


@dataclass
class ImportResult:
    """What an importer gives: the fleet tables as DataFrames in their file form

    * ``plots``, ``navigation``, ``sensors``, ``platforms``, ``reference``;
    * ``targets``: the surface targets table, or None when the format gives none;

    ``rejected``: the records set aside (a rejected ledger's frame: ``file``, where in the file,
    reason code, reason); ``summary``: a JSON-able dict of counts, time span and what the format
    adds."""

    plots: pd.DataFrame
    navigation: pd.DataFrame
    sensors: pd.DataFrame
    platforms: pd.DataFrame
    reference: pd.DataFrame
    rejected: pd.DataFrame
    summary: dict = field(default_factory=dict)
    targets: pd.DataFrame | None = None

    @property
    def tables(self) -> dict[str, pd.DataFrame]:
        """The fleet tables by file name stem, in :data:`FLEET_TABLES` order (``targets`` only
        when given)."""
        tables = {name: getattr(self, name) for name in FLEET_TABLES}
        return {name: frame for name, frame in tables.items() if frame is not None}

    def write(self, folder, fmt: str = "csv") -> dict[str, Path]:
        """Write the tables with rows as ``<name>.csv`` (or ``.parquet``, ``fmt``), ``rejected.csv``
        and ``import_summary.json`` into ``folder`` (created); a table without rows is not written
        (a fleet file needs one). CSV floats read back exactly. Returns name -> path (``rejected``,
        ``summary`` for the last two)."""
        if fmt not in ("csv", "parquet"):
            raise ValueError(f"fmt: expected 'csv' or 'parquet', got {fmt!r}")
        folder = Path(folder)
        folder.mkdir(parents=True, exist_ok=True)
        written = write_tables(folder, {n: f for n, f in self.tables.items() if len(f)}, fmt)
        written.update(write_tables(folder, {"rejected": self.rejected}, "csv"))
        path = folder / SUMMARY_FILE
        write_json(path, self.summary, default=str)
        written["summary"] = path
        return written
