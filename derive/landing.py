"""Carrier landing (Wang, Liu and Gao 2017): the radar/camera space alignment chain and its
Jacobians (eqs. 7-11).

Frames (all right-handed, metres; see docs/background/landing.md for pictures in words and numeric examples):

- ``deck``: ship-fixed (docs/reference/conventions.md): origin at the ship's motion centre (the point the ship
  pitches, rolls and yaws about), x starboard, y bow, z up along the deck normal.
- ``level``: same origin, not rotating with the ship's oscillations: x starboard and y bow along
  the ship's *mean* heading, z up (vertical). ``R_level_deck = Rz(yaw) Rx(pitch) Ry(roll)``, the
  package's attitude formula with the heading replaced by the yaw deviation from the mean heading
  (positive yaw turns the bow to starboard, positive pitch lifts the bow, positive roll puts the
  starboard side down). This is the paper's ``T_R^-1``.
- ``lnd`` (paper's T_L): the level frame with x aft, y starboard, z up: ``R_lnd_level = Rz(-pi/2)``.
- ``td``: the ideal touchdown-point frame. Origin at the ideal touchdown point (a deck-fixed point,
  so it heaves and sways with the ship's motion); axes level: x horizontal along the angled-deck
  centreline pointing aft (towards the approaching aircraft), z up, y = z x x (horizontal, 90 deg
  counter-clockwise from x seen from above; it has a starboard component). With the angled-deck
  angle phi_c (positive: the landing area's forward end points to port, as on US carriers),
  ``R_td_level = T_A(phi_c) T_L = Rz(phi_c) Rz(-pi/2)`` where ``T_A = Rz(phi_c)`` is the paper's
  matrix. ``M = R_td_deck = R_td_level R_level_deck`` (eq. 8).
- ``mtd``: the td frame at zero attitude: td axes, origin at the touchdown point's mean position.
  It only translates with the ship's mean velocity; the aircraft's glide path is straight in it.
- ``rdr``: the radar's measurement. Origin at the radar, deck axes; polar ``[r, a, b]`` with the
  azimuth a counter-clockwise from x_deck (starboard) towards y_deck (bow) and the elevation b
  above the deck plane (paper eq. 2, the convention of derive/polar.py): dead astern is a = -pi/2.
- ``cam``: the centreline camera's measurement. Origin at the camera, deck-fixed, with the td axes
  it would have at zero attitude (``R_cam_deck = R_td_level``): x along the angled-deck centreline
  aft, z deck normal. Angles ``[a, b]`` as above (eq. 4).
- ``ctd``: camera-centred touchdown axes: origin at the camera, td axes. Fusion happens in the
  polar coordinates ``[r, a, b]`` of this frame (eq. 12).

Lever arms (the paper's assumption 2, relative positions known): ``d_radar_deck`` and
``d_camera_deck`` are the radar's and camera's positions minus the touchdown point's, in deck axes;
``l_td_deck`` is the touchdown point relative to the motion centre. The paper's eq. (7) adds a
constant offset in the touchdown frame; here the lever arm rotates with the deck
(``p_td = M (u_deck + d_radar_deck)``), which is exact for deck-fixed sensors.
"""

import sympy as sp

from .attitude import deck2enu_rotation_expr, rz
from .polar import cartesian2polar3_expr, polar2cartesian3_expr
from .spec import FunctionSpec, JacobianDecl, Port

PI = 3.141592653589793

_X, _Y, _Z = sp.symbols("_x _y _z", real=True)
_R, _AZ, _EL = sp.symbols("_r _az _el", real=True)
#: dpolar/dp of cartesian2polar3 at a generic point (the paper's B), substituted below
_B_GENERIC = cartesian2polar3_expr(_X, _Y, _Z).jacobian(sp.Matrix([_X, _Y, _Z]))
#: dp/dpolar of polar2cartesian3 at a generic polar point (the paper's A)
_A_GENERIC = polar2cartesian3_expr(_R, _AZ, _EL).jacobian(sp.Matrix([_R, _AZ, _EL]))


def _vec(name: str, n: int) -> sp.Matrix:
    return sp.Matrix(sp.symbols(f"{name}_0:{n}", real=True))


