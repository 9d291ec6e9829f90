"""The observability report names heading/bearing sums even when the null space is degenerate or tilted."""

from __future__ import annotations

import numpy as np

from registration.core.observability import observability_report
from registration.online import RegistrationConfig, register
from registration.online.contract import STATE_LABELS, STATE_NAMES, STATE_UNITS
from registration.online.scenario import paper_scenario

PRIOR = np.array(RegistrationConfig().prior_sigma)


def _pair(i: int, j: int) -> np.ndarray:
    """e_i - e_j (own units) in prior-scaled coordinates, normalised."""
    v = np.zeros(12)
    v[i], v[j] = 1.0 / PRIOR[i], -1.0 / PRIOR[j]
    return v / np.linalg.norm(v)


def _report(null_vectors: list[np.ndarray], big: float = 1e4):
    """Information ``big`` everywhere except along the (orthonormal) null vectors, which get
    tiny distinct values 1e-9, 2e-9, ... so that the eigenvectors are those vectors exactly."""
    U = np.array(null_vectors).T
    scaled = big * (np.eye(12) - U @ U.T) + sum((k + 1) * 1e-9 * np.outer(u, u) for k, u in enumerate(U.T))
    info = scaled / PRIOR[:, None] / PRIOR[None, :]
    return observability_report(info, PRIOR, STATE_NAMES, STATE_LABELS, STATE_UNITS)


def test_pairs_named_when_the_null_space_mixes_both_ships():
    a, b = _pair(0, 4), _pair(6, 10)  # dC_a - dq_a, dC_b - dq_b
    rep = _report([(a + b) / np.sqrt(2), (a - b) / np.sqrt(2)])
    assert sorted(rep.identifiable_sums) == [("dC_a", "dq_a"), ("dC_b", "dq_b")]
    assert {rep.status[n] for n in ("dC_a", "dq_a", "dC_b", "dq_b")} == {"not identifiable"}


def test_pairs_named_when_the_null_space_is_slightly_tilted():
    """Evaluated at a small corrected pitch/roll, the null direction tilts off e_C - e_q: the
    information along the exact pair direction is then above the threshold, yet the pair is it.
    Mixed with the other ship's pair, no single eigenvector names it either."""
    a, b = _pair(0, 4), _pair(6, 10)
    tilt_a, tilt_b = np.zeros(12), np.zeros(12)
    tilt_a[1], tilt_b[7] = 0.003, -0.003  # a little pitch error of each ship mixed in (seed 84: ~0.002)
    a_tilted = (a + tilt_a) / np.linalg.norm(a + tilt_a)
    b_tilted = (b + tilt_b) / np.linalg.norm(b + tilt_b)
    assert 1e4 * (1 - (a @ a_tilted) ** 2) > 0.01  # information along the exact pair: above the threshold
    rep = _report(
        [(a_tilted + b_tilted) / np.sqrt(2), (a_tilted - b_tilted) / np.sqrt(2)]
    )  # and mixed between ships
    assert sorted(rep.identifiable_sums) == [("dC_a", "dq_a"), ("dC_b", "dq_b")]


def test_no_pair_named_where_there_is_none():
    rep = _report([_pair(3, 9)])  # range biases: same unit, but this null direction is not a sum of C and q
    assert ("dC_a", "dq_a") not in rep.identifiable_sums
    rep = _report([np.eye(12)[1]])  # a lone unobservable state
    assert rep.identifiable_sums == [] and rep.status["dphi_a"] == "not identifiable"


def test_level_ship_at_low_noise_names_both_sums():
    """Seed 84 at 0.1 deg: the two null eigenvalues are ~1e-11 and their eigenvectors mix ships."""
    sc = paper_scenario(seed=84, angle_sigma=np.radians(0.1))
    res = register(sc.data, RegistrationConfig(sigma0=tuple(sc.sigma0)))
    assert sorted(c["name"] for c in res.identifiable_combinations()) == ["dC_a + dq_a", "dC_b + dq_b"]


def test_a_lone_unobservable_state_with_a_small_prior_makes_no_pairs():
    """Pitch error A does not enter at all and has a 10x smaller prior: the pair directions
    (1/d_i, -1/d_j) then point almost along it, yet no pair may be named (review finding)."""
    prior = PRIOR.copy()
    prior[1] /= 10
    scaled = 1e4 * np.eye(12)
    scaled[1, 1] = 0.0
    info = scaled / prior[:, None] / prior[None, :]
    rep = observability_report(info, prior, STATE_NAMES, STATE_LABELS, STATE_UNITS)
    assert rep.identifiable_sums == []
    assert rep.status["dphi_a"] == "not identifiable"
    assert all(rep.status[n] == "identifiable" for n in STATE_NAMES if n != "dphi_a")


def test_default_scenario_names_only_the_heading_bearing_sums():
    """Ship B sees the target near its bow, so pitch error B and elevation bias B are nearly
    degenerate there; that is a weak combination, not an 'enter only as their sum' fact."""
    for seed in (0, 5):
        res = register(paper_scenario(seed=seed).data)
        assert sorted(c["name"] for c in res.identifiable_combinations()) == ["dC_a + dq_a", "dC_b + dq_b"]
        texts = " | ".join(res.observability.to_json()["unobservable"])
        assert "dphi_b + de_b" not in texts
