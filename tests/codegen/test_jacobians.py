"""Every declared Jacobian, three ways: the sympy-derived generated output, CasADi automatic
differentiation of the generated primal function, and central finite differences of it.

Points: 1200 uniform random points in each function's domain (see derive/*.py ``domain``) with
edge cases written into random rows (poles, +-180 deg longitude, zero elevation, bearings at
and near +-pi, elevation near +-90 deg; tests/codegen/_edges.py).

Tolerances, per point i, Jacobian entry (row a, column k):

* symbolic vs automatic differentiation: both are exact derivatives evaluated in double
  precision, differing only in operation order, so they agree to a few ulps of the largest
  magnitude in the column: ``|dJ| <= 1e-12 * max(S_k, P_ak)`` with ``S_k = max_a |J[a, k]|``
  (+1e-300) and ``P_ak`` the largest ``|J[a, k']|`` over the columns k' of the same input vector
  (a column that is a cancelling component of a rotated vector, _port_scale).
* symbolic vs central differences with step ``h_k = 1e-5 * max(1, |x_k|)``: the quotient has a
  rounding error of about ``eps * F / h_k`` (F = largest |f| at the point; eps = 2.2e-16) and a
  truncation error ``h_k^2 |f'''| / 6``. Every function here is a product of trigonometric
  functions of the angles with lengths, so |f'''| <= F-ish per unit angle and the truncation
  term is <= 2e-11 F. We allow ``|dJ| <= 1e-6 * S_k + 100 * eps * F / h_k`` - far below any
  real derivative error (a wrong sign or a missing term changes J by O(S_k)), with margin for
  the crude bound. Angle outputs are differenced modulo 2 pi (the atan2 branch cut).
"""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

from registration import _codegen
from tests.conftest import emitted, sample_inputs

from ._edges import with_edges

N_POINTS = 1200
EPS = np.finfo(float).eps


def _jacobian_cases():
    for name, function in emitted().items():
        for jacobian in function["jacobians"]:
            yield pytest.param(name, jacobian["output"], id=f"{name}:{jacobian['output']}")


def _angle_mask(port) -> np.ndarray:
    """Which entries of an output are angles (unit list 'm, rad, rad' or a single unit)."""
    n = port.shape[0] * port.shape[1]
    units = [u.strip() for u in port.unit.split(",")]
    if len(units) != n:
        units = [port.unit.strip()] * n
    return np.array([u == "rad" for u in units])


def _flatten_point(arr: np.ndarray, n: int) -> np.ndarray:
    return arr.reshape(n, -1)


def _casadi_ad(spec, decl, inputs, n):
    fn = _codegen.get(spec.name).casadi
    syms = [ca.SX.sym(p.name, *p.shape) for p in spec.inputs]
    outs = fn.call(syms)
    out_names = [p.name for p in spec.outputs]
    of = outs[out_names.index(decl.of)]
    wrt = ca.vertcat(*[ca.vec(syms[[p.name for p in spec.inputs].index(w)]) for w in decl.wrt])
    jac = ca.Function("jac_ad", syms, [ca.densify(ca.jacobian(ca.vec(of), wrt))])
    mapped = jac.map(n, "serial")
    dms = []
    for p, a in zip(spec.inputs, inputs):
        r, c = p.shape
        dms.append(ca.DM(a.reshape(n, r, c).transpose(1, 0, 2).reshape(r, n * c)))
    res = np.asarray(mapped(*dms).full())
    m = res.shape[0]
    return res.reshape(m, n, -1).transpose(1, 0, 2)


def _central_differences(spec, decl, inputs, n):
    fn = _codegen.get(spec.name)
    out_idx = [p.name for p in spec.outputs].index(decl.of)
    angle = _angle_mask(spec.outputs[out_idx])
    cols = []
    for w in decl.wrt:
        j = [p.name for p in spec.inputs].index(w)
        size = spec.inputs[j].shape[0] * spec.inputs[j].shape[1]
        for k in range(size):
            plus = [a.copy() for a in inputs]
            minus = [a.copy() for a in inputs]
            base = inputs[j].reshape(n, -1)[:, k]
            h = 1e-5 * np.maximum(1.0, np.abs(base))
            plus[j].reshape(n, -1)[:, k] += h
            minus[j].reshape(n, -1)[:, k] -= h
            h_eff = plus[j].reshape(n, -1)[:, k] - minus[j].reshape(n, -1)[:, k]  # exact representable step
            diff = _flatten_point(fn(*plus)[out_idx], n) - _flatten_point(fn(*minus)[out_idx], n)
            diff[:, angle] = np.angle(np.exp(1j * diff[:, angle]))
            cols.append((diff / h_eff[:, None], h))
    jac = np.stack([c for c, _ in cols], axis=-1)
    steps = np.stack([h for _, h in cols], axis=-1)
    return jac, steps


