"""Target position in ECEF (eq. 3) and the two-sensor pseudo-measurement model (eqs. 7-19).

For radars A and B seeing one target at one instant:
``Z = X_A - X_B`` with ``X_i = T_i Phi_i + X_e,i``;
``H = [T_A Psi_A, -T_B Psi_B]`` (3x12, state order of registration.online.contract);
``M = [T_A Gamma_A, -T_B Gamma_B]`` (3x6); ``R = M R0 M^T``, ``R0 = diag(sigma^2)``.
H and M are exactly dZ/d(attitude, measurement) and dZ/d(measurement): the tests check that.
"""

import sympy as sp

from .attitude import MEAS_DOMAIN, deck2enu_rotation_expr, phi_expr
from .geodesy import GEO_DOMAIN, T_VARIANTS, geodetic2ecef_expr
from .spec import FunctionSpec, JacobianDecl, Port, jacobian


def _vec(prefix: str, names: list[str]) -> sp.Matrix:
    return sp.Matrix(sp.symbols([f"{prefix}_{n}" for n in names], real=True))


def plot2ecef_expr(nav, att, meas, variant: str) -> sp.Matrix:
    """Eq. (3): X = T(B, L) Phi(C, phi, theta, r, q, e) + geodetic2ecef(B, L, H)."""
    T = T_VARIANTS[variant](nav[0], nav[1])
    return T * phi_expr(att[0], att[1], att[2], meas[0], meas[1], meas[2]) + geodetic2ecef_expr(*nav)


def ecef2plot_expr(p_ecef, nav, att, variant: str) -> sp.Matrix:
    """Inverse of eq. (3): target ECEF -> the radar plot [r, q, e] a ship would measure.

    u_enu = T^T (X - X_e); u_deck = R_enu_deck^T u_enu; r = |u|, q = atan2(u_x, u_y) (from the bow,
    starboard positive), e = atan2(u_z, hypot(u_x, u_y)).
    """
    T = T_VARIANTS[variant](nav[0], nav[1])
    u_enu = T.T * (sp.Matrix(p_ecef) - geodetic2ecef_expr(*nav))
    u = deck2enu_rotation_expr(*att).T * u_enu
    return sp.Matrix(
        [
            sp.sqrt(u[0] ** 2 + u[1] ** 2 + u[2] ** 2),
            sp.atan2(u[0], u[1]),
            sp.atan2(u[2], sp.sqrt(u[0] ** 2 + u[1] ** 2)),
        ]
    )


PAIR_DOMAIN = {
    "nav_a": [GEO_DOMAIN["lat"], GEO_DOMAIN["lon"], GEO_DOMAIN["alt"]],
    "att_a": [MEAS_DOMAIN["heading"], MEAS_DOMAIN["pitch"], MEAS_DOMAIN["roll"]],
    "meas_a": [MEAS_DOMAIN["r"], MEAS_DOMAIN["q"], MEAS_DOMAIN["e"]],
    "sigma0": [(1.0, 200.0), (1e-4, 0.02), (1e-4, 0.02)] * 2,
}
PAIR_DOMAIN["nav_b"], PAIR_DOMAIN["att_b"], PAIR_DOMAIN["meas_b"] = (
    PAIR_DOMAIN["nav_a"],
    PAIR_DOMAIN["att_a"],
    PAIR_DOMAIN["meas_a"],
)