def td_level_rotation_expr(angled_deck) -> sp.Matrix:
    """R_td_level = T_A(phi_c) T_L with T_A = Rz(phi_c) (paper) and T_L = Rz(-pi/2) (x aft, y starboard)."""
    return rz(angled_deck) * rz(-sp.pi / 2)


def td_deck_rotation_expr(attitude, angled_deck) -> sp.Matrix:
    """M = R_td_deck = T_A T_L T_R^-1 with T_R^-1 = R_level_deck = Rz(yaw) Rx(pitch) Ry(roll) (eq. 8)."""
    return td_level_rotation_expr(angled_deck) * deck2enu_rotation_expr(attitude[0], attitude[1], attitude[2])


def polar_jacobian_at(p) -> sp.Matrix:
    """B = dpolar/dp of cartesian2polar3 evaluated at the expression vector p (eq. 9)."""
    return _B_GENERIC.xreplace({_X: p[0], _Y: p[1], _Z: p[2]})


def cartesian_jacobian_at(polar) -> sp.Matrix:
    """A = dp/dpolar of polar2cartesian3 evaluated at the polar vector (eq. 8)."""
    return _A_GENERIC.xreplace({_R: polar[0], _AZ: polar[1], _EL: polar[2]})


def radar2td_expr(polar_rdr, attitude, angled_deck, d_radar_deck) -> sp.Matrix:
    """Eq. (7), lever arm rotating with the deck: p_td = M (u_deck + d_radar_deck)."""
    u_deck = polar2cartesian3_expr(*polar_rdr)
    return td_deck_rotation_expr(attitude, angled_deck) * (u_deck + d_radar_deck)


def td2ctd_expr(p_td, attitude, angled_deck, d_camera_deck) -> sp.Matrix:
    """Camera-centred touchdown axes: v_ctd = p_td - M d_camera_deck (m)."""
    return p_td - td_deck_rotation_expr(attitude, angled_deck) * d_camera_deck


def camera_to_ctd_rotation_expr(attitude, angled_deck) -> sp.Matrix:
    """R_ctd_cam = R_td_deck R_deck_cam with R_deck_cam = R_td_level^T (camera aligned with the
    landing area)."""
    return td_deck_rotation_expr(attitude, angled_deck) * td_level_rotation_expr(angled_deck).T


ATTITUDE_DOMAIN = [(-0.05, 0.05), (-0.1, 0.1), (-0.15, 0.15)]
ANGLED_DECK_DOMAIN = (0.0, 0.25)
LEVER_DOMAIN = [(-80.0, 80.0), (-80.0, 120.0), (-10.0, 40.0)]
#: target points on or near an approach: aft, within a wide cone, above the deck
P_TD_DOMAIN = [(300.0, 6000.0), (-400.0, 400.0), (5.0, 500.0)]
POLAR_RDR_DOMAIN = [(300.0, 6000.0), (-2.4, -0.8), (0.0, 0.3)]


