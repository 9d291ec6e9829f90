"""Landing capability (registration.landing): frame conventions, round trips, error transfer, fusion.

Monte Carlo statistics used below. For N independent draws x_i ~ N(mu, P) pushed through a
function f, the sample covariance S of f(x_i) is compared with the predicted ``J P J^T`` after
whitening by the prediction's Cholesky factor L: ``W = L^-1 S L^-T`` should be the identity up
to sampling error, whose standard deviation is sqrt(2/N) on the diagonal and sqrt(1/N) off it
(Wishart). We accept |W - I| < 5 sqrt(2/N) entrywise (false alarm < 1e-5 per entry). The
linearisation error is of order (sigma / range)^2 < 1e-3 at the geometries used, far below the
tolerance (0.035 at N = 40000). A negative control shows that a wrong transfer (the rotation M
left out) fails the same check by a wide margin.
"""

from __future__ import annotations

import numpy as np
import pytest

from registration import _codegen
from registration.landing import (
    LandingGeometry,
    combine,
    deck_to_touchdown_rotation,
    default_geometry,
    radar_to_touchdown,
    transfer_camera,
    transfer_radar,
    variance_ratios,
)

GEOM = default_geometry()
ATT = np.array([0.006, 0.015, -0.03])  # yaw, pitch, roll (rad): a few tenths of a degree to 2 deg
SIG_R = np.array([3.0, 1e-3, 1e-3])
SIG_C = np.array([3e-4, 3e-4])


def _level_geometry(angled_deck=0.0):
    z = np.zeros(3)
    return LandingGeometry(angled_deck, z, z, z)


def _radar_polar_of(p_td, att=ATT, geom=GEOM):
    return _codegen.get("landing_td2radar")(p_td, att, geom.angled_deck_rad, geom.d_radar_deck_m)[0]


def _camera_angles_of(p_td, att=ATT, geom=GEOM):
    return _codegen.get("landing_td2camera")(p_td, att, geom.angled_deck_rad, geom.d_camera_deck_m)[0]


# --------------------------------------------------------------------------- conventions
def test_dead_astern_on_a_level_ship_is_plus_x_in_the_touchdown_frame():
    """Radar at the touchdown point, no angled deck: azimuth -90 deg (from starboard, towards the
    bow positive) is dead astern, which is +x_td (the approach direction)."""
    p, _ = radar_to_touchdown([100.0, -np.pi / 2, 0.0], np.zeros(3), _level_geometry())
    assert p[0] == pytest.approx([100.0, 0.0, 0.0], abs=1e-9)


def test_angled_deck_centreline_points_aft_and_to_starboard():
    """9 deg angled deck (forward end to port): x_td, seen in deck axes, is aft (-y) and starboard (+x)."""
    M0 = deck_to_touchdown_rotation(np.zeros(3), GEOM)[0]
    x_td_in_deck = M0.T @ [1.0, 0.0, 0.0]
    assert x_td_in_deck == pytest.approx([np.sin(np.radians(9)), -np.cos(np.radians(9)), 0.0], abs=1e-12)


def test_positive_pitch_lowers_the_stern_so_the_aircraft_appears_higher():
    """The touchdown point is 105 m aft of the motion centre: 0.01 rad bow-up pitch drops it ~1 m,
    so a point fixed in the mean frame is ~1 m higher in the (deck-following) touchdown frame."""
    p = _codegen.get("landing_mtd2td")(
        np.zeros(3), [0.0, 0.01, 0.0], GEOM.angled_deck_rad, GEOM.l_touchdown_deck_m
    )[0][0]
    assert p[2] == pytest.approx(105.0 * np.sin(0.01) + 20.0 * (1 - np.cos(0.01)), abs=1e-3)


def test_positive_roll_lowers_starboard():
    """A deck point 10 m to starboard of the touchdown point (camera there) moves down with roll."""
    z = np.zeros(3)
    g = LandingGeometry(0.0, z, z, np.array([10.0, 0.0, 0.0]))
    polar = _codegen.get("landing_td2ctd")(
        np.array([1000.0, 0.0, 0.0]), [0.0, 0.0, 0.02], 0.0, g.d_camera_deck_m
    )[0][0]
    assert polar[2] > 0  # the camera went down, so the target is seen higher


