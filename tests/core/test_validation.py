"""Bad input gets a clear ValueError naming the argument, the first bad index and the unit."""

import numpy as np
import pytest

from registration.core import frames


def test_latitude_out_of_range_names_index_and_unit():
    with pytest.raises(ValueError, match=r"lat: value 2.* at index 1 .*rad"):
        frames.geodetic2ecef([0.1, 2.0], 0.0, 0.0)


def test_degrees_passed_as_radians_get_a_hint():
    with pytest.raises(ValueError, match="look like degrees"):
        frames.geodetic2ecef(45.0, 10.0, 0.0)
    with pytest.raises(ValueError, match="look like degrees"):
        frames.deck2enu(1000.0, 90.0, 0.0, 0.0, 0.0, 0.0)


def test_non_finite_values_are_refused():
    with pytest.raises(ValueError, match=r"alt: non-finite value nan at index 2"):
        frames.geodetic2ecef(0.0, 0.0, [0.0, 1.0, np.nan])
    with pytest.raises(ValueError, match="heading: non-finite"):
        frames.deck2enu(1000.0, 0.0, 0.0, np.inf, 0.0, 0.0)


@pytest.mark.parametrize("bad", [0.0, -5.0])
def test_non_positive_range_is_refused(bad):
    with pytest.raises(ValueError, match=r"r: value .* at index 1 must be > 0 m"):
        frames.deck2enu_jacobians([100.0, bad], 0.0, 0.0, 0.0, 0.0, 0.0)


def test_mismatched_lengths_are_refused():
    with pytest.raises(ValueError, match="lengths must match"):
        frames.geodetic2ecef([0.1, 0.2], [0.1, 0.2, 0.3], 0.0)


def test_unknown_variant_is_refused():
    with pytest.raises(ValueError, match="variant"):
        frames.enu2ecef_rotation(0.1, 0.2, variant="wgs72")


def test_non_numeric_input_is_refused():
    with pytest.raises(ValueError, match="lat: expected numbers"):
        frames.geodetic2ecef("north", 0.0, 0.0)


def test_length_one_array_broadcasts_like_a_scalar():
    out = frames.geodetic2ecef(np.array([0.1]), np.array([0.1, 0.2]), 0.0)
    assert out.shape == (2, 3)
    assert np.allclose(out[0], frames.geodetic2ecef(0.1, 0.1, 0.0)[0])


@pytest.mark.parametrize(
    "value, shown",
    [(None, "None"), (True, "True"), ("0.5", "'0.5'"), ([0.1, None], "a list holding non-numbers")],
)
def test_none_booleans_and_strings_are_not_numbers(value, shown):
    with pytest.raises(ValueError, match=f"lat: expected numbers, got {shown}"):
        frames.geodetic2ecef(value, 0.0, 0.0)


def test_float32_poles_are_accepted_and_clipped():
    for pole in (np.float32(np.pi / 2), np.float32(-np.pi / 2)):
        assert abs(float(pole)) > np.pi / 2  # float32 rounding leaves the float64 range
        p = frames.geodetic2ecef(pole, np.float32(0.3), np.float32(0.0))
        np.testing.assert_allclose(
            p, frames.geodetic2ecef(float(np.sign(pole)) * np.pi / 2, 0.3, 0.0), atol=1e-6
        )
    with pytest.raises(ValueError, match="lat: value"):
        frames.geodetic2ecef(np.pi / 2 + 1e-6, 0.0, 0.0)


def test_scalar_errors_name_no_index_and_altitude_uses_the_one_window():
    from registration.core.validation import ALTITUDE_LIMITS_M

    with pytest.raises(ValueError) as info:
        frames.geodetic2ecef(0.0, 0.0, np.nan)
    assert "index" not in str(info.value)
    frames.geodetic2ecef(0.0, 0.0, ALTITUDE_LIMITS_M[1])
    with pytest.raises(ValueError, match=r"alt: value .* is outside \[-12000, 1e\+06\] m"):
        frames.geodetic2ecef(0.0, 0.0, ALTITUDE_LIMITS_M[1] * 1.01)
