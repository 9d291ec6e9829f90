"""Geodesy: geodetic -> ECEF position and the ENU -> ECEF rotation T (Wang et al. 2011, eqs. (1), (4)).

Frames (docs/reference/conventions.md): ``ecef`` is WGS-84 earth-centred earth-fixed; ``enu`` is the
local geographic frame at a platform (x east, y north, z up along the geodetic normal).
Latitude B, longitude L in radians, height H above the ellipsoid in metres.
"""

import sympy as sp

from .constants import WGS84_A, WGS84_B, WGS84_E2
from .spec import FunctionSpec, JacobianDecl, Port, jacobian

lat, lon, alt = sp.symbols("lat lon alt", real=True)


def geodetic2ecef_expr(B, L, H) -> sp.Matrix:
    """Eq. (1): ECEF position (m) of geodetic (B, L, H)."""
    N = WGS84_A / sp.sqrt(1 - WGS84_E2 * sp.sin(B) ** 2)  # prime-vertical radius of curvature
    return sp.Matrix(
        [
            (N + H) * sp.cos(B) * sp.cos(L),
            (N + H) * sp.cos(B) * sp.sin(L),
            (N * (1 - WGS84_E2) + H) * sp.sin(B),
        ]
    )


def enu2ecef_standard_expr(B, L) -> sp.Matrix:
    """R_ecef_enu: the orthonormal rotation taking ENU components to ECEF components."""
    sB, cB, sL, cL = sp.sin(B), sp.cos(B), sp.sin(L), sp.cos(L)
    return sp.Matrix([[-sL, -sB * cL, cB * cL], [cL, -sB * sL, cB * sL], [0, cB, sB]])


def enu2ecef_paper_expr(B, L) -> sp.Matrix:
    """Eq. (4) of Wang et al. 2011 exactly as printed (reproduction only).

    It is a rotation too, but it equals the standard one evaluated at a latitude psi
    with tan(psi) = (a/b)^2 tan(B): the local frame is tilted by ~0.12 deg at 20 deg N.
    """
    a4, b4 = WGS84_A**4, WGS84_B**4
    sB, cB, sL, cL = sp.sin(B), sp.cos(B), sp.sin(L), sp.cos(L)
    d1 = sp.sqrt(1 - (a4 - b4) / a4 * cB**2)
    d2 = sp.sqrt(1 + (a4 - b4) / b4 * sB**2)
    return sp.Matrix(
        [[-sL, -sB * cL / d1, cB * cL / d2], [cL, -sB * sL / d1, cB * sL / d2], [0, cB / d2, sB / d1]]
    )


T_VARIANTS = {"standard": enu2ecef_standard_expr, "paper": enu2ecef_paper_expr}


def radii_of_curvature_expr(B) -> sp.Matrix:
    """[M, N]: meridian and prime-vertical radii of curvature (m) at geodetic latitude B.

    Used to move platforms over the ellipsoid: dB/dt = v_north / (M + H),
    dL/dt = v_east / ((N + H) cos B).
    """
    w2 = 1 - WGS84_E2 * sp.sin(B) ** 2
    return sp.Matrix([WGS84_A * (1 - WGS84_E2) / w2 ** sp.Rational(3, 2), WGS84_A / sp.sqrt(w2)])


def ecef2geodetic_expr(x, y, z, iterations: int = 2) -> sp.Matrix:
    """[lat, lon, alt] (rad, rad, m) of an ECEF point (m), the inverse of eq. (1).

    Bowring's iteration on the parametric latitude beta, written without trigonometry inside the
    loop (sin and cos of beta from the previous latitude's atan2 arguments): two iterations reach
    the float64 rounding of latitude for heights from -12 km to 1000 km. The height
    ``p cos(lat) + z sin(lat) - a sqrt(1 - e^2 sin^2 lat)`` is well conditioned at the poles too.
    Undefined at the earth's centre.
    """
    one_f = WGS84_B / WGS84_A
    ep2 = (WGS84_A**2 - WGS84_B**2) / WGS84_B**2
    p = sp.sqrt(x**2 + y**2)
    s_b, c_b = z, one_f * p
    for _ in range(iterations):
        h = sp.sqrt(s_b**2 + c_b**2)
        s_b, c_b = s_b / h, c_b / h
        Y = z + ep2 * WGS84_B * s_b**3
        X = p - WGS84_E2 * WGS84_A * c_b**3
        s_b, c_b = one_f * Y, X
    h = sp.sqrt(X**2 + Y**2)
    s_lat, c_lat = Y / h, X / h
    alt_expr = p * c_lat + z * s_lat - WGS84_A * sp.sqrt(1 - WGS84_E2 * s_lat**2)
    return sp.Matrix([sp.atan2(Y, X), sp.atan2(y, x), alt_expr])


