"""The generated plot model of fleet registration (derive/fleet.py): declared for the three-way
Jacobian tests, consistent with the two-ship model's ecef2plot, inverted by fleet_plot2ecef, the
lever arm and the error signs of docs/reference/conventions.md, and the rows function equal to its NumPy
composition."""

from __future__ import annotations

import numpy as np

from registration import _codegen
from registration.core.angles import wrap_angle

N = 500


def _random_inputs(rng, n=N):
    nav = [
        rng.uniform(-1.4, 1.4, n),
        rng.uniform(-3.1, 3.1, n),
        rng.uniform(0, 50, n),
        rng.uniform(-3.1, 3.1, n),
        rng.uniform(-0.3, 0.3, n),
        rng.uniform(-0.3, 0.3, n),
    ]
    att_err = rng.uniform(-0.1, 0.1, (n, 3))
    bias = np.c_[rng.uniform(-3000, 3000, n), rng.uniform(-0.1, 0.1, (n, 2))]
    lever = rng.uniform(-50, 50, (n, 3))
    plot = [rng.uniform(5e3, 2e5, n), rng.uniform(-3.1, 3.1, n), rng.uniform(-1.2, 1.2, n)]
    return nav, att_err, bias, lever, plot


def test_the_fleet_functions_are_covered_by_the_jacobian_tests():
    """derive.fleet is in the registry (so tests/codegen/test_jacobians.py checks every declared
    Jacobian three ways) and the manifest records the residual's Jacobian declaration."""
    import derive.fleet
    import derive.registry

    assert derive.fleet in derive.registry.MODULES
    functions = _codegen.manifest()["functions"]
    assert {"output": "J", "of": "residual", "wrt": ["p_ecef", "att_err", "bias"]} in functions[
        "fleet_residual"
    ]["jacobians"]
    for name in ("fleet_plot2ecef", "fleet_rows_1", "fleet_rows_4"):
        assert name in functions


def test_plot2ecef_inverts_the_residual_model():
    """A plot turned into ECEF with given errors is predicted back exactly: residual 0."""
    nav, att_err, bias, lever, plot = _random_inputs(np.random.default_rng(1))
    p = _codegen.get("fleet_plot2ecef")(*nav, att_err, bias, lever, *plot)[0]
    residual, _, predicted = _codegen.get("fleet_residual")(p, *nav, att_err, bias, lever, *plot)
    assert np.abs(residual[:, 0]).max() < 1e-6  # m, at up to 200 km
    assert np.abs(residual[:, 1:]).max() < 1e-11  # rad
    np.testing.assert_allclose(wrap_angle(predicted[:, 1] - plot[1]), 0.0, atol=1e-11)


def test_without_lever_errors_and_biases_it_is_the_two_ship_ecef2plot():
    nav, _, _, _, plot = _random_inputs(np.random.default_rng(2))
    p = _codegen.get("plot2ecef_standard")(*nav, *plot)[0]
    z3 = np.zeros(3)
    _, _, predicted = _codegen.get("fleet_residual")(p, *nav, z3, z3, z3, 0.0, 0.0, 0.0)
    expected = _codegen.get("ecef2plot_standard")(p, *nav)[0]
    np.testing.assert_allclose(predicted[:, 0], expected[:, 0], rtol=1e-12)
    np.testing.assert_allclose(wrap_angle(predicted[:, 1:] - expected[:, 1:]), 0.0, atol=1e-11)


