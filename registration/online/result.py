"""What a registration run produced (:class:`RegistrationResult`) and its summaries.

:func:`estimate_rows` is the one table of final estimates (each state and each identifiable sum,
with 1 sigma and observability status) that the API, the CLI and the recorded-data summary share.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.core.consistency import ConsistencyReport, check_consistency
from registration.core.observability import ObservabilityReport
from registration.online.config import RegistrationConfig
from registration.online.contract import IS_ANGLE, STATE_NAMES

__all__ = ["RegistrationResult", "difference_statistics", "identifiable_combinations", "estimate_rows"]


def difference_statistics(diff: np.ndarray) -> dict:
    """max |.|, mean and standard deviation per ECEF axis of a (K, 3) difference, in metres."""
    diff = np.asarray(diff)
    return {
        "max": np.abs(diff).max(axis=0).tolist(),
        "mean": diff.mean(axis=0).tolist(),
        "std": diff.std(axis=0, ddof=1).tolist() if len(diff) > 1 else [0.0, 0.0, 0.0],
    }


def identifiable_combinations(x: np.ndarray, P: np.ndarray, report: ObservabilityReport) -> list[dict]:
    """Estimates (rad or m, the states' unit) and 1 sigma of the sums
    that are identifiable when their parts are not (e.g. dC_a + dq_a)."""
    out = []
    for a, b in report.identifiable_sums:
        i, j = STATE_NAMES.index(a), STATE_NAMES.index(b)
        var = P[i, i] + P[j, j] + 2 * P[i, j]
        out.append(
            {
                "name": f"{a} + {b}",
                "indices": [i, j],
                "estimate": float(x[i] + x[j]),
                "sigma": float(np.sqrt(max(var, 0.0))),
            }
        )
    return out


def estimate_rows(x: np.ndarray, P: np.ndarray, report: ObservabilityReport, truth_state=None) -> list[dict]:
    """One dict per state and per identifiable sum: name,
    unit ('rad' or 'm'), estimate, sigma, truth, status."""
    rows = []
    sigma = np.sqrt(np.diag(P))
    for i, name in enumerate(STATE_NAMES):
        rows.append(
            {
                "name": name,
                "unit": "rad" if IS_ANGLE[i] else "m",
                "estimate": float(x[i]),
                "sigma": float(sigma[i]),
                "truth": None if truth_state is None else float(truth_state[i]),
                "status": report.status[name],
            }
        )
    for comb in identifiable_combinations(x, P, report):
        i, j = comb["indices"]
        rows.append(
            {
                "name": comb["name"],
                "unit": "rad" if IS_ANGLE[i] else "m",
                "estimate": comb["estimate"],
                "sigma": comb["sigma"],
                "truth": None if truth_state is None else float(truth_state[i] + truth_state[j]),
                "status": "identifiable combination",
            }
        )
    return rows


@dataclass
class RegistrationResult:
    """Everything a batch run produced. Shapes: K rows; 12 states in STATE_NAMES order; SI units."""

    config: RegistrationConfig
    time: np.ndarray  # (K,) s
    estimates: np.ndarray  # (K, 12) posterior estimate after each row
    covariances: np.ndarray  # (K, 12, 12)
    innovations: np.ndarray  # (K, 3) m
    innovation_covariances: np.ndarray  # (K, 3, 3) m^2
    nis: np.ndarray  # (K,)
    information: (
        np.ndarray
    )  # (12, 12) sum H^T R^-1 H as the filter accumulated it (at its linearisation points)
    information_at_estimate: (
        np.ndarray
    )  # (12, 12) the same sum re-evaluated at the final estimate (observability)
    raw_difference_ecef: np.ndarray  # (K, 3) m, X_A - X_B from the measured values
    corrected_difference_ecef: np.ndarray  # (K, 3) m, X_A - X_B corrected with the estimate after each row
    corrected_a_ecef: np.ndarray  # (K, 3) m, corrected target position from radar A
    corrected_b_ecef: np.ndarray  # (K, 3) m
    observability: ObservabilityReport
    state_names: tuple = STATE_NAMES

    @property
    def final(self) -> np.ndarray:
        return self.estimates[-1]

    @property
    def final_sigma(self) -> np.ndarray:
        return np.sqrt(np.diag(self.covariances[-1]))

    def statistics(self) -> dict:
        """The before/after statistics of the ECEF differences (metres), as in the paper's Table 1."""
        return {
            "before": difference_statistics(self.raw_difference_ecef),
            "after": difference_statistics(self.corrected_difference_ecef),
        }

    @property
    def consistency(self) -> ConsistencyReport:
        """Mean NIS (3 degrees of freedom per row) against its chi-square band; ``.ok`` is the gate."""
        return check_consistency(self.nis, 3, "NIS")

    def identifiable_combinations(self) -> list[dict]:
        """Estimates of the sums that are identifiable when the parts are not (e.g. dC_a + dq_a)."""
        return identifiable_combinations(self.final, self.covariances[-1], self.observability)

    def estimate_rows(self, truth_state=None) -> list[dict]:
        """The final estimates as :func:`estimate_rows` tabulates them."""
        return estimate_rows(self.final, self.covariances[-1], self.observability, truth_state)

    def __repr__(self) -> str:
        counts: dict[str, int] = {}
        for status in self.observability.status.values():
            counts[status] = counts.get(status, 0) + 1
        states = ", ".join(f"{n} {s}" for s, n in sorted(counts.items()))
        return (
            f"RegistrationResult({len(self.time)} rows, linearization={self.config.linearization!r}, "
            f"t_variant={self.config.t_variant!r}, states: {states}, mean NIS {float(np.mean(self.nis)):.3g})"
        )
