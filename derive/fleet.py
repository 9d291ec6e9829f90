"""The plot model of fleet registration: one sensor on one platform sees one target.

Built on the two-ship model's expressions (derive/pseudo_measurement.py: ``ecef2plot_expr`` and
``plot2ecef_expr``, themselves built from geodesy.py and attitude.py), extended by the sensor's
lever arm and by the registration errors of the fleet problem (docs/background/fleet-model.md):

* the platform reports navigation (lat, lon rad; alt m) and attitude (heading, pitch, roll rad);
  its true attitude is ``reported - att_err`` (``att_err`` = heading, pitch, roll errors, rad);
* the sensor sits at ``lever_deck`` (m, deck frame: x starboard, y bow, z up) from the platform's
  navigation point and measures ``[r, q, e] = true + bias + noise`` (``bias`` = range m, bearing
  rad, elevation rad), the plot of docs/reference/conventions.md in the deck frame.

With ``u_deck = R_enu_deck^T R_ecef_enu^T (p_ecef - p_nav_ecef) - lever_deck``, the prediction is
``ecef2plot(p_ecef - R_ecef_enu R_enu_deck lever_deck)`` (the sensor's position moved to the
navigation point) plus the biases. The residual is measured minus predicted, the bearing wrapped
to (-pi, pi] as ``atan2(sin d, cos d)``; its Jacobian is that of the unwrapped difference (the
wrap has derivative 1 wherever it is continuous). The slant range is the same number as
ecef2plot's first entry but taken as ``|p_ecef - p_sensor_ecef|`` before any rotation: the
rotations preserve length, so the range depends on the attitude only through the lever arm, and
differentiating ``|R^T v|`` instead would subtract terms of the size of the range (1e5 m) to get
that lever-arm term (1e1 m), losing eight digits in d range / d attitude.

Channel subsets (2-D radar, passive angle sensor, bearing-only, range-only) use the same function:
the runtime weights the unmeasured channels by zero.

``fleet_rows_<n>`` composes ``fleet_residual`` in CasADi (no second copy of the model) into the
rows the batch solver's normal equations are built from (registration/fleet/batch/normal.py): with
weights ``w = mask / sigma`` per channel and the values ``basis`` (n) of the target window's
polynomial basis at the plot time, ``Z = [basis^T (x) diag(w) J_p | diag(w) J_x | w * residual]``
(3 x (3 n + 7): target-coefficient columns, the 6 state columns, the whitened residual), emitted
transposed so that each plot's three rows lie contiguous in memory.
"""

import sympy as sp

from .attitude import MEAS_DOMAIN, deck2enu_rotation_expr
from .geodesy import GEO_DOMAIN, T_VARIANTS, geodetic2ecef_expr
from .pseudo_measurement import ecef2plot_expr, plot2ecef_expr
from .spec import CasadiPort, CasadiSpec, FunctionSpec, JacobianDecl, Port, jacobian

VARIANT = "standard"  # the orthonormal ENU -> ECEF rotation; the paper's eq. (4) is for reproduction only
#: Sizes of the polynomial basis the rows function is emitted for: 1 (a position per instant) and
#: 4 (up to cubic; lower degrees mask the higher coefficients).
ROW_BASIS_SIZES = (1, 4)


def vec(prefix: str, names: list[str]) -> sp.Matrix:
    return sp.Matrix(sp.symbols([f"{prefix}_{n}" for n in names], real=True))


def lever_ecef_expr(nav, att, lever_deck) -> sp.Matrix:
    """The lever arm in ECEF components (m): R_ecef_enu(lat, lon) R_enu_deck(att) lever_deck."""
    return T_VARIANTS[VARIANT](nav[0], nav[1]) * deck2enu_rotation_expr(*att) * sp.Matrix(lever_deck)


def sensor_offset_expr(p_ecef, nav, att, lever_deck, pos_err_enu=None) -> sp.Matrix:
    """Target ECEF (m) moved by the sensor's offset from the navigation point: ``p_ecef`` minus the
    lever arm in ECEF plus ``R_ecef_enu pos_err_enu`` (the stated sensor position is the true one
    plus ``pos_err_enu``, m in the local ENU frame of the navigation point), so that the plot seen
    from the navigation point equals the plot of ``p_ecef`` seen from the true sensor position."""
    p_shifted = sp.Matrix(p_ecef) - lever_ecef_expr(nav, att, lever_deck)
    if pos_err_enu is not None:
        p_shifted = p_shifted + T_VARIANTS[VARIANT](nav[0], nav[1]) * sp.Matrix(pos_err_enu)
    return p_shifted


