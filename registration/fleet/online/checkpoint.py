"""The online fleet filter's state as named arrays, to write and to continue from
(:class:`Checkpoints`, a part of :class:`~registration.fleet.online.filter.FleetFilter`)."""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["Checkpoints", "NO_EPOCH"]

#: ``closed_key`` of a checkpoint taken before any epoch was processed.
NO_EPOCH = -(2**62)


class Checkpoints:
    """:meth:`checkpoint` and :meth:`restore` of the filter (its attributes are the filter's)."""

    layout: Any
    x: np.ndarray
    P: np.ndarray
    information: np.ndarray
    _closed_key: int | None
    _open_key: int | None
    _t_last: float | None
    _n_read: int
    n_unconverged_plots: int
    _history: list
    _buffer: dict

    def checkpoint(self) -> dict[str, np.ndarray]:
        """The filter's state as named arrays (for ``numpy.savez``, no pickle): the estimate ``x``,
        covariance ``P``, ``information``, the last epoch processed and its time, the history
        (``history_time``, ``history_x``, ``history_sigma``, ``history_nis``, ``history_dof``,
        ``history_plots``), the plots read, those set aside in windows whose fit did not converge
        (``n_unconverged``) and the state names. Plots of the epoch still open are
        not part of it."""
        h, n = self._history, self.layout.n
        return {
            "names": np.array(self.layout.names, dtype=str),
            "x": self.x.copy(),
            "P": self.P.copy(),
            "information": self.information.copy(),
            "closed_key": np.array(
                NO_EPOCH if self._closed_key is None else self._closed_key, dtype=np.int64
            ),
            "t_last": np.array(np.nan if self._t_last is None else self._t_last),
            "n_read": np.array(self._n_read, dtype=np.int64),
            "n_unconverged": np.array(self.n_unconverged_plots, dtype=np.int64),
            "history_time": np.array([e[0] for e in h], dtype=np.float64),
            "history_x": np.array([e[1] for e in h], dtype=np.float64).reshape(len(h), n),
            "history_sigma": np.array([e[2] for e in h], dtype=np.float64).reshape(len(h), n),
            "history_nis": np.array([e[3] for e in h], dtype=np.float64),
            "history_dof": np.array([e[4] for e in h], dtype=np.int64),
            "history_plots": np.array([e[5] for e in h], dtype=np.int64),
        }

    def restore(self, state: dict[str, np.ndarray]) -> None:
        """Continue from a :meth:`checkpoint` of a filter over the same states (ValueError naming
        both sets of states otherwise); the plots buffered here are dropped."""
        names = tuple(str(v) for v in np.asarray(state["names"]).tolist())
        if names != self.layout.names:
            raise ValueError(
                f"the checkpoint's states {list(names)} are not this filter's {list(self.layout.names)}"
            )
        n = self.layout.n
        x, P, info = (np.asarray(state[k], dtype=np.float64) for k in ("x", "P", "information"))
        if x.shape != (n,) or P.shape != (n, n) or info.shape != (n, n) or not np.isfinite(P).all():
            raise ValueError(f"the checkpoint's estimate or covariance is not finite of {n} states")
        self.x, self.P, self.information = x.copy(), P.copy(), info.copy()
        key = int(state["closed_key"])
        self._closed_key = None if key == NO_EPOCH else key
        self._open_key = self._closed_key
        t_last = float(state["t_last"])
        self._t_last = None if not np.isfinite(t_last) else t_last
        self._n_read = int(state["n_read"])
        self.n_unconverged_plots = int(state.get("n_unconverged", 0))  # absent before it was counted
        self._history = list(
            zip(
                state["history_time"].tolist(),
                list(state["history_x"]),
                list(state["history_sigma"]),
                state["history_nis"].tolist(),
                state["history_dof"].tolist(),
                state["history_plots"].tolist(),
            )
        )
        self._buffer = {k: [] for k in self._buffer}
