"""The eccentric plot model of fleet registration: the extended model (derive/fleet.py,
``extended_specs``) with the azimuth eccentricity of a rotating antenna.

An antenna whose axis of rotation is off the centre of its azimuth encoder, or whose encoder is
not level, reports a bearing error that varies once per turn: ``a sin theta + b cos theta`` with
``theta`` the measured bearing (rad) and ``a``, ``b`` (rad) the states ``eccentricity_sin`` and
``eccentricity_cos`` (docs/background/fleet-model.md). ``theta`` is an input, the plot's measured
bearing ``q``, not a state: the error is a function of what the radar reports, so the model stays
exactly invertible (``fleet_plot2ecef_ecc`` subtracts the same term at the same ``q``).

``fleet_residual_ecc`` has the inputs of ``fleet_residual_ext`` and ``ecc = [a, b]`` after the
position error; its Jacobian has two more columns (d residual / d ecc = [0, -sin q, 0] and
[0, -cos q, 0]). The rows functions ``fleet_rows_ecc_<n>`` have 13 state columns: the 11 of the
extended model, then ``a`` and ``b``; ``fleet_rows_ecc3_<n>`` hold the extended errors at 0 and
have 8: the attitude errors, the biases, ``a`` and ``b`` (the rows of a run whose sensors have no
extended error: the sums over the 5 columns that only the sink holds are not formed). The
runtime uses these families only when some sensor has an eccentricity, so every run without one
evaluates the extended or three-error functions as before.
"""

import sympy as sp

from .fleet import (
    FLEET_DOMAIN,
    ROW_BASIS_SIZES,
    corrected_plot2ecef_expr,
    make_nav_ports,
    predicted_plot_expr,
    rows_spec,
    vec,
    wrap,
)
from .spec import CasadiPort, CasadiSpec, FunctionSpec, JacobianDecl, Port, jacobian

#: The inputs of fleet_residual_ecc that its rows without the extended errors hold at 0.
ECC3_HELD = ("dt", "v_ecef", "nav_rate", "gain", "pos_err")
#: The state columns of those rows among the 16 columns of fleet_residual_ecc's J (p_ecef, att_err,
#: bias, gain, dt, pos_err, ecc): the attitude errors, the biases and the eccentricity terms.
ECC3_STATES = (3, 4, 5, 6, 7, 8, 14, 15)


def specs() -> list:
    """``fleet_residual_ecc``, ``fleet_plot2ecef_ecc`` and ``fleet_rows_ecc_<n>`` (module docstring)."""
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
    ecc = vec("ecc", ["sin", "cos"])
    nav6 = [lat, lon, alt, heading, pitch, roll]
    seen = [nav6[i] - rate[i] * dt for i in range(6)]
    p_seen = p_ecef - v_ecef * dt
    predicted = predicted_plot_expr(
        p_seen, seen[:3], seen[3:], att_err, bias, lever, gain, pos_err, ecc=ecc, theta=q
    )
    difference = sp.Matrix([r, q, e]) - predicted
    residual = sp.Matrix([difference[0], wrap(difference[1]), difference[2]])
    J = jacobian(difference, p_ecef, att_err, bias, gain, dt, pos_err, ecc)
    plot = sp.Matrix([predicted[0], wrap(predicted[1]), predicted[2]])
    navigation = make_nav_ports(*nav6)
    error_ports = (
        Port("att_err", att_err, "rad"),
        Port("bias", bias, "m, rad, rad"),
        Port("gain", gain, "1"),
    )
    domain = {**FLEET_DOMAIN, "ecc": [(-0.01, 0.01)] * 2}
    residual_spec = FunctionSpec(
        name="fleet_residual_ecc",
        doc=(
            "One plot of fleet registration with the extended sensor errors and the azimuth eccentricity: "
            "the inputs of fleet_residual_ext and ecc = [a, b] (rad), the bearing seen with the error "
            "a sin q + b cos q at the measured bearing q. Outputs residual = measured - predicted (bearing "
            "wrapped), J = d residual / d(p_ecef, att_err, bias, gain, dt, pos_err, ecc) (3x16) and the "
            "predicted plot."
        ),
        inputs=(
            Port("p_ecef", p_ecef, "m"),
            Port("v_ecef", v_ecef, "m/s"),
            *navigation,
            Port("nav_rate", rate, "rad/s, rad/s, m/s, rad/s, rad/s, rad/s"),
            *error_ports,
            Port("dt", dt, "s"),
            Port("pos_err", pos_err, "m"),
            Port("ecc", ecc, "rad"),
            Port("lever_deck", lever, "m"),
            Port("r", r, "m"),
            Port("q", q, "rad"),
            Port("e", e, "rad"),
        ),
        outputs=(
            Port("residual", residual, "m, rad, rad"),
            Port("J", J, "m/m, m/rad, 1, m, m/s, 1, m/rad; rad/m, 1, 1, rad, rad/s, rad/m, 1"),
            Port("plot", plot, "m, rad, rad"),
        ),
        jacobians=(
            JacobianDecl("J", "residual", ("p_ecef", "att_err", "bias", "gain", "dt", "pos_err", "ecc")),
        ),
        domain=domain,
    )
    p_target = corrected_plot2ecef_expr(
        nav6[:3], nav6[3:], att_err, bias, lever, [r, q, e], gain, pos_err, ecc=ecc
    )
    plot2ecef_spec = FunctionSpec(
        name="fleet_plot2ecef_ecc",
        doc=(
            "Target ECEF (m) of one plot corrected by the extended registration errors and the azimuth "
            "eccentricity: the inputs of fleet_plot2ecef_ext and ecc = [a, b] (rad) after pos_err. The "
            "inverse of fleet_residual_ecc's predicted plot at dt = 0."
        ),
        inputs=(
            *navigation,
            *error_ports,
            Port("pos_err", pos_err, "m"),
            Port("ecc", ecc, "rad"),
            Port("lever_deck", lever, "m"),
            Port("r", r, "m"),
            Port("q", q, "rad"),
            Port("e", e, "rad"),
        ),
        outputs=(Port("p_ecef", p_target, "m"),),
        domain=domain,
    )
    return [
        residual_spec,
        plot2ecef_spec,
        *[rows_spec(residual_spec, n, "ecc") for n in ROW_BASIS_SIZES],
        *[ecc3_rows_spec(residual_spec, n) for n in ROW_BASIS_SIZES],
    ]


