"""The ISA of ICAO Doc 7488 and its warmer or colder day with a QNH: tabulated pressures, the
closed form of the troposphere, and the inverse."""

from __future__ import annotations

import numpy as np
import pytest

from registration.core import atmosphere as atm


def test_isa_pressures_are_the_tabulated_ones():
    # ICAO Doc 7488 table values (geopotential m -> Pa), to their printed digits
    table = {0.0: 101325.0, 5000.0: 54019.9, 11000.0: 22632.1, 15000.0: 12044.6, 20000.0: 5474.89}
    got = atm.pressure_at(list(table))
    np.testing.assert_allclose(got, list(table.values()), rtol=5e-6)  # printed to 6 digits


def test_the_isa_itself_maps_pressure_altitude_to_its_geometric_height():
    hp = np.linspace(-300.0, 18000.0, 50)
    np.testing.assert_allclose(atm.pressure_altitude2height(hp), atm.geopotential2geometric(hp), atol=1e-6)


@pytest.mark.parametrize("dt, qnh", [(12.0, 102500.0), (-15.0, 99000.0)])
def test_troposphere_is_the_straight_line_of_the_docstring(dt, qnh):
    hp = np.linspace(0.0, 10000.0, 21)
    k = (atm.P0_PA / qnh) ** (atm.R_AIR * atm.LAPSE_K_PER_M / atm.G0)
    t0 = atm.T0_K + dt
    H = t0 / atm.LAPSE_K_PER_M * (1 - k) + k * t0 / atm.T0_K * hp
    np.testing.assert_allclose(
        atm.pressure_altitude2height(hp, dt, qnh), atm.geopotential2geometric(H), atol=1e-6
    )


def test_isa_plus_12_qnh_1025_is_hundreds_of_metres_above_the_flight_level_and_inverts():
    hp = np.array([0.0, 3000.0, 6000.0, 11000.0, 12500.0])
    h = atm.pressure_altitude2height(hp, 12.0, 102500.0)
    assert 90.0 < h[0] - hp[0] < 110.0  # about 8.6 m per hPa at sea level
    assert np.all(np.diff(h - hp) > 0) and h[3] - hp[3] > 500.0  # warmer air: higher
    np.testing.assert_allclose(atm.height2pressure_altitude(h, 12.0, 102500.0), hp, atol=1e-6)
