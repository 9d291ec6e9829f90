"""What a live feed adds to the online fleet filter while the plots stream (:class:`LiveInputs`, a
part of :class:`~registration.fleet.online.filter.FleetFilter`): a moving platform's navigation
and the targets that move on a surface (ships, from AIS), as they arrive.

A platform given with one navigation row (a fixed site, or a ship whose navigation has not come
yet) has that row replaced by the first rows added for it; later rows are appended after its last
time, their longitude and heading unwrapped to continue the track. A plot outside its platform's
navigation span is refused by :meth:`~registration.fleet.online.filter.FleetFilter.update`:
:meth:`LiveInputs.outside_navigation` finds those first.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from registration.fleet.data.known_targets import SurfaceTargets, read_surface
from registration.fleet.data.navigation import outside_navigation, platform_navigation
from registration.fleet.data.tables import NAV_COLUMNS, index_of, read_table

__all__ = ["LiveInputs"]

_UNWRAPPED = tuple(NAV_COLUMNS.index(c) for c in ("lon", "heading"))


class LiveInputs:
    """:meth:`add_navigation`, :meth:`add_surface`, :meth:`outside_navigation` and
    :meth:`forget_navigation` of the filter (its attributes are the filter's)."""

    tracks: dict
    platform_ids: Any
    specs: Any
    surface: SurfaceTargets | None

    def add_navigation(self, navigation) -> int:
        """Add navigation rows (the navigation table of :func:`registration.fleet.build_problem`,
        SI) of platforms of the filter (module docstring); rows of other platforms and rows not
        after a platform's last time are ignored. Returns the rows added. ValueError naming the row
        for values out of range or times not strictly increasing."""
        table = read_table("navigation", navigation, ("platform",))
        present = [p for p in self.platform_ids if p in set(table.ids("platform").tolist())]
        added = 0
        for pid, (t, v) in platform_navigation(table, present).items():
            t_old, v_old = self.tracks[pid]
            if t_old.size > 1:
                after = t > t_old[-1]
                t, v = t[after], v[after]
                if t.size == 0:
                    continue
                for j in _UNWRAPPED:
                    v[:, j] += 2 * np.pi * np.round((v_old[-1, j] - v[0, j]) / (2 * np.pi))
                t, v = np.concatenate([t_old, t]), np.concatenate([v_old, v])
            added += int(t.size - (t_old.size if t_old.size > 1 else 0))
            self.tracks[pid] = (t, v)
        return added

    def forget_navigation(self, before_s: float) -> None:
        """Drop the navigation rows of moving platforms before ``before_s`` (s), keeping the row
        before it (so that a time from ``before_s`` on is still interpolated)."""
        for pid, (t, v) in self.tracks.items():
            if t.size > 2:
                first = max(int(np.searchsorted(t, before_s, side="right")) - 1, 0)
                first = min(first, t.size - 2)
                self.tracks[pid] = (t[first:], v[first:])

    def outside_navigation(self, sensor_ids: np.ndarray, time: np.ndarray) -> np.ndarray:
        """(N,) bool: the plots (sensor ids, times s) outside their platform's navigation span."""
        time = np.asarray(time, dtype=np.float64)
        if all(t.size == 1 for t, _ in self.tracks.values()):  # fixed sites only
            return np.zeros(time.shape, dtype=bool)
        sensor = index_of(np.asarray(sensor_ids).astype(str), list(self.specs.ids))
        platform = np.where(sensor >= 0, np.asarray(self.specs.platform)[np.maximum(sensor, 0)], -1)
        return outside_navigation(self.tracks, self.platform_ids, platform, time)

    def add_surface(self, targets) -> int:
        """Add surface targets (the targets table of :func:`registration.fleet.build_problem`: target,
        surface_alt, sigma_surface) not known yet; returns how many were added."""
        new = read_surface(targets)
        if new is None:
            return 0
        old = self.surface
        if old is None:
            self.surface = new
            return int(new.target.size)
        fresh = ~np.isin(new.target.astype(str), old.target.astype(str))
        if fresh.any():
            self.surface = SurfaceTargets(
                np.concatenate([old.target, new.target[fresh]]),
                np.concatenate([old.alt, new.alt[fresh]]),
                np.concatenate([old.sigma, new.sigma[fresh]]),
            )
        return int(fresh.sum())
