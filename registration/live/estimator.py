"""The live service's estimator: the online fleet filter
(:class:`~registration.fleet.online.filter.FleetFilter`) fed batch by batch, with change alarms
(:class:`~registration.fleet.online.alarms.ChangeDetector`), the recent history of the estimates and
the residuals per sensor.

The filter is the batch problem's model processed epoch by epoch (docs/background/fleet-online.md):
biases follow a random walk (its process noise lets them drift), ADS-B reports are reference
positions, and plots need a target id (Mode S address or Mode 3/A code); plots without one are
counted, not used (association of plots without ids runs in the batch path only). A plot that
arrives after its epoch was processed is counted as late and not used. Each target window of an
epoch is fitted on its own (:mod:`registration.fleet.batch.window_fit`): a Mode A/C aircraft
without a measured height flying over a radar starts far from its minimum, and fitted together
with the others its window once ended in a wrong minimum whose gradient raised three false
alarms. A window whose fit has not converged is not used, and its plots are counted
(``filter.n_unconverged_plots``, ``/api/status`` ``ingest.unconverged_plots``). When a state
moves beyond its uncertainty an alarm is raised and its variance opened, so the filter follows
the new value.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from registration.fleet.batch.residuals import residuals_at
from registration.fleet.data.layout import FILE_UNITS
from registration.fleet.data.tables import EXTENDED_PRIOR_COLUMNS
from registration.fleet.online.alarms import Change, ChangeDetector, open_states
from registration.fleet.online.filter import FleetFilter
from registration.fleet.online.options import EpochUpdate, OnlineOptions
from registration.io.asterix.tables.fleetfiles import site_tables
from registration.io.fleet.estimates import estimate_rows
from registration.io.fleet.reading.cells import check_frame
from registration.live.inputs.asterix import StreamBatch

__all__ = ["Alarm", "LiveEstimator", "HISTORY_S"]

#: The estimates over time are kept for this long of data time (s): the page's last hour.
HISTORY_S = 3600.0
#: Reference positions are kept this long (s) before the latest plot: late epochs still find them.
KEEP_REFERENCES_S = 300.0
#: The residuals are computed on one epoch in this many (they cost a second fit of its windows):
#: a sample for the page, not every plot.
RESIDUALS_EVERY = 5
_CHANNELS = (("range", "m", 1.0), ("bearing", "deg", float(np.degrees(1.0))))


@dataclass(frozen=True)
class Alarm:
    """A change alarm in file units: data time (s), object, state, unit, estimate before and after,
    the sigma of the difference and z."""

    time_s: float
    object: str
    state: str
    unit: str
    before: float
    after: float
    sigma: float
    z: float

    def to_json(self) -> dict:
        return dict(self.__dict__)


def _tables(sites, ship=None) -> dict:
    """The SITES tables (navigation, sensors, platforms) and the ship's (``ship``: its sensors and
    platforms file tables; its navigation comes with the stream, a placeholder row until then) in
    the fleet tables' SI form, merged (a column one of them lacks: :func:`_absent`)."""
    import pandas as pd

    parts = []
    if sites is not None:
        parts.append(site_tables(sites, 0.0))
    if ship is not None:
        sensors, platforms = ship
        platform = str(platforms["platform"].iloc[0])
        nav = pd.DataFrame({c: [0.0] for c in _NAV_FILE})
        nav.insert(1, "platform", [platform])
        parts.append({"sensors": sensors, "platforms": platforms, "navigation": nav})
    out = {}
    for name in ("sensors", "navigation", "platforms"):
        tables = [
            check_frame(name, Path("SITES"), p[name], skip=False, whole_file=False).table for p in parts
        ]
        out[name] = _merge(tables)
    return out


_NAV_FILE = ("time_s", "lat_deg", "lon_deg", "alt_m", "heading_deg", "pitch_deg", "roll_deg")


def _absent(column: str) -> float:
    """The value of a column one table lacks: an extended error it does not model held at 0 (an
    empty cell would estimate it), a lever arm 0, no prior (inf) for the others."""
    if column in EXTENDED_PRIOR_COLUMNS or column.startswith("lever"):
        return 0.0
    return np.inf if column.startswith("prior") else np.nan