def specs() -> list[FunctionSpec]:
    out = []
    lat, lon, alt = sp.symbols("lat lon alt", real=True)
    heading, pitch, roll, r, q, e = sp.symbols("heading pitch roll r q e", real=True)
    for variant in T_VARIANTS:
        X = plot2ecef_expr([lat, lon, alt], [heading, pitch, roll], [r, q, e], variant)
        out.append(
            FunctionSpec(
                name=f"plot2ecef_{variant}",
                doc=(
                    f"Eq. (3), T variant '{variant}': a radar plot (r m, q rad, e rad) from a ship at "
                    "(lat, lon rad; alt m) with attitude (heading, pitch, roll rad) -> target ECEF (m)."
                ),
                inputs=tuple(
                    Port(n, s, u)
                    for n, s, u in [
                        ("lat", lat, "rad"),
                        ("lon", lon, "rad"),
                        ("alt", alt, "m"),
                        ("heading", heading, "rad"),
                        ("pitch", pitch, "rad"),
                        ("roll", roll, "rad"),
                        ("r", r, "m"),
                        ("q", q, "rad"),
                        ("e", e, "rad"),
                    ]
                ),
                outputs=(Port("p_ecef", X, "m"),),
                domain={**GEO_DOMAIN, **MEAS_DOMAIN},
            )
        )

        x, y, z = sp.symbols("x y z", real=True)
        out.append(
            FunctionSpec(
                name=f"ecef2plot_{variant}",
                doc=(
                    f"Inverse of eq. (3), T variant '{variant}': target ECEF p (m) seen from a ship at "
                    "(lat, lon rad; alt m) with attitude (heading, pitch, roll rad) -> plot [r m, q rad, "
                    "e rad]."
                ),
                inputs=(
                    Port("p_ecef", sp.Matrix([x, y, z]), "m"),
                    Port("lat", lat, "rad"),
                    Port("lon", lon, "rad"),
                    Port("alt", alt, "m"),
                    Port("heading", heading, "rad"),
                    Port("pitch", pitch, "rad"),
                    Port("roll", roll, "rad"),
                ),
                outputs=(
                    Port(
                        "plot",
                        ecef2plot_expr([x, y, z], [lat, lon, alt], [heading, pitch, roll], variant),
                        "m, rad, rad",
                    ),
                ),
                domain={**GEO_DOMAIN, **MEAS_DOMAIN, "p_ecef": [(-7.0e6, 7.0e6)] * 3},
            )
        )

    nav_a, att_a, meas_a = (
        _vec("a", ["lat", "lon", "alt"]),
        _vec("a", ["C", "phi", "theta"]),
        _vec("a", ["r", "q", "e"]),
    )
    nav_b, att_b, meas_b = (
        _vec("b", ["lat", "lon", "alt"]),
        _vec("b", ["C", "phi", "theta"]),
        _vec("b", ["r", "q", "e"]),
    )
    sigma0 = sp.Matrix(sp.symbols("s_ra s_qa s_ea s_rb s_qb s_eb", positive=True))
    for variant in T_VARIANTS:
        X_a = plot2ecef_expr(list(nav_a), list(att_a), list(meas_a), variant)
        X_b = plot2ecef_expr(list(nav_b), list(att_b), list(meas_b), variant)
        Z = X_a - X_b
        H = jacobian(Z, att_a, meas_a, att_b, meas_b)
        M = jacobian(Z, meas_a, meas_b)
        R = M * sp.diag(*[s**2 for s in sigma0]) * M.T
        out.append(
            FunctionSpec(
                name=f"pseudo_measurement_{variant}",
                doc=(
                    f"Two-sensor pseudo-measurement (eqs. 7-19), T variant '{variant}'. Inputs per "
                    "sensor: nav [lat rad, lon rad, alt m], att [heading, pitch, roll rad], meas [r m, q "
                    "rad, e rad]; "
                    "sigma0 = [sr_A m, sq_A rad, se_A rad, sr_B, sq_B, se_B]. Outputs Z = X_A - X_B (m), "
                    "H (3x12), M (3x6), R = M R0 M^T (m^2), and X_A, X_B (ECEF m)."
                ),
                inputs=(
                    Port("nav_a", nav_a, "rad, rad, m"),
                    Port("att_a", att_a, "rad"),
                    Port("meas_a", meas_a, "m, rad, rad"),
                    Port("nav_b", nav_b, "rad, rad, m"),
                    Port("att_b", att_b, "rad"),
                    Port("meas_b", meas_b, "m, rad, rad"),
                    Port("sigma0", sigma0, "m, rad, rad, m, rad, rad"),
                ),
                outputs=(
                    Port("Z", Z, "m"),
                    Port("H", H, "m/rad, m/m"),
                    Port("M", M, "m/m, m/rad"),
                    Port("R", R, "m^2"),
                    Port("p_a_ecef", X_a, "m"),
                    Port("p_b_ecef", X_b, "m"),
                ),
                jacobians=(
                    JacobianDecl("H", "Z", ("att_a", "meas_a", "att_b", "meas_b")),
                    JacobianDecl("M", "Z", ("meas_a", "meas_b")),
                ),
                domain=PAIR_DOMAIN,
            )
        )
    return out
