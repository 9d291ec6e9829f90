"""Consistency of the batch estimator over a small Monte Carlo: the reported covariance (the
Cramér-Rao bound at the estimate) matches the actual errors.

30 independent runs of the default fleet (2 minutes each, new noise and new error signs every
run). The average NEES of the 24 estimated states must lie in its two-sided 99 % interval
(``nees_interval(30, 24)``), and so must the average NEES of each target's fused position at
one instant per run (3 degrees of freedom), and the average chi-square check.
"""

from __future__ import annotations

import numpy as np
import pytest

from registration.core.consistency import nees_interval
from registration.fleet import fleet_scenario, solve_batch

RUNS = 30


@pytest.fixture(scope="module")
def runs():
    out = []
    for seed in range(100, 100 + RUNS):
        sc = fleet_scenario(seed, duration_s=120.0)
        out.append((sc, solve_batch(sc.problem())))
    return out


def test_state_nees_in_its_interval(runs):
    nees = []
    for sc, result in runs:
        free = result.layout.free
        err = (result.estimate - sc.truth_vector(result.layout))[free]
        nees.append(err @ np.linalg.solve(result.covariance[np.ix_(free, free)], err))
    n = runs[0][1].layout.free.size
    lo, hi = nees_interval(RUNS, n, level=0.99)
    assert all(r.converged for _, r in runs)
    assert lo <= np.mean(nees) <= hi, (
        f"mean NEES {np.mean(nees):.2f} outside [{lo:.2f}, {hi:.2f}] for {n} states"
    )


def test_fused_target_nees_in_its_interval(runs):
    lo, hi = nees_interval(RUNS, 3, level=0.99)
    for tid in ("T1", "T2", "T3", "T4", "T5"):
        nees = []
        for sc, result in runs:
            t, p, cov = result.targets.of(tid)
            k = t.size // 2
            d = p[k] - sc.target_ecef(tid, t[k : k + 1])[0]
            nees.append(d @ np.linalg.solve(cov[k], d))
        assert lo <= np.mean(nees) <= hi, f"{tid}: mean NEES {np.mean(nees):.2f} outside [{lo:.2f}, {hi:.2f}]"


def test_mean_chi_square_matches_its_degrees_of_freedom(runs):
    chi2 = sum(r.chi_square.chi2 for _, r in runs)
    dof = sum(r.chi_square.dof for _, r in runs)
    lo, hi = nees_interval(1, dof, level=0.99)
    assert lo <= chi2 <= hi, f"chi2 {chi2:.0f} outside [{lo:.0f}, {hi:.0f}] for {dof} dof"