def _merge(tables: list[dict]) -> dict:
    keys = list(dict.fromkeys(k for t in tables for k in t))
    out = {}
    for k in keys:
        cols = []
        for t in tables:
            n = len(next(iter(t.values())))
            if k in t:
                cols.append(np.asarray(t[k]))
            elif any(np.asarray(u[k]).dtype.kind in "US" for u in tables if k in u):
                cols.append(np.full(n, ""))
            else:
                cols.append(np.full(n, _absent(k)))
        out[k] = np.concatenate(cols)
    return out


class LiveEstimator:
    """The estimator of the module docstring for the sites of ``sites`` (the checked SITES table).
    ``options``: the filter's (epochs, process noise); ``alarm_window_s``: the data a change test
    looks at."""

    def __init__(
        self, sites, options: OnlineOptions | None = None, alarm_window_s: float = 60.0, ship=None
    ) -> None:
        self.options = options or OnlineOptions()
        t = _tables(sites, ship)
        self.filter = FleetFilter(t["sensors"], t["navigation"], t["platforms"], None, options=self.options)
        self.layout = self.filter.layout
        epoch_s = self.options.window_s if self.options.window_s > 0 else max(self.options.epoch_s, 1.0)
        self.detector = ChangeDetector(self.layout, alarm_window_s, epoch_s)
        self.filter.on_epoch = self._on_epoch
        self.alarms: deque[Alarm] = deque(maxlen=200)
        self.history: deque[tuple[float, np.ndarray, np.ndarray]] = deque()
        self.residuals: deque[tuple[float, dict]] = deque()
        self.late_plots = 0
        self.plots_outside_navigation = 0
        self.epochs = 0
        self.data_time_s: float | None = None
        self._rows_cache: tuple[int, list[dict]] | None = None

    # -- input -----------------------------------------------------------------------------------
    def feed(self, batch: StreamBatch) -> int:
        """Add a batch's references and plots; returns the epochs processed."""
        if batch.references is not None and batch.references["time"].size:
            self.filter.add_references(batch.references)
        plots = batch.plots
        if plots["time"].size == 0:
            return 0
        plots = self.within_navigation(plots)
        late = self.filter.late(plots["time"])
        self.late_plots += int(late.sum())
        if late.any():
            plots = {k: v[~late] for k, v in plots.items()}
        if plots["time"].size == 0:
            return 0
        done = self.filter.update(plots)
        t = float(plots["time"].max())
        self.data_time_s = t if self.data_time_s is None else max(self.data_time_s, t)
        self.filter.forget(self.data_time_s - KEEP_REFERENCES_S)
        self.filter.forget_navigation(self.data_time_s - KEEP_REFERENCES_S)
        return done

    def add_ship_data(self, navigation, references, targets) -> None:
        """A ship's navigation, AIS references and surface targets (SI tables; None: none), given
        before the plots they serve."""
        if navigation is not None:
            self.filter.add_navigation(navigation)
        if targets is not None:
            self.filter.add_surface(targets)
        if references is not None and references["time"].size:
            self.filter.add_references(references)

    def within_navigation(self, plots: dict) -> dict:
        """``plots`` without those outside their platform's navigation (counted)."""
        outside = self.filter.outside_navigation(plots["sensor"], plots["time"])
        self.plots_outside_navigation += int(outside.sum())
        return {k: v[~outside] for k, v in plots.items()} if outside.any() else plots

    def flush(self) -> int:
        """Process the epoch still open (at the end of a replay, or before a checkpoint)."""
        return self.filter.flush()

    def _on_epoch(self, update: EpochUpdate) -> None:
        self.epochs += 1
        changes = self.detector.observe(update)
        if changes:
            self.filter.P = open_states(self.filter.P, changes)
            self.alarms.extend(self._alarm(c) for c in changes)
        sigma = np.sqrt(np.clip(np.diag(self.filter.P), 0.0, None))
        self.history.append((update.t_end, self.filter.x.copy(), sigma))
        while self.history and self.history[0][0] < update.t_end - HISTORY_S:
            self.history.popleft()
        if self.epochs % RESIDUALS_EVERY == 1 or RESIDUALS_EVERY == 1:
            self.residuals.append((update.t_end, self._residual_sums(update)))
        while self.residuals and self.residuals[0][0] < update.t_end - HISTORY_S:
            self.residuals.popleft()

    def _alarm(self, c: Change) -> Alarm:
        i, L = c.index, self.layout
        unit, k, _, _ = FILE_UNITS[L.units[i]]
        return Alarm(
            c.time_s, L.objects[i], L.quantities[i], unit, c.before * k, c.after * k, c.sigma * k, c.z
        )

    def _residual_sums(self, update: EpochUpdate) -> dict:
        """Per (sensor, channel): n, sum and sum of squares of the epoch's residuals (file units) at
        the updated estimate."""
        n = int(update.problem.time.size)
        numbered = replace(update.problem, row=np.arange(n), n_input_plots=n)  # rows of this epoch only
        try:
            res, _, problem = residuals_at(numbered, self.filter.x, self.options.batch())
        except ValueError:
            return {}
        out = {}
        raw = res[problem.row] * np.asarray(problem.sensor_sigma)[problem.sensor]  # normalised -> units
        for s, name in enumerate(problem.sensor_ids):
            mine = problem.sensor == s
            for ch, (label, _, k) in enumerate(_CHANNELS):
                v = raw[mine, ch] * k
                v = v[np.isfinite(v)]
                if v.size:
                    out[(name, label)] = (int(v.size), float(v.sum()), float((v**2).sum()))
        return out

    # -- output ----------------------------------------------------------------------------------
    def rows_changed(self) -> None:
        """Forget the cached rows (after a restore)."""
        self._rows_cache = None

    def values(self) -> dict[str, dict[str, float]]:
        """object -> quantity -> current estimate (SI: rad, m, 1, s) of the free states."""
        out: dict[str, dict[str, float]] = {}
        L = self.layout
        for i in np.asarray(L.free):
            out.setdefault(L.objects[i], {})[L.quantities[i]] = float(self.filter.x[i])
        return out

    def rows(self) -> list[dict]:
        """The estimates as ``estimates.csv`` rows (file units), with the status of each state."""
        if self._rows_cache is None or self._rows_cache[0] != self.epochs:
            self._rows_cache = (self.epochs, estimate_rows(self.filter.result()))
        return self._rows_cache[1]

    def consistency(self) -> dict:
        """The innovation check: value (mean normalised innovation squared per degree of freedom),
        its 95 % band and the verdict (None before an informative epoch)."""
        report = self.filter.result().consistency if self.epochs else None
        if report is None:
            return {"value": None, "band": None, "verdict": None}
        return {"value": report.mean, "band": list(report.interval), "verdict": report.status}

    def history_of(self, obj: str) -> list[dict]:
        """The estimates over the last hour of the states of ``obj`` (file units)."""
        L = self.layout
        t = np.array([h[0] for h in self.history])
        out = []
        for i in np.asarray(L.free):
            if L.objects[i] != obj:
                continue
            unit, k, _, _ = FILE_UNITS[L.units[i]]
            out.append(
                {
                    "state": L.quantities[i],
                    "unit": unit,
                    "time_s": t.tolist(),
                    "estimate": [float(h[1][i] * k) for h in self.history],
                    "sigma": [float(h[2][i] * k) for h in self.history],
                }
            )
        return out

    def residual_summary(self) -> list[dict]:
        """Per sensor and channel over the last hour: n, mean and rms of the residuals (m, deg)."""
        total: dict = {}
        for _, sums in self.residuals:
            for key, (n, s1, s2) in sums.items():
                a = total.setdefault(key, [0, 0.0, 0.0])
                a[0] += n
                a[1] += s1
                a[2] += s2
        out = []
        for sensor in self.filter.specs.ids:
            channels = []
            for label, unit, _ in _CHANNELS:
                n, s1, s2 = total.get((sensor, label), (0, 0.0, 0.0))
                channels.append(
                    {
                        "channel": label,
                        "unit": unit,
                        "n": n,
                        "mean": s1 / n if n else None,
                        "rms": float(np.sqrt(s2 / n)) if n else None,
                    }
                )
            out.append({"sensor": sensor, "channels": channels})
        return out
