"""The online fleet filter (:class:`FleetFilter`): the batch problem's model, processed epoch by
epoch as the plots arrive.

Plots are buffered until their *epoch* closes: with windows (``window_s > 0``) an epoch is one
window of the absolute time grid ``[k window_s, (k + 1) window_s)``, shared by every target;
with ``window_s = 0`` (synchronous sensors, one target position per instant) it is one instant,
or the instants of ``[k epoch_s, (k + 1) epoch_s)`` when ``epoch_s > 0``. An epoch closes when a
plot of a later epoch arrives (or at :meth:`FleetFilter.flush`), so plots must come in time
order across epochs; within an epoch their order does not matter, and feeding the same plots in
any number of chunks gives the same result bit for bit.

Each closed epoch is one Kalman update of the registration states (platform attitude errors,
sensor biases; rad and m):

* predict: the states are constant up to a random walk, ``P += diag(q^2) dt`` (``q`` in
  rad/sqrt(s) and m/sqrt(s), dt the time since the previous epoch);
* the epoch's information ``L`` and gradient ``b`` at the current estimate
  (:mod:`registration.fleet.online.epoch`: the target windows fitted with the states held, then
  eliminated by the Schur complement);
* update in coordinates scaled by each state's prior (or reference) sigma: with ``L = V w V^T``
  over its determined directions (``w`` above 1e-12 of the largest), the measurement
  ``nu = w^-1/2 V^T b`` of ``H = w^1/2 V^T`` with unit noise; ``S = H P H^T + I``,
  ``K = P H^T S^-1``, ``x += K nu`` and the Joseph form ``P = (I - K H) P (I - K H)^T + K K^T``
  (symmetric positive definite by construction), ``nis = nu^T S^-1 nu`` with ``dim nu`` degrees of
  freedom. The update equals ``P+ = (P^-1 + L)^-1``, ``x+ = x + P+ b``.

The starting point is either the priors of the tables (a state without prior starts with the
sigma ``DIFFUSE`` times its reference scale: 10 deg, 10 km) or a batch result (``prior=``:
its estimate and covariance). See docs/background/fleet-online.md.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from registration.core.consistency import ConsistencyReport
from registration.fleet.batch.blocks import SAME_INSTANT_S
from registration.fleet.data.known_targets import References, read_references, read_surface
from registration.fleet.data.layout import make_layout
from registration.fleet.data.navigation import navigation_at, platform_navigation
from registration.fleet.data.plot_rows import read_plots
from registration.fleet.data.problem import Exclusion, FleetProblem
from registration.fleet.data.sensor_specs import read_platforms, read_sensors
from registration.fleet.data.tables import index_of, read_table
from registration.fleet.observability import fleet_observability
from registration.fleet.online.checkpoint import Checkpoints
from registration.fleet.online.epoch import epoch_information
from registration.fleet.online.live import LiveInputs
from registration.fleet.online.options import EpochUpdate, OnlineOptions
from registration.fleet.online.result import OnlineHistory, OnlineResult
from registration.fleet.online.update import information_update, start_state

__all__ = ["EpochUpdate", "FleetFilter", "OnlineOptions"]

#: An epoch is linearised again at its updated estimate while the update moves a state by more
#: than this share of its reference scale (0.1 deg, 100 m), at most MAX_RELINEARISATIONS times (an
#: iterated update): large initial errors are then found as the batch finds them, while in the
#: steady state every epoch is linearised once (the second-order term of a 0.1 deg step is about
#: 0.3 m at 100 km, far below the noise of a radar).
RELINEARISE_ABOVE = 0.1
MAX_RELINEARISATIONS = 10
_BUFFER = ("time", "sensor", "target", "meas", "mask", "nav", "row")


class FleetFilter(Checkpoints, LiveInputs):
    """Online registration of a fleet (module docstring).

    ``sensors``, ``navigation``, ``platforms``, ``references``, ``targets``: the tables of
    :func:`registration.fleet.build_problem` (SI units, radians), given once; plots arrive with
    :meth:`update`. ``prior``: a batch result (or anything with ``layout``, ``estimate`` and
    ``covariance`` over the same states) to start from. A live feed adds navigation and surface
    targets as they arrive (:class:`~registration.fleet.online.live.LiveInputs`).
    """

    def __init__(
        self,
        sensors,
        navigation,
        platforms=None,
        references=None,
        *,
        options: OnlineOptions | None = None,
        prior=None,
        targets=None,
    ):
        self.options = options or OnlineOptions()
        sensors_t = read_table("sensors", sensors, ("sensor", "platform"))
        self.platform_ids, platform_priors = read_platforms(platforms, sensors_t.ids("platform"))
        self.specs = read_sensors(sensors_t, self.platform_ids)
        self.tracks = platform_navigation(
            read_table("navigation", navigation, ("platform",)), self.platform_ids
        )
        ref_ids = (
            []
            if references is None
            else list(dict.fromkeys(read_table("references", references).ids("target")))
        )
        self.references = read_references(references, ref_ids)
        self.surface = read_surface(targets)
        self.layout = make_layout(
            self.platform_ids,
            platform_priors,
            self.specs.ids,
            self.specs.channels,
            self.specs.prior,
            self.specs.extended_prior,
            self.specs.eccentricity_prior,
            self.specs.channel_of,
        )
        self.x, self.P = start_state(self.layout, prior)
        self.information = np.zeros((self.layout.n, self.layout.n))
        q = {
            "rad": self.options.q_angle,
            "m": self.options.q_range,
            "1": self.options.q_gain,
            "s": self.options.q_time,
        }
        self._q2 = np.array([q[u] for u in self.layout.units]) ** 2
        self._buffer: dict[str, list[np.ndarray]] = {k: [] for k in _BUFFER}
        self._n_read = 0
        self._closed_key: int | None = None
        self._open_key: int | None = None  # the latest epoch buffered
        self._t_last: float | None = None
        self._history: list[tuple] = []
        self._unused: dict[str, list] = {}
        self.n_linearisations = 0
        #: Plots of windows whose fit did not converge, set aside (epoch.py), over every epoch.
        self.n_unconverged_plots = 0
        #: Called after each informative epoch with its :class:`EpochUpdate` (None: not called).
        self.on_epoch: Callable[[EpochUpdate], None] | None = None

    # -- input -----------------------------------------------------------------------------------
    def update(self, plots) -> int:
        """Add plots (a table with ``time``, ``sensor``, ``target`` and the measured channels, as
        in :func:`registration.fleet.build_problem`) and process the epochs they close.
        Returns the number of epochs processed. ValueError naming the row for a bad plot or for a
        plot of an epoch already processed; the filter is unchanged when it raises."""
        table = read_table("plots", plots, ("time", "sensor", "target"))
        cols = read_plots(table, self.specs)
        key = self.options.epoch_key(cols.time)
        if self._closed_key is not None and (key <= self._closed_key).any():
            row = int(np.flatnonzero(key <= self._closed_key)[0])
            raise table.error(
                row,
                f"time {cols.time[row]:g} s falls in an epoch already processed; feed plots in "
                "time order (an epoch closes when a plot of a later epoch arrives)",
            )
        platform = self.specs.platform[cols.sensor]
        nav = navigation_at(
            self.tracks,
            self.platform_ids,
            platform,
            cols.time,
            lambda i: f"plots row {i} (sensor {self.specs.ids[cols.sensor[i]]!r}, time {cols.time[i]:g} s)",
        )
        new = {
            "time": cols.time,
            "sensor": cols.sensor,
            "target": cols.target.astype(str),
            "meas": cols.meas,
            "mask": cols.mask,
            "nav": nav,
            "row": self._n_read + np.arange(cols.time.size),
        }
        for k in _BUFFER:
            self._buffer[k].append(new[k])
        self._n_read += int(cols.time.size)
        if key.size == 0 or (self._open_key is not None and key.max() <= self._open_key):
            return 0  # no epoch closes: the plots wait in the buffer
        self._open_key = int(key.max())
        return self._process(closing_all=False)

    def add_references(self, references) -> int:
        """Add reference positions (the references table of :func:`registration.fleet.build_problem`,
        SI) that arrive while the plots stream (a live feed): an epoch uses those of its targets and
        time span present when it closes, so give them before the plots that close it. Returns the
        number added."""
        table = read_table("references", references, ("target", "time"))
        new = read_references(references, list(dict.fromkeys(table.ids("target"))))
        old = self.references
        self.references = References(
            np.concatenate([old.target.astype(object), new.target.astype(object)]),
            np.concatenate([old.time, new.time]),
            np.concatenate([old.p_ecef, new.p_ecef]),
            np.concatenate([old.sigma, new.sigma]),
            np.concatenate([old.up_sigma, new.up_sigma]),
        )
        return int(new.time.size)

    def late(self, time: np.ndarray) -> np.ndarray:
        """(N,) bool: the plot times (s) that fall in an epoch already processed (:meth:`update` would
        refuse them)."""
        key = self.options.epoch_key(np.asarray(time, dtype=np.float64))
        return key <= self._closed_key if self._closed_key is not None else np.zeros(key.shape, dtype=bool)

    def forget(self, before_s: float) -> None:
        """Drop what a stream that never ends no longer needs: the reference positions, the history
        and the record of unused plots from before ``before_s`` (s). The estimate, covariance and
        information are kept."""
        self.references = self.references.subset(self.references.time >= before_s)
        self._history = [h for h in self._history if h[0] >= before_s]
        self._unused = {k: [t[t >= before_s] for t in v] for k, v in self._unused.items()}
        self._unused = {k: v for k, v in self._unused.items() if any(t.size for t in v)}

    def flush(self) -> int:
        """Process every buffered epoch (the end of the data). Returns the number processed."""
        return self._process(closing_all=True)

    # -- processing ------------------------------------------------------------------------------
    def _process(self, closing_all: bool) -> int:
        if not self._buffer["time"]:  # every column is buffered with the time
            return 0
        buf = {k: np.concatenate(v) for k, v in self._buffer.items()}
        if buf["time"].size == 0:
            return 0
        key = self.options.epoch_key(buf["time"])
        keys = np.unique(key)
        closed = keys if closing_all else keys[:-1]
        for k in closed:
            sel = key == k
            self._epoch({name: v[sel] for name, v in buf.items()})
            self._closed_key = int(k)
        rest = ~np.isin(key, closed)
        self._buffer = {name: [v[rest]] for name, v in buf.items()}
        return int(closed.size)

    def _epoch(self, plots: dict) -> None:
        t_end = float(plots["time"].max())
        if self._t_last is not None:
            self.P[np.diag_indices_from(self.P)] += (
                self._q2 * max(t_end - self._t_last, 0.0) * (self.layout.prior_sigma > 0)
            )
        self._t_last = t_end
        problem = self._problem(plots)
        nis, dof, used, unconverged = 0.0, 0, 0, 0
        x_lin = self.x
        for _ in range(MAX_RELINEARISATIONS):
            info = epoch_information(problem, x_lin, self.options.batch())
            if info is None:
                break
            b = info.b + info.L @ (
                x_lin - self.x
            )  # the gradient at the prior mean of the model linearised at x_lin
            x, P, nis, dof = information_update(
                self.x, self.P, info.L, b, self.layout.free, self.layout.scale
            )
            moved = np.abs(x - x_lin)[self.layout.free] / self.layout.scale[self.layout.free]
            self.n_linearisations += 1
            x_lin, L, used, unconverged = x, info.L, info.n_plots, info.n_unconverged
            if not moved.max(initial=0.0) > RELINEARISE_ABOVE:
                break
        self.n_unconverged_plots += unconverged
        if used:
            x_before, P_before = self.x, self.P
            self.x, self.P = x_lin, P
            self.information += L
            if self.on_epoch is not None:
                self.on_epoch(EpochUpdate(t_end, x_before, P_before, L, b, problem, used))
        if used < plots["time"].size:
            for tid in np.unique(plots["target"]):
                self._unused.setdefault(str(tid), []).append(plots["time"][plots["target"] == tid])
        self._history.append(
            (t_end, self.x.copy(), np.sqrt(np.clip(np.diag(self.P), 0, None)), nis, dof, used)
        )

    def _problem(self, plots: dict) -> FleetProblem:
        target_ids = tuple(dict.fromkeys(plots["target"]))
        refs = self.references
        t0, t1 = plots["time"].min() - SAME_INSTANT_S, plots["time"].max() + SAME_INSTANT_S
        sel = np.isin(refs.target, target_ids) & (refs.time >= t0) & (refs.time <= t1)  # this epoch's only
        refs = refs.subset(sel)
        return FleetProblem(
            platform_ids=tuple(self.platform_ids),
            sensor_ids=self.specs.ids,
            target_ids=target_ids,
            sensor_platform=self.specs.platform,
            sensor_sigma=self.specs.sigma,
            sensor_lever=self.specs.lever,
            layout=self.layout,
            time=plots["time"],
            sensor=plots["sensor"],
            target=index_of(plots["target"], target_ids),
            meas=plots["meas"],
            mask=plots["mask"],
            nav=plots["nav"],
            row=plots["row"],
            n_input_plots=self._n_read,
            references=refs,
            ref_target=index_of(refs.target, target_ids),
            tracks=self.tracks,
            surface=self.surface,
        )

    # -- output ----------------------------------------------------------------------------------
    @property
    def estimate(self) -> np.ndarray:
        """(n,) the current estimate (rad, m), in the order of ``layout.names``."""
        return self.x.copy()

    @property
    def covariance(self) -> np.ndarray:
        """(n, n) its covariance."""
        return self.P.copy()

    def result(self) -> OnlineResult:
        """The estimates now, with the history, observability report and innovation check."""
        layout = self.layout
        f = layout.free
        report = fleet_observability(
            self.information[np.ix_(f, f)], f, layout, self.specs.platform, self.platform_ids, self.specs.ids
        )
        status = {layout.names[i]: "fixed" for i in layout.fixed}
        status.update(report.status)
        h = self._history
        hist = OnlineHistory(
            np.array([e[0] for e in h]),
            np.array([e[1] for e in h]).reshape(len(h), layout.n),
            np.array([e[2] for e in h]).reshape(len(h), layout.n),
            np.array([e[3] for e in h]),
            np.array([e[4] for e in h], dtype=np.int64),
            np.array([e[5] for e in h], dtype=np.int64),
        )
        dof = int(hist.dof.sum())
        consistency = (
            ConsistencyReport.from_mean(
                float(hist.nis.sum()) / dof, dof, 1, "normalised innovation squared per degree of freedom"
            )
            if dof
            else None
        )
        return OnlineResult(
            layout,
            self.estimate,
            self.covariance,
            np.sqrt(np.clip(np.diag(self.P), 0, None)),
            status,
            report,
            consistency,
            hist,
            self._exclusions(),
            self._n_read,
            int(hist.n_plots.sum()),
        )

    def _exclusions(self) -> tuple[Exclusion, ...]:
        out = []
        for tid, times in self._unused.items():
            t = np.concatenate(times)
            out.append(
                Exclusion(
                    tid,
                    "no registration information in some epochs (seen by one sensor only, without a "
                    "reference, or its position not determined by its plots)",
                    int(t.size),
                    float(t.min()),
                    float(t.max()),
                )
            )
        return tuple(out)
