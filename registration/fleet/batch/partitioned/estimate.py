"""Batch registration of an archive partition by partition: :func:`solve_batch_partitioned`
(docs/howto/register-an-archive.md).

The normal equations are sums over target windows, and every window lies in one partition
(:mod:`registration.fleet.batch.partitioned.plan`), so the Levenberg-Marquardt engine
(:mod:`registration.fleet.batch.levenberg_marquardt`) runs on their sums over the partitions
(:mod:`registration.fleet.batch.partitioned.equations`): the control, the two phases (windows alone,
then everything) and the stopping rule are ``solve_batch``'s, so the estimate is ``solve_batch``'s
to rounding. Memory holds one partition at a time (plus the windows' coefficients, 3 (d + 1)
floats per window) unless partitions are cached in memory; by default for files, each partition's
design is read and built once, in the setup pass, and kept on local disk for the later passes
(:mod:`registration.fleet.batch.partitioned.spill`).

What differs from ``solve_batch``: a window found undetermined at the start is set aside in its
partition with the archive's windows kept (``solve_batch`` cuts the target's windows anew, which
changes them only when the window is the first or last of its target: a warning says so); a window
undetermined at the solution, or plots that a time bias moves outside the navigation where setting
them aside would empty a window, raise NumericalError (``solve_batch`` solves again).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from registration.core.observability import ObservabilityReport
from registration.core.progress import progress_bar
from registration.fleet.batch.blocks import window_grid
from registration.fleet.batch.covariance import estimate_from_information
from registration.fleet.batch.levenberg_marquardt import two_phases
from registration.fleet.batch.partitioned.equations import PartitionedEquations, PassPoint, run_pass
from registration.fleet.batch.partitioned.partition_passes import final_pass, setup_pass
from registration.fleet.batch.partitioned.plan import DEFAULT_NAV_MARGIN_S, ArchivePlan, make_plan
from registration.fleet.batch.partitioned.spill import make_folder, remove_folder
from registration.fleet.batch.partitioned.task import PartitionTask, archive_sensors
from registration.fleet.batch.set_aside import time_bias_warnings
from registration.fleet.batch.solver import BatchOptions, NumericalError, starting_states
from registration.fleet.data.layout import StateLayout
from registration.fleet.data.problem import Exclusion
from registration.fleet.result import ChiSquareCheck, StateEstimates

__all__ = ["PartitionedResult", "remove_spill", "solve_batch_partitioned"]


@dataclass(kw_only=True)
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
    observability: ObservabilityReport
    status: dict
    scale: np.ndarray
    # the partitions solved, in the order of ``coefficients`` (with the spill folder when it was kept)
    tasks: tuple = ()
    # the spill folder kept for the output pass (``keep_spill``; the caller removes it: remove_spill)
    spill_folder: str | None = None

    @property
    def free_names(self) -> tuple[str, ...]:
        return tuple(self.layout.names[i] for i in self.layout.free)


@dataclass(frozen=True)
class PartitionedSetup:
    """The setup pass's sums: the tasks of the partitions with plots (windows set aside), their
    starting coefficients (B_p, n_coef, 3) ECEF m, the plots, the windows' exclusions and warnings."""

    tasks: list[PartitionTask]
    coefs: list[np.ndarray]
    n_plots: int
    exclusions: tuple[Exclusion, ...]
    warnings: tuple[str, ...]


