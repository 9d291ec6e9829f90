"""The registrations the association makes on its way (:class:`Registrar`): the labelled plots and
the references of their targets, solved by :func:`~registration.fleet.batch.estimate.solve_batch` from
the latest estimate, and the covariance the next tests use.

A state the labelled plots do not determine yet (a passive sensor's biases before any of its
tracks is joined, say) has no finite sigma in the batch's covariance, which leaves such directions
out (a pseudo-inverse). The tests need its uncertainty, not zero: along the directions left out,
the covariance gets the starting covariance ``P0`` (the tables' priors or the options' starting
sigmas) projected on them (:func:`usable_covariance`); a channel without plots yet starts from its
radar's states (:mod:`~registration.fleet.association.channels`).

At scale, a solve between passes registers every k-th window of each target (its last kept), with
all their plots and reference positions, about SOLVE_PLOTS of each (:func:`thin_windows`): its
estimate only sets the next gates, and its covariance is that of the plots it used. The checks
still see every labelled plot: their residuals come from the targets' windows fitted to all of
them under that estimate (:meth:`Registrar.plot_residuals`). The final registration uses every
accepted plot (a caller that registers them itself may end with a solve between passes instead).
"""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np

from registration.fleet.association.channels import channel_start
from registration.fleet.association.joining.windowfit import WindowFit, fit_windows, start_coefficients
from registration.fleet.association.options import AssociationOptions
from registration.fleet.association.problems import labelled_problem
from registration.fleet.batch.blocks import target_spans, window_grid, window_of
from registration.fleet.batch.estimate import solve_batch
from registration.fleet.data.known_targets import References
from registration.fleet.data.problem import FleetProblem
from registration.fleet.result import BatchResult

__all__ = [
    "INTERMEDIATE_TOLERANCE",
    "INTERMEDIATE_ITERATIONS",
    "SOLVE_PLOTS",
    "Registrar",
    "thin_windows",
    "usable_covariance",
]

#: Stopping tolerance (chi-square units) of the solves between association passes: their estimate
#: only sets the next gates, so a remaining change of about sqrt(0.01) = 0.1 sigma is enough.
INTERMEDIATE_TOLERANCE = 1e-2
#: Iterations per phase of those solves at most (a window that only 2-D radars determine can make
#: Levenberg-Marquardt crawl along its poorly determined height).
INTERMEDIATE_ITERATIONS = 25
#: Labelled plots above which a solve between passes registers a subsample (module docstring); the
#: fleets of the tests have fewer, the 10-radar benchmark up to 180 000.
SOLVE_PLOTS = 40_000


