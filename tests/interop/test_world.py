"""Stone Soup's world and body frames against Stone Soup's own rotations and pymap3d's ENU."""

import numpy as np
import pymap3d
import pytest
from stonesoup.functions import build_rotation_matrix

from registration.core.frames import deck2enu_rotation, enu2ecef_rotation, geodetic2ecef
from registration.interop.world import DECK2BODY, LocalFrame, orientation_rotation

ORIGIN = (np.radians(36.0), np.radians(14.5), 0.0)
RNG = np.random.default_rng(20261201)


def random_orientations(n: int) -> np.ndarray:
    return np.column_stack(
        [RNG.uniform(-1.2, 1.2, n), RNG.uniform(-1.4, 1.4, n), RNG.uniform(-np.pi, np.pi, n)]
    )


def random_navigation(frame: LocalFrame, n: int, spread: float = 60e3) -> np.ndarray:
    p = np.column_stack(
        [RNG.uniform(-spread, spread, n), RNG.uniform(-spread, spread, n), RNG.uniform(-5, 50, n)]
    )
    lat, lon, alt = frame.world2geodetic(p)
    return np.column_stack(
        [lat, lon, alt, RNG.uniform(-np.pi, np.pi, n), RNG.uniform(-0.3, 0.3, n), RNG.uniform(-0.4, 0.4, n)]
    )


def test_orientation_rotation_is_stonesoups_sensor_to_world_rotation():
    o = random_orientations(50)
    R_world_deck = orientation_rotation(o)
    for k in range(o.shape[0]):
        R_body_world = build_rotation_matrix(o[k][:, None])  # Stone Soup: world -> sensor axes
        np.testing.assert_allclose(R_world_deck[k] @ DECK2BODY.T, R_body_world.T, atol=1e-15)


def test_deck_axes_map_to_forward_port_up():
    # the bow is body x, starboard is -body y (port is +y), up is up
    np.testing.assert_array_equal(DECK2BODY @ [0, 1, 0], [1, 0, 0])
    np.testing.assert_array_equal(DECK2BODY @ [1, 0, 0], [0, -1, 0])
    np.testing.assert_array_equal(DECK2BODY @ [0, 0, 1], [0, 0, 1])
    assert np.linalg.det(DECK2BODY) == pytest.approx(1.0)


def test_at_the_origin_yaw_is_a_quarter_turn_minus_heading_and_pitch_roll_keep_their_signs():
    frame = LocalFrame(*ORIGIN)
    heading, pitch, roll = RNG.uniform(-3, 3, 20), RNG.uniform(-1.2, 1.2, 20), RNG.uniform(-1.2, 1.2, 20)
    o = frame.orientation(ORIGIN[0], ORIGIN[1], heading, pitch, roll)
    np.testing.assert_allclose(o[:, 0], roll, atol=1e-12)
    np.testing.assert_allclose(o[:, 1], pitch, atol=1e-12)
    np.testing.assert_allclose(np.cos(o[:, 2] - (np.pi / 2 - heading)), 1.0, atol=1e-12)
    # heading 90 deg (bow east) is yaw 0: Stone Soup's forward axis is world x = east
    np.testing.assert_allclose(
        frame.orientation(ORIGIN[0], ORIGIN[1], np.pi / 2, 0, 0), [[0, 0, 0]], atol=1e-15
    )


def test_away_from_the_origin_the_orientation_carries_the_tilt_of_the_local_axes():
    frame = LocalFrame(*ORIGIN)
    nav = random_navigation(frame, 30)
    o = frame.orientation(nav[:, 0], nav[:, 1], *nav[:, 3:].T)
    # the deck axes in world coordinates through ECEF match Stone Soup's rotation of o
    R_ecef_deck = np.stack([frame.R_ecef_world]) @ orientation_rotation(o)
    np.testing.assert_allclose(
        R_ecef_deck, enu2ecef_rotation(nav[:, 0], nav[:, 1]) @ deck2enu_rotation(*nav[:, 3:].T), atol=1e-14
    )
    assert (
        np.abs(o[:, 1] - nav[:, 4]).max() > 1e-4
    )  # 60 km out, the pitch relative to world is not the local one


