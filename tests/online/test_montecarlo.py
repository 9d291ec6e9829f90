"""Monte Carlo evaluation: shapes, RMSE behaviour, the Cramér-Rao bound, the chi-square arithmetic."""

from __future__ import annotations

import json

import numpy as np
import pytest

from registration.online import RegistrationConfig, register
from registration.online.contract import N_STATE, STATE_NAMES
from registration.online.montecarlo import (
    crlb_information,
    nees_interval,
    nees_series,
    parse_sum,
    run_montecarlo,
)
from registration.online.scenario import paper_scenario

RUNS = 8


@pytest.fixture(scope="module")
def level():
    return run_montecarlo(RUNS, seed0=0)


def test_shapes_and_quantities(level):
    k, m = len(level.time), len(level.quantities)
    assert k == 300 and level.runs == RUNS
    for name in ("rmse", "mean_error", "filter_sigma", "filter_two_sigma_mean", "crlb_sigma"):
        assert getattr(level, name).shape == (k, m), name
    assert level.nees.shape == (k,) and level.nis.shape == (k,)
    names = [q.name for q in level.quantities]
    # level ships: the range biases and the heading + bearing sums, never the parts of the sums
    assert {"dr_a", "dr_b", "dC_a + dq_a", "dC_b + dq_b"} <= set(names)
    assert not {"dC_a", "dq_a", "dC_b", "dq_b"} & set(names)
    assert {"dC_a", "dq_a"} <= set(level.excluded)
    assert level.nees_dof == m  # no weak or requested extras by default
    for q in level.quantities:
        assert q.direction.shape == (N_STATE,)


def test_json_round_trip(level):
    doc = json.loads(json.dumps(level.to_json()))
    assert doc["runs"] == RUNS and len(doc["series"]) == len(level.quantities)
    assert len(doc["series"][0]["rmse"]) == len(level.time)
    assert doc["nees"]["chi2_dof"] == RUNS * level.nees_dof


def test_rmse_finite_and_decreasing(level):
    prior = np.array(level.config.prior_sigma)
    for j, q in enumerate(level.quantities):
        r = level.rmse[:, j]
        assert np.isfinite(r).all() and (r > 0).all()
        assert r[-50:].mean() < r[:50].mean(), q.name
        prior_sigma = np.sqrt(np.square(q.direction * prior).sum())
        assert r[-1] < 0.5 * prior_sigma, q.name  # the data did shrink the prior spread


def test_crlb_below_filter_sigma_and_shrinking(level):
    c, s = level.crlb_sigma, level.filter_sigma
    assert np.isfinite(c).all() and (c > 0).all()
    # information only accumulates: the bound never grows
    assert (np.diff(c, axis=0) <= 1e-9 * c[:-1]).all()
    # the filter (H at the measured values) cannot beat the bound by more than a few per cent
    assert (c <= 1.1 * s).all()
    assert (c[-1] >= 0.8 * s[-1]).all()  # and it is close to it: the filter is nearly efficient in P


def test_crlb_information_matches_the_filter_without_errors():
    """With no biases and no noise, measured == true, so the filter's accumulated information
    (the generated Kalman step) equals the bound's (the generated pseudo-measurement at the truth)."""
    sc = paper_scenario(
        0,
        n_steps=40,
        range_sigma=0.0,
        angle_sigma=0.0,
        range_bias=0.0,
        angle_bias=0.0,
        heading_error=0.0,
        level_error=0.0,
    )
    cfg = RegistrationConfig()
    info = crlb_information(sc, sigma0=cfg.sigma0)
    assert info.shape == (40, N_STATE, N_STATE)
    np.testing.assert_allclose(info.transpose(0, 2, 1), info)
    assert np.linalg.eigvalsh(info).min() > -1e-9 * np.abs(info).max()
    got = register(sc.data, cfg).information
    np.testing.assert_allclose(info.sum(axis=0), got, rtol=1e-8, atol=1e-12 * np.abs(got).max())


