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
from registration.live.inputs.rows import concat_rows
from registration.live.inputs.tracks import TrackLabels

__all__ = ["Bridge", "HOLD_S", "STARTUP_S"]

#: The ship's plots wait this many seconds of data before the estimator gets them, so that the
#: association runs of that time can name their tracks' vessels (a track's first plots included).
HOLD_S = 60.0

#: Seconds of wall time the other inputs wait, at the start, for the ship's first lines (a feed that
#: starts later loses its plots of the epochs processed meanwhile: they are late).
STARTUP_S = 10.0


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
        self._cut = -np.inf  # the ship's plots up to this data time (s) were handed over
        self.hold_s = hold_s
        #: The data time (s) up to which the ship's plots were handed over (or will be, once their
        #: tracks are named): +inf once the feed went quiet, or when nothing came in the first
        #: :data:`STARTUP_S` seconds, so that other inputs held back for it
        #: (:class:`~registration.live.inputs.merge.TimeMerge`) go on.
        self.horizon = -np.inf

    def ship_tables(self) -> dict:
        """The ship's sensors and platforms tables in the fleet tables' SI form."""
        from registration.io.fleet.reading.cells import check_frame

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
        that are due (sorted by time; None without any). After the association's run at data time
        ``g`` the plots up to ``g - hold_s`` are due, labelled as that run left the labels: which
        plots are used does not depend on how the stream was cut into pieces. All of them are due
        after a last run when ``force``, or when nothing came for the stream's ``hold_s`` seconds
        of wall time (the end of a feed)."""
        batch = self.stream.take(force)
        now = wall.monotonic()
        out: list[dict | None] = []
        if batch is not None:
            self._last_batch, self._seen = now, True
            estimator.add_ship_data(batch.navigation, batch.references, batch.targets)
            self.labels.add(batch.plots, batch.navigation, batch.references, batch.targets)
            if batch.navigation is not None:
                self._nav_end = max(self._nav_end, float(batch.navigation["time"].max()))
            if batch.plots is not None:
                self._queue = concat_rows([self._queue, batch.plots])
            while self.labels.due():  # every run of the grid the piece passed, in order
                at = self.labels.next_time
                self.labels.run()
                self._cut = max(self._cut, min(at - self.hold_s, self._nav_end))
                out.append(self._release(self._queue_due(self._cut)))
        quiet = now - self._last_batch >= self.stream.hold_s
        if force or (quiet and self._seen) or (not self._seen and now - self._started >= STARTUP_S):
            self.horizon = np.inf
        else:
            self.horizon = self._cut
        if (force or quiet) and self._seen:  # the feed's end: a last run on its tail, all due
            if self.labels.behind():
                self.labels.run(final=True)
            self._cut = max(self._cut, self._nav_end)
            out.append(self._release(None if force else self._queue_due(self._nav_end)))
        plots = concat_rows(out)
        return None if plots is None else StreamBatch(plots, None, {})

    def _queue_due(self, cut: float) -> np.ndarray | None:
        return None if self._queue is None else self._queue["time"] <= cut

    def _release(self, due: np.ndarray | None) -> dict | None:
        """The queued plots where ``due`` (all of them for None), labelled now: those of tracks
        with a vessel, sorted by time (None without any); the others are counted."""
        p = self._queue
        if p is None or (due is not None and not due.any()):
            return None
        if due is None or due.all():
            self._queue = None
        else:
            self._queue = {k: v[~due] for k, v in p.items()}
            p = {k: v[due] for k, v in p.items()}
        target = self.labels.label(p["sensor"], p["track"])
        used = target != ""
        self.unassociated += int((~used).sum())
        if not used.any():
            return None
        order = np.argsort(p["time"][used], kind="stable")
        plots = {k: v[used][order] for k, v in p.items() if k != "track"}
        plots["target"] = target[used][order]
        return plots

    def to_json(self) -> dict:
        """The stream's counters, with the association's."""
        out = self.stream.counters.to_json()
        out["plots_unassociated"] = self.unassociated
        out["tracks_associated"] = len(self.labels.labels)
        out["association_runs"] = self.labels.runs
        if self.labels.note:
            out["association_note"] = self.labels.note
        return out
