"""The points the plots of a recorded-data run are drawn from, kept while the filter streams.

:class:`PlotSeries` keeps the registered rows whose ordinal ``k`` (0 for the first registered row)
is a multiple of ``step``, a power of two that doubles, dropping every other kept row, whenever
more than ``cap`` rows would be kept. Which rows are kept therefore depends only on how many
rows were registered (:func:`plot_step`), not on the block sizes, so a run resumed from a
checkpoint (which does not carry the series) selects the same rows again from its outputs.
Memory: at most ``cap`` rows of :data:`SERIES_FIELDS` (some 40 doubles each).
"""

from __future__ import annotations

import numpy as np

from registration.online.contract import SENSOR_COLUMNS, SENSOR_ROW

__all__ = ["PlotSeries", "plot_step", "PLOT_POINTS", "SERIES_FIELDS", "NAV_SLOTS"]

#: Most registered rows a plot shows (every 2^j-th row of a longer run).
PLOT_POINTS = 4000

#: name -> columns per row: time (s), estimates x and their 1 sigma (rad or m), ECEF differences
#: before/after and the corrected target from radar A and B (m), ships' latitude/longitude (deg)
SERIES_FIELDS = {
    "time": 1,
    "x": 12,
    "sigma": 12,
    "raw_diff": 3,
    "corrected_diff": 3,
    "a_ecef": 3,
    "b_ecef": 3,
    "nav_deg": 4,
}
#: the columns of an 18-value contract row that hold a_lat, a_lon, b_lat, b_lon (rad)
NAV_SLOTS = [SENSOR_ROW[s].start + SENSOR_COLUMNS.index(k) for s in ("a", "b") for k in ("lat", "lon")]


def plot_step(n: int, cap: int) -> int:
    """The smallest power of two ``step`` with ceil(n / step) <= cap: keep ordinals k % step == 0."""
    step = 1
    while -(-n // step) > cap:
        step *= 2
    return step


class PlotSeries:
    """Every ``step``-th registered row's values for the plots, at most ``cap`` rows."""

    def __init__(self, cap: int):
        self.cap, self.step, self.n = int(cap), 1, 0
        self._parts: dict[str, list] = {k: [] for k in [*SERIES_FIELDS, "_k"]}  # "_k": the kept ordinals

    def add(self, time, x, P, raw_diff, corrected_diff, a_ecef, b_ecef, rows) -> None:
        """Take in one run of K registered rows: times (s), estimates x (K, 12) and covariances P
        (K, 12, 12) in SI units/radians, ECEF differences before/after and corrected targets
        (K, 3) in m, and the (K, 18) contract rows they came from (for the ships' positions)."""
        k = len(time)
        ordinals = np.arange(self.n, self.n + k)
        keep = ordinals % self.step == 0
        kept = {
            "time": time[keep],
            "x": x[keep],
            "sigma": np.sqrt(np.einsum("kii->ki", P[keep])),
            "raw_diff": raw_diff[keep],
            "corrected_diff": corrected_diff[keep],
            "a_ecef": a_ecef[keep],
            "b_ecef": b_ecef[keep],
            "nav_deg": np.degrees(rows[keep][:, NAV_SLOTS]),
            "_k": ordinals[keep],
        }
        for name, values in kept.items():
            self._parts[name].append(np.array(values, dtype=float if name != "_k" else np.int64))
        self.n += k
        if -(-self.n // self.step) > self.cap:
            self._thin()

    def _thin(self) -> None:
        data = {name: np.concatenate(parts) for name, parts in self._parts.items()}
        self.step = plot_step(self.n, self.cap)
        keep = data["_k"] % self.step == 0
        self._parts = {name: [arr[keep]] for name, arr in data.items()}

    def arrays(self) -> dict[str, np.ndarray]:
        """The kept rows: one (M, width) array per :data:`SERIES_FIELDS` name (``time``: (M,))."""
        out = {
            name: np.concatenate(self._parts[name]) if self._parts[name] else np.empty((0, w))
            for name, w in SERIES_FIELDS.items()
        }
        out["time"] = out["time"].reshape(-1)
        return out
