"""The work on one partition of an archive (:mod:`registration.fleet.batch.partitioned.plan`) in one
pass of the partitioned solver (:mod:`registration.fleet.batch.partitioned.estimate`): per pass its
sums at the current estimate.

Each function takes one :class:`~registration.fleet.batch.partitioned.task.PartitionTask` and the current
states and coefficients and returns a small typed result of arrays; it is pure (its result depends on its
arguments only), so a pass can run in this process or on Dask workers, and a lost worker's task run again
gives the same result. Two caches save time and change no result:

* in memory, per process, the design and latest evaluations of ``task.cache`` partitions (0: none);
* on local disk, in the folder ``task.spill`` (None: none; :mod:`registration.fleet.batch.partitioned.spill`),
  every partition's design and its normal equations (with their latest reduction) at the current
  point and at the latest trial step: the setup pass writes the design, the reduce and step passes
  the points, and the later passes read them instead of reading the archive, building the
  partition and evaluating a point again. A file that is missing (say on another worker's
  machine) is built again and written.

Without either, every pass reads and builds its partition again. The setup pass hands its
partition's design and its normal equations at the starting point to both caches, so the first
reduce pass evaluates nothing again.

A partition's design carries no priors (their terms are added once, by the caller). With ``U``,
``b_x`` its plots' share of the states' block and right-hand side, the Schur-reduced contribution
is ``S_p = -sum_b W_b^T (V_b + lam D_b)^-1 W_b`` and ``r_p = b_x - sum_b W_b^T (V_b + lam D_b)^-1 b_b``
(:func:`registration.fleet.batch.schur.reduce` with ``U = 0``).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from registration.fleet.batch.initial import initial_coefficients
from registration.fleet.batch.normal import evaluate, normal_equations
from registration.fleet.batch.partitioned import spill
from registration.fleet.batch.partitioned.plan import window_index
from registration.fleet.batch.partitioned.task import (
    PartitionEntry,
    PartitionTask,
    PointTerms,
    keep_entry,
    new_entry,
    partition_design,
    partition_entry,
    partition_problem,
    spill_entry,
)
from registration.fleet.batch.residuals import chi_square_parts
from registration.fleet.batch.schur import Reduced, reduce
from registration.fleet.batch.set_aside import outside_exclusions, outside_weight, singular_exclusions
from registration.fleet.batch.solver import singular_blocks
from registration.fleet.data.problem import Exclusion

__all__ = [
    "FinalTerms",
    "ReduceTerms",
    "SetupFound",
    "StepTerms",
    "final_pass",
    "reduce_pass",
    "setup_pass",
    "step_pass",
]


@dataclass(frozen=True)
class SetupFound:
    """The setup pass of a partition: the windows set aside ``dropped`` (K, 2) (target index, window
    index), their ``exclusions``, the starting coefficients ``coef`` (B, n_coef, 3) ECEF m (None:
    no plot left) and the number of ``plots``."""

    dropped: np.ndarray
    exclusions: tuple[Exclusion, ...]
    coef: np.ndarray | None
    plots: int


@dataclass(frozen=True)
class ReduceTerms:
    """A partition's reduce pass at (x, coef): its sum of squares ``cost`` (plots, references,
    surface), its share ``U`` (n + 1, n + 1) and ``b_x`` (n + 1,) of the states' block and
    right-hand side, and per damping value asked its Schur-reduced ``S`` (n + 1, n + 1) and ``r``
    (n + 1,) (module docstring)."""

    cost: float
    U: np.ndarray
    b_x: np.ndarray
    S: list[np.ndarray]
    r: list[np.ndarray]


@dataclass(frozen=True)
class StepTerms:
    """A partition's step pass: the coefficients' step ``dc`` (B, n_coef, 3) ECEF m, ``b_dot`` (sum
    dc . b_c) and ``damp`` (sum diag(V) dc^2) of the predicted reduction, and the sum of squares
    ``cost`` at the trial point (x + dx, coef + dc)."""

    dc: np.ndarray
    b_dot: float
    damp: float
    cost: float


@dataclass(frozen=True)
class FinalTerms:
    """A partition's final pass at the solution: its reduce terms at lam = 0 (``terms``), its
    chi-square ``parts`` {name: (sum of squares, values)}, the coefficients used ``n_coef``, the
    windows ``singular`` there, the plots seen ``outside`` their navigation and their
    ``exclusions``, and the windows those would leave ``empty``."""

    terms: ReduceTerms
    parts: dict[str, tuple[float, int]]
    n_coef: int
    singular: int
    outside: int
    exclusions: tuple[Exclusion, ...]
    empty: int


#: The spill files of a partition's points: the current point (reduce pass) and the latest trial
#: (step pass), which is the next current point when the step is accepted.
_SLOTS = ("point", "trial")


def _point_digest(x: np.ndarray, coef: np.ndarray) -> str:
    return spill.digest(x.tobytes(), coef.tobytes(), str(coef.shape))


def _point(
    task: PartitionTask,
    entry: PartitionEntry,
    x: np.ndarray,
    coef: np.ndarray,
    with_normal: bool = True,
    with_ev: bool = False,
) -> PointTerms:
    """The terms at (x, coef), computed as asked (the latest two points are kept in the entry; the
    normal equations and cost of the latest one on disk too)."""
    key = (x.tobytes(), coef.tobytes())
    points = entry.points
    pt = points.get(key)
    if pt is None:
        pt = PointTerms()
        points[key] = pt
        while len(points) > 2:
            points.pop(next(iter(points)))
    design = entry.design
    if with_normal and pt.normal is None and task.spill is not None and not with_ev:
        digest = _point_digest(x, coef)
        for slot in _SLOTS:
            found = spill.load(task.spill, f"{task.spill_name}-{slot}", digest)
            if found is not None:
                pt.normal, pt.cost, pt.reduced = found["normal"], found["cost"], found["reduced"]
                break
    if pt.evaluation is None and (with_ev or pt.cost is None or (with_normal and pt.normal is None)):
        pt.evaluation = evaluate(design, x, coef)
        pt.cost = pt.evaluation.cost
    if with_normal and pt.normal is None:
        assert pt.evaluation is not None
        pt.normal = normal_equations(design, pt.evaluation)
    return pt


def _spill_point(
    task: PartitionTask, x: np.ndarray, coef: np.ndarray, pt: PointTerms, slot: str = "point"
) -> None:
    """Write a point's normal equations, cost and latest reduction to the disk cache (if the task has one)."""
    if task.spill is not None:
        spill.save(
            task.spill,
            f"{task.spill_name}-{slot}",
            {"normal": pt.normal, "cost": pt.cost, "reduced": pt.reduced},
            _point_digest(x, coef),
        )


