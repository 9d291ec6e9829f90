"""First association stage: tracks per sensor, one sensor at a time, in ECEF.

A sensor's biases and its platform's attitude errors are the same for every plot it makes, so
linking one sensor's plots over time does not need the registration: it is done once, at the
starting estimate. Each sensor's plots are grouped in scans (plots at the same time) and each scan
is assigned to the sensor's open tracks by :class:`~registration.fleet.association.grouping.geometry.Assigner`
(cost: negative log-likelihood of the plot given the track's prediction; gate at the
``gate_probability`` quantile of chi-square with 3 degrees of freedom; a plot left over opens a
track). A track is a constant-velocity Kalman filter on the plot positions (process noise: white
acceleration of ``accel_sigma`` m/s^2/sqrt(Hz); a new track's velocity has sigma ``max_speed``; the filter's
functions are generated, ``cv_start``, ``cv_predict``, ``cv_gate`` and ``cv_update`` of
derive/tracking.py), closed after ``max_missed`` scans in a row without a plot. Tracks with fewer than
``min_plots`` plots are clutter. All sensors advance together, scan k of every sensor in one step.
A track and a plot that are each other's only candidate in the gate are paired, or not, without the
assignment: an isolated pair is its own optimum, so the result is that of one assignment over the
whole step.

The loop runs in compiled code on the C backend (``registration._codegen.compiled_tracks``, 0.14 s
instead of 1.25 s for the association benchmark's three runs); the numpy loop here is its reference
(the same tracks plot for plot, ``tests/fleet/test_association_compiled_tracks.py``) and runs on the
serialized CasADi backend.
"""

from __future__ import annotations

import numpy as np

from registration import _codegen
from registration._generated import api as generated
from registration.core.distributions import chi2_ppf
from registration.fleet.association.grouping.geometry import FORBIDDEN, Assigner, PlotGeometry

__all__ = ["sensor_tracks", "track_breaks"]