def test_nees_interval_covers_the_average_of_chi_square_draws_at_its_level():
    """The interval holds the run-averaged NEES of a consistent filter with the stated probability."""
    rng = np.random.default_rng(7)
    for runs, dof, level in ((100, 4, 0.95), (20, 3, 0.99), (5, 12, 0.90)):
        lo, hi = nees_interval(runs, dof, level)
        avg = rng.chisquare(dof, size=(40_000, runs)).mean(axis=1)
        coverage = np.mean((avg >= lo) & (avg <= hi))
        assert coverage == pytest.approx(level, abs=0.006), (runs, dof, level, coverage)
        assert np.mean(avg < lo) == pytest.approx((1 - level) / 2, abs=0.005)  # two-sided, equal tails
    # one run, one dimension: the textbook chi2(1) quantiles
    lo1, hi1 = nees_interval(1, 1)
    assert lo1 == pytest.approx(0.000982, rel=1e-3) and hi1 == pytest.approx(5.0239, rel=1e-4)
    # more runs, narrower interval around the dimension
    assert (
        nees_interval(1000, 4)[1] - nees_interval(1000, 4)[0]
        < nees_interval(100, 4)[1] - nees_interval(100, 4)[0]
    )
    with pytest.raises(ValueError):
        nees_interval(0, 3)


def test_nees_of_a_consistent_filter_falls_inside_95_percent():
    """Errors drawn from the claimed covariance: the
    run-averaged NEES is inside the interval ~95% of the time."""
    rng = np.random.default_rng(1)
    runs, k, n = 10, 400, 5
    A = rng.normal(size=(n, n))
    P = np.broadcast_to(A @ A.T + n * np.eye(n), (runs, k, n, n))
    err = rng.normal(size=(runs, k, n)) @ np.linalg.cholesky(P[0, 0]).T
    T = np.array([[1, 0, 0, 0, 0], [0, 0, 1, 1, 0], [0, 0, 0, 0, 1]], dtype=float)
    avg = nees_series(err, P, T).mean(axis=0)
    lo, hi = nees_interval(runs, 3)
    inside = np.mean((avg >= lo) & (avg <= hi))
    assert 0.91 < inside < 0.99
    assert avg.mean() == pytest.approx(3.0, rel=0.05)


def test_flagged_extras_stay_out_of_the_nees():
    res = run_montecarlo(3, seed0=5, n_steps=60, include_weak=True, extra_sums=["dC_a+dq_a", "de_a+de_b"])
    kinds = {q.name: q.kind for q in res.quantities}
    assert kinds.get("de_a + de_b") == "requested sum"
    assert res.nees_dof == sum(k in ("identifiable", "identifiable combination") for k in kinds.values())
    assert "not identifiable" not in kinds.values()


def test_parse_sum():
    assert parse_sum("dq_a+dC_a") == ("dC_a", "dq_a")
    for bad in ("dC_a", "dC_a+dr_a", "dC_a+dC_a", "x+y"):
        with pytest.raises(ValueError):
            parse_sum(bad)
    assert set(STATE_NAMES) >= set(parse_sum("de_a + de_b"))


def test_cli_writes_json_and_png(tmp_path, capsys):
    from registration.cli import main

    rc = main(["montecarlo", "--runs", "3", "--steps", "60", "--ship-motion", "--out", str(tmp_path)])
    assert rc == 0
    out = capsys.readouterr().out
    assert "RMSE" in out and "NEES" in out
    doc = json.loads((tmp_path / "montecarlo.json").read_text())
    assert doc["runs"] == 3 and doc["scenario"]["ship_motion"] is not None
    assert (tmp_path / "montecarlo.png").stat().st_size > 10_000
    assert main(["montecarlo", "--runs", "1", "--out", str(tmp_path)]) == 2  # a clear error, not a traceback
