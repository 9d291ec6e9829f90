"""One ship's bridge as an input of the live service: its NMEA stream imported piece by piece
(:class:`~registration.live.inputs.nmea.NmeaStream`), its TTM tracks associated with the AIS
vessels (:class:`~registration.live.inputs.tracks.TrackLabels`), and what the estimator needs: the
navigation, the AIS references and surface targets given to it at once, the associated plots
handed back as a :class:`~registration.live.inputs.asterix.StreamBatch` for the estimator's queue after
:data:`HOLD_S` seconds of data (the estimates lag the data by that much; the plots of a track
before its vessel is known are used too). Plots of tracks still without a vessel then are counted
(``plots_unassociated``), not used."""

from __future__ import annotations

import datetime as dt
import time as wall
from pathlib import Path

import numpy as np

from registration.live.inputs.asterix import StreamBatch
from registration.live.inputs.nmea import NmeaStream
from registration.live.inputs.tracks import TrackLabels

__all__ = ["Bridge", "HOLD_S", "STARTUP_S"]

#: The ship's plots wait this many seconds of data before the estimator gets them, so that the
#: association runs of that time can name their tracks' vessels (a track's first plots included).
HOLD_S = 60.0

#: Seconds of wall time the other inputs wait, at the start, for the ship's first lines (a feed that
#: starts later loses its plots of the epochs processed meanwhile: they are late).
STARTUP_S = 10.0


def _cat(parts: list) -> dict | None:
    parts = [p for p in parts if p is not None]
    return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]} if parts else None


class Bridge:
    """The ship ``platform`` with the sensors of ``sensors`` (a sensors file with the optional
    ``talker`` column), its attitude errors held at 0 (as ``import nmea`` writes them by default);
    ``window_s``: the estimator's epochs; ``name``: the stream's address, for notes."""

    def __init__(
        self,
        platform: str,
        sensors: str | Path,
        window_s: float,
        *,
        date: dt.date | None = None,
        name: str = "nmea",
        hold_s: float = HOLD_S,
    ) -> None:
        priors = {c: 0.0 for c in ("prior_heading_deg", "prior_pitch_deg", "prior_roll_deg")}
        self.stream = NmeaStream(platform, sensors, platform_priors=priors, date=date, name=name)
        ship = self.ship_tables()
        self.labels = TrackLabels(ship["sensors"], ship["platforms"], window_s)
        self.unassociated = 0
        self._nav_end = -np.inf
        self._queue: dict | None = None  # plots not yet due
        self._last_batch = self._started = wall.monotonic()
        self._seen = False
        self.hold_s = hold_s
        #: The data time (s) up to which the ship's plots were handed over (or will be, once their
        #: tracks are named): +inf once the feed went quiet, or when nothing came in the first
        #: :data:`STARTUP_S` seconds, so that other inputs held back for it
        #: (:class:`~registration.live.inputs.merge.TimeMerge`) go on.
        self.horizon = -np.inf

    def ship_tables(self) -> dict:
        """The ship's sensors and platforms tables in the fleet tables' SI form."""
        from registration.io.fleet.cells import check_frame

        return {
            name: check_frame(name, Path("--sensors"), frame, skip=False, whole_file=False).table
            for name, frame in (("sensors", self.stream.sensors), ("platforms", self.stream.platforms))
        }

    @property
    def file_tables(self) -> tuple:
        """(sensors, platforms) file tables, for :class:`~registration.live.estimator.LiveEstimator`."""
        return self.stream.sensors, self.stream.platforms

    def take(self, estimator, force: bool = False) -> StreamBatch | None:
        """Import what waits (:meth:`NmeaStream.take`), give the navigation, references and
        targets to ``estimator``, associate when due, and return the plots of tracks with a vessel
        that are due (sorted by time; None without any): those ``hold_s`` seconds of data older
        than the latest navigation, all of them when ``force`` or when nothing came for
        ``hold_s`` seconds of wall time (the end of a feed)."""
        batch = self.stream.take(force)
        now = wall.monotonic()
        if batch is not None:
            self._last_batch, self._seen = now, True
            estimator.add_ship_data(batch.navigation, batch.references, batch.targets)
            self.labels.add(batch.plots, batch.navigation, batch.references, batch.targets)
            while self.labels.due():  # every run of the grid the piece passed, in order
                self.labels.run()
            if batch.navigation is not None:
                self._nav_end = max(self._nav_end, float(batch.navigation["time"].max()))
            if batch.plots is not None:
                self._queue = _cat([self._queue, batch.plots])
        quiet = now - self._last_batch >= self.stream.hold_s
        if force or (quiet and self._seen) or (not self._seen and now - self._started >= STARTUP_S):
            self.horizon = np.inf
        else:
            self.horizon = self._nav_end - self.hold_s
        if (force or quiet) and self.labels.behind():  # the feed's end: a last run on its tail
            self.labels.run(final=True)
        p = self._queue
        if p is None:
            return None
        due = (
            p["time"] <= min(self._nav_end - self.hold_s, self._nav_end)
            if not (force or quiet)
            else (p["time"] <= self._nav_end)
        )
        if force:
            due[:] = True
        if not due.any():
            return None
        self._queue = {k: v[~due] for k, v in p.items()} if not due.all() else None
        p = {k: v[due] for k, v in p.items()}
        target = self.labels.label(p["sensor"], p["track"])
        used = target != ""
        self.unassociated += int((~used).sum())
        if not used.any():
            return None
        order = np.argsort(p["time"][used], kind="stable")
        plots = {k: v[used][order] for k, v in p.items() if k != "track"}
        plots["target"] = target[used][order]
        return StreamBatch(plots, None, {})

    def to_json(self) -> dict:
        """The stream's counters, with the association's."""
        out = self.stream.counters.to_json()
        out["plots_unassociated"] = self.unassociated
        out["tracks_associated"] = len(self.labels.labels)
        out["association_runs"] = self.labels.runs
        if self.labels.note:
            out["association_note"] = self.labels.note
        return out
