"""The one Levenberg-Marquardt engine of the batch solvers (Marquardt's diagonal scaling, Nielsen's
damping update with a lower floor, DECREASE_FLOOR) over a provider of normal equations
(:class:`NormalEquations`).

Two providers implement it: the design of a problem held in memory
(:class:`registration.fleet.batch.solver.DesignEquations`) and the passes over the partitions of an
archive (:class:`registration.fleet.batch.partitioned.equations.PartitionedEquations`). The engine owns
the control: the damping ``lam`` and its factor ``nu``, the gain ratio ``rho`` of each trial step,
the stopping rules, the cost history and the progress bar; the provider owns the arithmetic (the
Schur-reduced system at a point, a damped step and its predicted reduction, the cost at a trial
point). :func:`two_phases` runs it on the target windows alone (states held) and then on
everything, as both solvers do.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Generic, Protocol, TypeVar

import numpy as np

__all__ = [
    "DECREASE_FLOOR",
    "LAMBDA_MAX",
    "LAMBDA_START",
    "TARGETS_FIRST",
    "Costed",
    "NormalEquations",
    "Predicted",
    "Solved",
    "StopRules",
    "levenberg_marquardt",
    "two_phases",
]

LAMBDA_START = 1e-3
LAMBDA_MAX = 1e16
#: The most an accepted step lowers the damping by (Nielsen's rule takes 1/3): a run that raised the
#: damping on a curved stretch comes back to Gauss-Newton steps in half the iterations.
DECREASE_FLOOR = 0.1
#: The first phase (targets alone) stops when a step would gain less than this share of the cost.
TARGETS_FIRST = 1e-2


class Costed(Protocol):
    """A point of the problem: its sum of squared whitened residuals (chi-square units)."""

    @property
    def cost(self) -> float: ...


class StopRules(Protocol):
    """When a run stops (:class:`registration.fleet.batch.solver.BatchOptions` has them): after
    ``max_iterations``, or when a step predicts a reduction below ``tolerance`` (chi-square units)."""

    @property
    def max_iterations(self) -> int: ...

    @property
    def tolerance(self) -> float: ...


class Predicted(Protocol):
    """A damped step: the reduction of the sum of squares it predicts (chi-square units)."""

    @property
    def predicted(self) -> float: ...


PointT = TypeVar("PointT", bound=Costed)
StepT = TypeVar("StepT", bound=Predicted)


class NormalEquations(Protocol[PointT, StepT]):
    """What the engine needs of a least-squares problem over states ``x`` and window coefficients.

    A *point* carries its cost and, once :meth:`linearize` d, its normal equations (reduced on the
    states); a *step* its predicted reduction. ``free`` (k,) are the indices of the states moved,
    ``scale`` (k,) their scale (prior or reference sigma) and ``determined`` (k, m) the directions
    the undamped information determines, in scaled coordinates.
    """

    def scale(self, free: np.ndarray) -> np.ndarray:
        """(k,) the scale of the ``free`` states (rad, m, 1, s)."""
        ...

    def linearize(self, point: PointT, lams: tuple[float, ...]) -> PointT:
        """``point`` with its normal equations (those it has are kept); ``lams``: the damping values
        about to be used there (a provider may reduce the system for them at once)."""
        ...

    def determined(self, at: PointT, free: np.ndarray, scale: np.ndarray) -> np.ndarray:
        """(k, m) the directions of the free states the undamped information at ``at`` determines."""
        ...

    def step(
        self, at: PointT, lam: float, free: np.ndarray, scale: np.ndarray, determined: np.ndarray
    ) -> StepT:
        """The step damped by ``lam`` from the linearized point ``at``."""
        ...

    def trial(self, at: PointT, step: StepT) -> PointT:
        """The point ``at`` moved by ``step``, with its cost (not linearized)."""
        ...


@dataclass(frozen=True)
class Solved(Generic[PointT]):
    """The end of a run: the last accepted point, linearized; whether the predicted reduction fell
    below the tolerance; the iterations run; the cost of the start and of each accepted step."""

    point: PointT
    converged: bool
    iterations: int
    cost_history: list[float]


def levenberg_marquardt(
    equations: NormalEquations[PointT, StepT],
    start: PointT,
    free: np.ndarray,
    options: StopRules,
    relative: float = 0.0,
    bar: Any = None,
) -> Solved[PointT]:
    """Minimise the sum of squares over the ``free`` states and all coefficients from ``start``.

    Stops when the predicted reduction is below ``options.tolerance`` or ``relative`` times the sum
    of squares, or after ``options.max_iterations``. ``bar``: a progress bar, advanced once per
    iteration (None: none).
    """
    scale = equations.scale(free)
    lam, nu = LAMBDA_START, 2.0
    point = equations.linearize(start, (0.0, lam))
    determined = equations.determined(point, free, scale)  # structural: found once, at the start
    history, converged, it = [point.cost], False, 0
    for it in range(1, options.max_iterations + 1):
        accepted = False
        while lam < LAMBDA_MAX:
            step = equations.step(point, lam, free, scale, determined)
            pred = step.predicted
            if pred < max(options.tolerance, relative * point.cost) and lam <= 1.0:
                converged = True
                break
            trial = equations.trial(point, step)
            rho = (point.cost - trial.cost) / pred if pred > 0 else -1.0
            if np.isfinite(trial.cost) and rho > 0:
                lam *= max(DECREASE_FLOOR, 1.0 - (2.0 * rho - 1.0) ** 3)
                nu, point, accepted = 2.0, trial, True
                history.append(trial.cost)
                break
            lam, nu = lam * nu, nu * 2.0
        if bar is not None:
            bar.set_postfix_str(f"sum of squares {history[-1]:.6g}", refresh=False)
            bar.update()
        if converged or not accepted:
            break
        point = equations.linearize(point, (lam,))
    return Solved(point, converged, it, history)


def two_phases(
    equations: NormalEquations[PointT, StepT],
    start: PointT,
    free: np.ndarray,
    options: StopRules,
    bar: Any = None,
) -> Solved[PointT]:
    """:func:`levenberg_marquardt` on the target windows alone (states held, until a step would gain
    less than TARGETS_FIRST of the cost), then on the ``free`` states and the windows together."""
    first = levenberg_marquardt(equations, start, np.zeros(0, dtype=np.int64), options, TARGETS_FIRST, bar)
    second = levenberg_marquardt(equations, first.point, free, options, 0.0, bar)
    return Solved(
        second.point,
        second.converged,
        first.iterations + second.iterations,
        first.cost_history + second.cost_history[1:],
    )