def test_lever_arm_and_error_signs():
    """Level ship heading north, sensor 10 m towards the bow; a target 1000 m north is 990 m away.
    Reported heading = true + error and measured = true + bias: with the right errors the residual
    vanishes, with none it equals the errors' effect."""
    lat, lon = np.radians(36.0), np.radians(14.5)
    R_ecef_enu = _codegen.get("enu2ecef_rotation_standard")(lat, lon)[0][0]
    p = _codegen.get("geodetic2ecef")(lat, lon, 0.0)[0][0] + R_ecef_enu @ [0.0, 1000.0, 0.0]
    lever = np.array([0.0, 10.0, 0.0])
    heading_error, bearing_bias = np.radians(2.0), np.radians(-1.0)
    true_plot = _codegen.get("fleet_residual")(
        p, lat, lon, 0.0, 0.0, 0.0, 0.0, np.zeros(3), np.zeros(3), lever, 0.0, 0.0, 0.0
    )[2][0]
    assert abs(true_plot[0] - 990.0) < 1e-6 and abs(true_plot[1]) < 1e-12
    measured = true_plot + [0.0, bearing_bias, 0.0]
    reported_heading = heading_error  # true heading 0
    args = (p, lat, lon, 0.0, reported_heading, 0.0, 0.0)
    res = _codegen.get("fleet_residual")(
        *args, [heading_error, 0, 0], [0, bearing_bias, 0], lever, *measured
    )[0][0]
    assert np.abs(res).max() < 1e-9
    # without the lever arm, an uncorrected prediction is off by bias + error in bearing
    plot0 = _codegen.get("fleet_residual")(
        p, lat, lon, 0.0, 0.0, 0.0, 0.0, np.zeros(3), np.zeros(3), np.zeros(3), 0.0, 0.0, 0.0
    )[2][0] + [0.0, bearing_bias, 0.0]
    res = _codegen.get("fleet_residual")(*args, np.zeros(3), np.zeros(3), np.zeros(3), *plot0)[0][0]
    assert abs(res[1] - (bearing_bias + heading_error)) < 1e-12 and abs(res[0]) < 1e-6


def test_bearing_residual_is_wrapped():
    lat, lon = 0.3, 0.2
    p = _codegen.get("plot2ecef_standard")(lat, lon, 0.0, 0.0, 0.0, 0.0, 5e4, np.pi - 1e-3, 0.0)[0][0]
    res = _codegen.get("fleet_residual")(
        p, lat, lon, 0.0, 0.0, 0.0, 0.0, np.zeros(3), np.zeros(3), np.zeros(3), 5e4, -np.pi + 1e-3, 0.0
    )[0][0]
    assert abs(res[1] - 2e-3) < 1e-9


def test_rows_function_is_the_whitened_residual_times_the_basis():
    rng = np.random.default_rng(3)
    nav, att_err, bias, lever, plot = _random_inputs(rng)
    p = _codegen.get("fleet_plot2ecef")(*nav, np.zeros((N, 3)), np.zeros((N, 3)), lever, *plot)[0]
    p += rng.normal(size=p.shape) * 100.0
    weight = rng.uniform(0, 1, (N, 3)) * [0.05, 500.0, 500.0] * (rng.uniform(size=(N, 3)) > 0.2)
    basis = rng.uniform(-1, 1, (N, 4))
    residual, J, _ = _codegen.get("fleet_residual")(p, *nav, att_err, bias, lever, *plot)
    A = J * weight[:, :, None]
    expected = np.concatenate(
        [
            np.concatenate([basis[:, k, None, None] * A[:, :, :3] for k in range(4)], axis=2),
            A[:, :, 3:],
            (weight * residual)[:, :, None],
        ],
        axis=2,
    )
    rows = _codegen.get("fleet_rows_4")(p, *nav, att_err, bias, lever, *plot, weight, basis)[0].swapaxes(1, 2)
    np.testing.assert_allclose(rows, expected, rtol=1e-12, atol=1e-12 * np.abs(expected).max())
    rows1 = _codegen.get("fleet_rows_1")(p, *nav, att_err, bias, lever, *plot, weight, basis[:, 0])[
        0
    ].swapaxes(1, 2)
    np.testing.assert_allclose(
        rows1[:, :, :3], expected[:, :, :3], rtol=1e-12, atol=1e-12 * np.abs(expected).max()
    )
