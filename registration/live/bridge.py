"""One ship's bridge as an input of the live service: its NMEA stream imported piece by piece
(:class:`~registration.live.nmeaingest.NmeaStream`), its TTM tracks associated with the AIS
vessels (:class:`~registration.live.tracks.TrackLabels`), and what the estimator needs: the
navigation, the AIS references and surface targets given to it at once, the associated plots
handed back as a :class:`~registration.live.ingest.StreamBatch` for the estimator's queue."""

from __future__ import annotations

import datetime as dt
from pathlib import Path

import numpy as np

from registration.live.ingest import StreamBatch
from registration.live.nmeaingest import NmeaStream
from registration.live.tracks import TrackLabels

__all__ = ["Bridge"]


class Bridge:
    """The ship ``platform`` with the sensors of ``sensors`` (a sensors file with the optional
    ``talker`` column), its attitude errors held at 0 (as ``import nmea`` writes them by default);
    ``window_s``: the estimator's epochs; ``name``: the stream's address, for notes."""

    def __init__(
        self, platform: str, sensors: str | Path, window_s: float, *, date: dt.date | None = None, name: str = "nmea"
    ) -> None:
        priors = {c: 0.0 for c in ("prior_heading_deg", "prior_pitch_deg", "prior_roll_deg")}
        self.stream = NmeaStream(platform, sensors, platform_priors=priors, date=date, name=name)
        ship = self.ship_tables()
        self.labels = TrackLabels(ship["sensors"], ship["platforms"], window_s)
        self.unassociated = 0
        self._nav_end = -np.inf
        self._later: dict | None = None  # plots after the navigation so far: they wait for it

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
        (sorted by time; None without any)."""
        batch = self.stream.take(force)
        if batch is None:
            return None
        estimator.add_ship_data(batch.navigation, batch.references, batch.targets)
        self.labels.add(batch.plots, batch.navigation, batch.references, batch.targets)
        if self.labels.due():
            self.labels.run()
        if batch.navigation is not None:
            self._nav_end = max(self._nav_end, float(batch.navigation["time"].max()))
        p = self._later if batch.plots is None else batch.plots
        if self._later is not None and batch.plots is not None:
            p = {k: np.concatenate([self._later[k], batch.plots[k]]) for k in p}
        self._later = None
        if p is None:
            return None
        wait = p["time"] > self._nav_end
        if wait.any() and not force:
            self._later = {k: v[wait] for k, v in p.items()}
            p = {k: v[~wait] for k, v in p.items()}
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