def _reduced(entry: PartitionEntry, pt: PointTerms, lam: float) -> Reduced:
    red = pt.reduced.get(lam)
    if red is None:
        normal = pt.normal
        assert normal is not None
        red = reduce(entry.design.blocks, replace(normal, U=np.zeros_like(normal.U)), lam)
        pt.reduced = {lam: red}
    return red


def setup_pass(task: PartitionTask, x0: np.ndarray) -> SetupFound | None:
    """The windows whose position their plots do not determine (as determined_design finds them,
    with the archive's windows) and the starting coefficients at states ``x0`` (n,); None: no plot.
    The partition's design and its normal equations at the start go to the task's caches."""
    dropped = [task.dropped]
    exclusions: list[Exclusion] = []
    while True:
        task_k = replace(task, dropped=np.concatenate(dropped))
        problem = partition_problem(task_k)
        if problem is None:
            return None if not exclusions else SetupFound(task_k.dropped, tuple(exclusions), None, 0)
        design = partition_design(task_k, problem)
        coef = initial_coefficients(design, x0)
        ev = evaluate(design, x0, coef)
        normal = normal_equations(design, ev)
        bad = singular_blocks(design, normal)
        if bad.size == 0:
            if task.cache > 0 or task.spill is not None:
                entry = new_entry(problem, design)
                if task.spill is not None:
                    spill_entry(task_k, entry, problem)
                pt = PointTerms(ev, ev.cost, normal)
                entry.points[(x0.tobytes(), coef.tobytes())] = pt
                _spill_point(task_k, x0, coef, pt)
                keep_entry(task_k, entry)
            return SetupFound(task_k.dropped, tuple(exclusions), coef, problem.n_plots)
        blk = design.blocks
        first = blk.order[blk.block_start[bad]]
        w = window_index(task.plan, problem.target[first], problem.time[first])[0]
        dropped.append(np.stack([problem.target[first], w], axis=1))
        exclusions += singular_exclusions(problem, design, bad)[1]


