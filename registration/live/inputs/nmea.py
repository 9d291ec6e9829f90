"""NMEA lines to fleet-table rows: the NMEA import (``registration import nmea``) applied to a stream
of one ship's bridge, piece by piece, with the same steps
(:func:`~registration.io.nmea.lines.read_lines`, :func:`~registration.io.nmea.importer.read_sentences`).

The lines wait until position fixes (GGA, GNS or RMC) follow them, since navigation is never
extrapolated; when no line has come for ``hold_s`` of wall time (the end of a feed), the lines
waiting are imported anyway, as the import takes the end of its log. Each piece is imported together with
the lines of the :data:`CONTEXT_S` seconds before it (the previous fixes and headings to interpolate
from, the time of day to unwrap, the last sentences the duplicate check looks at) and the lines
received after it (the headings after a TTM's own time); only what comes from the piece's own
lines is kept and counted, so that each line is counted once, with the
import's reasons when set aside (docs/reference/nmea-import.md).

The time axis is the import's: seconds since midnight UTC of ``date``, or of the day of the first
piece that gives a date (ZDA, RMC or reception times), then kept.
"""

from __future__ import annotations

import datetime as dt
import re
import time as wall
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Sequence

import numpy as np

from registration.io.files.ledger import RejectedLedger
from registration.io.nmea.errors import LEDGER_COLUMNS, REASONS, NmeaImportError
from registration.io.nmea.importer import platforms_table, read_sentences
from registration.io.nmea.lines import read_lines
from registration.io.nmea.sensors import TALKER_COLUMN, platform_sensors, read_sensors, talker_map
from registration.live.inputs.asterix import si_columns

__all__ = ["NmeaBatch", "NmeaCounters", "NmeaStream", "CONTEXT_S", "HOLD_S"]

#: The seconds of lines before a piece imported with it (above the import's 10 s position gap).
CONTEXT_S = 12.0
#: At least this many sentences before a piece are imported with it (the duplicate check's 200).
CONTEXT_LINES = 250
#: A piece ends at a position fix this many fixes (GGA, GNS, RMC lines) before the last one
#: received: the lines after it, imported with the piece, give the fixes and headings after the
#: piece's last attitude samples and TTM times (a radar clock ahead of the navigation by seconds).
LOOKAHEAD_FIXES = 10
#: When no line has come for this many seconds of wall time, the lines waiting are imported.
HOLD_S = 2.0
#: Lines waiting beyond this many are imported without waiting for a fix.
MAX_WAITING_LINES = 20000
_FIX = re.compile(r"[$!][A-Z]{2}(?:GGA|GNS|RMC),")


@dataclass
class NmeaCounters:
    """What came in since the start: ``datagrams`` and ``bytes``, ``lines`` imported (blank ones
    included) and ``waiting_lines`` not yet, ``sentences`` per type, ``plots`` (TTM), ``navigation``
    rows, ``references`` (AIS positions), ``rejected`` per reason code (the
    import's), ``pieces_without_navigation`` (pieces the import refused as a whole: no valid
    position or heading; their lines are in ``lines_without_navigation``), the latest ``note``,
    and per sensor its ``sensor_plots`` and latest plot time ``sensor_last_s``."""

    datagrams: int = 0
    bytes: int = 0
    lines: int = 0
    waiting_lines: int = 0
    sentences: Counter = field(default_factory=Counter)
    plots: int = 0
    navigation: int = 0
    references: int = 0
    rejected: Counter = field(default_factory=Counter)
    pieces_without_navigation: int = 0
    lines_without_navigation: int = 0
    note: str = ""
    sensor_plots: Counter = field(default_factory=Counter)
    sensor_last_s: dict = field(default_factory=dict)

    def to_json(self) -> dict:
        return {
            "datagrams": self.datagrams,
            "bytes": self.bytes,
            "lines": self.lines,
            "waiting_lines": self.waiting_lines,
            "sentences_by_type": dict(sorted(self.sentences.items())),
            "plots": self.plots,
            "navigation": self.navigation,
            "references": self.references,
            "rejected": dict(sorted(self.rejected.items())),
            "pieces_without_navigation": self.pieces_without_navigation,
            "lines_without_navigation": self.lines_without_navigation,
            "note": self.note,
        }