def thin_windows(
    labels: np.ndarray, problem: FleetProblem, refs: References, window_s: float, cap: int = SOLVE_PLOTS
) -> tuple[np.ndarray, References]:
    """(labels (N,), references): of each target labelled in ``labels``, the plots and reference
    positions of every k-th of its windows of ``window_s`` s (the batch's grid: its labelled plots'
    span cut into equal windows), and of its last window; the other plots' labels '' and the
    references of the targets not labelled left out. k = ceil(n / ``cap``), n the larger of the
    labelled plots and their targets' reference positions; ``labels`` and ``refs`` themselves when
    both are no more than ``cap``.

    Whole windows, not every k-th plot: a window keeps all its plots and references, so its
    trajectory is as well determined as in the full solve. Every k-th plot left windows of two or
    three plots of 2-D radars, their heights hanging on a thinned height reference, and the solves
    crawled (to their iteration cap, 0.5 sigma from their minimum).
    """
    at = np.flatnonzero(labels != "")
    names, tg = np.unique(np.asarray(labels[at], dtype=str), return_inverse=True)
    tg = tg.reshape(-1)
    mine = np.flatnonzero(np.isin(refs.target.astype(str), names))
    k = -(-max(at.size, mine.size) // cap)
    if k <= 1:
        return labels, refs
    t0, t1 = target_spans(tg, problem.time[at], names.size)
    count, length, _ = window_grid(t0, t1, window_s)
    w = window_of(t0, count, length, tg, problem.time[at])
    out = np.array(labels, dtype=object)
    out[at[~((w % k == 0) | (w == count[tg] - 1))]] = ""
    rt = np.searchsorted(names, refs.target[mine].astype(str))
    time = refs.time[mine]
    rw = window_of(t0, count, length, rt, time)
    inside = (time >= t0[rt]) & (time <= t1[rt])
    keep = ~inside | (rw % k == 0) | (rw == count[rt] - 1)
    return out, refs.subset(mine[keep])


def usable_covariance(result, P0: np.ndarray) -> np.ndarray:
    """(n, n) the batch covariance with ``P0`` on the directions it leaves out (module docstring)."""
    P = np.array(result.covariance, dtype=np.float64)
    U = result.undetermined
    if U.size == 0:
        return P
    free = result.layout.free
    scale = result.scale
    p0 = np.diag(P0)[free] / scale**2  # the starting variances in scaled coordinates
    A = scale[:, None] * U
    P[np.ix_(free, free)] += A @ (U.T @ (p0[:, None] * U)) @ A.T
    return 0.5 * (P + P.T)


class Registrar:
    """Solves of the labelled plots of ``problem`` (all plots, one placeholder target) with the
    references ``refs`` by ``solver`` (:func:`solve_batch` or a stand-in with its signature); ``x``,
    ``P`` the latest estimate and usable covariance (start: 0, ``P0``),
    ``problem_solved`` and ``result`` the latest solve (None before any), ``seconds`` in the solver."""

    def __init__(
        self,
        problem: FleetProblem,
        refs: References,
        P0: np.ndarray,
        options: AssociationOptions,
        progress: bool = False,
        solver=solve_batch,
    ):
        self.problem, self.refs, self.P0, self.solver = problem, refs, P0, solver
        self.final_options = replace(options.batch, window_s=options.window_s)
        self.between = replace(
            self.final_options,
            tolerance=max(self.final_options.tolerance, INTERMEDIATE_TOLERANCE),
            max_iterations=min(self.final_options.max_iterations, INTERMEDIATE_ITERATIONS),
        )
        self.margin_s = options.window_s
        self.channel_sigma = options.channel_sigma()
        self.progress = progress
        self.x, self.P = np.zeros(problem.layout.n), P0.copy()
        self.problem_solved: FleetProblem | None = None
        self.result: BatchResult | None = None
        self.seconds, self.solves = 0.0, 0
        self.labels: np.ndarray | None = None
        self.thinned = False
        self._fit: WindowFit | None = None
        self._last_fit: WindowFit | None = None
        self._cold: tuple | None = None

    def solve(self, labels: np.ndarray, subset: np.ndarray | None = None, final: bool = False):
        """Register the plots labelled in ``labels`` (N,; only those in ``subset`` (N,) bool if given)
        from the latest estimate; ``final``: the caller's batch options (else the looser ones of the
        solves between passes). Returns the result, or None (estimate unchanged) when no target is
        seen by two sensors or is a reference. A solve between passes of the plots the last solve
        registered is not made again: its result stands (the same optimum, within the tolerance)."""
        lab = labels if subset is None else np.where(subset, labels, "")
        if not (lab != "").any():
            return None
        same = self.labels is not None and np.array_equal(lab, self.labels)
        if same and not final and self.result is not None:
            return self.result
        few, refs = (
            (lab, self.refs) if final else thin_windows(lab, self.problem, self.refs, self.between.window_s)
        )
        try:
            problem = labelled_problem(self.problem, few, refs, self.margin_s)
        except ValueError:
            return None
        t0 = time.perf_counter()
        try:
            result = self.solver(
                problem,
                self.final_options if final else self.between,
                x0=self._start(problem),
                progress=self.progress,
                coefficients=self._windows_start(),
                fused=final,
            )
        except ValueError:  # every window set aside: nothing to register yet
            return None
        finally:
            self.seconds += time.perf_counter() - t0
        self.solves += 1
        self.x, self.P = channel_start(
            result.estimate,
            usable_covariance(result, self.P0),
            problem.layout,
            np.unique(problem.sensor),
            self.channel_sigma,
        )
        self.problem_solved, self.result = problem, result
        self.labels, self.thinned, self._fit = np.array(lab, dtype=object), few is not lab, None
        return result

    def labelled_fit(self):
        """The windows of the last solve's targets fitted to all their plots (the problem the solve would
        have had without its subsample) under its estimate
        (:func:`~registration.fleet.association.joining.windowfit.fit_windows`; computed once per solve,
        started from the windows of the last such fit)."""
        if self._fit is None:
            self._fit = fit_windows(
                labelled_problem(self.problem, self.labels, self.refs, self.margin_s),
                self.x,
                self.between,
                self._last_fit,
            )
            self._last_fit = self._fit
        return self._fit

    def cold_fit(self, problem: FleetProblem | None) -> WindowFit:
        """:func:`~registration.fleet.association.joining.windowfit.fit_windows` of ``problem`` (labelled
        plots; None: none) under the latest estimate, from the plots' means; kept while the estimate
        and the problem's plots and targets stay the same (the join passes' curves and the single
        plots' curves often fit the same targets under the same estimate)."""
        if problem is None:
            return fit_windows(None, self.x, self.between)
        key = (self.solves, problem.target_ids, problem.row.tobytes(), problem.target.tobytes())
        if self._cold is None or self._cold[0] != key:
            self._cold = (key, fit_windows(problem, self.x, self.between))
        return self._cold[1]

    def plot_residuals(self) -> np.ndarray:
        """(N, 3) normalised residuals of the plots under the last solve (NaN where not measured, not
        registered or set aside); after a solve of a subsample, of every labelled plot
        (:meth:`labelled_fit`)."""
        if not self.thinned:
            assert self.result is not None  # the residuals follow a solve
            return self.result.residuals[self.problem.row]
        return self.labelled_fit().residual_table(self.problem.n_input_plots)[self.problem.row]

    def _start(self, problem: FleetProblem) -> np.ndarray:
        """The warm start: the latest estimate, with 0 for the states of the sensors (and platforms)
        without plots in ``problem`` (a state the data do not determine stays where the solve starts;
        one taught by a join that was dropped since must not)."""
        layout = problem.layout
        seen = layout.sensor_states(np.unique(problem.sensor), problem.sensor_platform)
        x0 = np.zeros(layout.n)
        keep = np.unique(seen[seen < layout.n])
        x0[keep] = self.x[keep]
        return x0

    def _windows_start(self):
        """The solver's starting windows: where the last :meth:`labelled_fit` has a window (same
        target, centre, length and degree), its coefficients, fitted to all the target's plots under
        an estimate of the passes (the plots' means start the solve far off: phase 1 then spends half
        the iterations of a solve between passes bringing the windows back); None before any fit."""
        prior = self._last_fit
        if prior is None:
            return None

        def coefficients(problem: FleetProblem, design, x0: np.ndarray) -> np.ndarray:
            return start_coefficients(design, tuple(str(t) for t in problem.target_ids), x0, prior)

        return coefficients

    def register(self, labels: np.ndarray, subset: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`solve` between passes; (estimate, covariance)."""
        self.solve(labels, subset)
        return self.x, self.P
