"""The state of the online fleet filter as a result (:class:`OnlineResult`): estimates with their
covariance, the history over the epochs, the observability report, and the run's one consistency
verdict (:attr:`OnlineResult.verdict`): the residuals of every plot and reference position at the
final estimate when they were computed, with the innovation check as subordinate information."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration.core.consistency import ConsistencyReport
from registration.core.observability import ObservabilityReport
from registration.fleet.combinations import linear_combination, sum_rows
from registration.fleet.data.layout import StateLayout
from registration.fleet.data.problem import Exclusion
from registration.fleet.result import ChiSquareCheck, state_lines, state_rows

__all__ = ["FINAL_RESIDUALS", "OnlineHistory", "OnlineResult"]

#: What the online verdict measures (the quantity of its ConsistencyReport).
FINAL_RESIDUALS = "squared normalised residual per degree of freedom at the final estimate"


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
    band (None before the first informative epoch): information about the filter's covariance, not
    the run's verdict, since an epoch's innovation carries only its information about the states
    and not its own misfit (:attr:`verdict`). ``excluded``: plots that carried no
    registration information, per target. ``residuals`` (input plot rows, 3) and ``fit_check``:
    the normalised residuals of every plot at the final estimate with the trajectories fitted, and
    their chi-square check (:func:`registration.fleet.batch.residuals.residuals_at`; None unless computed,
    as :func:`~registration.fleet.online.register.register_online` does).
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

    @property
    def verdict(self) -> ConsistencyReport | None:
        """The run's one consistency verdict and gate: the squared normalised residuals of every
        plot and reference position at the final estimate (``fit_check``, the statistic the batch
        gates on) when computed, else the normalised innovations (``consistency``); None before the
        first informative epoch. The innovations test only the part of each epoch's data that
        moves the states: a misfit the epoch's own target windows absorb (a sensor's or a
        reference's sigma stated too small) leaves them unchanged, while the residuals see it."""
        if self.fit_check is not None and self.fit_check.dof > 0:
            return ConsistencyReport.from_mean(self.fit_check.mean, self.fit_check.dof, 1, FINAL_RESIDUALS)
        return self.consistency

    @property
    def verdict_basis(self) -> str:
        """What :attr:`verdict` rests on: ``"residuals at the final estimate"``, ``"normalised
        innovations"`` or ``"none"``."""
        if self.fit_check is not None and self.fit_check.dof > 0:
            return "residuals at the final estimate"
        return "normalised innovations" if self.consistency is not None else "none"

    def innovation_text(self) -> str | None:
        """The innovation check as subordinate information (not a verdict), or None."""
        c = self.consistency
        if c is None:
            return None
        lo, hi = c.interval
        return (
            "normalised innovations (information on the filter's covariance, not the verdict): mean "
            f"{c.mean:.4g} per degree of freedom over {c.samples}, band for independent samples [{lo:.3g}, "
            f"{hi:.3g}]"
        )

    def combination(self, coefficients: dict) -> tuple[float, float]:
        """Value and sigma (1σ) of ``sum_i a_i x_i`` for ``coefficients`` {state name: a_i} (rad, m),
        from the filter's estimate and covariance (a direction the data did not determine keeps its
        prior's spread)."""
        return linear_combination(self.layout, self.estimate, self.covariance, coefficients)

    def rows(self, truth: dict | None = None) -> list[dict]:
        """One dict per state: name, object, quantity, label, unit, estimate, sigma (1σ), status (and
        truth); then one per sum the observability report names (as :meth:`BatchResult.rows`)."""
        return state_rows(self.layout, self.estimate, self.sigma, self.status, truth) + sum_rows(self, truth)

    def lines(self) -> list[str]:
        """A printable summary (angles in degrees)."""
        out = [f"{self.history.time.size} epochs, {self.n_plots_used} of {self.n_plots_read} plots used"]
        if self.verdict is not None:
            out.append(f"verdict ({self.verdict_basis}): {self.verdict.message()}")
        if self.fit_check is not None and self.fit_check.parts:
            out.append(f"  its terms (mean square per value): {self.fit_check.parts_text()}")
        innovations = self.innovation_text()
        if self.fit_check is not None and innovations is not None:
            out.append(innovations)
        out += state_lines(self.rows())
        out += self.observability.lines()
        out += [f"  excluded: {e.text()}" for e in self.excluded]
        return out