def test_positive_yaw_turns_the_bow_to_starboard():
    """Yaw 0.1 rad: the deck's bow axis, seen in td axes (x aft, y starboard-ish when phi_c = 0)."""
    M = deck_to_touchdown_rotation([0.1, 0.0, 0.0], _level_geometry())[0]
    bow_td = M @ [0.0, 1.0, 0.0]
    assert bow_td == pytest.approx([-np.cos(0.1), np.sin(0.1), 0.0], abs=1e-12)


# --------------------------------------------------------------------------- round trips
@pytest.fixture(scope="module")
def approach_points():
    rng = np.random.default_rng(2)
    s = rng.uniform(20.0, 4000.0, 300)
    g = np.radians(3.5)
    p = np.stack([s * np.cos(g), rng.normal(0, 5, s.size), s * np.sin(g) + rng.normal(0, 2, s.size)], axis=1)
    att = rng.uniform(-1, 1, (s.size, 3)) * [0.01, 0.02, 0.035]
    return p, att


def test_radar_round_trip(approach_points):
    p, att = approach_points
    back, _ = radar_to_touchdown(_radar_polar_of(p, att), att, GEOM)
    assert back == pytest.approx(p, abs=1e-9 * 4000)


def test_camera_angles_agree_with_the_ctd_polar_of_the_point(approach_points):
    p, att = approach_points
    cam = transfer_camera(_camera_angles_of(p, att), np.diag(SIG_C**2), att, GEOM)
    polar = _codegen.get("landing_td2ctd")(p, att, GEOM.angled_deck_rad, GEOM.d_camera_deck_m)[0]
    assert cam.angles_ctd == pytest.approx(polar[:, 1:], abs=1e-12)


def test_rebuild_from_ctd_polar_is_the_inverse(approach_points):
    p, att = approach_points
    polar = _codegen.get("landing_td2ctd")(p, att, GEOM.angled_deck_rad, GEOM.d_camera_deck_m)[0]
    back = _codegen.get("landing_ctd2td")(polar, att, GEOM.angled_deck_rad, GEOM.d_camera_deck_m)[0]
    assert back == pytest.approx(p, abs=1e-9 * 4000)


def test_bma_is_the_product_of_the_papers_three_matrices(approach_points):
    """Eq. (10): the emitted dpolar_ctd/dpolar_rdr equals B M A built from the separate outputs."""
    p, att = approach_points
    rt = transfer_radar(_radar_polar_of(p, att), np.diag(SIG_R**2), att, GEOM)
    assert rt.BMA == pytest.approx(rt.B @ rt.M @ rt.A, rel=1e-10, abs=1e-14)
    assert rt.M == pytest.approx(deck_to_touchdown_rotation(att, GEOM), abs=1e-15)
    assert np.einsum("nij,nkj->nik", rt.M, rt.M) == pytest.approx(
        np.broadcast_to(np.eye(3), rt.M.shape), abs=1e-14
    )


# --------------------------------------------------------------------------- error transfer, Monte Carlo
N_MC = 40000
TOL = 5 * np.sqrt(2 / N_MC)


def _whitened_error(samples: np.ndarray, P_pred: np.ndarray, angle_cols=()) -> float:
    d = samples - samples.mean(axis=0)
    for k in angle_cols:
        d[:, k] = np.angle(np.exp(1j * d[:, k]))
    S = d.T @ d / (len(d) - 1)
    Linv = np.linalg.inv(np.linalg.cholesky(P_pred))
    W = Linv @ S @ Linv.T
    return float(np.abs(W - np.eye(len(W))).max())


@pytest.mark.parametrize("slant_m", [120.0, 600.0, 3500.0])
def test_transferred_radar_covariance_matches_monte_carlo(slant_m):
    rng = np.random.default_rng(int(slant_m))
    g = np.radians(3.5)
    p_true = np.array([slant_m * np.cos(g), 3.0, slant_m * np.sin(g)])
    polar_true = _radar_polar_of(p_true)[0]
    P_R = np.diag(SIG_R**2)
    P_R[1, 2] = P_R[2, 1] = 0.3 * SIG_R[1] * SIG_R[2]  # a correlated radar, for generality
    draws = rng.multivariate_normal(polar_true, P_R, N_MC)
    moved = _codegen.get("landing_radar2ctd")(
        draws, ATT, GEOM.angled_deck_rad, GEOM.d_radar_deck_m, GEOM.d_camera_deck_m
    )[0]
    rt = transfer_radar(polar_true, P_R, ATT, GEOM)
    assert _whitened_error(moved, rt.P_ctd[0], angle_cols=(1,)) < TOL
    # negative control: leaving the rotation M out (B A instead of B M A) is detected, by > 25
    # sampling standard deviations even at 3.5 km where M mostly just shifts the azimuth origin
    wrong = rt.B[0] @ rt.A[0]
    assert _whitened_error(moved, wrong @ P_R @ wrong.T, angle_cols=(1,)) > 5 * TOL


