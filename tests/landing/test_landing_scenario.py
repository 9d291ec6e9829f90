"""The default carrier approach end to end: Monte Carlo RMSE ordering, covariance consistency, CLI.

Statistical reasoning. A Monte Carlo run is one independent realisation of every noise sample of
both sensors along the whole approach (same clocks, same trajectory). Within a run the fusion
instants of a range bin are correlated (overlapping alignment windows), but runs are i.i.d., so
every per-run bin statistic (MSE, NEES sum) is an i.i.d. sample across runs and its mean has the
standard error std/sqrt(R). With pooled RMSE and the same instants in every run,
"RMSE_fused <= RMSE_camera" in a bin is exactly "mean over runs of (MSE_camera - MSE_fused) >= 0";
the paired z-score of that mean is about 7 to 10 per bin at R = 100 on the default scenario (the
expected gain is small, ~0.5 % of RMSE, because the shared radar range error dominates, but the
paired difference has little variance). So a correct fusion fails the ordering with probability
about Phi(-7) ~ 1e-12 per bin, while swapping the weights (negative control) fails it at once.
The seed is fixed anyway, so the test is deterministic.
"""

from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest

from registration import cli
from registration.landing import (
    combine,
    deck_to_touchdown_rotation,
    default_scenario,
    monte_carlo,
    process,
    regroup,
    run_once,
    simulate,
    with_overrides,
)

RUNS = 100


@pytest.fixture(scope="module")
def default_mc():
    sc = default_scenario()
    return sc, monte_carlo(sc, runs=RUNS, seed=20240501)


def test_scenario_kinematics():
    sc = default_scenario()
    c = sc.closure_speed_mps
    # |v_ship + c d| = ground speed, with the ship's velocity along its mean heading
    d = -sc.glide_direction_mtd
    v_ship = deck_to_touchdown_rotation(np.zeros(3), sc.geometry)[0] @ [0.0, sc.ship.speed_mps, 0.0]
    assert np.linalg.norm(v_ship + c * d) == pytest.approx(70.0)
    assert 50 < c < 60
    p0, p1 = sc.truth_td([0.0, sc.duration_s])
    # starts 4 km up the glide path, ends at the touchdown point; the deck's heave moves both a little
    assert np.linalg.norm(p0) == pytest.approx(4000.0, abs=5.0)
    assert np.linalg.norm(p1) < 5.0
    assert np.degrees(np.arctan2(p0[2], p0[0])) == pytest.approx(3.5, abs=0.1)


def test_simulated_sensor_tracks_have_the_requested_rates_and_clocks():
    sc = default_scenario()
    sim = simulate(sc, runs=3, rng=0)
    assert np.diff(sim.true_t_radar) == pytest.approx(0.05)
    assert np.diff(sim.true_t_camera) == pytest.approx(0.04)
    assert sim.t_camera - sim.true_t_camera == pytest.approx(0.004)
    assert sim.polar_rdr.shape == (3, sim.t_radar.size, 3) and sim.angles_cam.shape == (
        3,
        sim.t_camera.size,
        2,
    )
    resid = sim.polar_rdr - sc.truth_radar(sim.true_t_radar)[None]
    assert resid.std(axis=(0, 1)) == pytest.approx(sc.radar.sigma, rel=0.05)


def test_fused_rmse_is_at_most_the_better_input_in_every_bin(default_mc):
    sc, mc = default_mc
    assert mc.count.min() > 50  # every 500 m bin is populated (~90 instants per run)
    radar, camera, fused = mc.rmse("radar"), mc.rmse("camera"), mc.rmse("paper")
    better = np.minimum(radar, camera)
    assert np.all(fused <= better), np.c_[radar, camera, fused]
    z = mc.paired_z("paper", "camera")
    assert np.all(z > 3), z  # not luck: observed ~7-10 (see the module docstring)
    assert np.all(mc.paired_z("paper", "radar") > 3)


def test_joint_update_is_not_worse_than_eq12_and_wins_near_touchdown(default_mc):
    _, mc = default_mc
    joint, fused = mc.rmse("information"), mc.rmse("paper")
    assert joint[0] < 0.8 * fused[0]  # the camera angles pin down the radar's range error at close range
    # elsewhere equal within Monte Carlo error (both ~ unbiased, joint variance <= eq. 12 variance)
    assert np.all(joint <= fused * 1.002)


def test_predicted_covariances_are_consistent(default_mc):
    """Mean NEES of the touchdown-frame position is 3 per instant if P_td is right. Per-run bin sums
    are i.i.d. across runs: |mean NEES - 3| must be within 5 standard errors for every method and bin."""
    _, mc = default_mc
    for m in mc.methods:
        per_run = mc.nees_sum[m] / mc.count  # (R, B) mean NEES per run and bin
        se = per_run.std(axis=0, ddof=1) / np.sqrt(mc.runs)
        assert np.all(np.abs(per_run.mean(axis=0) - 3.0) < 5 * se + 0.02), (m, per_run.mean(axis=0), se)


