"""Frame transforms: geodetic -> ECEF, ENU -> ECEF rotation, deck -> ENU (with Jacobians).

Thin numpy wrappers over the generated functions (derive/geodesy.py, derive/attitude.py).
Vectorised over a leading axis of N points: scalars in give one row out. SI units and radians.

Frames (docs/reference/conventions.md): ``ecef`` WGS-84 earth-centred earth-fixed; ``enu`` x east, y north,
z up; ``deck`` x starboard, y bow, z up. Attitude: heading C clockwise from true north, pitch
phi positive bow up, roll theta positive starboard down; ``R_enu_deck = Rz(C) Rx(phi) Ry(theta)``.
Radar: range r (m), deck bearing q from the bow, starboard positive, elevation e above the deck.
"""

from __future__ import annotations

import numpy as np

from registration import _codegen
from registration._generated import api as generated
from registration.core.validation import (
    as_float_array,
    broadcast_1d,
    check_altitude,
    check_angle,
    check_finite,
    check_latitude,
    check_positive,
    check_range,
)

__all__ = [
    "geodetic2ecef",
    "ecef2geodetic",
    "enu2ecef_rotation",
    "deck2enu",
    "deck2enu_jacobians",
    "deck2enu_rotation",
    "enu2deck_attitude",
    "plot2ecef",
]

#: ENU->ECEF rotation variants that derive/ emitted: the standard one and the paper's eq. (4).
T_VARIANTS = _codegen.variants("t_variant")


def _geodetic(lat, lon, alt=None):
    lat = as_float_array("lat", lat)
    lon = as_float_array("lon", lon)
    lat = check_latitude("lat", lat)
    check_angle("lon", lon)
    out = {"lat": lat, "lon": lon}
    if alt is not None:
        alt = as_float_array("alt", alt)
        check_altitude("alt", alt)
        out["alt"] = alt
    return out


def _measurement(r, q, e):
    r, q, e = as_float_array("r", r), as_float_array("q", q), as_float_array("e", e)
    check_positive("r", r, "m (slant range)")
    check_angle("q", q)
    check_range("e", e, -np.pi / 2, np.pi / 2, "rad (elevation)", angle=True)
    return {"r": r, "q": q, "e": e}


def _attitude(heading, pitch, roll):
    h, p, rl = (
        as_float_array("heading", heading),
        as_float_array("pitch", pitch),
        as_float_array("roll", roll),
    )
    check_angle("heading", h)
    check_range("pitch", p, -np.pi / 2, np.pi / 2, "rad", angle=True)
    check_range("roll", rl, -np.pi / 2, np.pi / 2, "rad", angle=True)
    return {"heading": h, "pitch": p, "roll": rl}


def _broadcast(values: dict) -> dict:
    n = broadcast_1d(**values)
    # a length-1 array broadcasts like a scalar
    return {k: v.reshape(()) if v.shape == (1,) and n != 1 else v for k, v in values.items()}


def geodetic2ecef(lat, lon, alt) -> np.ndarray:
    """ECEF position (N, 3) in metres of geodetic points.

    lat, lon in radians (lat in [-pi/2, pi/2]); alt in metres above the WGS-84 ellipsoid.
    Example: ``geodetic2ecef(0, 0, 0)`` -> ``[[6378137, 0, 0]]``.
    """
    v = _geodetic(lat, lon, alt)
    return generated.geodetic2ecef(**_broadcast(v)).p_ecef


