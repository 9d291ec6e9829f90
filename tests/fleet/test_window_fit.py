"""The windows fitted with the states held (registration.fleet.batch.window_fit): each window is its
own problem, so one window started far from its minimum changes nothing in the others and ends
where it ends when fitted alone."""

from __future__ import annotations

import numpy as np

from registration.fleet import BatchOptions, fleet_scenario
from registration.fleet.batch.normal import evaluate, normal_equations
from registration.fleet.batch.solver import determined_design
from registration.fleet.batch.window_fit import fit_each_window, window_costs


def _fit(design, x, coef, options):
    start = evaluate(design, x, coef)
    ev, _, remaining = fit_each_window(design, start, normal_equations(design, start), options)
    return ev, remaining


def test_a_window_started_far_off_does_not_steer_the_others():
    sc = fleet_scenario(seed=5)
    options = BatchOptions(max_iterations=50)
    problem = sc.problem()
    x = np.zeros(problem.layout.n)
    problem, design, start, _ = determined_design(problem, options, x, priors=False)
    far = design.blocks.n_blocks // 2
    coef = start.coef.copy()
    coef[far, 0] += np.array([20e3, -15e3, 8e3])  # 26 km off: its sum of squares starts near 1e5 or more
    ev, remaining = _fit(design, x, coef, options)
    near, _ = _fit(design, x, start.coef, options)
    assert window_costs(design, evaluate(design, x, coef))[far] > 1e4
    others = np.arange(design.blocks.n_blocks) != far
    assert np.array_equal(ev.coef[others], near.coef[others])  # bit for bit: nothing shared
    assert np.all(remaining <= options.tolerance)
    cost, cost_near = window_costs(design, ev), window_costs(design, near)
    assert abs(cost[far] - cost_near[far]) < 1e-6 * max(cost_near[far], 1.0)
