"""First association stage: tracks per sensor, one sensor at a time, in ECEF.

A sensor's biases and its platform's attitude errors are the same for every plot it makes, so
linking one sensor's plots over time does not need the registration: it is done once, at the
starting estimate. Each sensor's plots are grouped in scans (plots at the same time) and each scan
is assigned to the sensor's open tracks by :class:`~registration.fleet.association.grouping.geometry.Assigner`
(cost: negative log-likelihood of the plot given the track's prediction; gate at the
``gate_probability`` quantile of chi-square with 3 degrees of freedom; a plot left over opens a
track). A track is a constant-velocity Kalman filter on the plot positions (process noise: white
acceleration of ``accel_sigma`` m/s^2; a new track's velocity has sigma ``max_speed``), closed after
``max_missed`` scans in a row without a plot. Tracks with fewer than ``min_plots`` plots are clutter.
All sensors advance together, scan k of every sensor in one step, so the filter arithmetic is
batched over the sensors' tracks (3x3 Cholesky factors written out). A track and a plot that are
each other's only candidate in the gate are paired, or not, without the assignment: an isolated
pair is its own optimum, so the result is that of one assignment over the whole step.
"""

from __future__ import annotations

import numpy as np

from registration.core.distributions import chi2_ppf
from registration.fleet.association.grouping.geometry import Assigner, PlotGeometry

__all__ = ["sensor_tracks", "track_breaks"]


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
    """Constant-velocity prediction of states (K, 6) and covariances (K, 6, 6, symmetric) by dt (K,) s
    (F P F^T + Q written out by blocks: position, velocity)."""
    d = dt[:, None, None]
    eye = np.eye(3)
    P11, P12, P22 = P[:, :3, :3], P[:, :3, 3:], P[:, 3:, 3:]
    out = np.empty_like(P)
    out[:, :3, :3] = P11 + d * (P12 + np.swapaxes(P12, 1, 2)) + d * d * P22 + (q * q * d**3 / 3) * eye
    out[:, :3, 3:] = P12 + d * P22 + (q * q * d * d / 2) * eye
    out[:, 3:, :3] = np.swapaxes(out[:, :3, 3:], 1, 2)
    out[:, 3:, 3:] = P22 + (q * q * d) * eye
    x = x.copy()
    x[:, :3] += dt[:, None] * x[:, 3:]
    return x, out


def _cholesky3(S: np.ndarray) -> tuple[np.ndarray, ...]:
    """Cholesky factors (l00, l10, l20, l11, l21, l22), each (K,), of symmetric positive definite
    3x3 matrices S (K, 3, 3), written out (batched numpy linalg costs more for 3x3)."""
    l00 = np.sqrt(S[:, 0, 0])
    l10, l20 = S[:, 1, 0] / l00, S[:, 2, 0] / l00
    l11 = np.sqrt(S[:, 1, 1] - l10 * l10)
    l21 = (S[:, 2, 1] - l20 * l10) / l11
    l22 = np.sqrt(S[:, 2, 2] - l20 * l20 - l21 * l21)
    return l00, l10, l20, l11, l21, l22


def _forward3(L: tuple[np.ndarray, ...], b: np.ndarray) -> np.ndarray:
    """y = L^-1 b for the factors L of :func:`_cholesky3` and b (K, 3) or (K, 3, m)."""
    l00, l10, l20, l11, l21, l22 = (v.reshape(v.shape + (1,) * (b.ndim - 2)) for v in L)
    y0 = b[:, 0] / l00
    y1 = (b[:, 1] - l10 * y0) / l11
    y2 = (b[:, 2] - l20 * y0 - l21 * y1) / l22
    return np.stack([y0, y1, y2], axis=1)