def ecef2geodetic(p_ecef) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Geodetic ``lat, lon`` (rad) and ``alt`` (m above
    WGS-84), each (N,), of ECEF points (N, 3) or (3,) in m.

    The inverse of :func:`geodetic2ecef` (generated, Bowring's iteration: float64 rounding of the
    latitude from -12 km to 1000 km of height). Points within 100 km of the earth's centre are refused.
    """
    p = as_float_array("p_ecef", p_ecef)
    if p.ndim not in (1, 2) or p.shape[-1] != 3:
        raise ValueError(f"p_ecef: expected shape (N, 3) or (3,) in m, got {p.shape}")
    p = p.reshape(-1, 3)
    check_finite("p_ecef", p, "m")
    close = np.einsum("ij,ij->i", p, p) < 1e10
    if close.any():
        raise ValueError(
            f"p_ecef: point {int(np.argmax(close))} lies within 100 km of the earth's centre; expected ECEF "
            "metres"
        )
    geo = generated.ecef2geodetic(p_ecef=p).geodetic.reshape(-1, 3)
    return geo[:, 0], geo[:, 1], geo[:, 2]


def enu2ecef_rotation(lat, lon, variant: str = "standard") -> np.ndarray:
    """R_ecef_enu (N, 3, 3) at geodetic (lat, lon) in radians: ``v_ecef = R_ecef_enu @ v_enu``.

    ``variant='standard'`` is the orthonormal rotation about the geodetic normal. ``'paper'`` is
    eq. (4) of Wang et al. 2011 as printed, for reproduction only: it equals the standard rotation
    at a latitude psi with tan psi = (a/b)^2 tan lat, a tilt of ~0.12 deg at 20 deg N.
    """
    if variant not in T_VARIANTS:
        raise ValueError(f"variant: expected one of {T_VARIANTS}, got {variant!r}")
    v = _geodetic(lat, lon)
    return generated.enu2ecef_rotation(t_variant=variant, **_broadcast(v)).R_ecef_enu


def deck2enu_rotation(heading, pitch, roll) -> np.ndarray:
    """R_enu_deck (N, 3, 3) = Rz(heading) Rx(pitch) Ry(roll), angles in radians."""
    v = _attitude(heading, pitch, roll)
    return generated.deck2enu_rotation(**_broadcast(v)).R_enu_deck


def enu2deck_attitude(R_enu_deck) -> np.ndarray:
    """(N, 3) heading, pitch, roll (rad) of rotations R_enu_deck (N, 3, 3) or (3, 3) built as
    :func:`deck2enu_rotation` builds them: its inverse for pitch in [-pi/2, pi/2] (heading in
    (-pi, pi]). Entries rounded just past +-1 are clipped before the arcsine of the pitch."""
    R = as_float_array("R_enu_deck", R_enu_deck)
    if R.shape[-2:] != (3, 3) or R.ndim not in (2, 3):
        raise ValueError(f"R_enu_deck: expected shape (N, 3, 3) or (3, 3), got {R.shape}")
    R = R.reshape(-1, 3, 3).copy()
    check_finite("R_enu_deck", R, "1")
    R[:, 2, 1] = np.clip(R[:, 2, 1], -1.0, 1.0)
    return generated.enu2deck_attitude(R_enu_deck=R).attitude.reshape(-1, 3)


def deck2enu(r, q, e, heading, pitch, roll) -> np.ndarray:
    """Phi (eq. 2): radar plot -> target offset from the radar in ENU, (N, 3) metres.

    r slant range (m, > 0); q deck bearing from the bow, starboard positive (rad); e elevation
    above the deck (rad); heading, pitch, roll (rad). Example: heading 90 deg, level ship,
    q = 0, e = 0, r = 1000 -> ``[[1000, 0, 0]]`` (the bow points east).
    """
    v = {**_measurement(r, q, e), **_attitude(heading, pitch, roll)}
    return generated.deck2enu(**_broadcast(v)).u_enu


def deck2enu_jacobians(r, q, e, heading, pitch, roll) -> tuple[np.ndarray, np.ndarray]:
    """Psi (N, 3, 6) = dPhi/d(heading, pitch, roll, r, q, e) and Gamma (N, 3, 3) = dPhi/d(r, q, e).

    Units: metres per radian for angle columns, dimensionless for the range column. Eq. (11).
    """
    v = {**_measurement(r, q, e), **_attitude(heading, pitch, roll)}
    out = generated.deck2enu_jacobians(**_broadcast(v))
    return out.Psi, out.Gamma


def plot2ecef(lat, lon, alt, heading, pitch, roll, r, q, e, variant: str = "standard") -> np.ndarray:
    """Eq. (3): a radar plot from a ship at (lat, lon rad,
    alt m) with attitude (rad) -> target ECEF (N, 3) m."""
    if variant not in T_VARIANTS:
        raise ValueError(f"variant: expected one of {T_VARIANTS}, got {variant!r}")
    v = {**_geodetic(lat, lon, alt), **_attitude(heading, pitch, roll), **_measurement(r, q, e)}
    return generated.plot2ecef(t_variant=variant, **_broadcast(v)).p_ecef
