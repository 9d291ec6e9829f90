"""Do the data fit the model? Normalised innovations (NIS) or residuals against their chi-square band.

For a consistent estimator each normalised squared innovation is chi-square with ``dof`` degrees of
freedom, so their mean over ``n`` independent samples has the interval of :func:`nees_interval`.
A mean far above ``dof`` (more than :data:`GROSS_FACTOR` times) means the data do not fit the model
at all: typically a unit mistake, not a tuning matter.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["nees_interval", "ConsistencyReport", "check_consistency", "GROSS_FACTOR", "LIKELY_CAUSES"]

#: A mean normalised innovation above this many times its expectation fails the consistency gate.
GROSS_FACTOR = 10.0
#: What usually makes recorded data grossly inconsistent with the model.
LIKELY_CAUSES = (
    "angles in radians in *_deg columns (or degrees in radian data)",
    "noise sigmas in the wrong unit (degrees vs radians, km vs m)",
    "a different sign or zero convention for bearing, heading, pitch or roll",
    "plots and navigation out of step in time (clock offset, wrong time alignment)",
)


def nees_interval(runs: int, dof: int, level: float = 0.95) -> tuple[float, float]:
    """Two-sided ``level`` interval of the average of ``runs`` independent chi-square(``dof``) values.

    ``runs * avg ~ chi2(runs * dof)``, so the interval is ``chi2.ppf((1 -+ level) / 2, runs * dof) / runs``
    (:func:`registration.core.distributions.chi2_ppf`).
    """
    from registration.core.distributions import chi2_ppf

    if runs < 1 or dof < 1:
        raise ValueError(f"nees_interval: need runs >= 1 and dof >= 1, got runs={runs}, dof={dof}")
    alpha = 1.0 - level
    n = runs * dof
    return float(chi2_ppf(alpha / 2, n) / runs), float(chi2_ppf(1 - alpha / 2, n) / runs)


@dataclass(frozen=True)
class ConsistencyReport:
    """Mean normalised squared innovation against its expectation ``dof`` and 95 % band."""

    quantity: str
    samples: int
    dof: int
    mean: float
    interval: tuple[float, float]

    @property
    def ratio(self) -> float:
        """mean / dof: 1 for a consistent filter."""
        return self.mean / self.dof

    @property
    def status(self) -> str:
        """``consistent``, ``outside band`` or ``grossly inconsistent`` (mean > GROSS_FACTOR x dof)."""
        if not np.isfinite(self.mean) or self.ratio > GROSS_FACTOR:
            return "grossly inconsistent"
        lo, hi = self.interval
        return "consistent" if lo <= self.mean <= hi else "outside band"

    @property
    def ok(self) -> bool:
        """False only when the data grossly contradict the model (the gate)."""
        return self.status != "grossly inconsistent"

    def message(self) -> str:
        """One paragraph: the figures, and for a failed gate the likely causes."""
        lo, hi = self.interval
        text = (
            f"mean {self.quantity} {self.mean:.4g} over {self.samples} samples, expected {self.dof} "
            f"(95 % band for independent samples [{lo:.3g}, {hi:.3g}]): {self.status}"
        )
        if not self.ok:
            text += "; the data do not fit the model. Likely causes: " + "; ".join(LIKELY_CAUSES) + "."
        return text

    @classmethod
    def from_mean(cls, mean: float, samples: int, dof: int, quantity: str = "NIS") -> "ConsistencyReport":
        """The report for a mean already accumulated over ``samples`` values (streaming runs)."""
        if samples < 1:
            raise ValueError(f"{quantity}: no samples to check")
        return cls(quantity, int(samples), int(dof), float(mean), nees_interval(int(samples), int(dof)))

    def to_json(self) -> dict:
        return {
            "quantity": self.quantity,
            "samples": self.samples,
            "dof": self.dof,
            "mean": self.mean,
            "interval_95": list(self.interval),
            "ratio": self.ratio,
            "status": self.status,
            "gross_factor": GROSS_FACTOR,
        }


def check_consistency(values, dof: int, quantity: str = "NIS") -> ConsistencyReport:
    """Report on normalised squared innovations ``values``
    (any shape) with ``dof`` degrees of freedom each."""
    values = np.asarray(values, dtype=np.float64).reshape(-1)
    if values.size == 0:
        raise ValueError(f"{quantity}: no samples to check")
    return ConsistencyReport.from_mean(float(np.mean(values)), int(values.size), int(dof), quantity)