def specs() -> list[FunctionSpec]:
    att = _vec("attitude", 3)
    phic = sp.Symbol("angled_deck", real=True)
    pol_r = _vec("polar_rdr", 3)
    ang_c = _vec("angles_cam", 2)
    pol_c = _vec("polar_ctd", 3)
    p_td = _vec("p_td", 3)
    p_mtd = _vec("p_mtd", 3)
    d_r = _vec("d_radar_deck", 3)
    d_c = _vec("d_camera_deck", 3)
    l_td = _vec("l_td_deck", 3)

    M = td_deck_rotation_expr(att, phic)
    att_port = Port("attitude", att, "rad: yaw deviation from the mean heading, pitch, roll")
    phic_port = Port("angled_deck", phic, "rad")
    dom_common = {"attitude": ATTITUDE_DOMAIN, "angled_deck": ANGLED_DECK_DOMAIN}

    # radar -> touchdown frame (eq. 7) with A, M and J = M A (eq. 8)
    u_deck = polar2cartesian3_expr(*pol_r)
    A = cartesian_jacobian_at(pol_r)
    p_td_r = radar2td_expr(pol_r, att, phic, d_r)

    # touchdown frame -> camera-centred polar, B (eq. 9)
    v_ctd = td2ctd_expr(p_td, att, phic, d_c)
    polar_from_td = cartesian2polar3_expr(*v_ctd)
    B_td = polar_jacobian_at(v_ctd)

    # radar -> camera-centred polar directly: polar_ctd and B M A (eq. 10)
    v_ctd_r = td2ctd_expr(p_td_r, att, phic, d_c)
    polar_from_radar = cartesian2polar3_expr(*v_ctd_r)
    BMA = polar_jacobian_at(v_ctd_r) * M * A

    # camera angles -> camera-centred touchdown angles (unit direction rotated), and their Jacobian
    unit_cam = polar2cartesian3_expr(1, ang_c[0], ang_c[1])
    R_ctd_cam = camera_to_ctd_rotation_expr(att, phic)
    w_ctd = R_ctd_cam * unit_cam
    angles_ctd = cartesian2polar3_expr(*w_ctd)[1:, :]
    J_cam = (
        polar_jacobian_at(w_ctd)[1:, :]
        * R_ctd_cam
        * cartesian_jacobian_at([sp.Integer(1), ang_c[0], ang_c[1]])[:, 1:]
    )

    # camera-centred polar -> touchdown frame (rebuild after fusion)
    p_td_c = polar2cartesian3_expr(*pol_c) + M * d_c
    J_ctd = cartesian_jacobian_at(pol_c)

    # simulation: mean touchdown frame -> touchdown frame; touchdown frame -> sensor readings
    R_td_level = td_level_rotation_expr(phic)
    p_td_m = p_mtd - R_td_level * (deck2enu_rotation_expr(att[0], att[1], att[2]) - sp.eye(3)) * l_td
    u_deck_sim = M.T * p_td - d_r
    polar_rdr_sim = cartesian2polar3_expr(*u_deck_sim)
    u_cam_sim = R_td_level * M.T * v_ctd
    angles_cam_sim = cartesian2polar3_expr(*u_cam_sim)[1:, :]

    return [
        FunctionSpec(
            name="landing_deck2td_rotation",
            doc="M = R_td_deck = T_A(phi_c) T_L R_level_deck(yaw, pitch, roll) (eqs. 7-8); angles in rad.",
            inputs=(att_port, phic_port),
            outputs=(Port("R_td_deck", M, "1"),),
            domain=dom_common,
        ),
        FunctionSpec(
            name="landing_radar2td",
            doc=(
                "Eq. (7): radar polar [r m, a rad, b rad] in deck axes -> target p_td (m) in the touchdown "
                "frame, with u_deck (m), A = du_deck/dpolar, M = R_td_deck and J = dp_td/dpolar = M A."
            ),
            inputs=(
                Port("polar_rdr", pol_r, "m, rad, rad"),
                att_port,
                phic_port,
                Port("d_radar_deck", d_r, "m"),
            ),
            outputs=(
                Port("p_td", p_td_r, "m"),
                Port("u_deck", u_deck, "m"),
                Port("A", A, "1, m/rad"),
                Port("M", M, "1"),
                Port("J", M * A, "1, m/rad"),
            ),
            jacobians=(
                JacobianDecl("A", "u_deck", ("polar_rdr",)),
                JacobianDecl("J", "p_td", ("polar_rdr",)),
            ),
            domain={**dom_common, "polar_rdr": POLAR_RDR_DOMAIN, "d_radar_deck": LEVER_DOMAIN},
        ),
        FunctionSpec(
            name="landing_td2ctd",
            doc=(
                "Touchdown-frame point p_td (m) -> polar [r m, a rad, b rad] about the camera in td axes "
                "(ctd), and B = dpolar/dp_td (eq. 9)."
            ),
            inputs=(Port("p_td", p_td, "m"), att_port, phic_port, Port("d_camera_deck", d_c, "m")),
            outputs=(Port("polar_ctd", polar_from_td, "m, rad, rad"), Port("B", B_td, "1, rad/m")),
            jacobians=(JacobianDecl("B", "polar_ctd", ("p_td",)),),
            domain={**dom_common, "p_td": P_TD_DOMAIN, "d_camera_deck": LEVER_DOMAIN},
        ),
        FunctionSpec(
            name="landing_radar2ctd",
            doc=(
                "Eqs. (7)-(10): radar polar [r m, a rad, b rad] (deck axes) -> polar about the camera in td "
                "axes (ctd), and BMA = dpolar_ctd/dpolar_rdr for P_RL = BMA P_R BMA^T (eq. 11)."
            ),
            inputs=(
                Port("polar_rdr", pol_r, "m, rad, rad"),
                att_port,
                phic_port,
                Port("d_radar_deck", d_r, "m"),
                Port("d_camera_deck", d_c, "m"),
            ),
            outputs=(Port("polar_ctd", polar_from_radar, "m, rad, rad"), Port("BMA", BMA, "1, m/rad, rad/m")),
            jacobians=(JacobianDecl("BMA", "polar_ctd", ("polar_rdr",)),),
            domain={
                **dom_common,
                "polar_rdr": POLAR_RDR_DOMAIN,
                "d_radar_deck": LEVER_DOMAIN,
                "d_camera_deck": [(-10.0, 10.0), (-10.0, 40.0), (-2.0, 2.0)],
            },
        ),
        FunctionSpec(
            name="landing_camera2ctd",
            doc=(
                "Camera angles [a, b] (rad, deck-fixed landing-area axes) -> angles about the camera in td "
                "axes (ctd), and J = dangles_ctd/dangles_cam (2x2) for the camera's error transfer."
            ),
            inputs=(Port("angles_cam", ang_c, "rad"), att_port, phic_port),
            outputs=(Port("angles_ctd", angles_ctd, "rad"), Port("J", J_cam, "1")),
            jacobians=(JacobianDecl("J", "angles_ctd", ("angles_cam",)),),
            domain={**dom_common, "angles_cam": [(-0.5, 0.5), (-0.2, 0.5)]},
        ),
        FunctionSpec(
            name="landing_ctd2td",
            doc=(
                "Polar [r m, a rad, b rad] about the camera in td axes -> p_td (m), and J = dp_td/dpolar "
                "(rebuilds the fused position, eq. 12)."
            ),
            inputs=(
                Port("polar_ctd", pol_c, "m, rad, rad"),
                att_port,
                phic_port,
                Port("d_camera_deck", d_c, "m"),
            ),
            outputs=(Port("p_td", p_td_c, "m"), Port("J", J_ctd, "1, m/rad")),
            jacobians=(JacobianDecl("J", "p_td", ("polar_ctd",)),),
            domain={
                **dom_common,
                "polar_ctd": [(10.0, 6000.0), (-PI, PI), (-1.2, 1.2)],
                "d_camera_deck": LEVER_DOMAIN,
            },
        ),
        FunctionSpec(
            name="landing_mtd2td",
            doc=(
                "Simulation: point in the mean touchdown frame p_mtd (m) -> touchdown frame p_td (m), the "
                "touchdown point at l_td_deck (m, from the motion centre) moving with the attitude (rad)."
            ),
            inputs=(Port("p_mtd", p_mtd, "m"), att_port, phic_port, Port("l_td_deck", l_td, "m")),
            outputs=(Port("p_td", p_td_m, "m"),),
            domain={**dom_common, "p_mtd": P_TD_DOMAIN, "l_td_deck": LEVER_DOMAIN},
        ),
        FunctionSpec(
            name="landing_td2radar",
            doc=(
                "Simulation (inverse of eq. 7): p_td (m) -> the radar polar [r m, a rad, b rad] in deck axes."
            ),
            inputs=(Port("p_td", p_td, "m"), att_port, phic_port, Port("d_radar_deck", d_r, "m")),
            outputs=(Port("polar_rdr", polar_rdr_sim, "m, rad, rad"),),
            domain={**dom_common, "p_td": P_TD_DOMAIN, "d_radar_deck": LEVER_DOMAIN},
        ),
        FunctionSpec(
            name="landing_td2camera",
            doc="Simulation: p_td (m) -> the camera angles [a, b] (rad) in its deck-fixed landing-area axes.",
            inputs=(Port("p_td", p_td, "m"), att_port, phic_port, Port("d_camera_deck", d_c, "m")),
            outputs=(Port("angles_cam", angles_cam_sim, "rad"),),
            domain={**dom_common, "p_td": P_TD_DOMAIN, "d_camera_deck": LEVER_DOMAIN},
        ),
    ]