def _port_scale(spec, decl, j_sym: np.ndarray) -> np.ndarray:
    """(N, 3, K) per point and row, the largest |J| over the columns of the same input port: the
    columns of one vector input (a position error east, north, up) are the components of one
    rotated vector, rounded relative to its length, so a component that cancels to 1e-5 of it
    (a line of sight nearly level, d range / d up) carries an absolute error of eps times the
    length, not of eps times itself."""
    out = np.empty_like(j_sym)
    start = 0
    for w in decl.wrt:
        port = spec.inputs[[p.name for p in spec.inputs].index(w)]
        size = port.shape[0] * port.shape[1]
        block = np.abs(j_sym[:, :, start : start + size]).max(axis=2, keepdims=True)
        out[:, :, start : start + size] = block
        start += size
    return out


@pytest.mark.parametrize("name,output", list(_jacobian_cases()))
def test_jacobian_three_ways(name, output, specs):
    spec = specs[name]
    decl = next(d for d in spec.jacobians if d.output == output)
    rng = np.random.default_rng(12345)
    inputs = with_edges(spec, sample_inputs(spec, N_POINTS, rng), rng)
    fn = _codegen.get(name)
    outs = dict(zip(fn.output_names, fn(*inputs)))
    j_sym = outs[decl.output].reshape(N_POINTS, -1, outs[decl.output].shape[-1])
    col_scale = np.abs(j_sym).max(axis=1, keepdims=True) + 1e-300

    j_ad = _casadi_ad(spec, decl, inputs, N_POINTS)
    assert j_ad.shape == j_sym.shape
    bad = np.abs(j_ad - j_sym) > 1e-12 * np.maximum(col_scale, _port_scale(spec, decl, j_sym))
    assert not bad.any(), f"{name}:{decl.output} symbolic vs AD differ at {np.argwhere(bad)[:5].tolist()}"

    j_fd, steps = _central_differences(spec, decl, inputs, N_POINTS)
    f_scale = np.abs(_flatten_point(outs[decl.of], N_POINTS)).max(axis=1)[:, None, None]
    tol = 1e-6 * col_scale + 100 * EPS * f_scale / steps[:, None, :]
    err = np.abs(j_fd - j_sym)
    bad = err > tol
    worst = np.unravel_index(np.argmax(err / tol), err.shape)
    assert not bad.any(), (
        f"{name}:{decl.output} symbolic vs finite differences: {bad.sum()} entries out of tolerance; "
        f"worst at point/row/col {worst}: err {err[worst]:.3g} tol {tol[worst]:.3g}"
    )


def test_every_spec_is_emitted(specs):
    """The names the tests are parametrized over (the manifest's) are the derive specs', with the
    same Jacobians."""
    derived = {name: sorted(d.output for d in s.jacobians) for name, s in specs.items()}
    recorded = {name: sorted(j["output"] for j in f["jacobians"]) for name, f in emitted().items()}
    assert recorded == derived


def test_every_jacobian_is_declared(specs):
    """The Jacobians the runtime relies on exist and are declared for checking."""
    declared = {(s.name, d.output) for s in specs.values() for d in s.jacobians}
    for need in [
        ("deck2enu_jacobians", "Psi"),
        ("deck2enu_jacobians", "Gamma"),
        ("pseudo_measurement_standard", "H"),
        ("pseudo_measurement_standard", "M"),
        ("pseudo_measurement_paper", "H"),
        ("polar2cartesian2", "J"),
        ("cartesian2polar2", "J"),
        ("polar2cartesian3", "J"),
        ("cartesian2polar3", "J"),
        ("fleet_residual", "J"),
        ("fleet_residual_ext", "J"),
        ("fleet_residual_ecc", "J"),
    ]:
        assert need in declared


def test_a_wrong_jacobian_is_caught(specs):
    """The check can fail: a Jacobian with one column sign-flipped is far outside tolerance."""
    spec = specs["deck2enu_jacobians"]
    decl = spec.jacobians[0]
    rng = np.random.default_rng(1)
    inputs = sample_inputs(spec, 50, rng)
    fn = _codegen.get(spec.name)
    psi = fn(*inputs)[1].copy()
    psi[:, :, 4] *= -1  # flip dPhi/dq
    j_fd, steps = _central_differences(spec, decl, inputs, 50)
    col_scale = np.abs(psi).max(axis=1, keepdims=True)
    assert (np.abs(j_fd - psi) > 1e-6 * col_scale).any()
