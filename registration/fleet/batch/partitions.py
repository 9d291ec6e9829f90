"""The fleet tables in memory as a partition source (:class:`TablesSource`) of the partitioned batch
solver: what a source gives is described in :mod:`registration.fleet.batch.partitioned.plan`.
"""

from __future__ import annotations

import uuid

import numpy as np

__all__ = ["TablesSource"]


def _columns(table) -> dict | None:
    """A DataFrame or a mapping of columns as a dict of numpy arrays (None stays None)."""
    if table is None:
        return None
    if hasattr(table, "columns") and hasattr(table, "to_dict"):
        return {str(c): table[c].to_numpy() for c in table.columns}
    return {str(k): np.asarray(v) for k, v in table.items()}


def _rows(table: dict, keep: np.ndarray) -> dict:
    return {k: v[keep] for k, v in table.items()}


class TablesSource:
    """The fleet tables in memory (:mod:`registration.fleet.data.tables`: SI units, radians) as a
    partition source (module docstring); ``batch_rows``: rows per batch of the first passes."""

    in_memory = True

    def __init__(
        self,
        plots,
        sensors,
        navigation,
        platforms=None,
        references=None,
        batch_rows: int = 1_000_000,
        targets=None,
    ):
        self.plots, self.navigation = _columns(plots), _columns(navigation)
        self.sensors, self.platforms, self.references = (
            _columns(sensors),
            _columns(platforms),
            _columns(references),
        )
        self.targets = _columns(targets)  # the surface targets (read whole: a row per target)
        self.batch_rows = int(batch_rows)
        self.token = uuid.uuid4().hex

    @staticmethod
    def name(table: str) -> str:
        return table

    def _batches(self, table: dict | None, columns):
        if table is None:
            return
        n = len(next(iter(table.values())))
        for a in range(0, n, self.batch_rows):
            yield {c: table[c][a : a + self.batch_rows] for c in columns}

    def plot_batches(self, columns):
        return self._batches(self.plots, columns)

    def navigation_batches(self, columns):
        return self._batches(self.navigation, columns)

    def reference_batches(self, columns):
        return self._batches(self.references, columns)

    def read_plots(self, lo: float, hi: float) -> dict:
        t = np.asarray(self.plots["time"], dtype=np.float64)
        return _rows(self.plots, (t >= lo) & (t <= hi))

    def read_references(self, lo: float, hi: float) -> dict | None:
        if self.references is None:
            return None
        t = np.asarray(self.references["time"], dtype=np.float64)
        return _rows(self.references, (t >= lo) & (t <= hi))

    def read_navigation(self, ranges: dict) -> dict:
        pid = np.asarray(self.navigation["platform"]).astype(str)
        t = np.asarray(self.navigation["time"], dtype=np.float64)
        keep = np.zeros(t.size, dtype=bool)
        for p, (a, b) in ranges.items():
            keep |= (pid == p) & (t >= a) & (t <= b)
        return _rows(self.navigation, keep)
