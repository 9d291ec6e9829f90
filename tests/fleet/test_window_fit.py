"""The windows fitted with the states held (registration.fleet.batch.window_fit): each window is its
own problem, so one window started far from its minimum changes nothing in the others and ends
where it ends when fitted alone."""

from __future__ import annotations

import dataclasses

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


def test_window_steps_equal_the_pseudo_inverse_steps():
    """The association's window fit solves each regular block by LU and a singular one (a window whose
    plots do not determine it) by the pseudo-inverse: the steps all blocks' pseudo-inverse gave."""
    from registration.fleet.association.joining.windowfit import window_steps
    from registration.fleet.batch.solver import SINGULAR_BLOCK

    rng = np.random.default_rng(7)
    A = rng.normal(size=(5, 12, 20))
    V = A @ A.transpose(0, 2, 1)
    V[3] = A[3, :, :4] @ A[3, :, :4].T  # rank 4
    b = rng.normal(size=(5, 12))
    b[3] = V[3] @ rng.normal(size=12)  # in its range
    w = np.linalg.eigvalsh(V)
    singular = np.flatnonzero(~(w[:, 0] > SINGULAR_BLOCK * w[:, -1]))
    assert singular.tolist() == [3]
    expected = (np.linalg.pinv(V) @ b[:, :, None])[:, :, 0]
    np.testing.assert_allclose(window_steps(V, b, singular), expected, rtol=1e-8, atol=1e-12)
    # told nothing, the LU solve gives block 3 another solution (its null space is free), not the
    # smallest one: that is why the singular blocks are named
    assert np.abs(window_steps(V, b, np.zeros(0, dtype=np.int64))[3] - expected[3]).max() > 1e-6
    V[1] = 0.0  # exactly singular and not named: the solve of the batch fails, every block falls back
    dc = window_steps(V, b, singular)
    assert np.all(dc[1] == 0.0) and np.all(np.isfinite(dc))
    np.testing.assert_allclose(dc[0], expected[0], rtol=1e-8, atol=1e-12)


def test_fitted_starting_windows_follow_a_target_the_means_miss():
    """fitted_coefficients: each window's cubic fitted to its plots' positions. At the true states,
    on nearly noise-free plots, the fitted windows put the plots' targets within metres of the
    truth, where the means (a constant per window) miss a moving target by up to its speed times
    half the window; a window whose position-fixing plots do not determine a fit keeps its mean."""
    from registration.fleet.batch.initial import fitted_coefficients, initial_coefficients
    from registration.fleet.batch.normal import positions

    sc = fleet_scenario(seed=5, noise_scale=1e-3)
    problem = sc.problem()
    x = sc.truth_vector(problem.layout)
    problem, design, _, _ = determined_design(problem, BatchOptions(), x)
    blk = design.blocks
    plot = blk.order  # the problem's plot of each sorted plot
    true_p = np.empty((plot.size, 3))
    for t, name in enumerate(problem.target_ids):
        mine = np.flatnonzero(problem.target[plot] == t)
        true_p[mine] = sc.target_ecef(str(name), problem.time[plot[mine]])
    miss = {}
    for label, coef in (
        ("fitted", fitted_coefficients(design, x)),
        ("means", initial_coefficients(design, x)),
    ):
        miss[label] = np.linalg.norm(positions(blk.basis, blk.block, coef) - true_p, axis=1)
    assert np.percentile(miss["fitted"], 99) < 20.0
    assert np.percentile(miss["means"], 99) > 10 * np.percentile(miss["fitted"], 99)
    # without plots that fix a position (2-D radars' only: placed at elevation 0) a window keeps its mean
    flat = dataclasses.replace(design, weight=design.weight * np.array([1.0, 1.0, 0.0]))
    assert np.array_equal(fitted_coefficients(flat, x), initial_coefficients(flat, x))


def test_a_cold_window_fit_from_fitted_windows_ends_where_the_means_ended(monkeypatch):
    """The association's fit of the windows with the states held (fit_windows) starts from the fitted
    windows: the same optimum (within its stopping tolerance) in fewer Gauss-Newton steps."""
    from registration.fleet.association.joining import windowfit

    sc = fleet_scenario(seed=6)
    problem = sc.problem()
    x = sc.truth_vector(problem.layout)
    steps = []
    real_steps = windowfit.window_steps
    monkeypatch.setattr(windowfit, "window_steps", lambda *args: steps.append(1) or real_steps(*args))
    fitted = windowfit.fit_windows(problem, x, BatchOptions())
    n_fitted = len(steps)
    steps.clear()
    monkeypatch.setattr(
        windowfit, "_fitted", lambda p, design, x0: windowfit.initial_coefficients(design, x0)
    )
    means = windowfit.fit_windows(problem, x, BatchOptions())
    assert n_fitted < len(steps)
    ok = np.isfinite(fitted.residuals) & np.isfinite(means.residuals)
    assert np.abs(fitted.residuals[ok] - means.residuals[ok]).max() < 0.05  # in sigma of each value


def test_a_last_small_step_on_the_linearised_model_leaves_the_residuals_of_an_evaluation(monkeypatch):
    """A fit's last Gauss-Newton step, when it predicts a reduction of at most LINEAR_REDUCTION, gives
    residuals of the linearised model instead of evaluating the model again: the same coefficients,
    the residuals within a thousandth of a sigma of those of the evaluation at them. A warm fit
    under a moved estimate (the association's fits after each solve) takes that step."""
    from registration.fleet.association.joining import windowfit

    sc = fleet_scenario(seed=6)
    problem = sc.problem()
    x = sc.truth_vector(problem.layout)
    prior = windowfit.fit_windows(problem, x, BatchOptions())
    free = problem.layout.free
    moved = x.copy()
    moved[free] += 0.1 * problem.layout.scale[free]  # a tenth of a prior sigma: a solve between passes
    evaluations = []
    real_evaluate = windowfit.evaluate
    monkeypatch.setattr(windowfit, "evaluate", lambda *a: evaluations.append(1) or real_evaluate(*a))
    linear = windowfit.fit_windows(problem, moved, BatchOptions(), prior)
    n_linear = len(evaluations)
    evaluations.clear()
    monkeypatch.setattr(windowfit, "LINEAR_REDUCTION", 0.0)
    evaluated = windowfit.fit_windows(problem, moved, BatchOptions(), prior)
    assert len(evaluations) == n_linear + 1  # the linear step saved one evaluation
    assert np.array_equal(linear.coef, evaluated.coef)
    ok = np.isfinite(evaluated.residuals)
    assert np.array_equal(ok, np.isfinite(linear.residuals))
    assert 0 < np.abs(linear.residuals[ok] - evaluated.residuals[ok]).max() < 1e-3  # sigma of each value
    # the windows' covariances are those of the step's start: 1.3e-4 of the sigmas' products here
    d = np.sqrt(np.abs(np.diagonal(evaluated.V_inv, axis1=1, axis2=2)))
    scale = d[:, :, None] * d[:, None, :] + 1e-300
    assert (np.abs(linear.V_inv - evaluated.V_inv) / scale).max() < 1e-3
