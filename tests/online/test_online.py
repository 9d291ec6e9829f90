"""Online registration filter: recovery, consistency, observability, bad rows."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

from registration.online import OnlineRegistrar, RegistrationConfig, register, validate_data
from registration.online.contract import DATA_COLUMNS, STATE_NAMES
from registration.online.scenario import ShipMotion, paper_scenario

QUIET = dict(angle_sigma=0.0, range_sigma=0.0)
SHARP = RegistrationConfig(sigma0=(1.0, 1e-4, 1e-4) * 2, linearization="relinearized")


def _identifiable_map(result) -> tuple[np.ndarray, list[str]]:
    """Rows of A pick the identifiable states and combinations (e.g. dC_a + dq_a)."""
    rows, names = [], []
    for i, name in enumerate(STATE_NAMES):
        if result.observability.status[name] == "identifiable":
            e = np.zeros(12)
            e[i] = 1
            rows.append(e)
            names.append(name)
    for comb in result.identifiable_combinations():
        e = np.zeros(12)
        e[comb["indices"]] = 1
        rows.append(e)
        names.append(comb["name"])
    return np.array(rows), names


@pytest.mark.parametrize("motion", [None, ShipMotion()], ids=["level", "rolling"])
def test_noise_off_recovers_identifiable_quantities(motion):
    scenario = paper_scenario(ship_motion=motion, **QUIET)
    result = register(scenario.data, SHARP)
    before = np.array(result.statistics()["before"]["std"])
    after = np.array(result.statistics()["after"]["std"])
    assert (after < before / 100).all(), f"residual spread {after} m did not shrink 100x from {before} m"
    A, names = _identifiable_map(result)
    assert len(names) >= 4
    err = A @ (result.final - scenario.truth_state)
    sigma = np.sqrt(np.einsum("ij,jk,ik->i", A, result.covariances[-1], A))
    assert (np.abs(err) <= 3 * sigma).all(), dict(zip(names, err / sigma))
    if motion is None:  # level ship: the heading/bearing sums are recovered to a few millidegrees
        combos = {c["name"]: c for c in result.identifiable_combinations()}
        for key, (i, j) in {"dC_a + dq_a": (0, 4), "dC_b + dq_b": (6, 10)}.items():
            truth = scenario.truth_state[i] + scenario.truth_state[j]
            assert combos[key]["estimate"] == pytest.approx(truth, abs=np.radians(0.005))
    else:  # a rolling ship makes every state identifiable
        assert len(names) == 12


def test_noisy_runs_are_consistent_across_seeds():
    """Identifiable estimates lie within 4 sigma and the NEES of the identifiable part is chi-square.

    Per seed, NEES = e^T (A P A^T)^-1 e ~ chi2(m) if the filter is consistent; summed over M seeds
    it is chi2(M m). We accept the two-sided 99 % interval; a 4-sigma bound on every single
    quantity fails by chance with probability < 0.3 % over all the checks here.
    """
    seeds = range(12)
    total, dof = 0.0, 0
    for seed in seeds:
        scenario = paper_scenario(seed=seed)
        result = register(scenario.data, RegistrationConfig(sigma0=tuple(scenario.sigma0)))
        A, names = _identifiable_map(result)
        err = A @ (result.final - scenario.truth_state)
        cov = A @ result.covariances[-1] @ A.T
        sigma = np.sqrt(np.diag(cov))
        assert (np.abs(err) <= 4 * sigma).all(), (seed, dict(zip(names, err / sigma)))
        total += float(err @ np.linalg.solve(cov, err))
        dof += len(names)
    lo, hi = stats.chi2.ppf([0.005, 0.995], dof)
    assert lo <= total <= hi, (
        f"NEES sum {total:.1f} outside the 99% interval [{lo:.1f}, {hi:.1f}] for {dof} dof"
    )


def test_nis_is_consistent():
    """Innovations are 3-D: the mean NIS over 300 steps should be near 3 (chi2(900)/300 interval)."""
    scenario = paper_scenario(seed=3)
    result = register(scenario.data, RegistrationConfig(sigma0=tuple(scenario.sigma0)))
    lo, hi = stats.chi2.ppf([0.005, 0.995], 3 * 300) / 300
    assert lo <= result.nis.mean() <= hi


def test_observability_flags_heading_bearing_on_a_level_ship_only():
    level = register(paper_scenario().data)
    texts = " | ".join(level.observability.to_json()["unobservable"])
    assert "dC_a + dq_a" in texts and "dC_b + dq_b" in texts
    assert level.observability.status["dC_a"] == "not identifiable"
    assert level.observability.status["dq_b"] == "not identifiable"
    rolling = register(paper_scenario(ship_motion=ShipMotion()).data)
    texts = " | ".join(rolling.observability.to_json()["unobservable"])
    assert "dC_a + dq_a" not in texts and "dC_b + dq_b" not in texts
    assert rolling.observability.status["dC_a"] != "not identifiable"
    assert not rolling.identifiable_combinations()


def test_paper_and_relinearized_agree_for_small_biases_and_differ_for_large():
    small = paper_scenario(
        ship_motion=ShipMotion(),
        range_bias=10.0,
        angle_bias=np.radians(0.01),
        heading_error=np.radians(0.002),
        level_error=np.radians(0.001),
        **QUIET,
    )
    cfg = dict(sigma0=(1.0, 1e-4, 1e-4) * 2)
    a = register(small.data, RegistrationConfig(linearization="paper", **cfg))
    for lin in ("relinearized", "fitted"):
        b = register(small.data, RegistrationConfig(linearization=lin, **cfg))
        assert (np.abs(a.final - b.final) < 0.01 * a.final_sigma).all(), (
            lin,
            np.abs(a.final - b.final) / a.final_sigma,
        )
    # Large errors: the paper linearises at the raw measurements, so second-order terms
    # (range x angle error^2 ~ 60 km x (3 deg)^2 / 2 ~ 80 m) stay in its residual.
    large = paper_scenario(
        ship_motion=ShipMotion(),
        range_bias=5000.0,
        angle_bias=np.radians(3.0),
        heading_error=np.radians(0.6),
        level_error=np.radians(0.2),
        **QUIET,
    )
    prior = (np.radians(2),) * 3 + (10000.0,) + (np.radians(6),) * 2
    a = register(large.data, RegistrationConfig(linearization="paper", prior_sigma=prior * 2, **cfg))
    b = register(large.data, RegistrationConfig(linearization="relinearized", prior_sigma=prior * 2, **cfg))
    res_a = np.array(a.statistics()["after"]["std"])
    res_b = np.array(b.statistics()["after"]["std"])
    assert np.linalg.norm(res_b) < 0.7 * np.linalg.norm(res_a), (res_a, res_b)
    # fitted: while P is large its linearisation point stays at the corrected plots, so it
    # removes the second-order residuals like relinearized (a fused-target point would not)
    c = register(large.data, RegistrationConfig(linearization="fitted", prior_sigma=prior * 2, **cfg))
    res_c = np.array(c.statistics()["after"]["std"])
    assert np.linalg.norm(res_c) < 0.7 * np.linalg.norm(res_a), (res_a, res_c)


def test_streaming_update_equals_batch():
    scenario = paper_scenario(n_steps=50, seed=5)
    batch = register(scenario.data)
    reg = OnlineRegistrar()
    for k in range(50):
        row = {c: scenario.data[c][k] for c in DATA_COLUMNS[1:]}
        out = reg.update(row, time=float(scenario.data["time"][k]))
    assert np.allclose(out["x"], batch.final, rtol=1e-12, atol=1e-15)
    assert np.allclose(reg.P, batch.covariances[-1], rtol=1e-12, atol=1e-18)
    assert np.allclose(reg.info, batch.information, rtol=1e-12)


def test_adaptive_q_is_the_window_covariance():
    scenario = paper_scenario(n_steps=40, seed=2)
    cfg = RegistrationConfig(q_mode="adaptive", q_window=10)
    result = register(scenario.data, cfg)
    assert np.isfinite(result.estimates).all()
    reg = OnlineRegistrar(cfg)
    for k in range(40):
        reg.update(np.array([scenario.data[c][k] for c in DATA_COLUMNS[1:]]))
    window = result.estimates[-10:]
    dev = window - window.mean(axis=0)
    expected = dev.T @ dev / 10 + np.diag(np.square(cfg.q_sigma))
    assert np.allclose(reg.process_noise(), expected, rtol=1e-10, atol=1e-20)


def _bad(column, value, row=7):
    data = {k: np.array(v, dtype=float) for k, v in paper_scenario(n_steps=20).data.items()}
    data[column][row] = value
    return data


@pytest.mark.parametrize(
    "column,value,message",
    [
        ("a_range", np.nan, "not finite"),
        ("b_range", 0.0, "must be > 0 m"),
        ("a_range", -3.0, "must be > 0 m"),
        ("b_lat", 2.0, r"outside \[-1.5708, 1.5708\] rad"),
        ("a_lat", 45.0, "look like degrees"),
        ("b_elevation", np.inf, "not finite"),
    ],
)
def test_bad_rows_name_row_and_column(column, value, message):
    with pytest.raises(ValueError, match=rf"row 7, column '{column}'.*{message}"):
        register(_bad(column, value))


def test_timestamps_must_increase():
    data = paper_scenario(n_steps=20).data
    data["time"] = data["time"].copy()
    data["time"][5] = data["time"][4]
    with pytest.raises(ValueError, match=r"row 5, column 'time'.*strictly increasing"):
        validate_data(data)
    data["time"][5] = data["time"][3]
    with pytest.raises(ValueError, match=r"row 5, column 'time'"):
        validate_data(data)


def test_missing_column_is_named():
    data = dict(paper_scenario(n_steps=5).data)
    del data["b_roll"]
    with pytest.raises(ValueError, match="b_roll"):
        register(data)


@pytest.mark.parametrize("column,value", [("a_range", np.nan), ("b_range", -1.0), ("a_lat", 3.0)])
def test_bad_row_leaves_streaming_state_untouched(column, value):
    scenario = paper_scenario(n_steps=10)
    reg = OnlineRegistrar()
    for k in range(5):
        reg.update({c: scenario.data[c][k] for c in DATA_COLUMNS[1:]})
    x, P, info, n = reg.x.copy(), reg.P.copy(), reg.info.copy(), reg.n_updates
    row = {c: scenario.data[c][5] for c in DATA_COLUMNS[1:]}
    row[column] = value
    with pytest.raises(ValueError, match=column):
        reg.update(row)
    assert np.array_equal(reg.x, x) and np.array_equal(reg.P, P) and np.array_equal(reg.info, info)
    assert reg.n_updates == n


def test_config_rejects_degrees_and_unknown_modes():
    with pytest.raises(ValueError, match="sigma0"):
        RegistrationConfig(sigma0=(50, 0.5, 0.5, 50, 0.5, 0.5))
    with pytest.raises(ValueError, match="linearization"):
        RegistrationConfig(linearization="iterated")
    with pytest.raises(ValueError, match="q_mode"):
        RegistrationConfig(q_mode="auto")


def test_paper_t_variant_tilts_absolute_positions_but_not_the_relative_registration():
    """The paper's T (eq. 4 as printed) is the standard T at the latitude psi with tan psi = (a/b)^2 tan B:
    a tilt delta = psi - B (about 0.12 deg at 20 N). It moves each target position by about r * delta,
    but both ships share it, so X_A - X_B and the registration estimates hardly change."""
    scenario = paper_scenario(n_steps=150)
    std = register(scenario.data, RegistrationConfig(t_variant="standard"))
    pap = register(scenario.data, RegistrationConfig(t_variant="paper"))
    a, b = 6378137.0, 6356752.314245  # WGS-84 semi-axes (m)
    lat = scenario.data["a_lat"]
    delta = np.arctan((a / b) ** 2 * np.tan(lat)) - lat
    moved = np.linalg.norm(std.corrected_a_ecef - pap.corrected_a_ecef, axis=1)
    ratio = moved / (scenario.data["a_range"] * delta)
    assert 0.8 < ratio.min() and ratio.max() < 1.05, (ratio.min(), ratio.max())
    assert np.linalg.norm(std.raw_difference_ecef - pap.raw_difference_ecef, axis=1).max() < 0.1 * moved.min()
    assert np.all(np.abs(std.final - pap.final) < 0.05 * std.final_sigma)


def test_information_matrix_equals_per_row_solves():
    from registration.online.information import information_matrix

    rng = np.random.default_rng(3)
    H = rng.normal(size=(50, 3, 12)) * np.array([1e3, 1.0, 1e-2])[None, :, None]
    A = rng.normal(size=(50, 3, 3))
    R = A @ A.transpose(0, 2, 1) + 0.1 * np.eye(3)
    ref = sum(H[k].T @ np.linalg.solve(R[k], H[k]) for k in range(50))
    J = information_matrix(H, R)
    assert np.allclose(J, ref, rtol=1e-9, atol=1e-12 * np.abs(ref).max())
    assert np.array_equal(J, J.T)


def test_information_at_estimate_compiled_equals_numpy_and_skips_extreme_rows():
    from registration.online.contract import correct_rows
    from registration.online.information import (
        information_at_estimate,
        information_skipping_bad_rows,
        pair_model,
    )

    sc = paper_scenario(seed=2, n_steps=80)
    cfg = RegistrationConfig(sigma0=tuple(sc.sigma0))
    _, rows = validate_data(sc.data)
    x = sc.truth_state
    pair = pair_model(correct_rows(rows, np.broadcast_to(x, (len(rows), 12))), cfg.sigma0, cfg.t_variant)
    ref, _ = information_skipping_bad_rows(pair["H"], pair["R"])
    J, used = information_at_estimate(rows, x, cfg.sigma0, cfg.t_variant)
    assert used == 80 and np.allclose(J, ref, rtol=1e-10, atol=1e-12 * np.abs(ref).max())
    bad = rows.copy()
    bad[5, 7] = np.nan  # a bearing that slipped through: its term is not finite
    J_bad, used_bad = information_at_estimate(bad, x, cfg.sigma0, cfg.t_variant)
    assert used_bad == 79 and np.isfinite(J_bad).all()
    keep = np.arange(80) != 5
    assert np.allclose(
        J_bad, information_at_estimate(rows[keep], x, cfg.sigma0, cfg.t_variant)[0], rtol=1e-10
    )


def test_scalars_and_file_columns_get_a_message_that_says_what_to_do():
    scenario = paper_scenario(n_steps=10)
    with pytest.raises(
        ValueError, match="column 'time': expected a 1-D array with one value per row, got a single value"
    ):
        register({k: float(v[0]) for k, v in scenario.data.items()})
    file_named = {
        ("time_s" if k == "time" else f"{k}_deg" if k.endswith(("lat", "lon")) else k): v
        for k, v in scenario.data.items()
    }
    with pytest.raises(
        ValueError, match=r"missing column\(s\).*read the file with registration.recorded.read_table"
    ):
        register(file_named)
    with pytest.raises(ValueError, match="column 'a_lat': 10 values, but 'time' has 9"):
        register({**scenario.data, "time": scenario.data["time"][:9]})


def test_update_takes_a_dataframe_row_and_refuses_several():
    pd = pytest.importorskip("pandas")
    scenario = paper_scenario(n_steps=10)
    frame = pd.DataFrame(scenario.data)
    by_series, by_frame, by_array = OnlineRegistrar(), OnlineRegistrar(), OnlineRegistrar()
    for i in range(3):
        a = by_series.update(frame.iloc[i].drop("time"))
        b = by_frame.update(frame.iloc[[i]])
        c = by_array.update(frame.iloc[i][list(DATA_COLUMNS[1:])].to_numpy())
        np.testing.assert_array_equal(a["x"], c["x"])
        np.testing.assert_array_equal(b["x"], c["x"])
    with pytest.raises(ValueError, match="holds 2 values; update\\(\\) takes one row"):
        by_frame.update(frame.iloc[[4, 5]])
    assert by_frame.n_updates == 3


def test_result_prints_in_one_line():
    text = repr(register(paper_scenario(n_steps=20).data))
    assert text.startswith("RegistrationResult(20 rows") and "\n" not in text and len(text) < 200


def test_a_sum_of_ranges_is_tabulated_in_metres():
    from registration.core.observability import ObservabilityReport
    from registration.online.result import estimate_rows

    report = ObservabilityReport(np.ones(12), status={n: "weak" for n in STATE_NAMES})
    from registration.core.observability import Combination

    report.unobservable.append(Combination({}, 0.0, "dr_a + dr_b", identifiable_sum=("dr_a", "dr_b")))
    rows = estimate_rows(np.arange(12.0), np.eye(12), report)
    assert rows[-1]["name"] == "dr_a + dr_b" and rows[-1]["unit"] == "m" and rows[-1]["estimate"] == 3.0 + 9.0
