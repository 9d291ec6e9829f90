"""Datagrams to fleet-table rows: the ASTERIX import (``registration import asterix``) applied to a
stream, batch by batch, with the same decoding, record rules, duplicate check and time axis.

Each batch of UDP payloads becomes a capture of kind ``udp``
(:func:`~registration.io.asterix.capture.capture.capture_from_datagrams`), is decoded
(:func:`~registration.io.asterix.decode.reader.decode_capture`) and turned into rows
(:func:`~registration.io.asterix.tables.assemble.assemble_file`) with a time axis and a duplicate
check that carry over from batch to batch. The duplicate check remembers the records of the last
``horizon_s`` seconds only, so that memory stays flat on a stream that never ends. Records set
aside are counted by the import's reasons (docs/reference/asterix-import.md).

The flight levels of aircraft without ADS-B become height-only references, with the relation of
flight level to height learned on the stream's recent ADS-B reports
(:mod:`registration.live.inputs.flightlevels`).

The time axis: seconds since midnight UTC of the day the service started (or ``date``), carried
across midnight as the import does; the datagrams' arrival times are not used, so that a replay
faster than real time places its records as the recording did.
"""

from __future__ import annotations

import datetime as dt
from collections import Counter
from dataclasses import dataclass, field
from typing import Mapping, Sequence

import numpy as np

from registration.io.asterix.capture.capture import capture_from_datagrams
from registration.io.asterix.decode.reader import decode_capture
from registration.io.asterix.decode.uap import check_editions
from registration.io.asterix.errors import LEDGER_COLUMNS, REASONS
from registration.io.asterix.tables.assemble import SiteLookup, assemble_file
from registration.io.asterix.tables.duplicates import StreamChecks
from registration.io.asterix.tables.fleetfiles import PLOT_COLUMNS, REFERENCE_COLUMNS
from registration.io.asterix.tables.sites import channel_sensors
from registration.io.asterix.tables.timeofday import Unwrapper
from registration.io.files.ledger import RejectedLedger
from registration.io.fleet.reading.cells import FILE_COLUMNS
from registration.live.inputs.flightlevels import StreamFlightLevels

__all__ = [
    "AsterixStream",
    "IngestCounters",
    "StreamBatch",
    "DUPLICATE_HORIZON_S",
    "si_columns",
    "split_batch",
]

#: Records are checked for duplicates against those of the last this many seconds.
DUPLICATE_HORIZON_S = 600.0


@dataclass
class IngestCounters:
    """What came in since the start: ``datagrams`` and ``bytes`` imported, ``waiting_datagrams``
    received and not yet imported, ``records`` per category (``"048"``: n), ``plots`` kept (with a
    target id or not), ``plots_without_id``, ``references`` kept (ADS-B reports),
    ``flight_level_heights`` (height-only references made of the flight levels of aircraft without
    ADS-B) and ``flight_levels_unused`` (such flight levels without a relation yet, or outside the
    levels it was learned on), ``rejected`` per reason code
    (the import's), and per sensor its ``sensor_plots`` and the time of its latest plot
    (``sensor_last_s``, s on the time axis)."""

    datagrams: int = 0
    bytes: int = 0
    records: Counter = field(default_factory=Counter)
    plots: int = 0
    plots_without_id: int = 0
    references: int = 0
    flight_level_heights: int = 0
    flight_levels_unused: int = 0
    rejected: Counter = field(default_factory=Counter)
    sensor_plots: Counter = field(default_factory=Counter)
    sensor_last_s: dict = field(default_factory=dict)
    waiting_datagrams: int = 0

    def to_json(self) -> dict:
        return {
            "datagrams": self.datagrams,
            "waiting_datagrams": self.waiting_datagrams,
            "bytes": self.bytes,
            "records_by_category": {k: n for k, n in sorted(self.records.items()) if n},
            "plots": self.plots,
            "plots_without_id": self.plots_without_id,
            "references": self.references,
            "flight_level_heights": self.flight_level_heights,
            "flight_levels_unused": self.flight_levels_unused,
            "rejected": dict(sorted(self.rejected.items())),
        }


@dataclass(frozen=True)
class StreamBatch:
    """One batch's rows, in the tables of :mod:`registration.fleet.data.tables` (SI, radians):
    ``plots`` (time, sensor, target, range, bearing) of plots with a target id, sorted by time;
    ``references`` (time, target, lat, lon, alt, sigma, sigma_up), None when there are none;
    ``file_plots``: every plot kept, in file form (time_s, sensor, target, range_m, bearing_deg;
    target '' without id)."""

    plots: dict
    references: dict | None
    file_plots: dict


def si_columns(name: str, columns: dict) -> dict:
    """File-form columns of the import (rows its rules kept) -> the table's columns (SI, radians),
    by the fleet files' one schema: renamed, degrees to radians."""
    out = {}
    for column, key, unit, _, _ in FILE_COLUMNS[name]:
        if column in columns:
            v = np.asarray(columns[column])
            out[key] = (
                v.astype(str)
                if unit == "id"
                else np.radians(v.astype(np.float64))
                if unit == "deg"
                else v.astype(np.float64)
            )
    return out


