"""The association tracker's generated filter (derive/tracking.py) against an independent numpy
composition, and the compiled loop's assignment against scipy's ``linear_sum_assignment``."""

import numpy as np
import pytest
from scipy.optimize import linear_sum_assignment

from registration import _codegen
from registration._generated import api as generated

pytestmark = pytest.mark.skipif(_codegen.backend() != "c", reason="the compiled tracker needs the C backend")

H = np.hstack([np.eye(3), np.zeros((3, 3))])


def _spd(rng, n, k, scale):
    A = rng.normal(size=(k, n, n)) * scale
    return A @ np.swapaxes(A, 1, 2) + scale**2 * np.eye(n)


@pytest.fixture
def points():
    rng = np.random.default_rng(20261208)
    k = 200
    x = np.concatenate([rng.uniform(-7e6, 7e6, (k, 3)), rng.uniform(-300, 300, (k, 3))], axis=1)
    P = _spd(rng, 6, k, 30.0)
    z = x[:, :3] + rng.normal(size=(k, 3)) * 100.0
    R = _spd(rng, 3, k, 20.0)
    return x, P, z, R, rng.uniform(0.0, 10.0, k), rng.uniform(0.5, 10.0, k)


def test_prediction_is_f_p_ft_plus_q(points):
    x, P, _z, _R, dt, q = points
    xp, Pp = generated.cv_predict(x=x, P=P, dt=dt, accel_sigma=q)
    for i in range(x.shape[0]):
        F = np.eye(6)
        F[:3, 3:] = dt[i] * np.eye(3)
        # white acceleration of density q^2 integrated over dt
        Q = q[i] ** 2 * np.block(
            [
                [dt[i] ** 3 / 3 * np.eye(3), dt[i] ** 2 / 2 * np.eye(3)],
                [dt[i] ** 2 / 2 * np.eye(3), dt[i] * np.eye(3)],
            ]
        )
        np.testing.assert_allclose(xp[i], F @ x[i], rtol=1e-14, atol=1e-8)
        np.testing.assert_allclose(Pp[i], F @ P[i] @ F.T + Q, rtol=1e-12, atol=1e-9)


def test_gate_and_update_are_the_kalman_filter(points):
    x, P, z, R, _dt, _q = points
    d2, logdet = generated.cv_gate(x_pred=x, P_pred=P, z=z, R=R)
    xu, Pu = generated.cv_update(x_pred=x, P_pred=P, z=z, R=R)
    for i in range(x.shape[0]):
        S = H @ P[i] @ H.T + R[i]
        v = z[i] - H @ x[i]
        K = P[i] @ H.T @ np.linalg.inv(S)
        assert d2[i] == pytest.approx(v @ np.linalg.solve(S, v), rel=1e-10)
        assert logdet[i] == pytest.approx(np.linalg.slogdet(S)[1], rel=1e-12)
        np.testing.assert_allclose(xu[i], x[i] + K @ v, rtol=1e-12, atol=1e-8)
        np.testing.assert_allclose(Pu[i], (np.eye(6) - K @ H) @ P[i], rtol=1e-9, atol=1e-9)
        assert np.array_equal(Pu[i], Pu[i].T)


def test_a_track_starts_at_the_plot_with_unknown_velocity(points):
    _x, _P, z, R, _dt, _q = points
    xs, Ps = generated.cv_start(z=z, R=R, max_speed=250.0)
    np.testing.assert_array_equal(xs[:, :3], z)
    assert not xs[:, 3:].any()
    np.testing.assert_array_equal(Ps[:, :3, :3], R)
    np.testing.assert_array_equal(Ps[:, 3:, 3:], np.broadcast_to(250.0**2 * np.eye(3), (z.shape[0], 3, 3)))
    assert not Ps[:, :3, 3:].any()


def test_a_covariance_that_is_not_positive_definite_gives_nan_not_a_number():
    P = np.zeros((6, 6))
    d2, logdet = generated.cv_gate(x_pred=np.zeros(6), P_pred=P, z=np.ones(3), R=-np.eye(3))
    assert np.isnan(d2).all() and np.isnan(logdet).all()


@pytest.mark.parametrize("kind", ["real", "integer ties", "forbidden entries"])
def test_the_assignment_is_scipys_even_in_ties(kind):
    rng = np.random.default_rng({"real": 1, "integer ties": 2, "forbidden entries": 3}[kind])
    for _ in range(500):
        r = int(rng.integers(1, 8))
        c = int(rng.integers(r, 12))
        cost = rng.normal(size=(r, c)) if kind == "real" else rng.integers(0, 4, size=(r, c)).astype(float)
        if kind == "forbidden entries":
            cost[rng.random((r, c)) < 0.5] = 1e12
        assert np.array_equal(_codegen.compiled_assignment(cost), linear_sum_assignment(cost)[1]), cost


@pytest.mark.parametrize("cost", [np.ones((3, 2)), np.array([[1.0, np.inf]]), np.ones(3)])
def test_the_assignment_refuses_what_it_cannot_solve(cost):
    with pytest.raises(ValueError, match="finite"):
        _codegen.compiled_assignment(cost)


def test_the_compiled_assignment_says_when_a_row_has_no_finite_cost():
    """scipy's "infeasible": the C function returns -2 instead of reading outside its arrays."""
    import ctypes

    from registration._codegen.cbackend import library

    cost = np.array([[np.inf, np.inf], [1.0, 2.0]])
    col4row = np.full(2, -1, dtype=np.int64)
    status = library().registration_assign(
        ctypes.c_longlong(2),
        ctypes.c_longlong(2),
        cost.ctypes.data_as(ctypes.c_void_p),
        col4row.ctypes.data_as(ctypes.c_void_p),
    )
    assert status == -2
