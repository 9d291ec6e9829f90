"""The batch estimator against the two-ship filter (registration.online) on the paper's scenario.

Both estimate the same thing from the same data: the 12 registration errors of two ships with
one 3-D radar each, with the filter's prior (the batch is then maximum a posteriori), the target
position at each synchronous instant being a nuisance (``window_s = 0`` in the batch; the
pseudo-measurement X_A - X_B in the filter). The filter's estimate after the last pair should
therefore sit near the batch optimum. It is not the optimum: it linearises once per pair (at its
'fitted' point) and adds a little process noise each step. Tolerance: 0.25 of the batch sigma,
on every state the data determine (status identifiable or weak) and on the heading + bearing
sums when a ship does not pitch or roll.
"""

from __future__ import annotations

import numpy as np
import pytest

from registration.fleet import BatchOptions, build_problem, solve_batch
from registration.online import RegistrationConfig, register
from registration.online.scenario import ShipMotion, paper_scenario
from tests.fleet.two_ship import STATE_MAP, fleet_tables

TOLERANCE = 0.25  # of the batch sigma


def _both(seed: int, motion):
    sc = paper_scenario(seed, ship_motion=motion)
    config = RegistrationConfig()
    filtered = register(sc.data, config)
    batch = solve_batch(
        build_problem(**fleet_tables(sc.data, config.sigma0, config.prior_sigma)), BatchOptions(window_s=0)
    )
    return sc, filtered, batch


@pytest.mark.parametrize("seed", [0, 1])
def test_moving_ships_filter_ends_at_the_batch_solution(seed):
    sc, filtered, batch = _both(seed, ShipMotion())
    assert batch.converged and batch.chi_square.ok
    compared = 0
    for k, (online_name, name) in enumerate(STATE_MAP.items()):
        if batch.status[name] in ("identifiable", "weak"):
            sigma = batch.sigma_of(name)
            assert abs(filtered.final[k] - batch.value(name)) < TOLERANCE * sigma, (
                online_name,
                filtered.final[k],
                batch.value(name),
                sigma,
            )
            assert abs(filtered.final_sigma[k] - sigma) < 0.1 * sigma  # the same posterior spread
            compared += 1
    assert compared >= 6


def test_level_ships_agree_on_the_identifiable_sums():
    sc, filtered, batch = _both(3, None)
    x_online = dict(zip(STATE_MAP.values(), filtered.final))
    for ship in ("a", "b"):
        coeffs = {f"{ship}:heading_error": 1.0, f"{ship}-radar:bearing_bias": 1.0}
        value, sigma = batch.combination(coeffs)
        online = sum(x_online[n] for n in coeffs)
        assert np.isfinite(sigma) and abs(online - value) < TOLERANCE * sigma
    for name in ("a-radar:range_bias", "b-radar:range_bias"):
        assert batch.status[name] == "identifiable"
        assert abs(x_online[name] - batch.value(name)) < TOLERANCE * batch.sigma_of(name)
