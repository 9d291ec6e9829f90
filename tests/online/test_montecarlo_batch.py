"""Monte Carlo as one batch: the scenarios of many seeds at once, all runs' filters in one compiled
call, and the statistics, each equal bit for bit to the run-by-run definition (paper_scenario and
register() per seed); the Cramér-Rao bound is the same in every run and computed once."""

from __future__ import annotations

import numpy as np
import pytest

from registration.online import RegistrationConfig, register
from registration.online.contract import DATA_COLUMNS, N_STATE, ROW_COLUMNS
from registration.online.crlb import crlb_from_information, crlb_information, quadratic_forms
from registration.online.montecarlo import run_montecarlo
from registration.online.runs import check_run_rows, filter_runs, information_at_estimates
from registration.online.scenario import ShipMotion, paper_scenario, paper_scenarios

SEEDS = (3, 4, 5)
KW = dict(n_steps=40, ship_motion=ShipMotion())


@pytest.fixture(scope="module")
def sims():
    return paper_scenarios(SEEDS, **KW)


@pytest.mark.parametrize(
    "kwargs", [KW, dict(n_steps=30, dt=1, t_variant="paper", antenna_height=35.0, range_sigma=20.0)]
)
def test_scenarios_of_many_seeds_equal_one_scenario_per_seed(kwargs):
    sims = paper_scenarios(SEEDS, **kwargs)
    assert sims.rows.shape == (len(SEEDS), kwargs["n_steps"], len(ROW_COLUMNS))
    for i, seed in enumerate(SEEDS):
        one, again = paper_scenario(seed, **kwargs), sims.scenario(i)
        for sc in (one, again):
            assert list(sc.data) == list(DATA_COLUMNS)
            np.testing.assert_array_equal(sims.rows[i], np.stack([sc.data[c] for c in ROW_COLUMNS], axis=1))
            assert sc.data["time"].dtype == np.asarray(kwargs.get("dt", 1.0) * np.arange(2)).dtype
        for key in one.truth:
            np.testing.assert_array_equal(one.truth[key], again.truth[key])
        assert one.description == again.description and one.description["seed"] == seed


def test_scenarios_are_independent_copies_of_the_cached_tracks():
    a, b = paper_scenario(0, n_steps=20), paper_scenario(0, n_steps=20)
    a.data["a_lat"][:] = 0.0
    a.truth["a_plot"][:] = 0.0
    assert b.data["a_lat"][0] != 0.0 and b.truth["a_plot"][0, 0] != 0.0
    assert paper_scenario(0, n_steps=20).data["a_lat"][0] == b.data["a_lat"][0]
    assert (
        not paper_scenarios((0,), n_steps=20).truth["a_plot"].flags.writeable
    )  # the cache cannot be changed


@pytest.mark.parametrize(
    "config",
    [RegistrationConfig(), RegistrationConfig(q_mode="adaptive", q_window=5)],
    ids=["fixed", "adaptive"],
)
def test_filter_runs_equal_register_per_run(sims, config):
    out = filter_runs(config, sims.rows)
    J = information_at_estimates(sims.rows, out["x"][:, -1], config.sigma0, config.t_variant)
    for i in range(len(SEEDS)):
        res = register(sims.scenario(i).data, config)
        np.testing.assert_array_equal(out["x"][i], res.estimates)
        np.testing.assert_array_equal(out["P"][i], res.covariances)
        np.testing.assert_array_equal(out["nis"][i], res.nis)
        np.testing.assert_array_equal(out["info"][i], res.information)
        np.testing.assert_array_equal(J[i], res.information_at_estimate)


def test_a_bad_row_or_a_failing_step_names_the_run(sims):
    rows = sims.rows.copy()
    rows[1, 7, ROW_COLUMNS.index("b_range")] = -1.0
    with pytest.raises(ValueError, match=r"run 1: row 7, column 'b_range'"):
        check_run_rows(rows)
    check_run_rows(sims.rows)
    rows[1, 7, ROW_COLUMNS.index("b_range")] = 1e300  # accepted, but the step overflows
    with pytest.raises(RuntimeError, match="run 1: row 7: the filter step produced non-finite values"):
        filter_runs(RegistrationConfig(), rows)


def test_the_bound_is_the_same_in_every_run():
    """It uses only the exact navigation, the true attitude and the true plots: computed once."""
    infos = [crlb_information(paper_scenario(seed, **KW)) for seed in SEEDS]
    for info in infos[1:]:
        np.testing.assert_array_equal(info, infos[0])


def test_montecarlo_equals_register_run_by_run():
    """Every statistic from the per-seed definition: paper_scenario + register() per run."""
    cfg = RegistrationConfig()
    res = run_montecarlo(len(SEEDS), seed0=SEEDS[0], config=cfg, extra_sums=["de_a+de_b"], **KW)
    err, P, nis = [], [], []
    for seed in SEEDS:
        sc = paper_scenario(seed, **KW)
        r = register(sc.data, cfg)
        err.append(r.estimates - sc.truth_state)
        P.append(r.covariances)
        nis.append(r.nis)
        assert {q.name for q in res.quantities if q.kind == "identifiable"} <= {
            n for n, s in r.observability.status.items() if s == "identifiable"
        }
    err, P = np.array(err), np.array(P)
    T = np.array([q.direction for q in res.quantities]).reshape(-1, N_STATE)
    e_q = err @ T.T
    var_q = np.einsum("qi,rkij,qj->rkq", T, P, T, optimize=True)
    np.testing.assert_array_equal(res.rmse, np.sqrt(np.mean(e_q**2, axis=0)))
    np.testing.assert_array_equal(res.mean_error, np.mean(e_q, axis=0))
    np.testing.assert_array_equal(res.filter_sigma, np.sqrt(np.mean(var_q, axis=0)))
    np.testing.assert_array_equal(res.nis, np.mean(nis, axis=0))
    crlb = crlb_from_information(crlb_information(paper_scenario(SEEDS[0], **KW)), cfg.prior_sigma)
    np.testing.assert_array_equal(
        res.crlb_sigma, np.sqrt(np.clip(np.einsum("qi,kij,qj->kq", T, crlb, T), 0.0, None))
    )
    assert sum(res.status_counts["dr_a"].values()) == len(SEEDS)


@pytest.mark.parametrize("rows", [[[3]], [[0, 4], [3], [6, 10]], [[1, 2], [0, 11]]])
def test_quadratic_forms_of_states_and_sums_equal_the_einsum(rows):
    """Gathered T P T^T equals numpy.einsum's bit for bit (each stage adds at most two terms)."""
    rng = np.random.default_rng(2)
    A = rng.normal(size=(4, 7, N_STATE, N_STATE)) * np.logspace(-8, 3, N_STATE)
    P = A @ A.swapaxes(-1, -2)
    T = np.zeros((len(rows), N_STATE))
    for q, idx in enumerate(rows):
        T[q, idx] = 1.0
    np.testing.assert_array_equal(
        quadratic_forms(P, T), np.einsum("qi,rkij,pj->rkqp", T, P, T, optimize=True)
    )
    np.testing.assert_array_equal(
        quadratic_forms(P, T, diagonal=True), np.einsum("qi,rkij,qj->rkq", T, P, T, optimize=True)
    )
    W = T * 0.5  # any other direction goes through the einsum
    np.testing.assert_array_equal(
        quadratic_forms(P, W), np.einsum("qi,rkij,pj->rkqp", W, P, W, optimize=True)
    )
