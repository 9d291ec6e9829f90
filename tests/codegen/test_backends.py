"""The compiled-C path, the serialized CasADi path and direct sympy evaluation agree.

Tolerance 1e-12 relative to each output's largest magnitude at the point (an output like
Z = X_A - X_B is measured against the ECEF positions it is the difference of, since its
rounding comes from them). All three evaluate the same expressions in double precision, so
they differ by a few ulps of intermediate values.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from registration import _codegen
from tests.conftest import emitted, sample_inputs

SCALE_FROM = {"Z": ("p_a_ecef", "p_b_ecef")}


def _sympy_eval(spec, inputs, n):
    symbols = [s for p in spec.inputs for s in p.matrix.T]  # column-major, as CasADi
    cols = []
    for p, a in zip(spec.inputs, inputs):
        r, c = p.shape
        cols.append(a.reshape(n, r, c).transpose(0, 2, 1).reshape(n, r * c))  # column-major
    values = np.concatenate(cols, axis=1)
    outs = []
    for port in spec.outputs:
        f = sp.lambdify(symbols, port.matrix, modules="numpy", cse=True)
        res = np.array([np.asarray(f(*row), dtype=float) for row in values])
        outs.append(res)
    return outs


@pytest.mark.parametrize("name", sorted(emitted()))
def test_c_casadi_and_sympy_agree(name, specs):
    spec = specs[name]
    n = 40
    inputs = sample_inputs(spec, n, np.random.default_rng(7))
    c_out = _codegen.GeneratedFunction(name, force_backend="c")(*inputs)
    ca_out = _codegen.GeneratedFunction(name, force_backend="casadi")(*inputs)
    has_sympy = not hasattr(spec, "build")  # CasadiSpec functions are checked against NumPy elsewhere
    sy_out = _sympy_eval(spec, inputs, n) if has_sympy else [None] * len(spec.outputs)
    by_name = dict(zip([p.name for p in spec.outputs], c_out))
    for port, a, b, s in zip(spec.outputs, c_out, ca_out, sy_out):
        a = a.reshape(n, *port.shape)
        b = b.reshape(n, *port.shape)
        s = s.reshape(n, *port.shape) if has_sympy else None
        scale = np.abs(a).reshape(n, -1).max(axis=1)
        for other in SCALE_FROM.get(port.name, ()):
            scale = np.maximum(scale, np.abs(by_name[other]).max(axis=1))
        scale = scale[:, None, None] + 1e-300
        assert (np.abs(a - b) <= 1e-12 * scale).all(), f"{name}.{port.name}: C vs CasADi"
        if has_sympy:
            assert (np.abs(a - s) <= 1e-12 * scale).all(), f"{name}.{port.name}: C vs sympy"


def test_vectorised_call_equals_pointwise_calls(specs):
    fn = _codegen.get("plot2ecef_standard")
    spec = specs["plot2ecef_standard"]
    inputs = sample_inputs(spec, 5, np.random.default_rng(3))
    batch = fn(*inputs)[0]
    for i in range(5):
        assert fn(*[a[i] for a in inputs])[0][0] == pytest.approx(batch[i], rel=0, abs=0)


def test_broadcast_input_uses_stride_zero():
    fn = _codegen.get("geodetic2ecef")
    out = fn(np.array([0.1, 0.2, 0.3]), 0.5, 10.0)[0]
    ref = np.vstack([fn(v, 0.5, 10.0)[0] for v in (0.1, 0.2, 0.3)])
    assert np.array_equal(out, ref)


def test_mismatched_lengths_are_refused():
    fn = _codegen.get("geodetic2ecef")
    with pytest.raises(ValueError, match="points"):
        fn(np.zeros(3), np.zeros(4), 0.0)


@pytest.mark.parametrize("name", ["kalman_step_paper_standard", "deck2enu_jacobians", "cartesian2polar3"])
def test_bound_single_point_call_equals_vectorised_call(name, specs):
    spec = specs[name]
    inputs = sample_inputs(spec, 3, np.random.default_rng(11))
    fn = _codegen.get(name)
    bound = fn.bind()
    batch = fn(*inputs)
    for i in range(3):
        single = bound(*[a[i] for a in inputs])
        for b, s in zip(batch, single):
            assert np.array_equal(np.asarray(b[i]), np.asarray(s))
