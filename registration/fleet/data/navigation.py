"""Platform navigation at the plot times: checks of the navigation table and interpolation.

Rows of platforms that carry no sensor are ignored (:func:`unused_platforms` names them: a real
navigation export carries every ship). A platform with one navigation row is a fixed site: that
row holds at every time. Otherwise the rows (strictly increasing times) are interpolated linearly
to each plot time, longitude and heading unwrapped first and wrapped back to (-pi, pi] after. A
plot outside its platform's navigation time span is an error: extrapolating a ship's attitude is
not done.

Linear interpolation of a rolling ship's attitude errs by at most ``h^2 w^2 A / 8`` (step h s,
roll amplitude A rad, angular frequency w rad/s): 0.002 deg for 5 deg at a 12 s period sampled at
10 Hz, 0.2 deg sampled at 1 Hz. Give navigation at least as fast as the ship moves.
"""

from __future__ import annotations

import numpy as np

from registration.core.angles import wrap_angle
from registration.core.validation import TIME_LIMIT_S, check_range
from registration.fleet.data.tables import NAV_COLUMNS, Table

__all__ = [
    "NAV_LIMITS",
    "SeenNavigation",
    "catmull_rom_slopes",
    "hermite_cubics",
    "platform_navigation",
    "unused_platforms",
    "navigation_at",
    "navigation_rate_at",
    "outside_navigation",
]

#: Accepted window (low, high, unit) of each navigation column.
NAV_LIMITS = {
    "lat": (-np.pi / 2, np.pi / 2, "rad (latitude)"),
    "lon": (-2 * np.pi, 2 * np.pi, "rad"),
    "alt": (-1.2e4, 1.0e6, "m above the WGS-84 ellipsoid"),
    "heading": (-2 * np.pi, 2 * np.pi, "rad"),
    "pitch": (-np.pi / 2, np.pi / 2, "rad"),
    "roll": (-np.pi / 2, np.pi / 2, "rad"),
}
_UNWRAP = ("lon", "heading")


def unused_platforms(nav: Table, platform_ids) -> list[str]:
    """Notes naming the platforms of the navigation table that are not in ``platform_ids`` (they
    carry no sensor): :func:`platform_navigation` ignores their rows."""
    ids = nav.ids("platform")
    unknown = ~np.isin(ids, list(platform_ids))
    if not unknown.any():
        return []
    return [
        f"navigation: platform(s) {sorted(np.unique(ids[unknown]).tolist())} carry no sensor; their "
        f"{int(unknown.sum())} rows are ignored (platforms used: {list(platform_ids)})"
    ]