def test_swapped_weights_break_the_ordering():
    """Negative control: weighting each sensor by the *other's* variance must lose to the camera."""
    sc = default_scenario()
    sim = simulate(sc, runs=20, rng=5)
    res = run_once(sim, sc.config(methods=("camera", "paper")))
    rt, ct = res.radar, res.camera
    swapped = replace(ct, P_ctd=rt.P_ctd[:, 1:, 1:].copy())
    swapped_rt = replace(
        rt,
        P_ctd=np.concatenate(
            [
                np.concatenate([rt.P_ctd[:, :1, :1], np.zeros((rt.P_ctd.shape[0], 1, 2))], axis=2),
                np.concatenate([np.zeros((rt.P_ctd.shape[0], 2, 1)), ct.P_ctd], axis=2),
            ],
            axis=1,
        ),
    )
    att = np.tile(res.attitude, (res.runs, 1))
    bad = combine(swapped_rt, swapped, att, sc.geometry, "paper")
    truth = np.tile(sc.truth_td(res.t), (res.runs, 1))
    mse_bad = np.mean(np.sum((bad.p_td - truth) ** 2, axis=1))
    mse_cam = np.mean(np.sum((res.estimates["camera"].p_td - truth) ** 2, axis=1))
    assert mse_bad > 1.05 * mse_cam


def test_uncorrected_clock_offset_shows_up_as_inconsistency():
    """A 20 ms camera clock offset left uncorrected biases the camera angles (deck motion moves them
    by ~20 mrad/s): the fused NEES rises well above 3; corrected, it is 3."""
    sc = with_overrides(default_scenario(), camera={"clock_offset_s": 0.020})
    good = monte_carlo(sc, sc.config(), runs=30, seed=3)
    bad = monte_carlo(sc, sc.config(camera_clock_offset_s=0.0), runs=30, seed=3)
    n_good = good.nees_sum["paper"].sum() / (good.count.sum() * good.runs)
    n_bad = bad.nees_sum["paper"].sum() / (bad.count.sum() * bad.runs)
    assert n_good == pytest.approx(3.0, abs=0.1)
    assert n_bad > 4.0


def test_regrouped_fine_bins_equal_the_coarse_bins_computed_directly():
    """The CLI computes 100 m bins once and merges them into 500 m bins: same statistics."""
    sc = default_scenario()
    fine = monte_carlo(sc, runs=4, seed=9, bin_edges_m=np.arange(0.0, 4050.0, 100.0))
    coarse = monte_carlo(sc, runs=4, seed=9, bin_edges_m=np.arange(0.0, 4250.0, 500.0))
    merged = regroup(fine, coarse.bin_edges_m)
    assert merged.count.tolist() == coarse.count.tolist() and coarse.count.sum() > 0
    for m in coarse.methods:
        assert merged.sse[m] == pytest.approx(coarse.sse[m], rel=1e-12)
        assert merged.nees_sum[m] == pytest.approx(coarse.nees_sum[m], rel=1e-12)
        assert merged.polar_sse[m] == pytest.approx(coarse.polar_sse[m], rel=1e-12)
    with pytest.raises(ValueError, match="coarse bin edges must be fine bin edges"):
        regroup(fine, np.array([0.0, 250.0, 4000.0]))


def test_cli_writes_summary_and_plots(tmp_path, capsys):
    out = tmp_path / "landing"
    code = cli.main(["landing", "--out", str(out), "--runs", "6", "--seed", "2"])
    assert code == 0
    text = capsys.readouterr().out
    assert "range bin (m)" in text and "fused (m)" in text
    summary = json.loads((out / "summary.json").read_text())
    assert len(summary["bins"]) == 8
    for b in summary["bins"]:
        assert set(b) >= {"range_min_m", "range_max_m", "rmse_radar_m", "rmse_camera_m", "rmse_fused_m"}
        assert all(np.isfinite(b[k]) and b[k] > 0 for k in ("rmse_radar_m", "rmse_camera_m", "rmse_fused_m"))
    assert summary["bins"][0]["range_min_m"] == 0.0 and summary["bins"][-1]["range_max_m"] == 4000.0
    for name in ("attitude.png", "variance_ratios.png", "rmse.png", "fused_polar.png"):
        assert (out / name).stat().st_size > 20_000, name


def test_cli_rejects_bad_options(tmp_path, capsys):
    assert cli.main(["landing", "--out", str(tmp_path), "--runs", "1"]) == 2
    assert "--runs: expected at least 2" in capsys.readouterr().err
    assert cli.main(["landing", "--out", str(tmp_path), "--plot-bin-m", "300"]) == 2
    assert "must divide --bin-m" in capsys.readouterr().err
    assert cli.main(["landing", "--out", str(tmp_path), "--roll-deg", "60"]) == 2
    assert "roll_amplitude_rad" in capsys.readouterr().err


def test_process_refuses_bad_tracks_with_the_alignment_messages():
    sc = default_scenario()
    sim = simulate(sc, runs=1, rng=1)
    args = dict(
        sigma_rdr=sc.radar.sigma, sigma_cam=sc.camera.sigma, attitude_fn=sc.attitude, geometry=sc.geometry
    )
    t_bad = sim.t_radar.copy()
    t_bad[10] = t_bad[9]
    with pytest.raises(ValueError, match="radar track .*t: duplicate timestamp"):
        process(t_bad, sim.polar_rdr, t_camera=sim.t_camera, angles_cam=sim.angles_cam, **args)
    ang = sim.angles_cam.copy()
    ang[0, 5, 1] = np.nan
    with pytest.raises(ValueError, match="camera track .*y: non-finite sample nan at index 5"):
        process(sim.t_radar, sim.polar_rdr, t_camera=sim.t_camera, angles_cam=ang, **args)
    with pytest.raises(ValueError, match=r"polar_rdr: expected shape \(\d+, 3\) or \(R, \d+, 3\)"):
        process(sim.t_radar, sim.polar_rdr[:, :-1], t_camera=sim.t_camera, angles_cam=sim.angles_cam, **args)
