"""The state of the online fleet filter as a result (:class:`OnlineResult`): estimates with their
covariance, the history over the epochs, the observability report and the innovation check."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration.core.consistency import ConsistencyReport
from registration.core.observability import ObservabilityReport
from registration.fleet.layout import StateLayout
from registration.fleet.problem import Exclusion
from registration.fleet.result import ChiSquareCheck, state_lines, state_rows

__all__ = ["OnlineHistory", "OnlineResult"]


@dataclass(frozen=True)
class OnlineHistory:
    """The estimate after each epoch: ``time`` (E,) s (the epoch's last plot), ``estimate`` (E, n)
    and ``sigma`` (E, n) in rad and m, ``nis`` (E,) and ``dof`` (E,) of each epoch's update,
    ``n_plots`` (E,) plots used."""

    time: np.ndarray
    estimate: np.ndarray
    sigma: np.ndarray
    nis: np.ndarray
    dof: np.ndarray
    n_plots: np.ndarray

    def of(self, layout: StateLayout, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(time s, estimate, sigma) of state ``name`` over the epochs (rad or m)."""
        i = layout.index(name)
        return self.time, self.estimate[:, i], self.sigma[:, i]


@dataclass
class OnlineResult:
    """Estimates and covariance of the online fleet filter after its last epoch.

    ``estimate`` (n,) and ``covariance`` (n, n) in the order of ``layout.names`` (rad, m); fixed
    states are 0 with zero covariance. ``sigma`` (n,) the square root of the covariance's diagonal.
    ``status`` per state from the information the data gave (``fixed``, ``identifiable``, ``weak``,
    ``not identifiable``); where a state is not identifiable its sigma stays that of the prior.
    ``consistency``: the normalised innovations squared of all epochs against their chi-square
    band (None before the first informative epoch). ``excluded``: plots that carried no
    registration information, per target. ``residuals`` (input plot rows, 3) and ``fit_check``:
    the normalised residuals of every plot at the final estimate with the trajectories fitted, and
    their chi-square check (:func:`registration.fleet.residuals.residuals_at`; None unless computed,
    as :func:`~registration.fleet.online.register_online` does).
    """

    layout: StateLayout
    estimate: np.ndarray
    covariance: np.ndarray
    sigma: np.ndarray
    status: dict
    observability: ObservabilityReport
    consistency: ConsistencyReport | None
    history: OnlineHistory
    excluded: tuple[Exclusion, ...]
    n_plots_read: int
    n_plots_used: int
    residuals: np.ndarray | None = field(default=None)
    fit_check: ChiSquareCheck | None = field(default=None)

    def value(self, name: str) -> float:
        return float(self.estimate[self.layout.index(name)])

    def sigma_of(self, name: str) -> float:
        return float(self.sigma[self.layout.index(name)])

    def rows(self, truth: dict | None = None) -> list[dict]:
        """One dict per state: name, object, quantity, label, unit, estimate, sigma, status (and truth)."""
        return state_rows(self.layout, self.estimate, self.sigma, self.status, truth)

    def lines(self) -> list[str]:
        """A printable summary (angles in degrees)."""
        out = [f"{self.history.time.size} epochs, {self.n_plots_used} of {self.n_plots_read} plots used"]
        if self.consistency is not None:
            out.append(self.consistency.message())
        if self.fit_check is not None:
            out.append("residuals at the final estimate: " + self.fit_check.text())
        out += state_lines(self.rows())
        out += self.observability.lines()
        out += [f"  excluded: {e.text()}" for e in self.excluded]
        return out
