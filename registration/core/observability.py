"""Observability of the registration state from the accumulated Fisher information.

The batch :func:`registration.online.register` evaluates the information at the final estimate
(the measurements corrected by it): along the estimated true geometry. Evaluated at the raw
measurements instead, a level ship whose pitch reads 0.03 deg (a pitch *error*) would seem to
separate heading error from bearing bias, an artefact that grows as the noise shrinks.

The information matrix ``J = sum_k H_k^T R_k^-1 H_k`` is scaled to comparable units with the
prior standard deviations ``D = diag(sigma_prior)``: ``J_s = D J D`` is dimensionless, and an
eigenvalue ``s`` of ``J_s`` says how much the data shrink the prior along that direction: the
posterior standard deviation is ``1 / sqrt(1 + s)`` of the prior one. Classes:

* **unobservable**: ``s < 0.01`` - the data change the prior by less than 0.5 %;
* **weak**: ``0.01 <= s < 10`` - the posterior keeps more than 30 % of the prior spread;
* observable otherwise.

Directions are named as combinations of prior-scaled states (``x_i / sigma_i``). A two-state direction
``x_i - x_j`` (equal coefficients in the states' own, identical units) means that only ``x_i + x_j``
enters the measurements: for a level ship, heading error and bearing bias (Phi depends on C and q only
through C + q).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = [
    "Combination",
    "ObservabilityReport",
    "observability_report",
    "UNOBSERVABLE_BELOW",
    "WEAK_BELOW",
    "PAIR_RELATIVE",
]

UNOBSERVABLE_BELOW = 1e-2
WEAK_BELOW = 10.0
#: a same-unit pair is named a sum when its difference carries less than this share of the
#: information of either state alone (see _pair_directions)
PAIR_RELATIVE = 1e-4


@dataclass
class Combination:
    """A direction in state space, with coefficients in the states' own units."""

    coefficients: dict[str, float]
    eigenvalue: float
    text: str
    identifiable_sum: tuple[str, str] | None = None  # (x_i, x_j) when only x_i + x_j is seen

    def to_json(self) -> dict:
        return {
            "coefficients": self.coefficients,
            "scaled_information": self.eigenvalue,
            "description": self.text,
        }


@dataclass
class ObservabilityReport:
    singular_values: np.ndarray  # of the scaled information matrix, descending
    unobservable: list[Combination] = field(default_factory=list)
    weak: list[Combination] = field(default_factory=list)
    status: dict[str, str] = field(default_factory=dict)  # state -> identifiable | weak | not identifiable

    @property
    def identifiable_sums(self) -> list[tuple[str, str]]:
        return [c.identifiable_sum for c in self.unobservable + self.weak if c.identifiable_sum]

    def to_json(self) -> dict:
        return {
            "singular_values": [float(s) for s in self.singular_values],
            "unobservable": [c.text for c in self.unobservable],
            "weak": [c.text for c in self.weak],
            "status": dict(self.status),
            "details": {
                "unobservable": [c.to_json() for c in self.unobservable],
                "weak": [c.to_json() for c in self.weak],
            },
            "thresholds": {"unobservable_below": UNOBSERVABLE_BELOW, "weak_below": WEAK_BELOW},
        }

    def lines(self) -> list[str]:
        out = [
            "singular values of the prior-scaled information matrix: "
            + " ".join(f"{s:.3g}" for s in self.singular_values)
        ]
        for c in self.unobservable:
            out.append(f"  UNOBSERVABLE: {c.text}")
        for c in self.weak:
            out.append(f"  weak:         {c.text}")
        if not self.unobservable and not self.weak:
            out.append("  every state is observable")
        return out


def _name_direction(
    v_scaled: np.ndarray, d: np.ndarray, units, names, labels, eigenvalue: float
) -> Combination:
    """Name a direction given in prior-scaled (dimensionless) coordinates."""
    v = v_scaled / np.abs(v_scaled).max()
    idx = [i for i in np.argsort(-np.abs(v)) if abs(v[i]) >= 0.15]
    coeffs = {names[i]: round(float(v[i]), 3) for i in idx}
    terms = " ".join(f"{'+' if v[i] >= 0 else '-'} {abs(v[i]):.2f} {names[i]}/sigma" for i in idx).lstrip(
        "+ "
    )
    pair = None
    text = f"combination {terms} (prior-scaled)"
    if len(idx) == 2 and units[idx[0]] == units[idx[1]]:
        i, j = sorted(idx)
        own = d * v_scaled  # back to the states' own units
        if abs(abs(own[i]) - abs(own[j])) < 0.05 * max(abs(own[i]), abs(own[j])):
            if np.sign(own[i]) != np.sign(own[j]):
                pair = (names[i], names[j])
                text = f"{labels[i]} and {labels[j]} enter only as their sum {names[i]} + {names[j]}"
            else:
                text = f"{labels[i]} and {labels[j]} enter only as their difference {names[i]} - {names[j]}"
    elif len(idx) == 1:
        text = f"{labels[idx[0]]} ({names[idx[0]]})"
    return Combination(coeffs, float(eigenvalue), text, pair)


