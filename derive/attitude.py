"""Ship attitude and the radar measurement: deck frame -> ENU (paper eq. 2, eq. 11).

``deck`` frame: x starboard, y bow, z up along the deck normal. Attitude is the paper's
Cardan triple (C heading, phi pitch, theta roll), all in radians:
``R_enu_deck = Rz(C) Rx(phi) Ry(theta)`` (docs/reference/conventions.md). Radar measurement: slant range r
(m),
deck bearing q from the bow, starboard positive, and elevation eps above the deck plane.
"""

import sympy as sp

from .spec import FunctionSpec, JacobianDecl, Port, jacobian

r, q, e = sp.symbols("r q e", real=True)
heading, pitch, roll = sp.symbols("heading pitch roll", real=True)

PI = 3.141592653589793


def rz(C) -> sp.Matrix:
    return sp.Matrix([[sp.cos(C), sp.sin(C), 0], [-sp.sin(C), sp.cos(C), 0], [0, 0, 1]])


def rx(phi) -> sp.Matrix:
    return sp.Matrix([[1, 0, 0], [0, sp.cos(phi), -sp.sin(phi)], [0, sp.sin(phi), sp.cos(phi)]])


def ry(theta) -> sp.Matrix:
    return sp.Matrix([[sp.cos(theta), 0, sp.sin(theta)], [0, 1, 0], [-sp.sin(theta), 0, sp.cos(theta)]])


def deck2enu_rotation_expr(C, phi, theta) -> sp.Matrix:
    """R_enu_deck = Rz(C) Rx(phi) Ry(theta)."""
    return rz(C) * rx(phi) * ry(theta)


def radar2deck_expr(r_, q_, e_) -> sp.Matrix:
    """u_deck = [r sin q cos eps, r cos q cos eps, r sin eps]."""
    return sp.Matrix([r_ * sp.sin(q_) * sp.cos(e_), r_ * sp.cos(q_) * sp.cos(e_), r_ * sp.sin(e_)])


def phi_expr(C, phi, theta, r_, q_, e_) -> sp.Matrix:
    """Phi(C, phi, theta, r, q, eps) = R_enu_deck u_deck: the target in the platform's ENU frame (m)."""
    return deck2enu_rotation_expr(C, phi, theta) * radar2deck_expr(r_, q_, e_)


MEAS_INPUTS = (
    Port("r", r, "m"),
    Port("q", q, "rad"),
    Port("e", e, "rad"),
    Port("heading", heading, "rad"),
    Port("pitch", pitch, "rad"),
    Port("roll", roll, "rad"),
)
MEAS_DOMAIN = {
    "r": (100.0, 3.0e5),
    "q": (-PI, PI),
    "e": (-PI / 2, PI / 2),
    "heading": (-PI, PI),
    "pitch": (-0.5, 0.5),
    "roll": (-0.7, 0.7),
}


#: A rotation matrix as nine symbols (row-major names R_<row><column>).
R_ENU_DECK = sp.Matrix(3, 3, lambda i, j: sp.Symbol(f"R_{i}{j}", real=True))


def enu2deck_attitude_expr(R) -> sp.Matrix:
    """[heading, pitch, roll] of ``R = deck2enu_rotation_expr(C, phi, theta)``: with cos(phi) > 0 its
    column 1 (the bow) is (sin C cos phi, cos C cos phi, sin phi) and its row 2 is
    (-cos phi sin theta, sin phi, cos phi cos theta)."""
    return sp.Matrix([sp.atan2(R[0, 1], R[1, 1]), sp.asin(R[2, 1]), sp.atan2(-R[2, 0], R[2, 2])])


def specs() -> list[FunctionSpec]:
    Phi = phi_expr(heading, pitch, roll, r, q, e)
    Psi = jacobian(Phi, heading, pitch, roll, r, q, e)
    Gamma = jacobian(Phi, r, q, e)
    return [
        FunctionSpec(
            name="deck2enu_rotation",
            doc="R_enu_deck from heading, pitch, roll (rad): Rz(C) Rx(phi) Ry(theta).",
            inputs=MEAS_INPUTS[3:],
            outputs=(Port("R_enu_deck", deck2enu_rotation_expr(heading, pitch, roll), "1"),),
            domain=MEAS_DOMAIN,
        ),
        FunctionSpec(
            name="enu2deck_attitude",
            doc=(
                "heading, pitch, roll (rad) of a rotation R_enu_deck = Rz(C) Rx(phi) Ry(theta): the inverse "
                "of deck2enu_rotation for pitch in [-pi/2, pi/2] (heading from the bow's horizontal "
                "components, pitch from the bow's up component, roll from the up row)."
            ),
            inputs=(Port("R_enu_deck", R_ENU_DECK, "1"),),
            outputs=(Port("attitude", enu2deck_attitude_expr(R_ENU_DECK), "rad"),),
            domain={"R_enu_deck": [(-0.999, 0.999)] * 9},
        ),
        FunctionSpec(
            name="deck2enu",
            doc=(
                "Phi (eq. 2): radar measurement (r m, q rad, e rad) and attitude (rad) -> target ENU "
                "offset (m)."
            ),
            inputs=MEAS_INPUTS,
            outputs=(Port("u_enu", Phi, "m"),),
            domain=MEAS_DOMAIN,
        ),
        FunctionSpec(
            name="deck2enu_jacobians",
            doc=(
                "Psi = dPhi/d(C, phi, theta, r, q, e) (3x6, m/rad or m/m) and "
                "Gamma = dPhi/d(r, q, e) (3x3), eq. (11), by symbolic differentiation."
            ),
            inputs=MEAS_INPUTS,
            outputs=(
                Port("u_enu", Phi, "m"),
                Port("Psi", Psi, "m/rad, m/m"),
                Port("Gamma", Gamma, "m/m, m/rad"),
            ),
            jacobians=(
                JacobianDecl("Psi", "u_enu", ("heading", "pitch", "roll", "r", "q", "e")),
                JacobianDecl("Gamma", "u_enu", ("r", "q", "e")),
            ),
            domain=MEAS_DOMAIN,
        ),
    ]