def _solve3(L: tuple[np.ndarray, ...], b: np.ndarray) -> np.ndarray:
    """S^-1 b for S = L L^T (factors of :func:`_cholesky3`) and b (K, 3, m)."""
    y = _forward3(L, b)
    l00, l10, l20, l11, l21, l22 = (v[:, None] for v in L)
    x2 = y[:, 2] / l22
    x1 = (y[:, 1] - l21 * x2) / l11
    x0 = (y[:, 0] - l10 * x1 - l20 * x2) / l00
    return np.stack([x0, x1, x2], axis=1)


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
        P = np.zeros((n, 6, 6))
        P[:, :3, :3] = R
        P[:, 3:, 3:] = max_speed**2 * np.eye(3)
        # np.concatenate, not np.r_ (ten times its cost, once a scan step)
        self.sensor = np.concatenate([self.sensor, sensor])
        self.id = np.concatenate([self.id, ids])
        self.x = np.concatenate([self.x, np.concatenate([z, np.zeros((n, 3))], axis=1)])
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
    near = np.einsum("ki,ki->k", v, v) < gate * bound
    ki, pj, v = ki[near], pj[near], v[near]
    if ki.size == 0:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    L = _cholesky3(np.ascontiguousarray(Pp[:, :3, :3])[ki] + cov[pj])
    y = _forward3(L, v)
    d2 = np.einsum("ki,ki->k", y, y)
    logdet = 2.0 * np.log(L[0] * L[3] * L[5])
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
    L = _cholesky3(Pp[:, :3, :3] + R)
    Kt = _solve3(L, Pp[:, :3, :])  # K^T = S^-1 H P (3, 6)
    K = np.swapaxes(Kt, 1, 2)
    x = xp + (K @ (z - xp[:, :3])[..., None])[..., 0]
    P = Pp - K @ Pp[:, :3, :]
    tracks.x[ti] = x
    tracks.P[ti] = 0.5 * (P + np.swapaxes(P, 1, 2))
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
) -> np.ndarray:
    """(N,) track id of each plot (ids unique over all sensors), -1 for plots in no track of at
    least ``min_plots`` plots (clutter). ``time`` (N,) s, ``sensor`` (N,) sensor index."""
    gate = float(chi2_ppf(gate_probability, 3))
    track = np.full(time.size, -1, dtype=np.int64)
    tracks = _Tracks()
    n_sensors = int(sensor.max()) + 1
    scan_time = np.zeros(n_sensors)
    trace = np.trace(geom.cov, axis1=1, axis2=2)
    for idx, sen in _scan_steps(time, sensor):
        stepping = np.zeros(n_sensors, dtype=bool)
        stepping[sen] = True
        live = np.flatnonzero(stepping[tracks.sensor])
        scan_time[sen] = time[idx]
        dt = scan_time[tracks.sensor[live]] - tracks.t[live]
        xp, Pp = _predict(tracks.x[live], tracks.P[live], dt, accel_sigma)
        p, cov = geom.p_ecef[idx], geom.cov[idx]
        ti, pj = _match_scan(tracks, live, xp, Pp, sen, p, cov, trace[idx], gate, assigner)
        missed = np.ones(live.size, dtype=bool)
        fresh = np.ones(idx.size, dtype=bool)
        if ti.size:
            a = np.searchsorted(live, ti)
            _update(tracks, ti, xp[a], Pp[a], p[pj], cov[pj], time[idx[pj]])
            track[idx[pj]] = tracks.id[ti]
            missed[a] = False
            fresh[pj] = False
        tracks.missed[live[missed]] += 1
        track[idx[fresh]] = tracks.open(sen[fresh], p[fresh], cov[fresh], time[idx[fresh]], max_speed)
        tracks.keep(tracks.missed <= max_missed)
    ids, counts = np.unique(track, return_counts=True)
    track[np.isin(track, ids[counts < min_plots])] = -1
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
            L = _cholesky3(Pp[:, :3, :3] + cov)
            y = _forward3(L, p - xp[:, :3])
            d2 = np.einsum("ki,ki->k", y, y)
            restart = d2 > gate
            breaks[at[restart]], dist[at] = True, d2
            ok = ~restart
            Kt = _solve3(tuple(v[ok] for v in L), Pp[ok][:, :3, :])
            K = np.swapaxes(Kt, 1, 2)
            x[tr[ok]] = xp[ok] + (K @ (p[ok] - xp[ok, :3])[..., None])[..., 0]
            Pn = Pp[ok] - K @ Pp[ok][:, :3, :]
            P[tr[ok]] = 0.5 * (Pn + np.swapaxes(Pn, 1, 2))
        fresh = tr[restart]
        x[fresh] = np.concatenate([p[restart], np.zeros((fresh.size, 3))], axis=1)
        P[fresh] = 0.0
        P[fresh, :3, :3] = cov[restart]
        P[fresh, 3:, 3:] = max_speed**2 * np.eye(3)
        t_last[tr] = time[plot]
    out_b, out_d = np.zeros(order.size, dtype=bool), np.zeros(order.size)
    out_b[order], out_d[order] = breaks, dist
    return out_b, out_d
