"""The result of batch fleet registration (:class:`BatchResult`)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration.core.consistency import ConsistencyReport
from registration.core.observability import ObservabilityReport
from registration.fleet.combinations import linear_combination, sigma_text, sum_rows
from registration.fleet.data.layout import FILE_UNITS, StateLayout

__all__ = ["BatchResult", "ChiSquareCheck", "FusedTargets", "StateEstimates", "state_lines", "state_rows"]

_QUANTITY = "squared normalised residual per degree of freedom"


@dataclass(frozen=True)
class FusedTargets:
    """Fused positions at every instant (target, time) where a target was measured.

    ``target`` (M,) ids, ``time`` (M,) s, ``p_ecef`` (M, 3) m, ``covariance`` (M, 3, 3) m^2,
    ``n_plots`` (M,) plots at that instant.
    """

    target: np.ndarray
    time: np.ndarray
    p_ecef: np.ndarray
    covariance: np.ndarray
    n_plots: np.ndarray

    @classmethod
    def empty(cls) -> "FusedTargets":
        """No fused positions (a solve that was not asked for them)."""
        return cls(
            np.zeros(0, dtype=str),
            np.zeros(0),
            np.zeros((0, 3)),
            np.zeros((0, 3, 3)),
            np.zeros(0, dtype=np.int64),
        )

    def of(self, target: str):
        """(time, p_ecef, covariance) of one target."""
        sel = self.target == str(target)
        if not sel.any():
            raise ValueError(f"no fused positions of target {target!r} (targets: {sorted(set(self.target))})")
        return self.time[sel], self.p_ecef[sel], self.covariance[sel]


@dataclass(frozen=True)
class ChiSquareCheck:
    """Sum of squared normalised residuals (plots, references, priors) against its degrees of freedom.

    ``dof`` = measured values - estimated parameters (states and trajectory coefficients).
    ``mean`` = chi2 / dof is 1 for data that fit the model; :attr:`report` judges it as the package's
    consistency check does (a mean over ``dof`` values of one degree of freedom each). ``parts``:
    the terms of ``chi2``, {"plots" | "references" | "priors": (sum of squares, number of values)}
    (dimensionless; empty if not known), shown by :meth:`parts_text`.
    """

    chi2: float
    dof: int
    parts: dict = field(default_factory=dict, compare=False)

    @property
    def mean(self) -> float:
        return self.chi2 / self.dof if self.dof > 0 else float("nan")

    @property
    def report(self) -> ConsistencyReport:
        """The consistency report: band, status and the gate (``.ok`` false above 10x its expectation)."""
        if self.dof < 1:
            return ConsistencyReport(_QUANTITY, 0, 1, float("nan"), (float("nan"), float("nan")))
        return ConsistencyReport.from_mean(self.mean, self.dof, 1, _QUANTITY)

    @property
    def interval(self) -> tuple[float, float]:
        """Two-sided 95 % band of ``mean``."""
        return self.report.interval

    @property
    def ok(self) -> bool:
        """``mean`` inside its 95 % band."""
        return self.report.status == "consistent"

    def text(self) -> str:
        lo, hi = self.interval
        return (
            f"mean squared normalised residual {self.mean:.4f} over {self.dof} degrees of freedom "
            f"(95 % band [{lo:.4f}, {hi:.4f}]): {'consistent' if self.ok else 'OUTSIDE the band'}"
        )

    def parts_text(self) -> str:
        """The terms of the sum, each as its mean square per value over its count (about 1 each where
        the stated sigmas are right, a little less for the plots, whose windows absorb part of
        them), e.g. ``plots 0.99 over 11000 values; references 9.1 over 900 values; priors 0.2 over
        3 values``; ``references none`` when no reference position entered."""
        terms = []
        for name, (ss, n) in self.parts.items():
            terms.append(f"{name} {ss / n:.4g} over {n} values" if n else f"{name} none")
        return "; ".join(terms)


def state_rows(
    layout: StateLayout, estimate: np.ndarray, sigma: np.ndarray, status: dict, truth: dict | None = None
) -> list[dict]:
    """One dict per state of ``layout``: name, object (platform or sensor id), quantity, label,
    unit, estimate, sigma (rad, m), status (and truth when given, {name: value})."""
    out = []
    for i, name in enumerate(layout.names):
        row = {
            "name": name,
            "object": layout.objects[i],
            "quantity": layout.quantities[i],
            "label": layout.labels[i],
            "unit": layout.units[i],
            "estimate": float(estimate[i]),
            "sigma": float(sigma[i]),
            "status": status[name],
        }
        if truth is not None:
            row["truth"] = float(truth[name])
        out.append(row)
    return out


def state_lines(rows: list[dict]) -> list[str]:
    """One printable line per row of :func:`state_rows` or ``sum_rows``: label, estimate and its σ
    (one standard deviation, or ``undetermined``) in display units (angles in degrees, ranges and
    positions in m, range gains in ppm, time biases in s), status."""
    out, width = [], max([36, *(len(row["label"]) for row in rows)])
    for row in rows:
        _, _, unit, k = FILE_UNITS[row["unit"]]
        out.append(
            f"  {row['label']:<{width}s} {k * row['estimate']:+12.4f} {unit:<3}  "
            f"σ {sigma_text(k * row['sigma']):<12}  {row['status']}"
        )
    return out


class StateEstimates:
    """What a batch estimate gives per state and per combination of states, for a result with
    ``layout``, ``estimate``, ``covariance``, ``sigma``, ``status``, ``observability``,
    ``undetermined`` and ``scale`` (:class:`BatchResult` and the partitioned solver's result)."""

    layout: StateLayout
    estimate: np.ndarray  # (n,) rad, m, 1, s
    covariance: np.ndarray  # (n, n)
    sigma: np.ndarray  # (n,)
    status: dict
    undetermined: np.ndarray  # (n_free, k) scaled
    scale: np.ndarray  # (n_free,)

    def value(self, name: str) -> float:
        return float(self.estimate[self.layout.index(name)])

    def sigma_of(self, name: str) -> float:
        return float(self.sigma[self.layout.index(name)])

    def combination(self, coefficients: dict) -> tuple[float, float]:
        """Value and sigma (1σ) of ``sum_i a_i x_i`` for ``coefficients`` {state name: a_i}, e.g.
        ``{"A:heading_error": 1, "A1:bearing_bias": 1}`` (rad, m). The sigma is inf when the combination
        leans on a direction the data do not determine (more than 1 % of it, in scaled units)."""
        return linear_combination(
            self.layout, self.estimate, self.covariance, coefficients, self.undetermined, self.scale
        )

    def rows(self, truth: dict | None = None) -> list[dict]:
        """One dict per state: name, object (platform or sensor id), quantity, label, unit,
        estimate, sigma (1σ), status (and truth when given); then one per sum the observability
        report names (:func:`~registration.fleet.combinations.sum_rows`)."""
        return state_rows(self.layout, self.estimate, self.sigma, self.status, truth) + sum_rows(self, truth)


@dataclass
class BatchResult(StateEstimates):
    """Estimates, their covariance, fused targets, residuals and observability.

    ``estimate`` (n,) and ``covariance`` (n, n) in the order of ``layout.names`` (rad, m); fixed states
    are 0 with zero covariance. ``sigma`` (n,): 0 for fixed states, inf for states that lean on a
    direction neither the data nor a prior determine (left out of the covariance). ``status`` per state,
    from the data alone (:mod:`registration.fleet.observability`): ``fixed``, ``identifiable``, ``weak``
    or ``not identifiable``. ``residuals`` (rows of the input plots table, 3): normalised residuals
    (measured - predicted) / sigma of range, bearing, elevation; NaN where not measured or where the plot
    was excluded. ``information``: the free states' information from the data alone (targets eliminated),
    in the order of ``free_names``. ``reference_residuals`` (R', 3): per reference position used,
    ``(known - fitted position) / sigma`` per ECEF axis (sigma: the reference's, m per axis), or, for the
    references of a run where some reference has a vertical sigma (``sigma_up`` not equal to ``sigma``),
    the east, north and up components of that difference over ``sigma``, ``sigma``, ``sigma_up``; of
    target ``reference_target`` (R',); ``references_given``: the reference positions of the problem's
    targets, used or not (a warning names those not used).
    """

    layout: StateLayout
    estimate: np.ndarray
    covariance: np.ndarray
    sigma: np.ndarray
    status: dict
    targets: FusedTargets
    residuals: np.ndarray
    chi_square: ChiSquareCheck
    observability: ObservabilityReport
    excluded: tuple
    information: np.ndarray
    free_names: tuple
    scale: np.ndarray  # (n_free,) prior or reference sigma of each free state (rad, m)
    undetermined: np.ndarray  # (n_free, k) directions left out of the covariance, scaled by ``scale``
    converged: bool
    iterations: int
    plot_target: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=str))  # (input rows,)
    plot_sensor: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=str))  # (input rows,)
    cost_history: list = field(default_factory=list)
    warnings: tuple = ()  # what the user should know about this estimate (e.g. a time bias near the window)
    reference_target: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=str))  # (R',)
    reference_residuals: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))  # (R', 3)
    references_given: int = 0

    def residual_check(self, by: str = "target") -> dict:
        """Mean squared normalised residual of the plots per target (``by="target"``) or per sensor
        (``by="sensor"``), or of the reference positions used per reference target (``by="reference"``, 3
        values per position, one per ECEF axis, or east, north, up): {id: (mean, number of values)}.
        Where the model fits it is a little below 1 (the fitted trajectory coefficients absorb part of
        the residuals: for a target about ``1 - 3 x its coefficients / its values``); well above 1 points
        at that target's track model (a window too long for its manoeuvres), at that sensor's stated
        noise or an unmodelled error, or at a reference sigma
        (``sigma_m``) stated too small; far below 1 at a sigma stated too large."""
        if by not in ("target", "sensor", "reference"):
            raise ValueError(f"by: expected 'target', 'sensor' or 'reference', got {by!r}")
        if by == "reference":
            out = {}
            for t in dict.fromkeys(self.reference_target):
                e = self.reference_residuals[self.reference_target == t]
                e = e[np.isfinite(e)]  # a reference without a height has no up value
                out[str(t)] = (float(np.mean(e**2)) if e.size else float("nan"), int(e.size))
            return out
        ids = self.plot_target if by == "target" else self.plot_sensor
        sq = np.nansum(self.residuals**2, axis=1)
        n = np.sum(np.isfinite(self.residuals), axis=1)
        out = {}
        for key in np.unique(ids[n > 0]):
            sel = (ids == key) & (n > 0)
            out[str(key)] = (float(sq[sel].sum() / n[sel].sum()), int(n[sel].sum()))
        return out

    def lines(self) -> list[str]:
        """A printable summary (angles in degrees)."""
        out = [f"converged: {self.converged} after {self.iterations} iterations", self.chi_square.text()]
        if self.chi_square.parts:
            out.append(
                f"  its terms (mean square per value): {self.chi_square.parts_text()} "
                f"({self.reference_target.size} of {self.references_given} reference positions used)"
            )
        out += [f"WARNING: {w}" for w in self.warnings]
        out += state_lines(self.rows())
        out += self.observability.lines()
        out += [f"  excluded: {e.text()}" for e in self.excluded]
        return out