def _pair_directions(
    scaled: np.ndarray, d: np.ndarray, units, names, labels
) -> list[tuple[Combination, np.ndarray]]:
    """Same-unit pairs of which only the sum enters the measurements.

    For states i, j in the same unit, only x_i + x_j is seen when the own-unit direction
    e_i - e_j carries (almost) no information while each state alone carries a lot. All three
    are read from the prior-scaled information, so the test does not depend on how the
    eigen-solver splits a degenerate null space (two tiny, nearly equal eigenvalues whose
    eigenvectors mix both ships' pairs), and a null direction tilted slightly off e_i - e_j
    (evaluated at a small corrected pitch) is still recognised. Named when

    * each state alone is observable: ``J_ii, J_jj >= WEAK_BELOW``;
    * the difference carries next to nothing: ``info(e_i - e_j) < WEAK_BELOW`` and below
      ``PAIR_RELATIVE`` times ``min(J_ii, J_jj)``. The heading/bearing pairs of a level ship
      sit at 1e-8 to 4e-6. Near-degeneracies of a particular geometry sit at 6e-4 and above, for
      example pitch error and elevation bias for a target near the bow. Such a pair stays a weak
      combination and is not named.
    """
    found = []
    n = len(names)
    diag = np.diag(scaled)
    for i in range(n):
        for j in range(i + 1, n):
            if units[i] != units[j]:
                continue
            v = np.zeros(n)
            v[i], v[j] = 1.0 / d[i], -1.0 / d[j]  # e_i - e_j in prior-scaled coordinates
            v /= np.linalg.norm(v)
            info = float(v @ scaled @ v)
            alone = min(diag[i], diag[j])
            if alone >= WEAK_BELOW and info < WEAK_BELOW and info < PAIR_RELATIVE * alone:
                text = f"{labels[i]} and {labels[j]} enter only as their sum {names[i]} + {names[j]}"
                coeffs = {names[i]: 1.0, names[j]: -1.0}
                found.append((Combination(coeffs, info, text, (names[i], names[j])), v))
    return found


def observability_report(
    information: np.ndarray, prior_sigma: np.ndarray, names, labels, units=None
) -> ObservabilityReport:
    """Classify state directions from the accumulated information ``sum H^T R^-1 H`` (12x12).

    ``units`` (one string per state) lets same-unit pairs be recognised (e.g. heading error and
    bearing bias, both radians).
    """
    information = np.asarray(information, dtype=float)
    d = np.asarray(prior_sigma, dtype=float)
    n = len(names)
    units = list(units) if units is not None else [""] * n
    scaled = d[:, None] * information * d[None, :]
    scaled = 0.5 * (scaled + scaled.T)
    eigval_all = np.clip(np.linalg.eigvalsh(scaled), 0.0, None)[::-1]
    report = ObservabilityReport(singular_values=eigval_all)

    pairs = _pair_directions(scaled, d, units, names, labels)
    unobs_basis, weak_basis = [v for _, v in pairs], []
    report.unobservable.extend(c for c, _ in pairs)
    # the rest of the space, orthogonal to the named pair directions
    if pairs:
        w = np.linalg.qr(np.array(unobs_basis).T)[0]
        u, sv, _ = np.linalg.svd(np.eye(n) - w @ w.T)
        basis = u[:, : n - w.shape[1]]
    else:
        basis = np.eye(n)
    eigval, eigvec = np.linalg.eigh(basis.T @ scaled @ basis)
    for s_val, u_vec in sorted(zip(np.clip(eigval, 0, None), (basis @ eigvec).T), key=lambda t: t[0]):
        if s_val >= WEAK_BELOW:
            continue
        comb = _name_direction(u_vec, d, units, names, labels, s_val)
        if s_val < UNOBSERVABLE_BELOW:
            report.unobservable.append(comb)
            unobs_basis.append(u_vec)
        else:
            report.weak.append(comb)
            weak_basis.append(u_vec)
    q_unobs = np.linalg.qr(np.array(unobs_basis).T)[0] if unobs_basis else None
    for i, name in enumerate(names):
        e = np.zeros(n)
        e[i] = 1.0
        p_unobs = np.linalg.norm(q_unobs.T @ e) if q_unobs is not None else 0.0
        p_weak = np.linalg.norm(np.array(weak_basis) @ e) if weak_basis else 0.0
        if p_unobs > 0.3:
            report.status[name] = "not identifiable"
        elif p_weak > 0.3 or p_unobs > 0.1:
            report.status[name] = "weak"
        else:
            report.status[name] = "identifiable"
    return report
