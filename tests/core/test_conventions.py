"""Sign conventions (docs/reference/conventions.md), one readable check each (deck: x starboard, y bow, z up;
ENU: x east, y north, z up)."""

import numpy as np
import pytest

from registration.core import frames

R = 1000.0


def ahead(heading=0.0, pitch=0.0, roll=0.0, q=0.0, e=0.0):
    return frames.deck2enu(R, q, e, heading, pitch, roll)[0]


def test_level_ship_heading_north_bow_points_north():
    assert ahead() == pytest.approx([0, R, 0], abs=1e-9)


def test_heading_90_deg_turns_the_bow_east():
    assert ahead(heading=np.pi / 2) == pytest.approx([R, 0, 0], abs=1e-9)


def test_heading_is_clockwise_from_north():
    east, north, _ = ahead(heading=np.radians(30))
    assert east > 0 and north > 0 and np.degrees(np.arctan2(east, north)) == pytest.approx(30)


def test_positive_pitch_raises_the_bow():
    assert ahead(pitch=np.radians(5))[2] > 0


def test_positive_roll_lowers_starboard():
    starboard = frames.deck2enu(R, np.pi / 2, 0.0, 0.0, 0.0, np.radians(5))[0]
    assert starboard[2] < 0


def test_bearing_plus_90_deg_points_to_starboard():
    # heading north: starboard is east
    assert frames.deck2enu(R, np.pi / 2, 0.0, 0.0, 0.0, 0.0)[0] == pytest.approx([R, 0, 0], abs=1e-9)


def test_positive_elevation_is_up():
    assert ahead(e=np.radians(10))[2] == pytest.approx(R * np.sin(np.radians(10)))


def test_rotation_composition_matches_phi():
    """Phi = R_enu_deck @ u_deck with u_deck = [r sin q cos e, r cos q cos e, r sin e]."""
    rng = np.random.default_rng(0)
    r, q, e = rng.uniform(1e3, 1e5, 50), rng.uniform(-np.pi, np.pi, 50), rng.uniform(-1.5, 1.5, 50)
    h, p, rl = rng.uniform(-np.pi, np.pi, 50), rng.uniform(-0.3, 0.3, 50), rng.uniform(-0.3, 0.3, 50)
    u_deck = np.stack([r * np.sin(q) * np.cos(e), r * np.cos(q) * np.cos(e), r * np.sin(e)], axis=1)
    R_enu_deck = frames.deck2enu_rotation(h, p, rl)
    assert np.einsum("nij,nj->ni", R_enu_deck, u_deck) == pytest.approx(
        frames.deck2enu(r, q, e, h, p, rl), abs=1e-8
    )


def test_jacobian_shapes_and_level_ship_degeneracy():
    """Level ship: dPhi/dC and dPhi/dq columns are identical (only C + q is observable)."""
    psi, gamma = frames.deck2enu_jacobians([1e4, 2e4], [0.3, -2.0], [0.01, 0.1], [2.6, -0.5], 0.0, 0.0)
    assert psi.shape == (2, 3, 6) and gamma.shape == (2, 3, 3)
    assert psi[:, :, 0] == pytest.approx(psi[:, :, 4])
    assert gamma == pytest.approx(psi[:, :, 3:])


def test_scalars_give_one_row_and_arrays_broadcast():
    assert frames.geodetic2ecef(0.1, 0.2, 3.0).shape == (1, 3)
    assert frames.geodetic2ecef([0.1, 0.2], 0.2, 3.0).shape == (2, 3)
    assert frames.enu2ecef_rotation(0.1, [0.2, 0.3, 0.4]).shape == (3, 3, 3)
