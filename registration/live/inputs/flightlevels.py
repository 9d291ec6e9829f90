"""Flight levels as heights in the live path (:class:`StreamFlightLevels`): the Mode C / Mode S
flight levels of the plots (I048/090, I001/090) of aircraft without ADS-B become height-only
reference rows (``sigma_m`` inf), as ``registration import asterix`` makes them
(:mod:`registration.io.asterix.tables.flightlevels`), with the relation of flight level to
geometric height learned from the stream's recent ADS-B reports that carry both (I021/145 and
I021/140).

The relation is learned again for every batch on the reports of the last ``horizon_s`` seconds of
data time (30 min by default: the day's temperature and pressure change over hours, and memory
stays flat on a stream that never ends), and applied to the batch's plots of targets that sent no
ADS-B report in that span, within the flight levels fitted. Until ten reports give both there is
no relation and the flight levels are counted, not used: the ISA's heights with one unknown
offset (the file import's fallback) would need a state the live filter does not carry.

A height tells the filter where a target without ADS-B is vertically, which the 2-D radars' slant
ranges give only weakly (docs/background/fleet-online.md, "Targets without a measured height").
"""

from __future__ import annotations

from collections import deque

import numpy as np

from registration.io.asterix.tables.flightlevels import height_rows, learn_relation

__all__ = ["FLIGHT_LEVEL_HORIZON_S", "StreamFlightLevels"]

#: The relation is learned on the ADS-B reports of this many seconds of data time before the latest.
FLIGHT_LEVEL_HORIZON_S = 1800.0


class StreamFlightLevels:
    """The flight levels of a stream (module docstring). ``sites``: the checked SITES table."""

    def __init__(self, sites, horizon_s: float = FLIGHT_LEVEL_HORIZON_S) -> None:
        self._names = sites["sensor"].astype(str).to_numpy()
        self._lla = np.stack(
            [
                np.radians(sites["lat_deg"].to_numpy(float)),
                np.radians(sites["lon_deg"].to_numpy(float)),
                sites["alt_m"].to_numpy(float),
            ],
            axis=1,
        ).reshape(-1, 3)
        self.horizon_s = float(horizon_s)
        self._reports: deque[tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]] = deque()
        #: Heights made (reference rows), and plots with a flight level of targets without ADS-B
        #: that got none (no relation yet, or outside the levels fitted).
        self.heights = 0
        self.unused = 0

    def add_reports(self, reference: dict) -> None:
        """Keep the ADS-B reports of a batch (file-form columns ``time_s``, ``target``, ``alt_m``,
        ``pressure_alt_m``) and forget those older than the horizon."""
        t = np.asarray(reference["time_s"], dtype=np.float64)
        if t.size:
            self._reports.append(
                (
                    t,
                    np.asarray(reference["target"]).astype(str),
                    np.asarray(reference["pressure_alt_m"], dtype=np.float64),
                    np.asarray(reference["alt_m"], dtype=np.float64),
                )
            )
        if self._reports:
            latest = max(float(r[0].max()) for r in self._reports)
            while self._reports and float(self._reports[0][0].max()) < latest - self.horizon_s:
                self._reports.popleft()

    def height_rows(self, plots: dict) -> dict | None:
        """The height-only reference rows (file form: the reference file's columns) of the flight
        levels of ``plots`` (file-form columns ``time_s``, ``sensor`` (a SITES name), ``target``,
        ``range_m``, ``bearing_deg``, ``pressure_alt_m``); None when there are none."""
        hp = np.asarray(plots.get("pressure_alt_m", np.zeros(0)), dtype=np.float64)
        if not np.isfinite(hp).any() or not self._reports:
            self.unused += int(np.isfinite(hp).sum()) if not self._reports else 0
            return None
        t, target, report_hp, report_h = (np.concatenate(c) for c in zip(*self._reports))
        adsb = set(np.unique(target).tolist())
        relation = learn_relation(report_hp, report_h, target)
        candidates = (
            (np.asarray(plots["target"]).astype(str) != "")
            & np.isfinite(hp)
            & ~np.isin(np.asarray(plots["target"]).astype(str), list(adsb))
        )
        if relation is None:
            self.unused += int(candidates.sum())
            return None
        order = np.argsort(self._names, kind="stable")
        sensor = np.asarray(plots["sensor"]).astype(str)
        row = order[np.searchsorted(self._names[order], sensor)]  # every plot's sensor is a SITES name
        rows, info = height_rows(plots, self._lla[row].reshape(-1, 3), relation, adsb)
        n = int(info.get("heights_written", 0))
        self.heights += n
        self.unused += int(candidates.sum()) - n
        return rows if n else None
