"""WGS-84 ellipsoid constants: the one definition in the project.

Exact rationals so that sympy keeps them exact until code generation, where they
become IEEE doubles. Nothing else in the project repeats these numbers; the
runtime reads them from ``generated/manifest.json`` (key ``constants``).
"""

import sympy as sp

#: semi-major axis a, metres
WGS84_A = sp.Integer(6378137)
#: flattening f = 1/298.257223563 (dimensionless)
WGS84_F = sp.Integer(1) / sp.Rational("298.257223563")
#: semi-minor axis b = a (1 - f), metres
WGS84_B = WGS84_A * (1 - WGS84_F)
#: first eccentricity squared e^2 = f (2 - f)
WGS84_E2 = WGS84_F * (2 - WGS84_F)

CONSTANTS = {"wgs84_a_m": WGS84_A, "wgs84_b_m": WGS84_B, "wgs84_f": WGS84_F, "wgs84_e2": WGS84_E2}