class AsterixStream:
    """The import of a stream of ASTERIX datagrams (module docstring). ``sites``: the checked SITES
    table (:func:`~registration.io.asterix.tables.sites.read_sites`); ``editions``: category ->
    edition; ``keep_duplicates`` as the import's; ``name``: how the stream is called in what is set
    aside (``udp://host:port``)."""

    def __init__(
        self,
        sites,
        editions: Mapping[int, str] | None = None,
        *,
        keep_duplicates: bool = False,
        horizon_s: float = DUPLICATE_HORIZON_S,
        date: dt.date | None = None,
        name: str = "udp",
    ) -> None:
        self.sites = sites
        self.names = sites["sensor"].astype(str).to_numpy()
        self.lookup = SiteLookup(sites["sac"].to_numpy(), sites["sic"].to_numpy())
        self.editions = check_editions(editions)
        self.unwrapper = Unwrapper(date or dt.datetime.now(dt.timezone.utc).date())
        self.checks = StreamChecks(keep_duplicates, horizon_s=horizon_s)
        self.flight_levels = StreamFlightLevels(sites)
        self.name = name
        self.counters = IngestCounters()

    def decode(self, payloads: Sequence[bytes], ports: Sequence[int]) -> StreamBatch:
        """The rows of a batch of datagrams (in arrival order); counts what came and what was set
        aside. Never raises for bad datagrams: they are counted."""
        c = self.counters
        c.datagrams += len(payloads)
        c.bytes += sum(len(p) for p in payloads)
        rejections = RejectedLedger(LEDGER_COLUMNS)
        cap = capture_from_datagrams(payloads, ports, self.name)
        decoded = decode_capture(cap, self.editions, rejections, refuse_non_asterix=False)
        for cat, rec in decoded.records.items():
            c.records[f"{cat:03d}"] += rec.size
        rows = assemble_file(
            decoded, self.unwrapper, self.lookup, self.names, self.editions, rejections, self.checks
        )
        for code, n in rejections.by_code(tuple(REASONS)).items():
            if n:
                c.rejected[code] += int(n)
        file_plots = (
            {k: rows.plots[k] for k in PLOT_COLUMNS} if rows.plots else {k: np.zeros(0) for k in PLOT_COLUMNS}
        )
        file_plots["target"] = file_plots["target"].astype(str)
        if rows.plots:  # the primary-only plots of radars whose PSR channel is its own sensor
            file_plots["sensor"] = channel_sensors(self.sites, file_plots["sensor"], rows.plots["primary"])
        n = int(file_plots["time_s"].size)
        c.plots += n
        if n:
            sensors, counts = np.unique(file_plots["sensor"].astype(str), return_counts=True)
            for s, k in zip(sensors.tolist(), counts.tolist()):
                c.sensor_plots[s] += k
                mine = file_plots["sensor"].astype(str) == s
                c.sensor_last_s[s] = max(
                    c.sensor_last_s.get(s, -np.inf), float(file_plots["time_s"][mine].max())
                )
        with_id = file_plots["target"] != ""
        c.plots_without_id += int((~with_id).sum())
        plots = {"time": np.zeros(0), "sensor": np.zeros(0, dtype=str), "target": np.zeros(0, dtype=str)}
        if with_id.any():
            table = si_columns("plots", {k: v[with_id] for k, v in file_plots.items()})
            order = np.argsort(table["time"], kind="stable")
            plots = {k: v[order] for k, v in table.items()}
        parts = []
        if rows.reference and rows.reference["time_s"].size:
            self.flight_levels.add_reports(rows.reference)
            parts.append({k: rows.reference[k] for k in REFERENCE_COLUMNS})
            c.references += int(rows.reference["time_s"].size)
        heights = self.flight_levels.height_rows(rows.plots) if rows.plots else None
        c.flight_level_heights, c.flight_levels_unused = self.flight_levels.heights, self.flight_levels.unused
        if heights is not None:
            parts.append({k: heights[k] for k in REFERENCE_COLUMNS})
        references = None
        if parts:
            references = si_columns(
                "reference", {k: np.concatenate([np.asarray(p[k]) for p in parts]) for k in REFERENCE_COLUMNS}
            )
        return StreamBatch(plots, references, file_plots)


def split_batch(batch: StreamBatch, plots: int) -> list[StreamBatch]:
    """``batch`` in pieces of at most ``plots`` plots (time order kept), the references all with the
    first piece (an epoch finds them when it closes); ``file_plots`` stays with the first."""
    n = int(batch.plots["time"].size)
    if n <= plots:
        return [batch]
    empty_refs = None
    pieces = []
    for a in range(0, n, plots):
        part = {k: v[a : a + plots] for k, v in batch.plots.items()}
        first = a == 0
        pieces.append(
            StreamBatch(part, batch.references if first else empty_refs, batch.file_plots if first else {})
        )
    return pieces