def test_transferred_camera_covariance_matches_monte_carlo():
    rng = np.random.default_rng(7)
    att = np.array([0.008, -0.017, 0.035])
    ang_true = np.array([0.02, 0.06])
    P_C = np.diag([4e-4, 2e-4]) ** 2
    draws = rng.multivariate_normal(ang_true, P_C, N_MC)
    moved = _codegen.get("landing_camera2ctd")(draws, att, GEOM.angled_deck_rad)[0]
    ct = transfer_camera(ang_true, P_C, att, GEOM)
    assert _whitened_error(moved, ct.P_ctd[0]) < TOL
    assert _whitened_error(moved, P_C) > TOL  # ignoring the attitude rotation is detected (it mixes a and b)


def test_variance_ratios_are_one_for_colocated_aligned_sensors():
    """Radar and camera at the same deck point, deck level: the radar's polar errors in the camera
    frame differ only by the fixed rotation of the azimuth origin, so every ratio is 1."""
    z = np.zeros(3)
    g = LandingGeometry(0.0, z, z, z)
    rt = transfer_radar([1500.0, -np.pi / 2 + 0.02, 0.06], np.diag(SIG_R**2), np.zeros(3), g)
    assert variance_ratios(rt.P_rdr, rt.P_ctd)[0] == pytest.approx([1.0, 1.0, 1.0], rel=1e-12)


def test_radar_range_error_dominates_the_camera_frame_angles_near_touchdown():
    """Near touchdown the radar (81 m from the touchdown point) sees the aircraft from a very
    different direction than the camera, so its 3 m range error becomes a large camera-frame angle
    error: the azimuth variance ratio grows steadily as the aircraft closes, from ~1 at 3.5 km."""
    ratios = []
    for s in (3500.0, 1000.0, 300.0, 150.0, 50.0):
        p = np.array([s * np.cos(0.061), 0.0, s * np.sin(0.061)])
        rt = transfer_radar(_radar_polar_of(p)[0], np.diag(SIG_R**2), ATT, GEOM)
        ratios.append(variance_ratios(rt.P_rdr, rt.P_ctd)[0][1])
    assert np.all(np.diff(ratios) > 0) and ratios[0] < 1.2 and ratios[-1] > 100, ratios


# --------------------------------------------------------------------------- fusion
def _random_transfers(rng, n=200):
    s = rng.uniform(100, 4000, n)
    p = np.stack([s * np.cos(0.061), rng.normal(0, 5, n), s * np.sin(0.061)], axis=1)
    att = rng.uniform(-1, 1, (n, 3)) * [0.01, 0.02, 0.035]
    vf_r, vf_c = rng.uniform(0.1, 1.0, n), rng.uniform(0.1, 1.0, n)
    rt = transfer_radar(_radar_polar_of(p, att), vf_r[:, None, None] * np.diag(SIG_R**2), att, GEOM)
    ct = transfer_camera(_camera_angles_of(p, att), vf_c[:, None, None] * np.diag(SIG_C**2), att, GEOM)
    return rt, ct, att, p


def test_fused_angle_variances_are_below_both_inputs():
    rt, ct, att, _ = _random_transfers(np.random.default_rng(1))
    f = combine(rt, ct, att, GEOM, "paper")
    s2_r = np.diagonal(rt.P_ctd, axis1=1, axis2=2)[:, 1:]
    s2_c = np.diagonal(ct.P_ctd, axis1=1, axis2=2)
    s2_f = np.diagonal(f.P_polar, axis1=1, axis2=2)
    assert np.all(s2_f[:, 1:] < s2_r) and np.all(s2_f[:, 1:] < s2_c)
    # eq. (12)'s closed form, and the range is the radar's
    assert s2_f[:, 1:] == pytest.approx(s2_r * s2_c / (s2_r + s2_c), rel=1e-12)
    assert s2_f[:, 0] == pytest.approx(rt.P_ctd[:, 0, 0], rel=1e-12)
    a_eq12 = s2_f[:, 1:] * (ct.angles_ctd / s2_c + rt.polar_ctd[:, 1:] / s2_r)
    assert f.polar_ctd[:, 1:] == pytest.approx(a_eq12, abs=1e-12)
    assert f.polar_ctd[:, 0] == pytest.approx(rt.polar_ctd[:, 0])