def predicted_plot_expr(
    p_ecef, nav, att_reported, att_err, bias, lever_deck, gain=None, pos_err_enu=None, ecc=None, theta=None
) -> sp.Matrix:
    """Plot [r m, q rad, e rad] the sensor reports for a target at p_ecef: true plot + bias (q unwrapped).

    ``gain`` (dimensionless, optional): the range is ``(1 + gain)`` times the true slant range
    before the range bias is added. ``pos_err_enu`` (m, optional): the stated sensor position
    minus the true one, in ENU at the navigation point. ``ecc`` (2, rad, optional) with ``theta``
    (rad, the measured bearing): the azimuth eccentricity, ``ecc[0] sin theta + ecc[1] cos theta``
    added to the bearing. Without them the expression is the original three-error model, term for
    term.
    """
    att = [att_reported[i] - att_err[i] for i in range(3)]
    p_shifted = sensor_offset_expr(p_ecef, nav, att, lever_deck, pos_err_enu)
    plot = ecef2plot_expr(p_shifted, nav, att, VARIANT)
    offset_ecef = p_shifted - geodetic2ecef_expr(*nav)
    slant = sp.sqrt(offset_ecef.dot(offset_ecef))  # = plot[0], without rotating first (see module doc)
    if gain is not None:
        slant = (1 + gain) * slant
    bearing = plot[1]
    if ecc is not None:
        bearing = bearing + _eccentricity(ecc, theta)
    return sp.Matrix([slant, bearing, plot[2]]) + sp.Matrix(bias)


def _eccentricity(ecc, theta):
    """The bearing error (rad) of an eccentric antenna, ``a sin theta + b cos theta``, at the
    measured bearing ``theta`` (rad); ``ecc = [a, b]`` (rad)."""
    return ecc[0] * sp.sin(theta) + ecc[1] * sp.cos(theta)


def corrected_plot2ecef_expr(
    nav, att_reported, att_err, bias, lever_deck, meas, gain=None, pos_err_enu=None, ecc=None
) -> sp.Matrix:
    """Target ECEF (m) from a plot corrected by the biases (and range gain, and eccentricity at the
    measured bearing) and an attitude corrected by its errors, seen from the true sensor position
    (the inverse of predicted_plot_expr)."""
    att = [att_reported[i] - att_err[i] for i in range(3)]
    plot = [meas[i] - bias[i] for i in range(3)]
    if ecc is not None:
        plot[1] = plot[1] - _eccentricity(ecc, meas[1])
    if gain is not None:
        plot[0] = plot[0] / (1 + gain)
    p = plot2ecef_expr(nav, att, plot, VARIANT) + lever_ecef_expr(nav, att, lever_deck)
    if pos_err_enu is not None:
        p = p - T_VARIANTS[VARIANT](nav[0], nav[1]) * sp.Matrix(pos_err_enu)
    return p


def wrap(x):
    """x wrapped to (-pi, pi] (differentiable away from the cut, derivative 1)."""
    return sp.atan2(sp.sin(x), sp.cos(x))


FLEET_DOMAIN = {
    **GEO_DOMAIN,
    **MEAS_DOMAIN,
    "p_ecef": [(-7.0e6, 7.0e6)] * 3,
    "att_err": [(-0.1, 0.1)] * 3,
    "bias": [(-5000.0, 5000.0), (-0.1, 0.1), (-0.1, 0.1)],
    "lever_deck": [(-100.0, 100.0)] * 3,
    # the extended model (fleet_residual_ext): target velocity, navigation rates, the new errors
    "v_ecef": [(-400.0, 400.0)] * 3,
    "nav_rate": [(-3e-6, 3e-6), (-3e-6, 3e-6), (-5.0, 5.0), (-0.05, 0.05), (-0.1, 0.1), (-0.1, 0.1)],
    "gain": (-0.01, 0.01),
    "dt": (-1.0, 1.0),
    "pos_err": [(-100.0, 100.0)] * 3,
}


