"""The settings of the online fleet filter (:class:`OnlineOptions`) and what it reports of each
epoch it processes (:class:`EpochUpdate`); see :mod:`registration.fleet.online.filter`."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fleet.batch.blocks import SAME_INSTANT_S
from registration.fleet.batch.solver import BatchOptions
from registration.fleet.data.problem import FleetProblem

__all__ = ["EpochUpdate", "OnlineOptions"]


@dataclass(frozen=True)
class EpochUpdate:
    """One informative epoch as the filter processed it: its last plot time ``t_end`` (s), the
    estimate and covariance before it (``x_before`` (n,), ``P_before`` (n, n), after the
    prediction), its information ``L`` (n, n) and gradient ``b`` (n,) at ``x_before`` (the
    Gauss-Newton step from there solves ``L dx = b``), the epoch's ``problem`` and the plots it
    used (``n_plots``)."""

    t_end: float
    x_before: np.ndarray
    P_before: np.ndarray
    L: np.ndarray
    b: np.ndarray
    problem: FleetProblem
    n_plots: int


@dataclass(frozen=True)
class OnlineOptions:
    """Settings of :class:`FleetFilter`.

    window_s, degree: the target windows, as in the batch
    (:class:`~registration.fleet.batch.solver.BatchOptions`);
        an epoch is one window of the absolute time grid. epoch_s: with ``window_s = 0``, the
        length (s) of an epoch of instants (0: one instant per epoch). q_angle (rad/sqrt(s)), q_range
        (m/sqrt(s); range biases and position errors), q_gain (1/sqrt(s); range gains), q_time
        (s/sqrt(s); time biases): random-walk process noise of the states. max_iterations: of each
        epoch's coefficient fit.
    """

    window_s: float = 20.0
    degree: int = 3
    epoch_s: float = 0.0
    q_angle: float = 1e-6
    q_range: float = 0.01
    q_gain: float = 1e-9
    q_time: float = 1e-5
    max_iterations: int = 20

    def __post_init__(self):
        BatchOptions(window_s=self.window_s, degree=self.degree if self.window_s > 0 else 0)  # same checks
        for name in ("epoch_s", "q_angle", "q_range", "q_gain", "q_time"):
            v = getattr(self, name)
            if not (np.isfinite(v) and v >= 0):
                raise ValueError(f"{name}: expected a finite value >= 0, got {v}")
        if not int(self.max_iterations) >= 1:
            raise ValueError(f"max_iterations: expected >= 1, got {self.max_iterations}")

    def batch(self) -> BatchOptions:
        return BatchOptions(
            window_s=self.window_s,
            degree=self.degree if self.window_s > 0 else 0,
            max_iterations=int(self.max_iterations),
        )

    def epoch_key(self, time: np.ndarray) -> np.ndarray:
        length = self.window_s if self.window_s > 0 else self.epoch_s
        if length > 0:
            return np.floor(time / length).astype(np.int64)
        return np.round(time / SAME_INSTANT_S).astype(np.int64)