def _entry(task: PartitionTask) -> PartitionEntry:
    entry = partition_entry(task)
    if entry is None:  # a task is made only for a partition whose setup pass found plots
        raise ValueError(f"partition {task.index} of the archive has no plot left")
    return entry


def reduce_pass(task: PartitionTask, x: np.ndarray, coef: np.ndarray, lams: tuple) -> ReduceTerms:
    """The partition's :class:`ReduceTerms` at (x, coef) for the damping values ``lams``."""
    entry = _entry(task)
    pt = _point(task, entry, x, coef)
    known = set(pt.reduced)
    out = _reduce_terms(entry, pt, lams)
    if set(pt.reduced) != known:
        _spill_point(task, x, coef, pt)
    return out


def _reduce_terms(entry: PartitionEntry, pt: PointTerms, lams: tuple) -> ReduceTerms:
    """The reduce pass's result: copies, so that the caller, who keeps every partition's, does not
    keep alive the buffer of a whole spill file the arrays may view."""
    normal = pt.normal
    assert normal is not None and pt.cost is not None
    reds = [_reduced(entry, pt, lam) for lam in lams]
    return ReduceTerms(
        pt.cost, normal.U.copy(), normal.b_x.copy(), [r.S.copy() for r in reds], [r.r.copy() for r in reds]
    )


def step_pass(task: PartitionTask, x: np.ndarray, coef: np.ndarray, dx: np.ndarray, lam: float) -> StepTerms:
    """The damped step's coefficients for states step ``dx`` (n + 1,; sink last) and the trial
    (:class:`StepTerms`)."""
    entry = _entry(task)
    pt = _point(task, entry, x, coef)
    blk, normal = entry.design.blocks, pt.normal
    assert normal is not None
    red = _reduced(entry, pt, lam)
    dc = red.y - np.matmul(red.Y, dx[blk.local_state][:, :, None])[:, :, 0]
    dc = dc * np.repeat(blk.coef_mask, 3, axis=1)
    q = dc.shape[1]
    diag_V = normal.V[:, np.arange(q), np.arange(q)]
    dc3 = dc.reshape(blk.n_blocks, blk.n_coef, 3)
    # with the disk cache, the trial's normal equations are kept there: an accepted step's next
    # reduce pass then reads them instead of evaluating the trial point again
    x_trial, coef_trial = x + dx[:-1], coef + dc3
    trial = _point(task, entry, x_trial, coef_trial, with_normal=task.spill is not None)
    _spill_point(task, x_trial, coef_trial, trial, "trial")
    assert trial.cost is not None
    return StepTerms(dc3, float(np.sum(dc * normal.b_c)), float(np.sum(diag_V * dc**2)), trial.cost)


def final_pass(task: PartitionTask, x: np.ndarray, coef: np.ndarray) -> FinalTerms:
    """At the solution: the reduce terms at lam = 0 and what the solver checks there (:class:`FinalTerms`)."""
    entry = _entry(task)
    plots, design = entry.plots, entry.design
    pt = _point(task, entry, x, coef, with_ev=True)
    assert pt.evaluation is not None and pt.normal is not None
    terms = _reduce_terms(entry, pt, (0.0,))
    outside, weight = outside_weight(design, x)
    empty = design.block_sums(weight.any(axis=1).astype(np.int64)) == 0
    return FinalTerms(
        terms,
        chi_square_parts(replace(design, weight=weight), pt.evaluation),
        int(design.blocks.coef_mask.sum()),
        int(singular_blocks(design, pt.normal).size),
        int(outside.sum()),
        outside_exclusions(plots, outside),
        int(empty.sum()),
    )