GEO_DOMAIN = {
    "lat": (-1.5707963267948966, 1.5707963267948966),
    "lon": (-3.141592653589793, 3.141592653589793),
    "alt": (-500.0, 1.0e5),
}


def specs() -> list[FunctionSpec]:
    out = [
        FunctionSpec(
            name="geodetic2ecef",
            doc="ECEF position (m) of a geodetic point (lat, lon in rad; alt in m above WGS-84). Eq. (1).",
            inputs=(Port("lat", lat, "rad"), Port("lon", lon, "rad"), Port("alt", alt, "m")),
            outputs=(Port("p_ecef", geodetic2ecef_expr(lat, lon, alt), "m"),),
            domain=GEO_DOMAIN,
        )
    ]
    px, py, pz = sp.symbols("x y z", real=True)
    out.append(
        FunctionSpec(
            name="ecef2geodetic",
            doc=(
                "Geodetic lat, lon (rad) and alt (m above WGS-84) of an ECEF point p_ecef (m): the inverse "
                "of eq. (1)."
            ),
            inputs=(Port("p_ecef", sp.Matrix([px, py, pz]), "m"),),
            outputs=(Port("geodetic", ecef2geodetic_expr(px, py, pz), "rad, rad, m"),),
            domain={"p_ecef": [(-7.4e6, 7.4e6)] * 3},
        )
    )
    alt_surface = sp.Symbol("alt_surface", real=True)
    p_ecef = sp.Matrix([px, py, pz])
    residual = sp.Matrix([alt_surface - ecef2geodetic_expr(px, py, pz)[2]])
    out.append(
        FunctionSpec(
            name="surface_residual",
            doc=(
                "Height residual of a target on a surface of known height (a ship on the sea): residual "
                "= alt_surface (m above WGS-84) - the geodetic height of p_ecef (m, the inverse of eq. "
                "(1)), and J = d residual / d p_ecef (1x3; minus the geodetic up at the point)."
            ),
            inputs=(Port("p_ecef", p_ecef, "m"), Port("alt_surface", alt_surface, "m")),
            outputs=(Port("residual", residual, "m"), Port("J", jacobian(residual, p_ecef), "1")),
            jacobians=(JacobianDecl("J", "residual", ("p_ecef",)),),
            domain={"p_ecef": [(-7.4e6, 7.4e6)] * 3, "alt_surface": (-100.0, 100.0)},
        )
    )
    out.append(
        FunctionSpec(
            name="radii_of_curvature",
            doc="Meridian radius M and prime-vertical radius N (m) of WGS-84 at latitude lat (rad).",
            inputs=(Port("lat", lat, "rad"),),
            outputs=(Port("radii", radii_of_curvature_expr(lat), "m"),),
            domain=GEO_DOMAIN,
        )
    )
    for variant, fn in T_VARIANTS.items():
        out.append(
            FunctionSpec(
                name=f"enu2ecef_rotation_{variant}",
                doc=f"R_ecef_enu at (lat, lon) in rad, '{variant}' variant (docs/background/online.md).",
                inputs=(Port("lat", lat, "rad"), Port("lon", lon, "rad")),
                outputs=(Port("R_ecef_enu", fn(lat, lon), "1"),),
                domain=GEO_DOMAIN,
            )
        )
    return out
