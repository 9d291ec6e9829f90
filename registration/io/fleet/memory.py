"""Fleet tables in memory as a :class:`~registration.fleet.data.source.FleetSource`:
:class:`TablesSource`, the tables of :mod:`registration.fleet.data.tables` (SI units, radians) given
as pandas DataFrames or mappings of column -> array, for the partitioned solver
(:func:`registration.fleet.batch.partitioned.solve_batch_partitioned`). The tables read from checked
files, :class:`registration.io.fleet.reading.read.FleetTables`, are such a source too."""

from __future__ import annotations

import uuid
from typing import Iterable, Iterator, Mapping

import numpy as np

__all__ = ["TablesSource", "columns_of"]


def columns_of(table) -> dict:
    """A DataFrame or a mapping of columns as a dict of numpy arrays."""
    if hasattr(table, "columns") and hasattr(table, "to_dict"):
        return {str(c): table[c].to_numpy() for c in table.columns}
    return {str(k): np.asarray(v) for k, v in table.items()}


def _optional(table) -> dict | None:
    return None if table is None else columns_of(table)


def _rows(table: dict, keep: np.ndarray) -> dict:
    return {k: v[keep] for k, v in table.items()}


class TablesSource:
    """The fleet tables in memory (:mod:`registration.fleet.data.tables`: SI units, radians) as a
    :class:`~registration.fleet.data.source.FleetSource`; ``batch_rows``: rows per batch of the
    first passes. Errors call each table by its name (``plots``, ...)."""

    #: Tables in memory: the solver keeps every partition's design rather than spilling it.
    in_memory = True
    batch_rows = 1_000_000
    plots: dict
    navigation: dict
    sensors: dict
    platforms: dict | None
    references: dict | None
    targets: dict | None
    token: str

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
        self.plots, self.navigation, self.sensors = (
            columns_of(plots),
            columns_of(navigation),
            columns_of(sensors),
        )
        self.platforms, self.references = _optional(platforms), _optional(references)
        self.targets = _optional(targets)  # the surface targets (read whole: a row per target)
        self.batch_rows = int(batch_rows)
        self.token = uuid.uuid4().hex

    def name(self, table: str) -> str:
        return table

    def _batches(self, table: dict | None, columns: Iterable[str]) -> Iterator[dict]:
        if table is None:
            return
        n = len(next(iter(table.values())))
        for a in range(0, n, self.batch_rows):
            yield {c: table[c][a : a + self.batch_rows] for c in columns if c in table}

    def plot_batches(self, columns: Iterable[str]) -> Iterator[dict]:
        return self._batches(self.plots, columns)

    def navigation_batches(self, columns: Iterable[str]) -> Iterator[dict]:
        return self._batches(self.navigation, columns)

    def reference_batches(self, columns: Iterable[str]) -> Iterator[dict]:
        return self._batches(self.references, columns)

    def read_plots(self, lo: float, hi: float) -> dict:
        t = np.asarray(self.plots["time"], dtype=np.float64)
        return _rows(self.plots, (t >= lo) & (t <= hi))

    def read_references(self, lo: float, hi: float) -> dict | None:
        if self.references is None:
            return None
        t = np.asarray(self.references["time"], dtype=np.float64)
        return _rows(self.references, (t >= lo) & (t <= hi))

    def read_navigation(self, ranges: Mapping[str, tuple[float, float]]) -> dict:
        pid = np.asarray(self.navigation["platform"]).astype(str)
        t = np.asarray(self.navigation["time"], dtype=np.float64)
        keep = np.zeros(t.size, dtype=bool)
        for p, (a, b) in ranges.items():
            keep |= (pid == p) & (t >= a) & (t <= b)
        return _rows(self.navigation, keep)