def platform_navigation(nav: Table, platform_ids) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Per platform id of ``platform_ids``: (times (K,), values (K, 6) in NAV_COLUMNS order, angles
    unwrapped). Rows of other platforms are ignored (:func:`unused_platforms` names them).

    ValueError for a platform with no navigation, values out of range, or times that are not
    finite and strictly increasing.
    """
    ids = nav.ids("platform")
    used = np.isin(ids, list(platform_ids))
    values = np.stack([nav.floats(c) for c in NAV_COLUMNS], axis=1)
    for j, c in enumerate(NAV_COLUMNS):
        lo, hi, unit = NAV_LIMITS[c]
        check_range(
            f"navigation.{c}", np.where(used, values[:, j], 0.0), lo, hi, unit, angle=unit.startswith("rad")
        )
    time = nav.floats("time", default=np.nan)
    out = {}
    for pid in platform_ids:
        rows = np.flatnonzero(ids == pid)
        if rows.size == 0:
            raise ValueError(f"navigation: platform {str(pid)!r} has no navigation rows")
        t, v = time[rows], values[rows].copy()
        if rows.size > 1:
            bad = np.flatnonzero(~(np.abs(t) <= TIME_LIMIT_S) | ~np.append(np.diff(t) > 0, True))
            if bad.size:
                r = int(rows[bad[0]])
                raise nav.error(
                    r,
                    f"time {t[bad[0]]} s of platform {str(pid)!r} is not finite or the next row's "
                    f"time does not increase (times must be finite, within +-{TIME_LIMIT_S:g} s, and "
                    "strictly increasing)",
                )
            for c in _UNWRAP:
                j = NAV_COLUMNS.index(c)
                v[:, j] = np.unwrap(v[:, j])
        out[pid] = (t, v)
    return out


def outside_navigation(
    tracks: dict, platform_ids, plot_platform: np.ndarray, plot_time: np.ndarray
) -> np.ndarray:
    """(N,) bool: the plots whose time (s) lies outside their platform's navigation time span (a
    fixed site, one navigation row, holds at every time; a NaN time is not flagged)."""
    out = np.zeros(plot_time.shape[0], dtype=bool)
    for p, pid in enumerate(platform_ids):
        t = tracks[pid][0]
        sel = plot_platform == p
        if t.shape[0] > 1 and sel.any():
            out[sel] = (plot_time[sel] < t[0]) | (plot_time[sel] > t[-1])
    return out


def navigation_at(
    tracks: dict, platform_ids, plot_platform: np.ndarray, plot_time: np.ndarray, describe_row
) -> np.ndarray:
    """(N, 6) navigation of each plot's platform at its time (NAV_COLUMNS order, angles wrapped).

    ``describe_row(i)`` names plot i in errors (row, sensor, time).
    """
    out = np.empty((plot_time.shape[0], 6))
    outside_all = outside_navigation(tracks, platform_ids, plot_platform, plot_time)
    for pid, sel, t, v in _moving_platforms(tracks, platform_ids, plot_platform, out):
        outside = np.flatnonzero(outside_all[sel])
        if outside.size:
            i = int(sel[outside[0]])
            raise ValueError(
                f"{describe_row(i)} lies outside the navigation of platform {str(pid)!r} "
                f"({t[0]:g} s to {t[-1]:g} s); {outside.size} plot(s) do"
            )
        for j in range(6):
            out[sel, j] = np.interp(plot_time[sel], t, v[:, j])
    return _wrapped(out)


def _moving_platforms(tracks: dict, platform_ids, plot_platform: np.ndarray, out: np.ndarray):
    """Per platform with plots: (id, its plots' indices, navigation times, values) where it has
    several navigation rows; a fixed site's one row is written into ``out`` (N, 6) instead."""
    for p, pid in enumerate(platform_ids):
        sel = np.flatnonzero(plot_platform == p)
        if sel.size == 0:
            continue
        t, v = tracks[pid]
        if t.shape[0] == 1:
            out[sel] = v[0]
            continue
        yield pid, sel, t, v


def _wrapped(nav: np.ndarray) -> np.ndarray:
    """``nav`` (N, 6) with longitude and heading wrapped to (-pi, pi] in place."""
    for c in _UNWRAP:
        j = NAV_COLUMNS.index(c)
        nav[:, j] = wrap_angle(nav[:, j])
    return nav


def navigation_rate_at(
    tracks: dict, platform_ids, plot_platform: np.ndarray, plot_time: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(nav (N, 6), rate (N, 6), outside (N,) bool) of each plot's platform at times ``plot_time`` (s),
    by :class:`SeenNavigation` (its docstring)."""
    return SeenNavigation(tracks, platform_ids, plot_platform, plot_platform, plot_time)(plot_time)


def catmull_rom_slopes(t: np.ndarray, v: np.ndarray) -> np.ndarray:
    """(K, m) slopes of samples ``v`` (K, m) at strictly increasing times ``t`` (K,): the centred
    difference (v[k+1] - v[k-1]) / (t[k+1] - t[k-1]), one-sided at the ends."""
    return (
        np.gradient(v, t, axis=0, edge_order=1)
        if t.size > 2
        else np.repeat((v[1:] - v[:1]) / (t[1] - t[0]), 2, 0)
    )


def hermite_cubics(t: np.ndarray, v: np.ndarray) -> np.ndarray:
    """(K - 1, 4, m) coefficients of each segment's cubic in s = (t - t_k) / (t_{k+1} - t_k) of the
    cubic Hermite curve through samples ``v`` (K, m) with :func:`catmull_rom_slopes`."""
    h = np.diff(t)[:, None]
    m = catmull_rom_slopes(t, v)
    v0, v1, m0, m1 = v[:-1], v[1:], h * m[:-1], h * m[1:]
    return np.stack([v0, m0, -3 * v0 - 2 * m0 + 3 * v1 - m1, 2 * v0 + m0 - 2 * v1 + m1], axis=1)


class SeenNavigation:
    """The navigation of fixed rows (platform, sensor, reported time) at times that move with
    the time-bias estimates: ``seen(time)`` -> (nav (rows, 6), rate (rows, 6), outside (rows,)).

    The time is an estimated quantity here, so the navigation is interpolated by a C1 cubic
    Hermite curve through the samples (Catmull-Rom slopes: the centred difference of the
    neighbouring samples, one-sided at the ends), whose value and rate (rad/s, m/s) are continuous
    in the time. Linear interpolation would kink the cost at every navigation sample and stall the
    solver there; between samples the two differ by the interpolation error of the navigation
    (about 0.002 deg of roll at 10 Hz, module docstring). The rows of one sensor at one reported
    time are seen at one time under any estimate, so each distinct (sensor, reported time)
    instant is interpolated once; each track's segment cubics are built once. Angles are wrapped.
    A time outside the platform's navigation span takes the nearest end's values (zero rate) and
    is flagged in ``outside``; a fixed site has zero rate.
    """

    def __init__(
        self,
        tracks: dict,
        platform_ids,
        row_platform: np.ndarray,
        row_sensor: np.ndarray,
        row_time: np.ndarray,
    ):
        order = np.lexsort((row_time, row_sensor))
        new = np.r_[True, (np.diff(row_sensor[order]) != 0) | (np.diff(row_time[order]) != 0)]
        self.first = order[new]  # one row per instant
        self.inverse = np.empty(order.size, dtype=np.int64)
        self.inverse[order] = np.cumsum(new) - 1
        platform = row_platform[self.first]
        self.parts = []
        for p, pid in enumerate(platform_ids):
            sel = np.flatnonzero(platform == p)
            if sel.size == 0:
                continue
            t, v = tracks[pid]
            if t.shape[0] == 1:
                self.parts.append((sel, None, v[0], None))
            else:
                self.parts.append((sel, t, hermite_cubics(t, v), 1.0 / np.diff(t)))

    def __call__(self, time: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        tu = time[self.first]
        n = tu.shape[0]
        nav, rate, outside = np.empty((6, n)), np.zeros((n, 6)), np.zeros(n, dtype=bool)
        for sel, t, cubic, inv_h in self.parts:
            if t is None:  # a fixed site
                nav[:, sel] = cubic[:, None]
                continue
            ts = tu[sel]
            out = (ts < t[0]) | (ts > t[-1])
            tp = np.clip(ts, t[0], t[-1])
            k = np.clip(np.searchsorted(t, tp, side="right") - 1, 0, t.shape[0] - 2)
            c = cubic[k]
            s = ((tp - t[k]) * inv_h[k])[:, None]
            nav[:, sel] = (c[:, 0] + s * (c[:, 1] + s * (c[:, 2] + s * c[:, 3]))).T
            r = (c[:, 1] + s * (2.0 * c[:, 2] + 3.0 * s * c[:, 3])) * inv_h[k][:, None]
            r[out] = 0.0
            rate[sel], outside[sel] = r, out
        for c in _UNWRAP:
            j = NAV_COLUMNS.index(c)
            nav[j] = wrap_angle(nav[j])
        inv = self.inverse
        return np.take(nav, inv, axis=1).T, rate[inv], outside[inv]  # nav columns contiguous for the C call
