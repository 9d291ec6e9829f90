"""Pressure altitude (what a flight level is) and geometric height in an ICAO standard atmosphere
shifted by a temperature offset and a sea-level pressure (QNH).

Source: ICAO Doc 7488/3, *Manual of the ICAO Standard Atmosphere* (the ISA; its constants below).

**The ISA.** Heights are geopotential ``H`` above mean sea level; the temperature falls at
``L = 0.0065 K/m`` from ``T0 = 288.15 K`` at sea level up to the tropopause at ``H = 11 000 m``
(``T11 = 216.65 K``) and is constant above it (to 20 km). With hydrostatic balance
``dp/dH = -g0 p / (R T)`` (``g0 = 9.80665 m/s^2``, ``R = 287.05287 J/(kg K)``) the pressure is

    p(H) = p0 (T(H) / T0)^(g0 / (R L))               H <= 11 000 m  (p0 = 101 325 Pa)
    p(H) = p11 exp(-g0 (H - 11 000) / (R T11))       11 000 m < H <= 20 000 m (p11 = p(11 000 m)).

The **pressure altitude** ``Hp`` of a pressure ``p`` is the ISA height at which the pressure is
``p``; a flight level is ``Hp`` in hundreds of feet (FL 350: ``Hp`` = 35 000 ft), which is what Mode C
and Mode S replies and ADS-B's barometric altitude carry (ASTERIX I048/090, I001/090, I021/145).

**The day's atmosphere.** The air is warmer or colder than the ISA by ``dT`` at every height (the
"ISA + dT" model of ICAO Doc 7488 and of aircraft performance manuals) and the sea-level pressure
is ``QNH`` instead of ``p0``: ``T(H) = T0 + dT - L H`` up to 11 000 m, ``T11 + dT`` above, and
``p(H) = QNH (T(H) / (T0 + dT))^(g0 / (R L))`` (then the isothermal layer as above). An aircraft at
pressure altitude ``Hp`` is where that pressure equals the ISA's at ``Hp``. In the troposphere this
gives exactly

    H = (T0 + dT) / L (1 - k) + k (T0 + dT) / T0 Hp,      k = (p0 / QNH)^(R L / g0),

a straight line in ``Hp`` whose offset comes mostly from QNH (about 8.3 m per hPa near sea level)
and whose slope from ``dT`` (about 1 + dT / T0: +4.2 % at ISA + 12 K); above the tropopause the
slope changes. Geometric height ``h`` follows from geopotential ``H`` with the Earth radius of the
ISA, ``r = 6 356 766 m``: ``h = r H / (r - H)`` (0.2 % at 11 km). The geometric height above the
WGS-84 ellipsoid is ``h`` plus the geoid undulation (not modelled here: a constant over a radar's
coverage, part of the offset the import learns).
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "T0_K",
    "P0_PA",
    "LAPSE_K_PER_M",
    "G0",
    "R_AIR",
    "TROPOPAUSE_M",
    "EARTH_RADIUS_M",
    "FOOT_M",
    "pressure_at",
    "pressure_altitude_of",
    "geopotential2geometric",
    "geometric2geopotential",
    "pressure_altitude2height",
    "height2pressure_altitude",
]

#: ICAO Doc 7488 constants: sea-level temperature (K), pressure (Pa), lapse rate (K/m) to the
#: tropopause, standard gravity (m/s^2), specific gas constant of air (J/(kg K)), tropopause height
#: (geopotential m), the Earth radius of the geopotential conversion (m).
T0_K = 288.15
P0_PA = 101325.0
LAPSE_K_PER_M = 0.0065
G0 = 9.80665
R_AIR = 287.05287
TROPOPAUSE_M = 11000.0
EARTH_RADIUS_M = 6356766.0
#: The international foot (m): a flight level is 100 ft of pressure altitude.
FOOT_M = 0.3048
_EXPONENT = G0 / (R_AIR * LAPSE_K_PER_M)


def pressure_at(H_m, delta_t_k: float = 0.0, qnh_pa: float = P0_PA) -> np.ndarray:
    """Pressure (Pa) at geopotential height ``H_m`` (m above mean sea level, up to 20 km) in the ISA
    warmer by ``delta_t_k`` (K) with sea-level pressure ``qnh_pa`` (module docstring; the ISA itself
    with the defaults)."""
    H = np.asarray(H_m, dtype=np.float64)
    t0 = T0_K + delta_t_k
    below = qnh_pa * ((t0 - LAPSE_K_PER_M * np.minimum(H, TROPOPAUSE_M)) / t0) ** _EXPONENT
    t11 = t0 - LAPSE_K_PER_M * TROPOPAUSE_M
    above = np.exp(-G0 * np.maximum(H - TROPOPAUSE_M, 0.0) / (R_AIR * t11))
    return below * above


def pressure_altitude_of(p_pa) -> np.ndarray:
    """The pressure altitude (m, ISA geopotential) of pressure ``p_pa`` (Pa): the inverse of
    :func:`pressure_at` with the ISA defaults."""
    return _height_of(np.asarray(p_pa, dtype=np.float64), 0.0, P0_PA)


def _height_of(p: np.ndarray, delta_t_k: float, qnh_pa: float) -> np.ndarray:
    """Geopotential height (m) of pressure ``p`` in the ISA + ``delta_t_k`` with ``qnh_pa``."""
    t0 = T0_K + delta_t_k
    t11 = t0 - LAPSE_K_PER_M * TROPOPAUSE_M
    p11 = qnh_pa * (t11 / t0) ** _EXPONENT
    below = t0 / LAPSE_K_PER_M * (1.0 - (p / qnh_pa) ** (1.0 / _EXPONENT))
    above = TROPOPAUSE_M + R_AIR * t11 / G0 * np.log(p11 / p)
    return np.where(p >= p11, below, above)


def geopotential2geometric(H_m) -> np.ndarray:
    """Geometric height (m) of geopotential height ``H_m`` (m): ``r H / (r - H)``."""
    H = np.asarray(H_m, dtype=np.float64)
    return EARTH_RADIUS_M * H / (EARTH_RADIUS_M - H)


def geometric2geopotential(h_m) -> np.ndarray:
    """Geopotential height (m) of geometric height ``h_m`` (m): ``r h / (r + h)``."""
    h = np.asarray(h_m, dtype=np.float64)
    return EARTH_RADIUS_M * h / (EARTH_RADIUS_M + h)


def pressure_altitude2height(hp_m, delta_t_k: float = 0.0, qnh_pa: float = P0_PA) -> np.ndarray:
    """Geometric height (m above mean sea level) of an aircraft at pressure altitude ``hp_m`` (m; a
    flight level x 100 ft x 0.3048) in the ISA + ``delta_t_k`` (K) with sea-level pressure ``qnh_pa``
    (Pa)."""
    return geopotential2geometric(_height_of(pressure_at(hp_m), delta_t_k, qnh_pa))


def height2pressure_altitude(h_m, delta_t_k: float = 0.0, qnh_pa: float = P0_PA) -> np.ndarray:
    """Pressure altitude (m) of geometric height ``h_m`` (m above mean sea level) in the ISA +
    ``delta_t_k`` (K) with sea-level pressure ``qnh_pa`` (Pa): the inverse of
    :func:`pressure_altitude2height`."""
    return pressure_altitude_of(pressure_at(geometric2geopotential(h_m), delta_t_k, qnh_pa))