def _setup(
    plan: ArchivePlan, source, options: BatchOptions, x0: np.ndarray, client, cache: int, spill: str | None
) -> PartitionedSetup:
    """The setup pass over the partitions at states ``x0`` (n,)."""
    empty = np.zeros((0, 2), dtype=np.int64)
    tasks = [PartitionTask(source, plan, k, options, empty, cache, spill) for k in range(plan.n_partitions)]
    found = run_pass(setup_pass, tasks, [(x0,)] * len(tasks), client)
    kept = [
        (PartitionTask(source, plan, t.index, options, f.dropped, cache, spill), f)
        for t, f in zip(tasks, found)
        if f is not None and f.coef is not None
    ]
    exclusions = tuple(e for f in found if f is not None for e in f.exclusions)
    count = window_grid(plan.t0, plan.t1, plan.window_s)[0]
    edge = [d for f in found if f is not None for d in f.dropped if d[1] in (0, count[d[0]] - 1)]
    warnings = (
        (
            f"{len(edge)} undetermined windows set aside at the ends of their targets' spans (first: "
            f"target {plan.target_ids[edge[0][0]]}); solve_batch would cut those targets' windows anew, "
            "so its estimate may differ slightly",
        )
        if edge
        else ()
    )
    if not kept:
        raise ValueError("no plots to register (every window was set aside)")
    return PartitionedSetup(
        [t for t, _ in kept], [f.coef for _, f in kept], sum(f.plots for _, f in kept), exclusions, warnings
    )


@dataclass(frozen=True)
class FinalSums:
    """At the solution: the information with priors (free, free), the chi-square check and the
    exclusions of the plots seen outside their navigation."""

    information: np.ndarray
    chi_square: ChiSquareCheck
    exclusions: tuple[Exclusion, ...]


def _final(
    passes: PartitionedEquations, x: np.ndarray, coefs: list, layout: StateLayout, plan: ArchivePlan
) -> FinalSums:
    """The final pass's sums; NumericalError where solve_batch would set windows aside and solve
    again (module docstring)."""
    parts = run_pass(final_pass, passes.tasks, [(x, c) for c in coefs], passes.client)
    singular, empty = sum(p.singular for p in parts), sum(p.empty for p in parts)
    if singular or empty:
        raise NumericalError(
            f"{singular} target windows are undetermined at the solution and {empty} would be left "
            "without plots by the plots a time bias moves outside the navigation; the partitioned "
            "solver does not solve again without them: register in memory (solve_batch)"
        )
    free = layout.free
    at = passes.add(x, coefs, [p.terms for p in parts], (0.0,))
    assert at.reduced is not None
    S = at.reduced.S[0.0]
    information = 0.5 * (S + S.T)[np.ix_(free, free)]
    xs = np.append(x, 0.0)
    prior = (xs * np.sqrt(passes.pw2))[free]
    keys = dict.fromkeys(
        key for p in parts for key in p.parts
    )  # plots, references and, with a surface, surface
    chi_parts = {
        key: (
            sum(p.parts.get(key, (0.0, 0))[0] for p in parts),
            sum(p.parts.get(key, (0.0, 0))[1] for p in parts),
        )
        for key in keys
    }
    chi_parts["priors"] = (float(np.sum(prior * prior)), int(np.count_nonzero(passes.pw2[free])))
    n_values = sum(n for _, n in chi_parts.values())
    n_params = free.size + 3 * sum(p.n_coef for p in parts)
    tb = layout.time_bias_index[layout.time_bias_index >= 0]
    if tb.size and np.max(np.abs(x[tb])) > plan.nav_margin_s:
        raise ValueError(
            f"a time bias of {np.max(np.abs(x[tb])):.3g} s exceeds the navigation margin of "
            f"{plan.nav_margin_s:g} s read around each partition: register again with a larger margin"
        )
    return FinalSums(
        information,
        ChiSquareCheck(at.cost, n_values - n_params, chi_parts),
        tuple(e for p in parts for e in p.exclusions),
    )