def ecc3_rows_spec(residual_spec: FunctionSpec, n_basis: int) -> CasadiSpec:
    """``fleet_rows_ecc3_<n_basis>``: the rows of ``fleet_residual_ecc`` (as ``rows_spec`` builds
    them) with the extended errors held at 0 (ECC3_HELD) and 8 state columns (ECC3_STATES)."""
    ports = [p for p in residual_spec.inputs if p.name not in ECC3_HELD]
    inputs = tuple(CasadiPort(p.name, p.shape, p.unit) for p in ports) + (
        CasadiPort("weight", (3, 1), "1/m, 1/rad, 1/rad"),
        CasadiPort("basis", (n_basis, 1), "1"),
    )
    m = 3 * n_basis + len(ECC3_STATES) + 1
    name = f"fleet_rows_ecc3_{n_basis}"

    def build():
        import casadi as ca

        from .emit import to_casadi_function

        residual = to_casadi_function(residual_spec)
        args = [ca.SX.sym(p.name, *p.shape) for p in inputs]
        given = {p.name: a for p, a in zip(inputs, args, strict=True)}
        res, J, _ = residual(*[given.get(p.name, ca.SX.zeros(*p.shape)) for p in residual_spec.inputs])
        w, basis = args[-2], args[-1]
        A = ca.diag(w) @ J
        Z = ca.horzcat(
            *[basis[k] * A[:, 0:3] for k in range(n_basis)], *[A[:, c] for c in ECC3_STATES], w * res
        )
        return ca.Function(name, args, [Z.T], [p.name for p in inputs], ["rows_t"], {"cse": True})

    domain = {
        **residual_spec.domain,
        "weight": [(0.0, 0.1), (0.0, 3000.0), (0.0, 3000.0)],
        "basis": [(-1.0, 1.0)] * n_basis,
    }
    scalar = {p.name for p in ports if p.shape == (1, 1)}
    return CasadiSpec(
        name=name,
        doc=(
            f"Rows of the batch normal equations for one plot, polynomial basis of size {n_basis}, of "
            f"{residual_spec.name} with the extended errors held at 0 (v_ecef, nav_rate, gain, dt, "
            "pos_err): its other inputs, channel weights w = mask / sigma (1/m, 1/rad, 1/rad) and the "
            f"basis values at the plot time. Output rows_t ({m}x3) = Z^T, Z = [basis^T (x) diag(w) J_p | "
            "diag(w) J_x | w * residual], J_x over the 8 states (attitude errors, biases, eccentricity "
            "sin and cos)."
        ),
        inputs=inputs,
        outputs=(CasadiPort("rows_t", (m, 3), "1/m, 1/rad"),),
        builder=build,
        domain={k: v for k, v in domain.items() if k in {p.name for p in inputs} | scalar},
    )
