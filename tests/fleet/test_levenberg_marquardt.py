"""The Levenberg-Marquardt engine of the batch solvers on a provider of its own: a small nonlinear
least-squares problem (an exponential decay fitted to noisy samples) with no window coefficients."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fleet.batch.levenberg_marquardt import (
    DECREASE_FLOOR,
    LAMBDA_START,
    levenberg_marquardt,
    two_phases,
)
from registration.fleet.batch.solver import BatchOptions


@dataclass(frozen=True)
class Point:
    x: np.ndarray
    cost: float
    H: np.ndarray | None = None  # J^T J
    g: np.ndarray | None = None  # -J^T e


@dataclass(frozen=True)
class Step:
    dx: np.ndarray
    predicted: float


class Decay:
    """e_i = a exp(-b t_i) - y_i over x = (a, b)."""

    def __init__(self, t: np.ndarray, y: np.ndarray):
        self.t, self.y = t, y

    def residual(self, x: np.ndarray) -> np.ndarray:
        return x[0] * np.exp(-x[1] * self.t) - self.y

    def point(self, x: np.ndarray) -> Point:
        e = self.residual(x)
        return Point(x, float(e @ e))

    def scale(self, free: np.ndarray) -> np.ndarray:
        return np.ones(free.size)

    def linearize(self, point: Point, lams: tuple[float, ...]) -> Point:
        x = point.x
        J = np.stack([np.exp(-x[1] * self.t), -x[0] * self.t * np.exp(-x[1] * self.t)], axis=1)
        return Point(x, point.cost, J.T @ J, -J.T @ self.residual(x))

    def determined(self, at: Point, free: np.ndarray, scale: np.ndarray) -> np.ndarray:
        return np.eye(free.size)

    def step(self, at: Point, lam: float, free: np.ndarray, scale: np.ndarray, determined) -> Step:
        assert at.H is not None and at.g is not None
        dx = np.zeros(at.x.size)
        H, g = at.H[np.ix_(free, free)], at.g[free]
        D = np.diag(np.diag(H))
        dx[free] = np.linalg.solve(H + lam * D, g) if free.size else 0.0
        d = dx[free]
        return Step(dx, float(d @ g + lam * d @ D @ d))

    def trial(self, at: Point, step: Step) -> Point:
        return self.point(at.x + step.dx)


class Bar:
    def __init__(self):
        self.updates, self.text = 0, ""

    def set_postfix_str(self, text: str, refresh: bool = False) -> None:
        self.text = text

    def update(self) -> None:
        self.updates += 1


def _problem():
    rng = np.random.default_rng(3)
    t = np.linspace(0.0, 4.0, 40)
    return Decay(t, 2.5 * np.exp(-1.3 * t) + 0.01 * rng.standard_normal(t.size))


def test_the_engine_reaches_the_least_squares_solution_with_a_falling_cost():
    problem, bar = _problem(), Bar()
    solved = levenberg_marquardt(
        problem, problem.point(np.array([1.0, 0.5])), np.arange(2), BatchOptions(), bar=bar
    )
    assert solved.converged
    np.testing.assert_allclose(solved.point.x, [2.5, 1.3], atol=0.05)
    assert np.all(np.diff(solved.cost_history) < 0) and len(solved.cost_history) >= 2
    assert solved.point.H is not None  # handed back linearized
    assert bar.updates == solved.iterations and bar.text.startswith("sum of squares")
    # at the solution the gradient vanishes: no direction lowers the cost further
    assert np.linalg.norm(solved.point.g) < 1e-3


def test_held_states_do_not_move_and_two_phases_join_their_histories():
    problem = _problem()
    start = problem.point(np.array([1.0, 1.3]))
    held = levenberg_marquardt(problem, start, np.zeros(0, dtype=np.int64), BatchOptions())
    np.testing.assert_array_equal(held.point.x, start.x)
    assert held.cost_history == [start.cost]
    solved = two_phases(problem, start, np.arange(2), BatchOptions())
    assert solved.cost_history[0] == start.cost and solved.converged
    np.testing.assert_allclose(solved.point.x, [2.5, 1.3], atol=0.05)


def test_it_stops_after_max_iterations():
    problem = _problem()
    solved = levenberg_marquardt(
        problem, problem.point(np.array([1.0, 0.5])), np.arange(2), BatchOptions(max_iterations=1)
    )
    assert solved.iterations == 1 and not solved.converged and len(solved.cost_history) == 2


class Exact(Decay):
    """A provider whose every step gains what it predicts (gain ratio 1), its damping recorded."""

    def __init__(self, t: np.ndarray, y: np.ndarray):
        super().__init__(t, y)
        self.lams: list[float] = []

    def step(self, at: Point, lam: float, free: np.ndarray, scale: np.ndarray, determined) -> Step:
        self.lams.append(lam)
        return Step(np.zeros(at.x.size), 1.0)

    def trial(self, at: Point, step: Step) -> Point:
        return Point(at.x, at.cost - step.predicted)


def test_the_damping_falls_by_the_floor_factor_while_steps_gain_what_they_predict():
    """Nielsen's factor max(floor, 1 - (2 rho - 1)^3) at rho = 1 is the floor: 0.1 here (Nielsen's
    1/3 took three times the steps to come back from a raised damping)."""
    base = _problem()
    problem = Exact(base.t, base.y)
    levenberg_marquardt(problem, Point(np.ones(2), 1e6), np.arange(2), BatchOptions(max_iterations=5))
    assert DECREASE_FLOOR == 0.1
    np.testing.assert_allclose(np.array(problem.lams[1:]) / problem.lams[:-1], DECREASE_FLOOR)
    assert problem.lams[0] == LAMBDA_START and len(problem.lams) == 5
