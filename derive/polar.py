"""Polar <-> Cartesian transforms and their Jacobians, 2-D and 3-D (docs/background/fusion.md,
docs/background/landing.md).

Convention shared by the fusion (D) and landing (L) capabilities: the angle ``az`` is measured
counter-clockwise from the +x axis towards +y; ``el`` is above the x-y plane.
2-D: ``p = [r cos az, r sin az]``. 3-D: ``p = [r cos el cos az, r cos el sin az, r sin el]``.
Ranges in metres, angles in radians. ``cartesian2polar*`` returns az in (-pi, pi] (atan2).
"""

import sympy as sp

from .spec import FunctionSpec, JacobianDecl, Port, jacobian

PI = 3.141592653589793


def polar2cartesian2_expr(r, az) -> sp.Matrix:
    return sp.Matrix([r * sp.cos(az), r * sp.sin(az)])


def polar2cartesian3_expr(r, az, el) -> sp.Matrix:
    return sp.Matrix([r * sp.cos(el) * sp.cos(az), r * sp.cos(el) * sp.sin(az), r * sp.sin(el)])


def cartesian2polar2_expr(x, y) -> sp.Matrix:
    return sp.Matrix([sp.sqrt(x**2 + y**2), sp.atan2(y, x)])


def cartesian2polar3_expr(x, y, z) -> sp.Matrix:
    rho = sp.sqrt(x**2 + y**2)
    return sp.Matrix([sp.sqrt(x**2 + y**2 + z**2), sp.atan2(y, x), sp.atan2(z, rho)])


def specs() -> list[FunctionSpec]:
    r, az, el = sp.symbols("r az el", real=True)
    x, y, z = sp.symbols("x y z", real=True)
    pol2 = sp.Matrix([r, az])
    pol3 = sp.Matrix([r, az, el])
    cart2 = sp.Matrix([x, y])
    cart3 = sp.Matrix([x, y, z])
    p2 = polar2cartesian2_expr(r, az)
    p3 = polar2cartesian3_expr(r, az, el)
    z2 = cartesian2polar2_expr(x, y)
    z3 = cartesian2polar3_expr(x, y, z)
    return [
        FunctionSpec(
            name="polar2cartesian2",
            doc="2-D: polar [r m, az rad] -> Cartesian p [m] and J = dp/dpolar.",
            inputs=(Port("polar", pol2, "m, rad"),),
            outputs=(Port("p", p2, "m"), Port("J", jacobian(p2, pol2), "1, m/rad")),
            jacobians=(JacobianDecl("J", "p", ("polar",)),),
            domain={"polar": [(1.0, 2.0e5), (-PI, PI)]},
        ),
        FunctionSpec(
            name="cartesian2polar2",
            doc="2-D: Cartesian p [m] -> polar [r m, az rad in (-pi, pi]] and J = dpolar/dp.",
            inputs=(Port("p", cart2, "m"),),
            outputs=(Port("polar", z2, "m, rad"), Port("J", jacobian(z2, cart2), "1, rad/m")),
            jacobians=(JacobianDecl("J", "polar", ("p",)),),
            domain={"p": [(-2.0e5, 2.0e5)] * 2},
        ),
        FunctionSpec(
            name="polar2cartesian3",
            doc="3-D: polar [r m, az rad, el rad] -> Cartesian p [m] and J = dp/dpolar.",
            inputs=(Port("polar", pol3, "m, rad, rad"),),
            outputs=(Port("p", p3, "m"), Port("J", jacobian(p3, pol3), "1, m/rad")),
            jacobians=(JacobianDecl("J", "p", ("polar",)),),
            domain={"polar": [(1.0, 2.0e5), (-PI, PI), (-PI / 2, PI / 2)]},
        ),
        FunctionSpec(
            name="cartesian2polar3",
            doc="3-D: Cartesian p [m] -> polar [r m, az rad, el rad] and J = dpolar/dp.",
            inputs=(Port("p", cart3, "m"),),
            outputs=(Port("polar", z3, "m, rad, rad"), Port("J", jacobian(z3, cart3), "1, rad/m")),
            jacobians=(JacobianDecl("J", "polar", ("p",)),),
            domain={"p": [(-2.0e5, 2.0e5)] * 3},
        ),
    ]
