"""First association stage: tracks per sensor, one sensor at a time, in ECEF.

A sensor's biases and its platform's attitude errors are the same for every plot it makes, so
linking one sensor's plots over time does not need the registration: it is done once, at the
starting estimate. Each sensor's plots are grouped in scans (plots at the same time) and each scan
is assigned to the sensor's open tracks by :class:`~registration.fleet.association_geometry.Assigner`
(cost: negative log-likelihood of the plot given the track's prediction; gate at the
``gate_probability`` quantile of chi-square with 3 degrees of freedom; a plot left over opens a
track). A track is a constant-velocity Kalman filter on the plot positions (process noise: white
acceleration of ``accel_sigma`` m/s^2; a new track's velocity has sigma ``max_speed``), closed after
``max_missed`` scans in a row without a plot. Tracks with fewer than ``min_plots`` plots are clutter.
All sensors advance together, scan k of every sensor in one step, so the filter arithmetic is
batched over the sensors' tracks.
"""

from __future__ import annotations

import numpy as np
from scipy.stats import chi2

from registration.fleet.association_geometry import Assigner, PlotGeometry

__all__ = ["sensor_tracks"]


def _scan_steps(time: np.ndarray, sensor: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
    """Per step k: (plot indices, their sensor) of scan k of every sensor, sorted by sensor."""
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
    bounds = np.flatnonzero(np.r_[True, ks[1:] != ks[:-1], True])
    return [(idx[a:b], sensor[idx[a:b]]) for a, b in zip(bounds[:-1], bounds[1:])]


def _predict(x: np.ndarray, P: np.ndarray, dt: np.ndarray, q: float) -> tuple[np.ndarray, np.ndarray]:
    """Constant-velocity prediction of states (K, 6) and covariances (K, 6, 6) by dt (K,) s."""
    n = dt.size
    F = np.tile(np.eye(6), (n, 1, 1))
    F[:, :3, 3:] = dt[:, None, None] * np.eye(3)
    Q = np.zeros((n, 6, 6))
    Q[:, :3, :3] = (q**2 * dt**3 / 3)[:, None, None] * np.eye(3)
    Q[:, :3, 3:] = Q[:, 3:, :3] = (q**2 * dt**2 / 2)[:, None, None] * np.eye(3)
    Q[:, 3:, 3:] = (q**2 * dt)[:, None, None] * np.eye(3)
    x = x.copy()
    x[:, :3] += dt[:, None] * x[:, 3:]
    return x, F @ P @ np.swapaxes(F, 1, 2) + Q


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
        for name in ("sensor", "id", "x", "P", "t", "missed"):
            setattr(self, name, getattr(self, name)[sel])

    def open(self, sensor: np.ndarray, z: np.ndarray, R: np.ndarray, t: np.ndarray, max_speed: float) -> np.ndarray:
        n = sensor.size
        ids = self.next_id + np.arange(n)
        self.next_id += n
        P = np.zeros((n, 6, 6))
        P[:, :3, :3] = R
        P[:, 3:, 3:] = max_speed**2 * np.eye(3)
        self.sensor = np.r_[self.sensor, sensor]
        self.id = np.r_[self.id, ids]
        self.x = np.concatenate([self.x, np.concatenate([z, np.zeros((n, 3))], axis=1)])
        self.P = np.concatenate([self.P, P])
        self.t = np.r_[self.t, t]
        self.missed = np.r_[self.missed, np.zeros(n, dtype=np.int64)]
        return ids


def _match_scan(tracks: _Tracks, live: np.ndarray, xp, Pp, idx, sen, geom: PlotGeometry, gate: float,
                assigner: Assigner) -> tuple[np.ndarray, np.ndarray]:
    """Pairs (track index into ``tracks``, plot index into ``idx``) of one step: one assignment
    over all sensors, tracks and plots of different sensors never paired (``sen`` is sorted)."""
    ts = tracks.sensor[live]
    lo, hi = np.searchsorted(sen, ts, side="left"), np.searchsorted(sen, ts, side="right")
    n = hi - lo
    ki = np.repeat(np.arange(live.size), n)
    pj = np.repeat(lo, n) + np.arange(ki.size) - np.repeat(np.cumsum(n) - n, n)
    v = geom.p_ecef[idx[pj]] - xp[ki, :3]
    # d2 >= |v|^2 / trace(S): pairs beyond the gate by this bound need no solve
    trace = np.trace(Pp[:, :3, :3], axis1=1, axis2=2)[ki] + np.trace(geom.cov[idx[pj]], axis1=1, axis2=2)
    near = np.einsum("ki,ki->k", v, v) < gate * trace
    ki, pj, v = ki[near], pj[near], v[near]
    if ki.size == 0:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    S = Pp[ki, :3, :3] + geom.cov[idx[pj]]
    d2 = np.einsum("ki,ki->k", v, np.linalg.solve(S, v[..., None])[..., 0])
    logdet = np.linalg.slogdet(S)[1]
    cost = np.full((live.size, idx.size), np.inf)
    cost[ki, pj] = np.where(d2 < gate, 0.5 * (d2 + logdet), np.inf)
    best = np.full(live.size, np.inf)
    np.minimum.at(best, ki, logdet)
    rows = np.unique(ki)
    col = assigner.assign(cost[rows], 0.5 * (gate + best[rows]))
    ok = col >= 0
    return live[rows[ok]], col[ok]


def _update(tracks: _Tracks, ti: np.ndarray, xp, Pp, z: np.ndarray, R: np.ndarray, t: np.ndarray) -> None:
    """Kalman update of tracks ``ti`` (their predictions xp, Pp) with plot positions z (m), R (m^2)."""
    S = Pp[:, :3, :3] + R
    K = np.swapaxes(np.linalg.solve(S, np.swapaxes(Pp[:, :, :3], 1, 2)), 1, 2)  # (n, 6, 3)
    x = xp + (K @ (z - xp[:, :3])[..., None])[..., 0]
    P = Pp - K @ Pp[:, :3, :]
    tracks.x[ti] = x
    tracks.P[ti] = 0.5 * (P + np.swapaxes(P, 1, 2))
    tracks.t[ti] = t
    tracks.missed[ti] = 0


def sensor_tracks(time: np.ndarray, sensor: np.ndarray, geom: PlotGeometry, assigner: Assigner, *,
                  max_speed: float, accel_sigma: float, gate_probability: float, max_missed: int,
                  min_plots: int) -> np.ndarray:
    """(N,) track id of each plot (ids unique over all sensors), -1 for plots in no track of at
    least ``min_plots`` plots (clutter). ``time`` (N,) s, ``sensor`` (N,) sensor index."""
    gate = float(chi2.ppf(gate_probability, 3))
    track = np.full(time.size, -1, dtype=np.int64)
    tracks = _Tracks()
    for idx, sen in _scan_steps(time, sensor):
        stepping = np.isin(tracks.sensor, sen)
        live = np.flatnonzero(stepping)
        scan_time = np.zeros(int(sensor.max()) + 1)
        scan_time[sen] = time[idx]
        dt = scan_time[tracks.sensor[live]] - tracks.t[live]
        xp, Pp = _predict(tracks.x[live], tracks.P[live], dt, accel_sigma)
        ti, pj = _match_scan(tracks, live, xp, Pp, idx, sen, geom, gate, assigner)
        if ti.size:
            a = np.searchsorted(live, ti)
            _update(tracks, ti, xp[a], Pp[a], geom.p_ecef[idx[pj]], geom.cov[idx[pj]], time[idx[pj]])
            track[idx[pj]] = tracks.id[ti]
        missed = np.setdiff1d(live, ti)
        tracks.missed[missed] += 1
        fresh = np.setdiff1d(np.arange(idx.size), pj)
        track[idx[fresh]] = tracks.open(sen[fresh], geom.p_ecef[idx[fresh]], geom.cov[idx[fresh]], time[idx[fresh]],
                                        max_speed)
        tracks.keep(tracks.missed <= max_missed)
    ids, counts = np.unique(track, return_counts=True)
    track[np.isin(track, ids[counts < min_plots])] = -1
    return track