@dataclass(frozen=True)
class NmeaBatch:
    """One piece's rows, in the tables of :mod:`registration.fleet.data.tables` (SI, radians):
    ``plots`` (time, sensor, track, range, bearing; deck bearing), ``navigation`` (time, platform,
    lat, lon, alt, heading, pitch, roll), ``references`` (time, target, lat, lon, alt, sigma,
    sigma_up) and ``targets`` (target, name, surface_alt, sigma_surface), each None when empty."""

    plots: dict | None
    navigation: dict | None
    references: dict | None
    targets: dict | None


def _split(data: bytes) -> list[str]:
    text = data.decode("latin-1").split("\n")
    return [line.rstrip("\r") for line in text]


class NmeaStream:
    """The import of one ship's NMEA stream (module docstring): ``platform`` and its ``sensors``
    (a sensors file with the optional ``talker`` column, as ``import nmea --sensors``), the
    attitude priors ``platform_priors`` (as :func:`~registration.io.nmea.import_nmea`'s), ``date``
    the origin of the time axis, ``name`` how the stream is called in notes."""

    def __init__(
        self,
        platform: str,
        sensors: str | Path,
        *,
        platform_priors: dict | None = None,
        date: dt.date | None = None,
        name: str = "nmea",
        hold_s: float = HOLD_S,
    ) -> None:
        self.platform, self.name, self.hold_s = str(platform), name, hold_s
        rows = platform_sensors(read_sensors(sensors), self.platform, str(sensors))
        self.talkers, self.only = talker_map(rows)
        self.sensors = rows.drop(columns=[TALKER_COLUMN], errors="ignore")
        self.platforms = platforms_table(self.platform, platform_priors)
        self.date = date
        self.counters = NmeaCounters()
        self._carry = ""  # a TCP stream's partial last line
        self._pending: list[str] = []
        self._pending_line = 1  # the line number of the first pending line
        self._last_arrival = wall.monotonic()
        self._context: list[str] = []
        self._last_nav = -np.inf
        self._targets: set[str] = set()

    # -- input -----------------------------------------------------------------------------------
    def add_datagrams(self, payloads: Sequence[bytes]) -> list[str]:
        """UDP datagrams, each one or more whole lines; returns the lines (without line ends)."""
        added: list[str] = []
        for p in payloads:
            lines = _split(p)
            if lines and lines[-1] == "":
                lines.pop()
            added.extend(lines)
        self._pending.extend(added)
        self.counters.datagrams += len(payloads)
        self.counters.bytes += sum(len(p) for p in payloads)
        self._waiting()
        return added

    def add_bytes(self, data: bytes) -> list[str]:
        """Octets of a TCP stream: lines end at LF; a partial last line waits for its end. Returns
        the lines completed (without line ends)."""
        lines = _split(data)
        lines[0] = self._carry + lines[0]
        self._carry = lines.pop()
        self._pending.extend(lines)
        self.counters.bytes += len(data)
        self._waiting()
        return lines

    def _waiting(self) -> None:
        self._last_arrival = wall.monotonic()
        self.counters.waiting_lines = len(self._pending)

    # -- import ----------------------------------------------------------------------------------
    def take(self, force: bool = False) -> NmeaBatch | None:
        """Import the lines up to the position fix :data:`LOOKAHEAD_FIXES` fixes before the last one
        received (all of them when ``force``, or when no line came for ``hold_s``); None when
        nothing was imported."""
        if not self._pending:
            return None
        fixes = [k for k, line in enumerate(self._pending) if _FIX.search(line)]
        cut = fixes[-1 - LOOKAHEAD_FIXES] + 1 if len(fixes) > LOOKAHEAD_FIXES else 0
        late = wall.monotonic() - self._last_arrival >= self.hold_s  # the feed went quiet
        if force or late or len(self._pending) > MAX_WAITING_LINES:
            cut = len(self._pending)
        if cut == 0:
            return None
        piece, self._pending = self._pending[:cut], self._pending[cut:]
        first = self._pending_line
        self._pending_line += cut
        self.counters.waiting_lines = len(self._pending)
        self.counters.lines += cut
        return self._import(piece, first)

    def _import(self, piece: list[str], first: int) -> NmeaBatch | None:
        """The rows of lines ``first`` .. ``end - 1`` (``piece``), imported with the context before
        them and the lines waiting after them (the headings after a TTM's time, for its true
        bearing); only what comes from the piece's lines is kept and counted."""
        window = self._context + piece + self._pending
        start, end = first - len(self._context), first + len(piece)
        rejections = RejectedLedger(LEDGER_COLUMNS, [self.name])
        log = read_lines(window, self.name, rejections, start)
        try:
            parts, _ = read_sentences(log, rejections, self.talkers, self.only, self.date)
        except NmeaImportError as exc:
            self._count_rejections(rejections, first, end)
            self._context = (self._context + piece)[-CONTEXT_LINES:]
            self.counters.pieces_without_navigation += 1
            self.counters.lines_without_navigation += len(piece)
            self.counters.note = f"{self.name}: lines {first}-{first + len(piece) - 1}: {exc}"
            return None
        self._count_rejections(rejections, first, end)
        clock, log = parts.clock, parts.log
        if self.date is None and clock.known:
            self.date = dt.date.fromisoformat(str(clock.origin_date()))
        mine = (log.line >= first) & (log.line < end)
        self.counters.sentences.update(log.kind[mine].astype(str).tolist())
        self._context = self._next_context(self._context + piece, start, end, log, clock)
        after = np.flatnonzero(log.line >= end)  # the lines after the piece: navigation up to its last fix
        t_cut = float(clock.previous_anchor_time(after[:1])[0]) if after.size else np.inf
        return NmeaBatch(
            self._plots(parts.plots, log, first, end),
            self._navigation(parts.navigation, t_cut),
            self._references(parts.references, log, first, end),
            self._new_targets(parts.references),
        )

    def _count_rejections(self, rejections: RejectedLedger, first: int, end: int) -> None:
        frame = rejections.frame()
        if len(frame):
            codes = frame.loc[(frame["line"] >= first) & (frame["line"] < end), "code"]
            self.counters.rejected.update(c for c in codes.tolist() if c in REASONS)

    def _next_context(self, lines: list[str], start: int, end: int, log, clock) -> list[str]:
        """The last ``CONTEXT_S`` seconds of ``lines`` (numbered from ``start`` up to ``end``, by
        their timed sentences), and at least the last ``CONTEXT_LINES``."""
        keep = CONTEXT_LINES
        before = log.line[clock.anchor_index] < end
        if before.any():
            u, index = clock.anchor_u[before], clock.anchor_index[before]
            recent = index[u >= float(u.max()) - CONTEXT_S]
            keep = max(keep, len(lines) - int(log.line[recent.min()] - start))
        return lines[-keep:]

    def _plots(self, plots, log, first: int, end: int) -> dict | None:
        sel = (log.line[plots.index] >= first) & (log.line[plots.index] < end)
        if not sel.any():
            return None
        out = {
            "time": plots.time[sel].astype(np.float64),
            "sensor": plots.sensor[sel].astype(str),
            "track": plots.track[sel].astype(str),
            "range": plots.range[sel].astype(np.float64),
            "bearing": plots.bearing[sel].astype(np.float64),
        }
        c = self.counters
        c.plots += int(sel.sum())
        for s in np.unique(out["sensor"]).tolist():
            mine = out["sensor"] == s
            c.sensor_plots[s] += int(mine.sum())
            c.sensor_last_s[s] = max(c.sensor_last_s.get(s, -np.inf), float(out["time"][mine].max()))
        return out

    def _navigation(self, nav, t_cut: float) -> dict | None:
        sel = (nav.time > self._last_nav) & (nav.time <= t_cut)
        if not sel.any():
            return None
        self._last_nav = float(nav.time[sel].max())
        self.counters.navigation += int(sel.sum())
        out = {"time": nav.time[sel], "platform": np.full(int(sel.sum()), self.platform)}
        for k in ("lat", "lon", "alt", "heading", "pitch", "roll"):
            out[k] = getattr(nav, k)[sel].astype(np.float64)
        return out

    def _references(self, refs, log, first: int, end: int) -> dict | None:
        sel = (log.line[refs.index] >= first) & (log.line[refs.index] < end)
        if not sel.any():
            return None
        self.counters.references += int(sel.sum())
        frame = refs.frame()[sel]
        return si_columns("reference", {k: frame[k].to_numpy() for k in frame.columns})

    def _new_targets(self, refs) -> dict | None:
        frame = refs.targets_frame()
        frame = frame[~frame["target"].isin(self._targets)]
        if not len(frame):
            return None
        self._targets.update(frame["target"].tolist())
        return si_columns("targets", {k: frame[k].to_numpy() for k in frame.columns})