def _scan_steps(time: np.ndarray, sensor: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(plot indices, bounds): step k, ``indices[bounds[k]:bounds[k + 1]]``, holds scan k of every
    sensor, sorted by sensor."""
    order = np.lexsort((time, sensor))
    s, t = sensor[order], time[order]
    new_scan = np.ones(order.size, dtype=bool)
    new_scan[1:] = (s[1:] != s[:-1]) | (t[1:] != t[:-1])
    scan_id = np.cumsum(new_scan) - 1
    first_scan = np.zeros(order.size, dtype=np.int64)
    sensor_start = np.flatnonzero(np.r_[True, s[1:] != s[:-1]])
    first_scan[sensor_start] = scan_id[sensor_start]
    first_scan = np.maximum.accumulate(first_scan)
    k = scan_id - first_scan  # scan number within the sensor
    by_step = np.lexsort((s, k))
    idx, ks = order[by_step], k[by_step]
    return idx, np.flatnonzero(np.r_[True, ks[1:] != ks[:-1], True])


def _predict(x: np.ndarray, P: np.ndarray, dt: np.ndarray, q: float) -> tuple[np.ndarray, np.ndarray]:
    """Constant-velocity prediction of states (K, 6) and covariances (K, 6, 6) by dt (K,) s
    (generated ``cv_predict``)."""
    if x.shape[0] == 0:
        return x.copy(), P.copy()
    return generated.cv_predict(x=x, P=P, dt=dt, accel_sigma=q)


def _gate(xp: np.ndarray, Pp: np.ndarray, z: np.ndarray, R: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(d2, log det S) (K,) of plots z (K, 3) m, R (K, 3, 3) m^2 against predictions (generated
    ``cv_gate``)."""
    if z.shape[0] == 0:
        return np.zeros(0), np.zeros(0)
    return generated.cv_gate(x_pred=xp, P_pred=Pp, z=z, R=R)


def _filtered(xp: np.ndarray, Pp: np.ndarray, z: np.ndarray, R: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Kalman update of predictions (K, 6), (K, 6, 6) with plots z (K, 3) m, R (K, 3, 3) m^2
    (generated ``cv_update``)."""
    if z.shape[0] == 0:
        return xp.copy(), Pp.copy()
    return generated.cv_update(x_pred=xp, P_pred=Pp, z=z, R=R)


def _started(z: np.ndarray, R: np.ndarray, max_speed: float) -> tuple[np.ndarray, np.ndarray]:
    """States (K, 6) and covariances (K, 6, 6) of tracks opened at plots z (K, 3) m, R (K, 3, 3)
    m^2 (generated ``cv_start``)."""
    if z.shape[0] == 0:
        return np.zeros((0, 6)), np.zeros((0, 6, 6))
    return generated.cv_start(z=z, R=R, max_speed=max_speed)


class _Tracks:
    """Open tracks of all sensors: sensor (K,), id (K,), state (K, 6), covariance (K, 6, 6),
    time of the last plot (K,), scans missed in a row (K,)."""

    def __init__(self):
        self.sensor = np.zeros(0, dtype=np.int64)
        self.id = np.zeros(0, dtype=np.int64)
        self.x = np.zeros((0, 6))
        self.P = np.zeros((0, 6, 6))
        self.t = np.zeros(0)
        self.missed = np.zeros(0, dtype=np.int64)
        self.next_id = 0

    def keep(self, sel: np.ndarray) -> None:
        if sel.all():
            return
        for name in ("sensor", "id", "x", "P", "t", "missed"):
            setattr(self, name, getattr(self, name)[sel])

    def open(
        self, sensor: np.ndarray, z: np.ndarray, R: np.ndarray, t: np.ndarray, max_speed: float
    ) -> np.ndarray:
        n = sensor.size
        if n == 0:
            return np.zeros(0, dtype=np.int64)
        ids = self.next_id + np.arange(n)
        self.next_id += n
        x, P = _started(z, R, max_speed)
        # np.concatenate, not np.r_ (ten times its cost, once a scan step)
        self.sensor = np.concatenate([self.sensor, sensor])
        self.id = np.concatenate([self.id, ids])
        self.x = np.concatenate([self.x, x])
        self.P = np.concatenate([self.P, P])
        self.t = np.concatenate([self.t, t])
        self.missed = np.concatenate([self.missed, np.zeros(n, dtype=np.int64)])
        return ids


def _match_scan(
    tracks: _Tracks,
    live: np.ndarray,
    xp,
    Pp,
    sen,
    p: np.ndarray,
    cov: np.ndarray,
    trace: np.ndarray,
    gate: float,
    assigner: Assigner,
) -> tuple[np.ndarray, np.ndarray]:
    """Pairs (track index into ``tracks``, plot index into the step) of one step: one assignment
    over all sensors, tracks and plots of different sensors never paired (``sen`` is sorted). The
    step's plots: positions ``p`` (M, 3) m, covariances ``cov`` (M, 3, 3) m^2 and their traces (M,)."""
    ts = tracks.sensor[live]
    lo, hi = np.searchsorted(sen, ts, side="left"), np.searchsorted(sen, ts, side="right")
    n = hi - lo
    ki = np.repeat(np.arange(live.size), n)
    pj = np.repeat(lo, n) + np.arange(ki.size) - np.repeat(np.cumsum(n) - n, n)
    v = p[pj] - np.ascontiguousarray(xp[:, :3])[ki]
    # d2 >= |v|^2 / trace(S): pairs beyond the gate by this bound need no solve
    bound = (Pp[:, 0, 0] + Pp[:, 1, 1] + Pp[:, 2, 2])[ki] + trace[pj]
    # summed in the compiled loop's order: the bound decides which pairs count in ``best`` below
    near = v[:, 0] * v[:, 0] + v[:, 1] * v[:, 1] + v[:, 2] * v[:, 2] < gate * bound
    ki, pj, v = ki[near], pj[near], v[near]
    d2, logdet = _gate(xp[ki], Pp[ki], p[pj], cov[pj])
    finite = np.isfinite(d2) & np.isfinite(logdet)  # not: a covariance not positive definite
    ki, pj, d2, logdet = ki[finite], pj[finite], d2[finite], logdet[finite]
    if ki.size == 0:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    best = np.full(live.size, np.inf)
    np.minimum.at(best, ki, logdet)
    no_match = 0.5 * (gate + best)
    inside = d2 < gate
    ki, pj, cost = ki[inside], pj[inside], 0.5 * (d2 + logdet)[inside]
    # a pair that is the only one of its track and of its plot is decided alone (the rest, linked
    # through shared tracks or plots, by one assignment: the optimum of the whole step is the same)
    alone = (np.bincount(ki, minlength=live.size)[ki] == 1) & (np.bincount(pj, minlength=p.shape[0])[pj] == 1)
    take = alone & (cost < no_match[ki])
    ti, pp = ki[take], pj[take]
    if not alone.all():
        rows, r_idx = np.unique(ki[~alone], return_inverse=True)
        cols, c_idx = np.unique(pj[~alone], return_inverse=True)
        matrix = np.full((rows.size, cols.size), np.inf)
        matrix[r_idx, c_idx] = cost[~alone]
        col = assigner.assign(matrix, no_match[rows])
        ok = col >= 0
        ti, pp = np.concatenate([ti, rows[ok]]), np.concatenate([pp, cols[col[ok]]])
    return live[ti], pp


def _update(tracks: _Tracks, ti: np.ndarray, xp, Pp, z: np.ndarray, R: np.ndarray, t: np.ndarray) -> None:
    """Kalman update of tracks ``ti`` (their predictions xp, Pp) with plot positions z (m), R (m^2)."""
    tracks.x[ti], tracks.P[ti] = _filtered(xp, Pp, z, R)
    tracks.t[ti] = t
    tracks.missed[ti] = 0


def sensor_tracks(
    time: np.ndarray,
    sensor: np.ndarray,
    geom: PlotGeometry,
    assigner: Assigner,
    *,
    max_speed: float,
    accel_sigma: float,
    gate_probability: float,
    max_missed: int,
    min_plots: int,
    compiled: bool | None = None,
) -> np.ndarray:
    """(N,) track id of each plot (ids unique over all sensors), -1 for plots in no track of at
    least ``min_plots`` plots (clutter). ``time`` (N,) s, ``sensor`` (N,) sensor index.

    ``compiled``: run the loop in compiled code (``registration._codegen.compiled_tracks``: the
    same steps, generated functions and assignment as the numpy loop here, its reference) or in
    numpy; None (default): compiled on the C backend. Its assignments count in ``assigner``."""
    if time.size == 0:
        return np.zeros(0, dtype=np.int64)
    gate = float(chi2_ppf(gate_probability, 3))
    idx, bounds = _scan_steps(time, sensor)
    if compiled is None:
        compiled = _codegen.backend() == "c"
    if compiled:
        out = _codegen.compiled_tracks(
            bounds,
            idx,
            geom.p_ecef,
            geom.cov,
            time,
            sensor,
            gate=gate,
            forbidden=FORBIDDEN,
            accel_sigma=accel_sigma,
            max_speed=max_speed,
            max_missed=max_missed,
        )
        assigner.seconds += out.seconds_assignment
        assigner.calls += out.assignments
        track = out.track
    else:
        options = (gate, accel_sigma, max_speed, max_missed)
        track = _numpy_tracks(idx, bounds, time, sensor, geom, assigner, *options)
    ids, counts = np.unique(track, return_counts=True)
    track[np.isin(track, ids[counts < min_plots])] = -1
    return track


def _numpy_tracks(idx, bounds, time, sensor, geom, assigner, gate, accel_sigma, max_speed, max_missed):
    """The tracker's loop in numpy, step by step (the reference of the compiled loop)."""
    track = np.full(time.size, -1, dtype=np.int64)
    tracks = _Tracks()
    n_sensors = int(sensor.max()) + 1
    scan_time = np.zeros(n_sensors)
    trace = np.trace(geom.cov, axis1=1, axis2=2)
    for a, b in zip(bounds[:-1], bounds[1:]):
        step = idx[a:b]
        sen = sensor[step]
        stepping = np.zeros(n_sensors, dtype=bool)
        stepping[sen] = True
        live = np.flatnonzero(stepping[tracks.sensor])
        scan_time[sen] = time[step]
        dt = scan_time[tracks.sensor[live]] - tracks.t[live]
        xp, Pp = _predict(tracks.x[live], tracks.P[live], dt, accel_sigma)
        p, cov = geom.p_ecef[step], geom.cov[step]
        ti, pj = _match_scan(tracks, live, xp, Pp, sen, p, cov, trace[step], gate, assigner)
        missed = np.ones(live.size, dtype=bool)
        fresh = np.ones(step.size, dtype=bool)
        if ti.size:
            at = np.searchsorted(live, ti)
            _update(tracks, ti, xp[at], Pp[at], p[pj], cov[pj], time[step[pj]])
            track[step[pj]] = tracks.id[ti]
            missed[at] = False
            fresh[pj] = False
        tracks.missed[live[missed]] += 1
        track[step[fresh]] = tracks.open(sen[fresh], p[fresh], cov[fresh], time[step[fresh]], max_speed)
        tracks.keep(tracks.missed <= max_missed)
    return track


def track_breaks(
    time: np.ndarray,
    track: np.ndarray,
    geom: PlotGeometry,
    *,
    max_speed: float,
    accel_sigma: float,
    probability: float,
) -> tuple[np.ndarray, np.ndarray]:
    """Where given tracks jump: each track (``track`` (M,) key per plot, ``time`` (M,) s, the plots'
    geometry ``geom`` rows in the same order) is followed by the constant-velocity filter of
    :func:`sensor_tracks`, and a plot outside the ``1 - probability`` gate (chi-square, 3 degrees
    of freedom) of the prediction starts a new piece, the filter starting again there. Returns
    ((M,) bool: the plot starts a new piece after a jump, (M,) its squared distance, 0 elsewhere).
    The tracks advance together, the k-th plot of every track in one step."""
    gate = float(chi2_ppf(1.0 - probability, 3))
    order = np.lexsort((time, track))
    key = track[order]
    first = np.r_[True, key[1:] != key[:-1]]
    start = np.flatnonzero(first)
    k = np.arange(order.size) - np.repeat(start, np.diff(np.r_[start, order.size]))
    n_tracks = start.size
    x, P, t_last = np.zeros((n_tracks, 6)), np.zeros((n_tracks, 6, 6)), np.zeros(n_tracks)
    which = np.cumsum(first) - 1
    breaks, dist = np.zeros(order.size, dtype=bool), np.zeros(order.size)
    by_step = np.argsort(k, kind="stable")
    bounds = np.flatnonzero(np.r_[True, np.diff(k[by_step]) != 0, True])
    for a, b in zip(bounds[:-1], bounds[1:]):
        at = by_step[a:b]  # positions in ``order`` of the k-th plot of each track that has one
        tr, plot = which[at], order[at]
        p, cov = geom.p_ecef[plot], geom.cov[plot]
        restart = np.ones(at.size, dtype=bool) if k[at[0]] == 0 else np.zeros(at.size, dtype=bool)
        if k[at[0]] > 0:
            xp, Pp = _predict(x[tr], P[tr], time[plot] - t_last[tr], accel_sigma)
            d2, _logdet = _gate(xp, Pp, p, cov)
            restart = d2 > gate
            breaks[at[restart]], dist[at] = True, d2
            ok = ~restart
            x[tr[ok]], P[tr[ok]] = _filtered(xp[ok], Pp[ok], p[ok], cov[ok])
        x[tr[restart]], P[tr[restart]] = _started(p[restart], cov[restart], max_speed)
        t_last[tr] = time[plot]
    out_b, out_d = np.zeros(order.size, dtype=bool), np.zeros(order.size)
    out_b[order], out_d[order] = breaks, dist
    return out_b, out_d
