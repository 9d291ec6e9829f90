"""The fit of the batch problem held in memory (:func:`fit`, which
:func:`registration.fleet.batch.estimate.solve_batch` evaluates), its options and its errors.

Jointly over every registration state (platform attitude errors, sensor biases) and every target
window's trajectory coefficients (:mod:`registration.fleet.batch.blocks`), the sum of squared whitened
residuals of all plots, reference positions and priors is minimised by the Levenberg-Marquardt
engine (:mod:`registration.fleet.batch.levenberg_marquardt`; Marquardt's diagonal scaling,
Nielsen's damping update) over the design's normal equations (:class:`DesignEquations`) with the
target blocks eliminated by the Schur complement (:mod:`registration.fleet.batch.schur`). Two
phases, both from the same code:

1. the target windows alone, registration states held at zero, from the window means of the
   plot positions (:mod:`registration.fleet.batch.initial`): the targets move to where the
   unregistered sensors jointly put them (roughly: until a step gains less than 1 %);
2. everything together.

The solver stops when the predicted reduction of the sum of squares falls below ``tolerance``
(chi-square units: a remaining change of order ``sqrt(tolerance)`` standard deviations).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from registration.core.progress import progress_bar
from registration.fleet.batch.blocks import make_blocks
from registration.fleet.batch.design import Design, make_design
from registration.fleet.batch.initial import initial_coefficients
from registration.fleet.batch.levenberg_marquardt import two_phases
from registration.fleet.batch.normal import Evaluation, Normal, evaluate, normal_equations
from registration.fleet.batch.schur import damped_step, determined_directions, masked_blocks, reduce
from registration.fleet.batch.set_aside import (
    exclude_singular,
    outside_exclusions,
    outside_when_seen,
    set_aside_outside,
    time_bias_warnings,
)
from registration.fleet.batch.window_fit import fit_each_window
from registration.fleet.data.layout import StateLayout
from registration.fleet.data.problem import FleetProblem

__all__ = [
    "BatchOptions",
    "DesignEquations",
    "DesignPoint",
    "DesignStep",
    "Fit",
    "NumericalError",
    "StartCoefficients",
    "determined_design",
    "fit",
    "fit_windows",
    "singular_blocks",
    "starting_states",
]

#: A window whose Jacobi-scaled information has an eigenvalue below this is not determined.
SINGULAR_BLOCK = 1e-10


class NumericalError(ArithmeticError):
    """A numerical failure the solver's checks did not foresee (for example a window's block that
    cannot be inverted at the solution): an internal error, not bad input. The command line exits
    with its own code for it (``registration.cli.errors.EXIT_NUMERICAL``)."""


@dataclass(frozen=True)
class BatchOptions:
    """Settings of :func:`solve_batch`.

    window_s: length (s) of the windows each target track is cut into; 0 = one window per
        distinct instant (synchronous sensors). degree: polynomial degree of the position in a
        window. max_iterations: per phase. tolerance: stop when the predicted reduction of the
        sum of squares is below this (chi-square units).
    """

    window_s: float = 20.0
    degree: int = 3
    max_iterations: int = 100
    tolerance: float = 1e-6

    def __post_init__(self):
        if not (np.isfinite(self.window_s) and self.window_s >= 0):
            raise ValueError(f"window_s: expected a length >= 0 s, got {self.window_s}")
        if int(self.degree) != self.degree or not 0 <= self.degree <= 3:
            raise ValueError(f"degree: expected an integer 0..3, got {self.degree}")
        if self.window_s == 0 and self.degree != 0:
            object.__setattr__(self, "degree", 0)
        if not self.max_iterations >= 1 or not self.tolerance > 0:
            raise ValueError("max_iterations must be >= 1 and tolerance > 0")


@dataclass(kw_only=True)
class Fit:
    """The solution of the least-squares problem and how it was reached; ``evaluation`` and
    ``normal`` are the residuals and the undamped normal equations at the solution."""

    problem: FleetProblem
    design: Design
    x: np.ndarray
    coef: np.ndarray
    converged: bool
    iterations: int
    cost_history: list
    evaluation: Evaluation
    normal: Normal
    warnings: tuple = ()


@dataclass(frozen=True)
class DesignPoint:
    """A point of the in-memory problem: its evaluation and, once linearized, its undamped normal
    equations (None: not yet)."""

    evaluation: Evaluation
    normal: Normal | None = None

    @property
    def cost(self) -> float:
        return self.evaluation.cost


@dataclass(frozen=True)
class DesignStep:
    """A damped step: states ``dx`` (n,; rad, m, 1, s), coefficients ``dc`` (B, n_coef, 3) ECEF m and
    the predicted reduction of the sum of squares."""

    dx: np.ndarray
    dc: np.ndarray
    predicted: float


class DesignEquations:
    """The normal equations of a problem held in memory (:class:`Design`), for the
    Levenberg-Marquardt engine (:class:`registration.fleet.batch.levenberg_marquardt.NormalEquations`)."""

    def __init__(self, design: Design):
        self.design = design

    def scale(self, free: np.ndarray) -> np.ndarray:
        return self.design.scale[free]

    def linearize(self, point: DesignPoint, lams: tuple[float, ...]) -> DesignPoint:
        if point.normal is not None:
            return point
        return DesignPoint(point.evaluation, normal_equations(self.design, point.evaluation))

    def determined(self, at: DesignPoint, free: np.ndarray, scale: np.ndarray) -> np.ndarray:
        assert at.normal is not None
        return determined_directions(reduce(self.design.blocks, at.normal, 0.0).S[np.ix_(free, free)], scale)

    def step(
        self, at: DesignPoint, lam: float, free: np.ndarray, scale: np.ndarray, determined: np.ndarray
    ) -> DesignStep:
        assert at.normal is not None
        return DesignStep(*damped_step(self.design.blocks, at.normal, free, scale, determined, lam))

    def trial(self, at: DesignPoint, step: DesignStep) -> DesignPoint:
        ev = at.evaluation
        return DesignPoint(evaluate(self.design, ev.x + step.dx, ev.coef + step.dc))


#: Starting window coefficients of a solve: ``(problem, design, x0) -> (B, n_coef, 3)`` m (ECEF), the
#: windows of ``design``'s blocks at the states ``x0`` (default: :func:`initial_coefficients`).
StartCoefficients = Callable[[FleetProblem, Design, np.ndarray], np.ndarray]


def starting_states(layout: StateLayout, x0: np.ndarray | None) -> np.ndarray:
    """The starting states (n,; rad, m, 1, s): ``x0`` checked (default zeros), the fixed states at 0."""
    x = np.zeros(layout.n) if x0 is None else np.array(x0, dtype=np.float64)
    if x.shape != (layout.n,) or not np.isfinite(x).all():
        raise ValueError(f"x0: expected {layout.n} finite starting states, got shape {x.shape}")
    x[layout.fixed] = 0.0
    return x


def singular_blocks(design: Design, normal: Normal) -> np.ndarray:
    """Indices of the windows whose position is not determined by their plots and references:
    the Jacobi-scaled block has an eigenvalue below SINGULAR_BLOCK times its largest."""
    V = masked_blocks(design.blocks, normal.V)
    q = V.shape[1]
    d = np.sqrt(np.abs(V[:, np.arange(q), np.arange(q)])) + 1e-300
    scaled = V / d[:, :, None] / d[:, None, :]
    w = np.linalg.eigvalsh(0.5 * (scaled + scaled.transpose(0, 2, 1)))
    return np.flatnonzero(~(w[:, 0] > SINGULAR_BLOCK * w[:, -1]))


def determined_design(
    problem: FleetProblem,
    options: BatchOptions,
    x0: np.ndarray,
    priors: bool = True,
    coefficients: StartCoefficients | None = None,
):
    """``(problem, design, start, normal)``: the design of ``problem`` with the windows whose position
    their plots do not determine set aside (:func:`singular_blocks`, ``set_aside.exclude_singular``, again
    until none is left), its evaluation at states ``x0`` (n,) with the window means of the plots
    corrected by ``x0`` and the normal equations there; None when no plot is left. Without
    ``priors`` the states' priors are left out of the sums (a filter carries them itself).
    ``coefficients(problem, design, x0)``: other starting window coefficients (default: the means)."""
    while problem.n_plots:
        design = make_design(problem, make_blocks(problem, options.window_s, options.degree))
        if not priors:
            design = replace(design, prior_weight=np.zeros_like(design.prior_weight))
        coef = initial_coefficients(design, x0) if coefficients is None else coefficients(problem, design, x0)
        start = evaluate(design, x0, coef)
        normal = normal_equations(design, start)
        bad = singular_blocks(design, normal)
        if bad.size == 0:
            return problem, design, start, normal
        problem = exclude_singular(problem, design, bad)
    return None


def fit_windows(
    design: Design, start: Evaluation, normal: Normal, options: BatchOptions
) -> tuple[Evaluation, Normal]:
    """The window coefficients fitted with the states held, each window on its own
    (:func:`~registration.fleet.batch.window_fit.fit_each_window`), until each window's predicted
    reduction of its sum of squares is below ``options.tolerance``."""
    ev, normal, _ = fit_each_window(design, start, normal, options)
    return ev, normal


#: Solves again after dropping plots that a time bias moves outside their navigation (where
#: setting them aside would empty a window), at most.
MAX_TIME_BIAS_REFITS = 3
#: Solves again, from the estimate, after that or after setting aside windows found undetermined
#: at the solution, at most (each such solve drops at least one window, so this bounds a rare chain).
MAX_REFITS = 10


def fit(
    problem: FleetProblem,
    options: BatchOptions | None = None,
    x0: np.ndarray | None = None,
    *,
    progress: bool = False,
    coefficients: StartCoefficients | None = None,
) -> Fit:
    """Solve the batch problem (module docstring) from states ``x0`` (n,; rad, m; default zeros: a
    warm start only saves iterations) and window coefficients ``coefficients(problem, design, x0)``
    ((B, n_coef, 3) m; default None: the window means of the plots, as :func:`determined_design`);
    windows of singular geometry are set aside, and so are plots
    that their sensor's estimated time bias moves outside their platform's navigation (they weigh
    0 in every evaluation where they are; at the solution they stay in ``Fit.problem``, listed in
    its exclusions, with no residual; if that would empty a window they are dropped and the
    problem solved anew from the estimate). A window whose position is determined at the start but
    not at the solution (:func:`singular_blocks` there: its plots seen outside the navigation weigh
    0, or its geometry at the estimate is degenerate) is set aside with its reason and the problem
    solved anew from the estimate; :class:`NumericalError` if windows are still undetermined after
    MAX_REFITS solves. ``progress``: a bar over the iterations on standard error
    (:func:`progress_bar`)."""
    options = options or BatchOptions()
    x0 = starting_states(problem.layout, x0)
    drops = 0
    with progress_bar(progress, "fleet batch solve", unit="iteration") as bar:
        for attempt in range(MAX_REFITS + 1):
            found = determined_design(problem, options, x0, coefficients=coefficients)
            if found is None:
                raise ValueError(
                    "no plots to register (every target was excluded: "
                    + "; ".join(e.text() for e in problem.excluded)
                    + ")"
                )
            problem, design, start, normal = found
            solved = two_phases(
                DesignEquations(design), DesignPoint(start, normal), problem.layout.free, options, bar
            )
            ev, normal = solved.point.evaluation, solved.point.normal
            assert normal is not None
            last = attempt == MAX_REFITS
            aside = set_aside_outside(problem, design, ev.x)
            outside = outside_when_seen(design, ev.x)
            if aside is None and drops < MAX_TIME_BIAS_REFITS and not last:  # a window would be left empty
                problem, x0, drops = (
                    problem.drop_plots(outside, outside_exclusions(problem, outside)),
                    ev.x,
                    drops + 1,
                )
                continue
            solved_problem, solved_design = aside if aside is not None else (problem, design)
            bad = singular_blocks(
                solved_design, normal
            )  # at the solution, with the plots set aside weighing 0
            if bad.size == 0:
                problem, design = solved_problem, solved_design
                break
            if last:
                raise NumericalError(
                    f"{bad.size} target windows are still undetermined at the solution after "
                    f"{attempt} solves that set such windows aside (first: target "
                    f"{problem.target_ids[design.blocks.block_target[bad[0]]]}); the covariance "
                    "cannot be computed"
                )
            problem, x0 = exclude_singular(problem, design, bad, outside), ev.x
    return Fit(
        problem=problem,
        design=design,
        x=ev.x,
        coef=ev.coef,
        converged=solved.converged,
        iterations=solved.iterations,
        cost_history=solved.cost_history,
        evaluation=ev,
        normal=normal,
        warnings=time_bias_warnings(problem.layout, ev.x, options.window_s),
    )
