"""The attitude read back from a deck-to-ENU rotation (generated enu2deck_attitude)."""

import numpy as np
import pytest


def test_enu2deck_attitude_inverts_deck2enu_rotation():
    """Round trip over random attitudes and the edges of the accepted ranges: heading at +-pi and
    0, pitch near +-pi/2, roll near +-pi/2."""
    from registration.core.frames import deck2enu_rotation, enu2deck_attitude

    rng = np.random.default_rng(7)
    n = 2000
    heading = rng.uniform(-np.pi, np.pi, n)
    pitch = rng.uniform(-1.5, 1.5, n)
    roll = rng.uniform(-np.pi / 2, np.pi / 2, n)
    heading[:3] = [np.pi, -np.pi + 1e-12, 0.0]
    pitch[3:6] = [np.pi / 2 - 1e-6, -np.pi / 2 + 1e-6, 0.0]
    roll[6:8] = [np.pi / 2, -np.pi / 2]
    got = enu2deck_attitude(deck2enu_rotation(heading, pitch, roll))
    want = np.stack([heading, pitch, roll], axis=1)
    d = got - want
    d[:, [0, 2]] = np.angle(np.exp(1j * d[:, [0, 2]]))  # the same angle across +-pi
    assert np.abs(d[6:]).max() < 1e-12
    assert (
        np.abs(d[:6, 1]).max() < 1e-9 and np.abs(d[:3]).max() < 1e-12
    )  # near +-pi/2 pitch, asin loses digits
    with pytest.raises(ValueError, match="R_enu_deck"):
        enu2deck_attitude(np.zeros((3, 4)))