def test_joint_update_is_never_worse_than_eq12():
    """The joint update is the linear minimum-variance combination, so P_paper - P_joint is PSD."""
    rt, ct, att, _ = _random_transfers(np.random.default_rng(2))
    P_paper = combine(rt, ct, att, GEOM, "paper").P_polar
    P_joint = combine(rt, ct, att, GEOM, "information").P_polar
    eig = np.linalg.eigvalsh(P_paper - P_joint)
    assert eig.min() > -1e-12 * np.abs(P_paper).max()


def test_methods_camera_and_radar_are_the_two_inputs():
    rt, ct, att, _ = _random_transfers(np.random.default_rng(3), n=20)
    cam = combine(rt, ct, att, GEOM, "camera")
    rad = combine(rt, ct, att, GEOM, "radar")
    assert cam.polar_ctd[:, 1:] == pytest.approx(ct.angles_ctd) and cam.polar_ctd[:, 0] == pytest.approx(
        rt.polar_ctd[:, 0]
    )
    assert rad.p_td == pytest.approx(rt.p_td, abs=1e-8)  # rebuilt through the camera = eq. (7) directly


@pytest.mark.parametrize("method", ["paper", "information"])
def test_fused_covariance_matches_monte_carlo(method):
    """Draw radar and camera noise, transfer and fuse each draw: the spread of the fused polar point
    matches the predicted covariance (the linear combination's exact covariance)."""
    rng = np.random.default_rng(4)
    s = 250.0  # where the radar's transfer is strongly correlated (range error into camera angles)
    p = np.array([[s * np.cos(0.061), 2.0, s * np.sin(0.061)]])
    pol_r, ang_c = _radar_polar_of(p)[0], _camera_angles_of(p)[0]
    P_R, P_C = np.diag(SIG_R**2), np.diag(SIG_C**2)
    dr = pol_r + rng.normal(size=(N_MC, 3)) * SIG_R
    dc = ang_c + rng.normal(size=(N_MC, 2)) * SIG_C
    att = np.broadcast_to(ATT, (N_MC, 3))
    f = combine(transfer_radar(dr, P_R, att, GEOM), transfer_camera(dc, P_C, att, GEOM), att, GEOM, method)
    assert _whitened_error(f.polar_ctd, f.P_polar[0], angle_cols=(1,)) < TOL
    # and the rebuilt touchdown-frame position has the predicted covariance too
    assert _whitened_error(f.p_td, f.P_td[0]) < TOL


# --------------------------------------------------------------------------- bad input
def test_bad_inputs_are_refused_with_clear_messages():
    P = np.diag(SIG_R**2)
    with pytest.raises(ValueError, match="attitude.*look like degrees"):
        transfer_radar([1000.0, -1.6, 0.05], P, [0.5, 2.0, 30.0], GEOM)
    with pytest.raises(ValueError, match=r"polar_rdr\[:, 0\].*must be > 0 m"):
        transfer_radar([-5.0, -1.6, 0.05], P, ATT, GEOM)
    with pytest.raises(ValueError, match="polar_rdr: non-finite"):
        transfer_radar([np.nan, -1.6, 0.05], P, ATT, GEOM)
    with pytest.raises(ValueError, match="P_rdr: variance .* must be > 0"):
        transfer_radar([1000.0, -1.6, 0.05], np.diag([9.0, 0.0, 1e-6]), ATT, GEOM)
    with pytest.raises(ValueError, match=r"angles_cam: expected shape \(2,\) or \(N, 2\)"):
        transfer_camera([0.1, 0.2, 0.3], np.eye(2), ATT, GEOM)
    with pytest.raises(ValueError, match="angled_deck_rad.*look like degrees"):
        LandingGeometry(9.0, np.zeros(3), np.zeros(3), np.zeros(3))
    with pytest.raises(ValueError, match="l_radar_deck_m: expected 3 numbers"):
        LandingGeometry(0.1, np.zeros(3), np.zeros(2), np.zeros(3))
    rt, ct, att, _ = _random_transfers(np.random.default_rng(5), n=4)
    with pytest.raises(ValueError, match="method: expected one of"):
        combine(rt, ct, att, GEOM, "average")