def make_nav_ports(lat, lon, alt, heading, pitch, roll) -> tuple:
    return (
        Port("lat", lat, "rad"),
        Port("lon", lon, "rad"),
        Port("alt", alt, "m"),
        Port("heading", heading, "rad"),
        Port("pitch", pitch, "rad"),
        Port("roll", roll, "rad"),
    )


def specs() -> list[FunctionSpec]:
    lat, lon, alt = sp.symbols("lat lon alt", real=True)
    heading, pitch, roll = sp.symbols("heading pitch roll", real=True)
    r, q, e = sp.symbols("r q e", real=True)
    p_ecef = sp.Matrix(sp.symbols("x y z", real=True))
    att_err = vec("d", ["heading", "pitch", "roll"])
    bias = vec("b", ["r", "q", "e"])
    lever = vec("lever", ["x", "y", "z"])
    nav, att = [lat, lon, alt], [heading, pitch, roll]

    predicted = predicted_plot_expr(p_ecef, nav, att, att_err, bias, lever)
    difference = sp.Matrix([r, q, e]) - predicted
    residual = sp.Matrix([difference[0], wrap(difference[1]), difference[2]])
    J = jacobian(difference, p_ecef, att_err, bias)
    plot = sp.Matrix([predicted[0], wrap(predicted[1]), predicted[2]])
    nav_ports = make_nav_ports(lat, lon, alt, heading, pitch, roll)
    residual_spec = FunctionSpec(
        name="fleet_residual",
        doc=(
            "One plot of fleet registration: target p_ecef (m); platform navigation lat, lon (rad), "
            "alt (m) and reported heading, pitch, roll (rad); attitude errors att_err (rad; true = "
            "reported - error); sensor biases [range m, bearing rad, elevation rad]; lever_deck (m, deck "
            "frame); measured r (m), q, e (rad). Outputs residual = measured - predicted (bearing wrapped "
            "to (-pi, pi]), J = d residual / d(p_ecef, att_err, bias) (3x9), and the predicted plot "
            "(true plot + bias, bearing wrapped)."
        ),
        inputs=(
            Port("p_ecef", p_ecef, "m"),
            *nav_ports,
            Port("att_err", att_err, "rad"),
            Port("bias", bias, "m, rad, rad"),
            Port("lever_deck", lever, "m"),
            Port("r", r, "m"),
            Port("q", q, "rad"),
            Port("e", e, "rad"),
        ),
        outputs=(
            Port("residual", residual, "m, rad, rad"),
            Port("J", J, "m/m, m/rad, 1; rad/m, 1, 1"),
            Port("plot", plot, "m, rad, rad"),
        ),
        jacobians=(JacobianDecl("J", "residual", ("p_ecef", "att_err", "bias")),),
        domain=FLEET_DOMAIN,
    )
    p_target = corrected_plot2ecef_expr(nav, att, att_err, bias, lever, [r, q, e])
    plot2ecef_spec = FunctionSpec(
        name="fleet_plot2ecef",
        doc=(
            "Target ECEF (m) of one plot corrected by the registration errors: navigation lat, lon (rad), "
            "alt (m), reported heading, pitch, roll (rad), attitude errors att_err (rad), sensor biases "
            "[range m, bearing rad, elevation rad], lever_deck (m, deck frame), measured r (m), q, e (rad). "
            "The inverse of fleet_residual's predicted plot."
        ),
        inputs=(
            *nav_ports,
            Port("att_err", att_err, "rad"),
            Port("bias", bias, "m, rad, rad"),
            Port("lever_deck", lever, "m"),
            Port("r", r, "m"),
            Port("q", q, "rad"),
            Port("e", e, "rad"),
        ),
        outputs=(Port("p_ecef", p_target, "m"),),
        domain=FLEET_DOMAIN,
    )
    return [
        residual_spec,
        plot2ecef_spec,
        *[rows_spec(residual_spec, n) for n in ROW_BASIS_SIZES],
        *extended_specs(),
    ]