def test_attitude_inverts_orientation():
    frame = LocalFrame(*ORIGIN)
    nav = random_navigation(frame, 40)
    o = frame.orientation(nav[:, 0], nav[:, 1], *nav[:, 3:].T)
    att = frame.attitude(nav[:, 0], nav[:, 1], o)
    d = att - nav[:, 3:]
    d[:, 0] = np.angle(np.exp(1j * d[:, 0]))
    np.testing.assert_allclose(d, 0, atol=1e-12)


def test_world_positions_agree_with_pymap3d_enu():
    frame = LocalFrame(*ORIGIN)
    lat = ORIGIN[0] + RNG.uniform(-0.01, 0.01, 20)
    lon = ORIGIN[1] + RNG.uniform(-0.01, 0.01, 20)
    alt = RNG.uniform(-10, 12e3, 20)
    ours = frame.geodetic2world(lat, lon, alt)
    theirs = np.column_stack(pymap3d.geodetic2enu(lat, lon, alt, *ORIGIN, deg=False))
    np.testing.assert_allclose(ours, theirs, atol=1e-6)
    back = np.column_stack(frame.world2geodetic(ours))
    np.testing.assert_allclose(back[:, :2], np.column_stack([lat, lon]), atol=1e-13)
    np.testing.assert_allclose(back[:, 2], alt, atol=1e-6)
    np.testing.assert_allclose(frame.ecef2world(frame.world2ecef(ours)), ours, atol=1e-8)


def test_sensor_pose_and_navigation_invert_each_other_with_lever_arms():
    frame = LocalFrame(*ORIGIN)
    nav = random_navigation(frame, 40)
    lever = RNG.uniform(-40, 40, (40, 3))
    p_world, o = frame.sensor_pose(nav, lever)
    # the sensor sits at the navigation point plus the lever arm turned by the attitude, in ECEF
    R_ecef_deck = enu2ecef_rotation(nav[:, 0], nav[:, 1]) @ deck2enu_rotation(*nav[:, 3:].T)
    expected = geodetic2ecef(*nav[:, :3].T) + np.einsum("nij,nj->ni", R_ecef_deck, lever)
    np.testing.assert_allclose(frame.world2ecef(p_world), expected, atol=1e-8)
    back = frame.navigation(p_world, o, lever)
    d = back - nav
    d[:, 3] = np.angle(np.exp(1j * d[:, 3]))
    np.testing.assert_allclose(d[:, [0, 1, 3, 4, 5]], 0, atol=1e-13)
    np.testing.assert_allclose(d[:, 2], 0, atol=1e-8)


def test_reference_point_is_what_stonesoups_geodetic_feeder_takes():
    from stonesoup.feeder.geo import LLAtoENUConverter
    from stonesoup.types.detection import Detection

    frame = LocalFrame(*ORIGIN)
    lat, lon, alt = ORIGIN[0] + 0.004, ORIGIN[1] - 0.006, 850.0
    det = Detection(
        np.array([[np.degrees(lon)], [np.degrees(lat)], [alt]])
    )  # Stone Soup order: lon, lat (deg), alt
    feeder = LLAtoENUConverter(reader=[(None, {det})], reference_point=frame.reference_point_deg)
    ((_, (converted,)),) = list(feeder)
    np.testing.assert_allclose(
        np.asarray(converted.state_vector, float).ravel(), frame.geodetic2world(lat, lon, alt)[0], atol=1e-6
    )


def test_centred_on_puts_the_origin_under_the_mean_position():
    frame = LocalFrame(*ORIGIN)
    nav = random_navigation(frame, 10, spread=20e3)
    centred = LocalFrame.centred_on({"lat": nav[:, 0], "lon": nav[:, 1], "alt": nav[:, 2]})
    mean = centred.geodetic2world(nav[:, 0], nav[:, 1], nav[:, 2]).mean(axis=0)
    np.testing.assert_allclose(mean[:2], 0, atol=1e-6)
