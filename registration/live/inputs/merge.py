"""The radar sites' plots and a ship's plots given to the estimator in data-time order.

The estimator's filter processes epochs of data time as plots arrive; a plot of an epoch already
processed is late and not used. A ship's bridge hands its plots over only after
:data:`~registration.live.inputs.bridge.HOLD_S` seconds of data (its tracks must be named first),
so radar plots given at once would close the epochs the ship's plots still need, and every one of
those would be late. :class:`TimeMerge` holds the radar plots until the bridge's horizon (the data
time up to which it has handed over its plots: ``Bridge.horizon``) and gives both, merged in time
order, as one batch. When the bridge's feed is quiet (or never started) its horizon is infinite and
the radar plots pass at once. The radars' reference reports (ADS-B) pass at once: the filter keeps
them until their epochs close.
"""

from __future__ import annotations

import numpy as np

from registration.live.inputs.asterix import StreamBatch
from registration.live.inputs.rows import concat_rows

__all__ = ["TimeMerge"]


def _split(table: dict, keep: np.ndarray) -> tuple[dict | None, dict | None]:
    """(rows where ``keep``, the other rows); None for no rows."""
    if keep.all():
        return table, None
    if not keep.any():
        return None, table
    return {k: v[keep] for k, v in table.items()}, {k: v[~keep] for k, v in table.items()}


class TimeMerge:
    """Radar plots held until a ship's horizon (module docstring)."""

    def __init__(self) -> None:
        self._held: dict | None = None
        self._references: list[dict] = []

    @property
    def held(self) -> int:
        """Radar plots waiting for the ship's horizon."""
        return 0 if self._held is None else int(self._held["time"].size)

    def add(self, batch: StreamBatch) -> None:
        """Hold a radar batch's plots; keep its references for the next release."""
        self._held = concat_rows([self._held, batch.plots])
        if batch.references is not None and batch.references["time"].size:
            self._references.append(batch.references)

    def release(self, horizon: float, ship: StreamBatch | None) -> StreamBatch | None:
        """The held radar plots up to ``horizon`` (s of data time) and the ship's batch, merged and
        sorted by time, with the references kept; None when there is nothing."""
        radar = None
        if self._held is not None:
            radar, self._held = _split(self._held, self._held["time"] <= horizon)
        plots = concat_rows([radar, None if ship is None else ship.plots])
        references = concat_rows([*self._references, None if ship is None else ship.references])
        self._references = []
        if plots is None and references is None:
            return None
        if plots is None:
            plots = {"time": np.zeros(0), "sensor": np.zeros(0, str), "target": np.zeros(0, str)}
        else:
            order = np.argsort(plots["time"], kind="stable")
            plots = {k: v[order] for k, v in plots.items()}
        return StreamBatch(plots, references, {})