def rows_spec(residual_spec: FunctionSpec, n_basis: int, family: str = "") -> CasadiSpec:
    """The rows function of ``residual_spec``: fleet_residual (``family`` ""), fleet_residual_ext
    ("ext") or fleet_residual_ecc ("ecc"); in the last two the input ``dt`` is held at 0, its
    Jacobian column being the time bias's."""
    extended = bool(family)
    ports = [p for p in residual_spec.inputs if p.name != "dt"]
    scalar = {p.name for p in ports if p.shape == (1, 1)}
    inputs = tuple(CasadiPort(p.name, p.shape, p.unit) for p in ports) + (
        CasadiPort("weight", (3, 1), "1/m, 1/rad, 1/rad"),
        CasadiPort("basis", (n_basis, 1), "1"),
    )
    n_state = {"": 6, "ext": 11, "ecc": 13}[family]
    m = 3 * n_basis + n_state + 1
    name = f"fleet_rows_{family}_{n_basis}" if extended else f"fleet_rows_{n_basis}"

    def build():
        import casadi as ca

        from .emit import to_casadi_function

        residual = to_casadi_function(residual_spec)
        args = [ca.SX.sym(p.name, *p.shape) for p in inputs]
        call = list(args[:-2])
        if extended:
            call.insert([p.name for p in residual_spec.inputs].index("dt"), ca.SX(0.0))
        res, J, _ = residual(*call)
        w, basis = args[-2], args[-1]
        A = ca.diag(w) @ J
        Z = ca.horzcat(*[basis[k] * A[:, 0:3] for k in range(n_basis)], A[:, 3 : 3 + n_state], w * res)
        return ca.Function(name, args, [Z.T], [p.name for p in inputs], ["rows_t"], {"cse": True})

    domain = {
        **residual_spec.domain,
        "weight": [(0.0, 0.1), (0.0, 3000.0), (0.0, 3000.0)],
        "basis": [(-1.0, 1.0)] * n_basis,
    }
    state_doc = {
        "": "J_x over the 6 states",
        "ext": (
            "J_x over the 11 states (attitude errors, biases, range gain, time bias, position errors; the "
            "time bias's column is d residual / d dt at dt = 0)"
        ),
        "ecc": (
            "J_x over the 13 states (attitude errors, biases, range gain, time bias, position errors, "
            "eccentricity sin and cos; the time bias's column is d residual / d dt at dt = 0)"
        ),
    }[family]
    return CasadiSpec(
        name=name,
        doc=(
            f"Rows of the batch normal equations for one plot, polynomial basis of size {n_basis}: the "
            f"inputs of {residual_spec.name}{' (without dt)' if extended else ''}, channel weights w = mask "
            "/ sigma (1/m, 1/rad, 1/rad) and the basis values at the plot time. Output rows_t "
            f"({m}x3) = Z^T, Z = [basis^T (x) diag(w) J_p | diag(w) J_x | w * residual], {state_doc}."
        ),
        inputs=inputs,
        outputs=(CasadiPort("rows_t", (m, 3), "1/m, 1/rad"),),
        builder=build,
        domain={k: v for k, v in domain.items() if k in {p.name for p in inputs} | scalar},
    )


