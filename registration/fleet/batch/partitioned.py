"""Batch registration of an archive partition by partition: :func:`solve_batch_partitioned`
(docs/archive.md).

The normal equations are sums over target windows, and every window lies in one partition
(:mod:`registration.fleet.batch.partitions`), so each Levenberg-Marquardt trial is two passes over
the partitions (:mod:`registration.fleet.batch.passes`): *map* each partition's Schur-reduced
contribution ``S_p``, ``r_p``, its share ``U_p``, ``b_x,p`` of the states' block and its sum of
squares at the current estimate; *reduce* them by adding in partition order (so the result does not
depend on where each partition ran); solve the damped reduced system on the free states as
:func:`registration.fleet.batch.schur.damped_step` does; then map each partition's
back-substitution ``dc_b = V_b^-1 (b_b - W_b dx)`` with its trial sum of squares. The
Levenberg-Marquardt control, the two phases (windows alone, then everything) and the stopping rule
are those of :mod:`registration.fleet.batch.levenberg_marquardt`, so the estimate is
``solve_batch``'s to rounding. Memory holds one partition at a time (plus the windows'
coefficients, 3 (d + 1) floats per window) unless partitions are cached in memory; by default
for files, each partition's design is read and built once, in the setup pass, and kept on local
disk for the later passes (:mod:`registration.fleet.batch.spill`).

What differs from ``solve_batch``: a window found undetermined at the start is set aside in its
partition with the archive's windows kept (``solve_batch`` cuts the target's windows anew, which
changes them only when the window is the first or last of its target: a warning says so); a window
undetermined at the solution, or plots that a time bias moves outside the navigation where setting
them aside would empty a window, raise NumericalError (``solve_batch`` solves again).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from registration.core.observability import ObservabilityReport
from registration.core.parallel import map_chunks
from registration.fleet.batch.blocks import window_grid
from registration.fleet.batch.covariance import estimate_from_information
from registration.fleet.batch.partitions import DEFAULT_NAV_MARGIN_S, ArchivePlan, TablesSource, make_plan
from registration.fleet.batch.passes import (
    PartitionTask,
    archive_sensors,
    final_pass,
    reduce_pass,
    setup_pass,
    step_pass,
)
from registration.fleet.batch.schur import determined_directions, solve_reduced
from registration.fleet.batch.levenberg_marquardt import two_phases
from registration.fleet.batch.solver import BatchOptions, NumericalError, progress_bar, time_bias_warnings
from registration.fleet.batch.spill import make_folder, remove_folder
from registration.fleet.data.layout import StateLayout
from registration.fleet.result import ChiSquareCheck, StateEstimates

__all__ = [
    "PartitionedEquations",
    "PartitionedResult",
    "PassPoint",
    "PassStep",
    "ReducedSums",
    "run_pass",
    "solve_batch_partitioned",
]


def _call(item):
    func, task, args = item
    return func(task, *args)


def run_pass(func, tasks: list, args: list, client=None) -> list:
    """``[func(task, *a) for task, a in zip(tasks, args)]`` in this process or on ``client``'s workers,
    in partition order."""
    return map_chunks(_call, [(func, t, a) for t, a in zip(tasks, args)], client)


@dataclass
class PartitionedResult(StateEstimates):
    """The estimate of :func:`solve_batch_partitioned` (units and names of ``layout``: rad, m, 1, s).

    ``estimate`` (n,), ``covariance`` (n, n), ``sigma`` (n,; inf: not determined), ``information``
    (free, free) with priors, ``coefficients``: per partition the windows' coefficients (B_p,
    n_coef, 3) ECEF m (None: no plot), in the partition's block order.
    """

    layout: StateLayout
    estimate: np.ndarray
    covariance: np.ndarray
    sigma: np.ndarray
    information: np.ndarray
    information_data: np.ndarray
    undetermined: np.ndarray
    converged: bool
    iterations: int
    cost_history: list
    chi_square: ChiSquareCheck
    coefficients: list
    excluded: tuple
    warnings: tuple
    n_plots: int
    plan: ArchivePlan
    observability: ObservabilityReport | None = None
    status: dict = field(default_factory=dict)
    scale: np.ndarray | None = None
    tasks: tuple = ()  # the partitions solved, in the order of ``coefficients`` (without the spill folder, gone)

    @property
    def free_names(self) -> tuple[str, ...]:
        return tuple(self.layout.names[i] for i in self.layout.free)


@dataclass(frozen=True)
class ReducedSums:
    """The partitions' terms at a point, added in partition order, priors included: the states'
    block ``U`` (n + 1, n + 1) and right-hand side ``b_x`` (n + 1,) and, per damping ``lam``, the
    Schur-reduced ``S`` (n + 1, n + 1) and ``r`` (n + 1,) (row/column n: the sink of absent states).
    ``S`` and ``r`` grow as further damping values are asked for."""

    U: np.ndarray
    b_x: np.ndarray
    S: dict[float, np.ndarray]
    r: dict[float, np.ndarray]


@dataclass(frozen=True)
class PassPoint:
    """A point of the partitioned problem: states ``x`` (n,), each partition's window coefficients
    (B_p, n_coef, 3) ECEF m, the sum of squares and, once linearized, the reduced sums there."""

    x: np.ndarray
    coefs: list[np.ndarray]
    cost: float
    reduced: ReducedSums | None = None


@dataclass(frozen=True)
class PassStep:
    """A damped step: states ``dx`` (n,), coefficients per partition, its predicted reduction and
    the sum of squares at the trial point (the step pass computes both at once)."""

    dx: np.ndarray
    dcs: list[np.ndarray]
    predicted: float
    cost: float


class PartitionedEquations:
    """The normal equations of an archive as sums over its partitions' passes (module docstring), for
    the Levenberg-Marquardt engine (:class:`registration.fleet.batch.levenberg_marquardt.NormalEquations`):
    the tasks, the client and the prior terms."""

    def __init__(self, tasks: list[PartitionTask], client, layout: StateLayout):
        self.tasks, self.client, self.layout = tasks, client, layout
        with np.errstate(divide="ignore"):
            p = layout.prior_sigma
            self.pw2 = np.append(np.where(np.isfinite(p) & (p > 0), 1.0 / p**2, 0.0), 0.0)

    def reduce(self, x: np.ndarray, coefs: list[np.ndarray], lams: tuple[float, ...]) -> PassPoint:
        """The point (x, coefs) with its reduced sums for damping values ``lams`` (one pass)."""
        parts = run_pass(reduce_pass, self.tasks, [(x, c, lams) for c in coefs], self.client)
        U = sum(p["U"] for p in parts) + np.diag(self.pw2)
        xs = np.append(x, 0.0)
        b_x = sum(p["b_x"] for p in parts) - self.pw2 * xs
        prior = float(np.sum(self.pw2 * xs * xs))
        S = {lam: U + sum(p["S"][i] for p in parts) for i, lam in enumerate(lams)}
        r = {lam: b_x - sum(p["b_x"] - p["r"][i] for p in parts) for i, lam in enumerate(lams)}
        cost = sum(p["cost"] for p in parts) + prior
        return PassPoint(x, coefs, cost, ReducedSums(U, b_x, S, r))

    def scale(self, free: np.ndarray) -> np.ndarray:
        return self.layout.scale[free]

    def linearize(self, point: PassPoint, lams: tuple[float, ...]) -> PassPoint:
        return self.reduce(point.x, point.coefs, lams)

    def determined(self, at: PassPoint, free: np.ndarray, scale: np.ndarray) -> np.ndarray:
        assert at.reduced is not None
        S0 = at.reduced.S[0.0]
        return determined_directions(0.5 * (S0 + S0.T)[np.ix_(free, free)], scale)

    def step(
        self, at: PassPoint, lam: float, free: np.ndarray, scale: np.ndarray, determined: np.ndarray
    ) -> PassStep:
        """The damped step ``lam`` at ``at`` and the cost at its trial point (one pass; one more to
        reduce for ``lam`` if not done yet)."""
        red, x = at.reduced, at.x
        assert red is not None
        if lam not in red.S:
            more = self.reduce(x, at.coefs, (lam,)).reduced
            assert more is not None
            red.S[lam], red.r[lam] = more.S[lam], more.r[lam]
        U = red.U
        S = red.S[lam] + lam * np.diag(np.diag(U))
        S = 0.5 * (S + S.T)
        n = x.size
        dx = np.zeros(n + 1)
        dx[free] = solve_reduced(S[np.ix_(free, free)], red.r[lam][free], scale, determined)
        parts = run_pass(step_pass, self.tasks, [(x, c, dx, lam) for c in at.coefs], self.client)
        b_dot = float(dx[free] @ red.b_x[free]) + sum(p["b_dot"] for p in parts)
        damp = lam * (float(np.sum(np.diag(U)[free] * dx[free] ** 2)) + sum(p["damp"] for p in parts))
        xs = np.append(x + dx[:n], 0.0)
        cost = sum(p["cost"] for p in parts) + float(np.sum(self.pw2 * xs * xs))
        return PassStep(dx[:n], [p["dc"] for p in parts], b_dot + damp, cost)

    def trial(self, at: PassPoint, step: PassStep) -> PassPoint:
        return PassPoint(at.x + step.dx, [c + d for c, d in zip(at.coefs, step.dcs)], step.cost)


def _setup(
    plan: ArchivePlan, source, options: BatchOptions, x0: np.ndarray, client, cache: int, spill: str | None
) -> tuple:
    """The tasks of the partitions with plots, their starting coefficients, exclusions and warnings."""
    empty = np.zeros((0, 2), dtype=np.int64)
    tasks = [PartitionTask(source, plan, k, options, empty, cache, spill) for k in range(plan.n_partitions)]
    found = run_pass(setup_pass, tasks, [(x0,)] * len(tasks), client)
    kept = [
        (PartitionTask(source, plan, t.index, options, f["dropped"], cache, spill), f)
        for t, f in zip(tasks, found)
        if f is not None and f["coef"] is not None
    ]
    exclusions = tuple(e for f in found if f is not None for e in f["exclusions"])
    count = window_grid(plan.t0, plan.t1, plan.window_s)[0]
    edge = [d for f in found if f is not None for d in f["dropped"] if d[1] in (0, count[d[0]] - 1)]
    warnings = (
        (
            f"{len(edge)} undetermined windows set aside at the ends of their targets' spans (first: target "
            f"{plan.target_ids[edge[0][0]]}); solve_batch would cut those targets' windows anew, so its "
            "estimate may differ slightly",
        )
        if edge
        else ()
    )
    if not kept:
        raise ValueError("no plots to register (every window was set aside)")
    return (
        [t for t, _ in kept],
        [f["coef"] for _, f in kept],
        sum(f["plots"] for _, f in kept),
        exclusions,
        warnings,
    )


def _final(
    passes: PartitionedEquations, x: np.ndarray, coefs: list, layout: StateLayout, plan: ArchivePlan
) -> tuple:
    """(information with priors (free, free), chi-square check, exclusions) at the solution;
    NumericalError where solve_batch would set windows aside and solve again (module docstring)."""
    parts = run_pass(final_pass, passes.tasks, [(x, c) for c in coefs], passes.client)
    singular, empty = sum(p["singular"] for p in parts), sum(p["empty"] for p in parts)
    if singular or empty:
        raise NumericalError(
            f"{singular} target windows are undetermined at the solution and {empty} would be left "
            "without plots by the plots a time bias moves outside the navigation; the partitioned "
            "solver does not solve again without them: register in memory (solve_batch)"
        )
    free = layout.free
    U = sum(p["U"] for p in parts) + np.diag(passes.pw2)
    S = U + sum(p["S"][0] for p in parts)
    information = 0.5 * (S + S.T)[np.ix_(free, free)]
    xs = np.append(x, 0.0)
    prior = (xs * np.sqrt(passes.pw2))[free]
    keys = dict.fromkeys(
        key for p in parts for key in p["parts"]
    )  # plots, references and, with a surface, surface
    chi_parts = {
        key: (
            sum(p["parts"].get(key, (0.0, 0))[0] for p in parts),
            sum(p["parts"].get(key, (0.0, 0))[1] for p in parts),
        )
        for key in keys
    }
    chi_parts["priors"] = (float(np.sum(prior * prior)), int(np.count_nonzero(passes.pw2[free])))
    n_values = sum(n for _, n in chi_parts.values())
    n_params = free.size + 3 * sum(p["n_coef"] for p in parts)
    cost = sum(p["cost"] for p in parts) + float(np.sum(passes.pw2 * xs * xs))
    tb = layout.time_bias_index[layout.time_bias_index >= 0]
    if tb.size and np.max(np.abs(x[tb])) > plan.nav_margin_s:
        raise ValueError(
            f"a time bias of {np.max(np.abs(x[tb])):.3g} s exceeds the navigation margin of "
            f"{plan.nav_margin_s:g} s read around each partition: register again with a larger margin"
        )
    return (
        information,
        ChiSquareCheck(cost, n_values - n_params, chi_parts),
        tuple(e for p in parts for e in p["exclusions"]),
    )


def _remove_spill(folder: str, client) -> None:
    """Remove the spill folder here and, with a client, on every worker (they may be on other machines)."""
    remove_folder(folder)
    if client is not None:
        try:
            client.run(remove_folder, folder)
        except Exception:  # a worker gone or a closed client: its temp folder is its own to clean
            pass


def solve_batch_partitioned(
    source,
    options: BatchOptions | None = None,
    x0: np.ndarray | None = None,
    *,
    partitions: int | None = None,
    partition_s: float | None = None,
    client=None,
    cache: int | None = None,
    spill: bool | None = None,
    spill_dir: str | None = None,
    nav_margin_s: float = DEFAULT_NAV_MARGIN_S,
    progress: bool = False,
) -> PartitionedResult:
    """:func:`registration.fleet.batch.solve.solve_batch`'s estimate and covariance of the states from an
    archive read partition by partition (module docstring).

    ``source``: :class:`~registration.fleet.batch.partitions.TablesSource` or
    :class:`~registration.fleet.batch.archive.ParquetSource`; ``partitions`` equal time ranges or
    ranges of ``partition_s`` seconds (default one); ``client``: a ``dask.distributed.Client`` to
    map the partitions on (None: this process); ``cache``: partitions whose design each process
    keeps (default: all for tables in memory without a client, else none); ``spill``: keep every
    partition's design (and its normal equations at the latest point) in a temporary folder on local
    disk after the setup pass, so the later passes read neither the archive nor build the partition
    again (default: on for files when not every partition is kept in memory; the folder is made in
    ``spill_dir``, default the system's temp folder, and removed at the end); ``nav_margin_s``: the
    navigation read around each partition (s), the largest time bias followed exactly; ``x0``
    (n,; rad, m): starting states.
    """
    options = options or BatchOptions()
    plan = make_plan(
        source, options.window_s, partitions=partitions, partition_s=partition_s, nav_margin_s=nav_margin_s
    )
    layout, platform_ids, sensor_ids, sensor_platform = archive_sensors(source)
    x = np.zeros(layout.n) if x0 is None else np.array(x0, dtype=np.float64)
    if x.shape != (layout.n,) or not np.isfinite(x).all():
        raise ValueError(f"x0: expected {layout.n} finite starting states, got shape {x.shape}")
    x[layout.fixed] = 0.0
    if cache is None:
        cache = plan.n_partitions if isinstance(source, TablesSource) and client is None else 0
    if spill is None:
        spill = cache < plan.n_partitions and not isinstance(source, TablesSource)
    folder = make_folder(spill_dir) if spill else None
    try:
        tasks, coefs, n_plots, exclusions, warnings = _setup(plan, source, options, x, client, cache, folder)
        passes = PartitionedEquations(tasks, client, layout)
        free = layout.free
        with progress_bar(progress, "fleet partitioned solve", unit="iteration") as bar:
            solved = two_phases(passes, PassPoint(x, coefs, float("nan")), free, options, bar)
        x, coefs = solved.point.x, solved.point.coefs
        information, chi2, outside = _final(passes, x, coefs, layout, plan)
    finally:
        if folder is not None:
            _remove_spill(folder, client)
    information_data = information - np.diag(passes.pw2[free])
    known = estimate_from_information(
        layout, information, information_data, sensor_platform, platform_ids, sensor_ids
    )
    return PartitionedResult(
        layout,
        x,
        known.covariance,
        known.sigma,
        information,
        information_data,
        known.undetermined,
        solved.converged,
        solved.iterations,
        solved.cost_history,
        chi2,
        coefs,
        plan.excluded + exclusions + outside,
        warnings + time_bias_warnings(layout, x, options),
        n_plots,
        plan,
        known.report,
        known.status,
        known.scale,
        tuple(replace(t, spill=None) for t in passes.tasks),
    )