def remove_spill(folder: str, client) -> None:
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
    client: Any = None,
    cache: int | None = None,
    spill: bool | None = None,
    spill_dir: str | None = None,
    keep_spill: bool = False,
    nav_margin_s: float = DEFAULT_NAV_MARGIN_S,
    progress: bool = False,
) -> PartitionedResult:
    """:func:`registration.fleet.batch.estimate.solve_batch`'s estimate and covariance of the states
    from an archive read partition by partition (module docstring).

    ``source``: a :class:`~registration.fleet.data.source.FleetSource` (the tables in memory,
    :class:`registration.io.fleet.memory.TablesSource`, or an archive read lazily,
    :class:`registration.io.fleet.archive.parquet.ParquetSource`); ``partitions`` equal time ranges or
    ranges of ``partition_s`` seconds (default one); ``client``: a ``dask.distributed.Client`` to
    map the partitions on (None: this process); ``cache``: partitions whose design each process
    keeps (default: all for tables in memory without a client, else none); ``spill``: keep every
    partition's design (and its normal equations at the latest point) in a temporary folder on local
    disk after the setup pass, so the later passes read neither the archive nor build the partition
    again (default: on for files when not every partition is kept in memory; the folder is made in
    ``spill_dir``, default the system's temp folder, and removed at the end; with ``keep_spill``
    it is kept, in ``result.spill_folder`` and the result's tasks, so that the output pass
    (:func:`registration.fleet.batch.outputs.archive_outputs`) reads each partition's problem and
    design from it instead of building them again; the caller then removes it with
    :func:`remove_spill`); ``nav_margin_s``: the
    navigation read around each partition (s), the largest time bias followed exactly; ``x0``
    (n,; rad, m): starting states.
    """
    options = options or BatchOptions()
    plan = make_plan(
        source, options.window_s, partitions=partitions, partition_s=partition_s, nav_margin_s=nav_margin_s
    )
    layout, platform_ids, sensor_ids, sensor_platform = archive_sensors(source, plan.height_offset_prior)
    x = starting_states(layout, x0)
    if cache is None:
        cache = plan.n_partitions if source.in_memory and client is None else 0
    if spill is None:
        spill = cache < plan.n_partitions and not source.in_memory
    folder = make_folder(spill_dir) if spill else None
    solved_ok = False
    try:
        setup = _setup(plan, source, options, x, client, cache, folder)
        passes = PartitionedEquations(setup.tasks, client, layout)
        free = layout.free
        with progress_bar(progress, "fleet partitioned solve", unit="iteration") as bar:
            solved = two_phases(passes, PassPoint(x, setup.coefs, float("nan")), free, options, bar)
        x, coefs = solved.point.x, solved.point.coefs
        final = _final(passes, x, coefs, layout, plan)
        solved_ok = True
    finally:
        if folder is not None:
            if not (keep_spill and solved_ok):
                remove_spill(folder, client)
    kept = folder if keep_spill else None
    return _result(
        layout, (platform_ids, sensor_ids, sensor_platform), solved, final, passes, plan, setup, options, kept
    )


def _result(
    layout, ids: tuple, solved, final, passes, plan, setup, options: BatchOptions, kept
) -> PartitionedResult:
    """The result of the solve: the covariance from the final information, ``kept`` the spill
    folder kept for the output pass (None: removed)."""
    platform_ids, sensor_ids, sensor_platform = ids
    x, coefs, free = solved.point.x, solved.point.coefs, layout.free
    information_data = final.information - np.diag(passes.pw2[free])
    known = estimate_from_information(
        layout, final.information, information_data, sensor_platform, platform_ids, sensor_ids
    )
    return PartitionedResult(
        layout=layout,
        estimate=x,
        covariance=known.covariance,
        sigma=known.sigma,
        information=final.information,
        information_data=information_data,
        undetermined=known.undetermined,
        converged=solved.converged,
        iterations=solved.iterations,
        cost_history=solved.cost_history,
        chi_square=final.chi_square,
        coefficients=coefs,
        excluded=plan.excluded + setup.exclusions + final.exclusions,
        warnings=setup.warnings + time_bias_warnings(layout, x, options.window_s),
        n_plots=setup.n_plots,
        plan=plan,
        observability=known.report,
        status=known.status,
        scale=known.scale,
        tasks=tuple(replace(t, spill=kept) for t in passes.tasks),
        spill_folder=kept,
    )