def extended_specs() -> list:
    """The extended plot model: range gain, time bias and sensor position error besides the
    attitude errors and biases (docs/background/fleet-model.md, "Sensor error model").

    ``fleet_residual_ext`` takes the target position ``p_ecef`` and velocity ``v_ecef`` (m, m/s)
    and the platform's navigation and its rates ``nav_rate`` (rad/s, m/s) all at one time, and
    sees the target and platform ``dt`` seconds earlier than that, to first order: ``p - v dt``,
    ``nav - nav_rate dt``. The runtime evaluates the inputs at the plot's time corrected by the
    current time-bias estimate and passes ``dt = 0``: the residual is then exact and the column
    d residual / d dt is the time bias's, target and platform motion included.
    """
    lat, lon, alt = sp.symbols("lat lon alt", real=True)
    heading, pitch, roll = sp.symbols("heading pitch roll", real=True)
    r, q, e = sp.symbols("r q e", real=True)
    gain, dt = sp.symbols("gain dt", real=True)
    p_ecef = sp.Matrix(sp.symbols("x y z", real=True))
    v_ecef = vec("v", ["x", "y", "z"])
    rate = vec("rate", ["lat", "lon", "alt", "heading", "pitch", "roll"])
    att_err = vec("d", ["heading", "pitch", "roll"])
    bias = vec("b", ["r", "q", "e"])
    lever = vec("lever", ["x", "y", "z"])
    pos_err = vec("pos", ["east", "north", "up"])
    nav6 = [lat, lon, alt, heading, pitch, roll]
    seen = [nav6[i] - rate[i] * dt for i in range(6)]
    p_seen = p_ecef - v_ecef * dt
    predicted = predicted_plot_expr(p_seen, seen[:3], seen[3:], att_err, bias, lever, gain, pos_err)
    difference = sp.Matrix([r, q, e]) - predicted
    residual = sp.Matrix([difference[0], wrap(difference[1]), difference[2]])
    J = jacobian(difference, p_ecef, att_err, bias, gain, dt, pos_err)
    plot = sp.Matrix([predicted[0], wrap(predicted[1]), predicted[2]])
    nav_ports = make_nav_ports(*nav6)
    error_ports = (
        Port("att_err", att_err, "rad"),
        Port("bias", bias, "m, rad, rad"),
        Port("gain", gain, "1"),
    )
    residual_spec = FunctionSpec(
        name="fleet_residual_ext",
        doc=(
            "One plot of fleet registration with the extended sensor errors: target p_ecef (m) and velocity "
            "v_ecef (m/s); platform navigation lat, lon (rad), alt (m), reported heading, pitch, roll (rad) "
            "and their rates nav_rate (rad/s, m/s); attitude errors att_err (rad); biases [range m, bearing "
            "rad, elevation rad]; range gain (1); dt (s): target and platform seen dt earlier, to first "
            "order; sensor position error pos_err (m, ENU, stated - true); lever_deck (m); measured r (m), "
            "q, e (rad). Outputs residual = measured - predicted (bearing wrapped), J = d residual / "
            "d(p_ecef, att_err, bias, gain, dt, pos_err) (3x14) and the predicted plot."
        ),
        inputs=(
            Port("p_ecef", p_ecef, "m"),
            Port("v_ecef", v_ecef, "m/s"),
            *nav_ports,
            Port("nav_rate", rate, "rad/s, rad/s, m/s, rad/s, rad/s, rad/s"),
            *error_ports,
            Port("dt", dt, "s"),
            Port("pos_err", pos_err, "m"),
            Port("lever_deck", lever, "m"),
            Port("r", r, "m"),
            Port("q", q, "rad"),
            Port("e", e, "rad"),
        ),
        outputs=(
            Port("residual", residual, "m, rad, rad"),
            Port("J", J, "m/m, m/rad, 1, m, m/s, 1; rad/m, 1, 1, rad, rad/s, rad/m"),
            Port("plot", plot, "m, rad, rad"),
        ),
        jacobians=(JacobianDecl("J", "residual", ("p_ecef", "att_err", "bias", "gain", "dt", "pos_err")),),
        domain=FLEET_DOMAIN,
    )
    p_target = corrected_plot2ecef_expr(nav6[:3], nav6[3:], att_err, bias, lever, [r, q, e], gain, pos_err)
    plot2ecef_spec = FunctionSpec(
        name="fleet_plot2ecef_ext",
        doc=(
            "Target ECEF (m) of one plot corrected by the extended registration errors: navigation lat, lon "
            "(rad), alt (m), reported heading, pitch, roll (rad), att_err (rad), biases [m, rad, rad], range "
            "gain (1), sensor position error pos_err (m, ENU, stated - true), lever_deck (m), measured r "
            "(m), q, e (rad). The inverse of fleet_residual_ext's predicted plot at dt = 0."
        ),
        inputs=(
            *nav_ports,
            *error_ports,
            Port("pos_err", pos_err, "m"),
            Port("lever_deck", lever, "m"),
            Port("r", r, "m"),
            Port("q", q, "rad"),
            Port("e", e, "rad"),
        ),
        outputs=(Port("p_ecef", p_target, "m"),),
        domain=FLEET_DOMAIN,
    )
    return [residual_spec, plot2ecef_spec, *[rows_spec(residual_spec, n, "ext") for n in ROW_BASIS_SIZES]]
