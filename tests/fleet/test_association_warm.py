"""The association's solves start from what the passes know: the windows of the last fit of the
labelled plots (not the plots' means), and a solve between passes of the plots the last solve
registered is not made again. The optimum is the same; only the iterations to it are fewer."""

from __future__ import annotations

from functools import partial

import numpy as np

import registration.fleet.association.associate as associate_module
import registration.fleet.association.solves as solves_module
from registration.fleet import (
    AssociationOptions,
    associate_and_register,
    association_scenario,
    fleet_scenario,
)
from registration.fleet.batch.estimate import solve_batch
from registration.fleet.batch.solver import fit


def test_a_fit_started_at_its_own_windows_stays_at_its_optimum():
    """The solver's ``coefficients`` hook: started from the solution's states and windows, a solve
    takes a step or two and ends where it was; from the states alone (windows at the plots' means)
    it takes longer to the same point."""
    problem = fleet_scenario(4, duration_s=200.0).problem()
    first = fit(problem)
    warm = fit(problem, x0=first.x, coefficients=lambda p, design, x0: first.coef)
    cold = fit(problem, x0=first.x)
    assert warm.converged and warm.iterations <= 2 < cold.iterations
    sigma = solve_batch(problem).sigma
    live = sigma > 0
    assert np.max(np.abs(warm.x - first.x)[live] / sigma[live]) < 1e-3


def test_the_solves_between_passes_start_from_the_fitted_windows_and_are_not_repeated(monkeypatch):
    sim = association_scenario(6, duration_s=300.0, seed=21)
    sc = sim.scenario
    calls = []
    solve = associate_module.solve_batch

    def watched(problem, options=None, x0=None, **kwargs):
        result = solve(problem, options, x0, **kwargs)
        key = (problem.row.tobytes(), problem.target.tobytes(), options.max_iterations)
        calls.append((key, kwargs.get("coefficients"), problem, options, x0, result))
        return result

    monkeypatch.setattr(associate_module, "solve_batch", watched)
    registrars = []

    class Kept(solves_module.Registrar):
        def __init__(self, *args, **kwargs):
            super().__init__(*args, **kwargs)
            registrars.append(self)

    monkeypatch.setattr(associate_module, "Registrar", Kept)
    # solves of at most 3000 plots between passes: thinned, as on a long recording, so the checks fit
    # the windows to every labelled plot (the fit the next solve starts from)
    monkeypatch.setattr(solves_module, "thin_windows", partial(solves_module.thin_windows, cap=3000))
    result = associate_and_register(
        sim.plots, sc.sensors, sc.navigation, sc.platforms, None, AssociationOptions()
    )
    keys = [c[0] for c in calls]
    assert all(a != b for a, b in zip(keys[:-2], keys[1:-1]))  # the between-solves: never the same twice
    (reg,) = registrars
    n, last = len(calls), reg.result
    assert reg.solve(reg.labels) is last and len(calls) == n  # the same plots again: no solve
    assert reg.solve(reg.labels, final=True) is not last and len(calls) == n + 1  # a final one is made
    calls.pop()
    assert calls[0][1] is None  # no window fit yet: the plots' means
    key, coefficients, problem, options, x0, final = calls[-1]
    assert coefficients is not None and final is result.batch
    cold = solve(problem, options, x0)  # the same final solve from the plots' means
    assert final.iterations < cold.iterations
    live = cold.sigma > 0
    assert np.max(np.abs(final.estimate - cold.estimate)[live] / cold.sigma[live]) < 1e-2
