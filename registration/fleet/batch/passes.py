"""The work on one partition of an archive (:mod:`registration.fleet.batch.partitions`) in one pass of
the partitioned solver (:mod:`registration.fleet.batch.partitioned`): its problem and design, and
per pass its sums at the current estimate.

Each function takes one :class:`PartitionTask` and the current states and coefficients and
returns plain arrays; it is pure (its result depends on its arguments only), so a pass can run in
this process or on Dask workers, and a lost worker's task run again gives the same result. Two
caches save time and change no result:

* in memory, per process, the design and latest evaluations of ``task.cache`` partitions (0: none);
* on local disk, in the folder ``task.spill`` (None: none; :mod:`registration.fleet.batch.spill`),
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

from collections import OrderedDict
from dataclasses import dataclass, replace

import numpy as np

from registration.fleet.batch import spill as _spill
from registration.fleet.batch.blocks import make_blocks
from registration.fleet.batch.initial import initial_coefficients
from registration.fleet.batch.normal import evaluate, make_design, normal_equations
from registration.fleet.batch.partitions import ArchivePlan, partition_of, window_index
from registration.fleet.batch.residuals import chi_square_parts
from registration.fleet.batch.schur import reduce
from registration.fleet.batch.solver import BatchOptions, outside_when_seen, singular_blocks
from registration.fleet.data.known_targets import read_references, read_surface
from registration.fleet.data.layout import StateLayout, make_layout
from registration.fleet.data.navigation import navigation_at, platform_navigation
from registration.fleet.data.plot_rows import read_plots
from registration.fleet.data.problem import Exclusion, FleetProblem
from registration.fleet.data.sensor_specs import read_platforms, read_sensors
from registration.fleet.data.tables import index_of, read_table

__all__ = [
    "PartitionTask",
    "archive_layout",
    "final_pass",
    "partition_problem",
    "reduce_pass",
    "setup_pass",
    "step_pass",
]


@dataclass(frozen=True)
class PartitionTask:
    """Partition ``index`` of ``plan`` read from ``source``, windows ``dropped`` ((K, 2) target index
    and window index) set aside; ``cache``: partitions whose design this process keeps in memory;
    ``spill``: folder of the disk cache (None: none; module docstring)."""

    source: object
    plan: ArchivePlan
    index: int
    options: BatchOptions
    dropped: np.ndarray
    cache: int = 0
    spill: str | None = None

    @property
    def key(self) -> tuple:
        return (self.plan.token, self.index, self.dropped.tobytes(), self.options)

    @property
    def spill_name(self) -> str:
        """The name of this partition's design file in the spill folder."""
        return f"p{self.index}-{_spill.digest(*self.key)}"


_CACHE: OrderedDict = OrderedDict()


def _read(source, what: str, read, *args):
    """``read(*args)``; a failure becomes a one-line ValueError naming the file."""
    try:
        return read(*args)
    except ValueError:
        raise
    except Exception as exc:  # pyarrow and OS errors of many kinds
        text = " ".join(str(exc).split()) or type(exc).__name__
        raise ValueError(f"{source.name(what)}: cannot be read ({text})") from exc


def partition_problem(task: PartitionTask) -> FleetProblem | None:
    """The partition's plots as a :class:`FleetProblem` over the archive's targets (module docstring of
    partitions), with the checks of build_problem; None when it holds no plot."""
    src, plan, k = task.source, task.plan, task.index
    lo, hi = plan.plot_ranges[k]
    if not np.isfinite(lo):
        return None
    sensors_t = read_table("sensors", src.sensors, ("sensor", "platform"))
    platform_ids, platform_priors = read_platforms(src.platforms, sensors_t.ids("platform"))
    specs = read_sensors(sensors_t, platform_ids)
    plots_t = read_table(
        src.name("plots"), _read(src, "plots", src.read_plots, lo, hi), ("time", "sensor", "target")
    )
    cols = read_plots(plots_t, specs)
    target = index_of(cols.target, plan.target_ids)
    keep = target >= 0
    keep[keep] = partition_of(plan, target[keep], cols.time[keep]) == k
    if task.dropped.size:
        w = window_index(plan, np.maximum(target, 0), cols.time)[0]
        gone = np.isin(target * (1 << 32) + w, task.dropped[:, 0] * (1 << 32) + task.dropped[:, 1])
        keep &= ~gone
    keep = np.flatnonzero(keep)
    if keep.size == 0:
        return None
    sensor, time = cols.sensor[keep], cols.time[keep]
    refs = read_references(_read(src, "reference", src.read_references, lo, hi), plan.all_targets)
    ref_target = index_of(refs.target, plan.target_ids)
    ref_keep = ref_target >= 0
    ref_keep[ref_keep] = partition_of(plan, ref_target[ref_keep], refs.time[ref_keep]) == k
    refs = refs.subset(ref_keep)
    nav_t = read_table(
        src.name("navigation"),
        _read(src, "navigation", src.read_navigation, plan.nav_ranges[k]),
        ("platform",),
    )
    tracks = platform_navigation(nav_t, platform_ids)

    def describe(i: int) -> str:
        return f"plot at {time[i]:g} s of sensor {str(specs.ids[sensor[i]])!r}"

    nav = navigation_at(tracks, platform_ids, specs.platform[sensor], time, describe)
    layout = make_layout(
        platform_ids, platform_priors, specs.ids, specs.channels, specs.prior, specs.extended_prior
    )
    return FleetProblem(
        platform_ids=tuple(platform_ids),
        sensor_ids=specs.ids,
        target_ids=plan.target_ids,
        sensor_platform=specs.platform,
        sensor_sigma=specs.sigma,
        sensor_lever=specs.lever,
        layout=layout,
        time=time,
        sensor=sensor,
        target=target[keep],
        meas=cols.meas[keep],
        mask=cols.mask[keep],
        nav=nav,
        row=keep,
        n_input_plots=int(cols.time.shape[0]),
        references=refs,
        ref_target=index_of(refs.target, plan.target_ids),
        tracks=tracks,
        surface=read_surface(getattr(src, "targets", None)),
    )


def archive_layout(source) -> StateLayout:
    """The state layout of a source's sensors and platforms tables (as build_problem lays it out)."""
    return archive_sensors(source)[0]


def archive_sensors(source) -> tuple:
    """(layout, platform ids, sensor ids, each sensor's platform index) of a source's sensors and
    platforms tables, as build_problem reads them."""
    sensors_t = read_table("sensors", source.sensors, ("sensor", "platform"))
    platform_ids, platform_priors = read_platforms(source.platforms, sensors_t.ids("platform"))
    specs = read_sensors(sensors_t, platform_ids)
    layout = make_layout(
        platform_ids, platform_priors, specs.ids, specs.channels, specs.prior, specs.extended_prior
    )
    return layout, tuple(platform_ids), tuple(specs.ids), specs.platform


def _design(task: PartitionTask, problem: FleetProblem):
    """The partition's design without priors; navigation and measurements column-major, as the
    generated functions take them column by column (the same numbers, without a copy per evaluation)."""
    design = make_design(
        problem, make_blocks(problem, task.options.window_s, task.options.degree, task.plan.span)
    )
    return replace(
        design,
        prior_weight=np.zeros_like(design.prior_weight),
        nav=np.asfortranarray(design.nav),
        meas=np.asfortranarray(design.meas),
    )


@dataclass(frozen=True)
class _Plots:
    """What the passes need of a partition's problem once its design is built (problem order)."""

    target: np.ndarray  # (N,) index into target_ids
    time: np.ndarray  # (N,) reported time, s
    target_ids: tuple


def _new_entry(problem: FleetProblem, design) -> dict:
    return {
        "problem": _Plots(problem.target, problem.time, problem.target_ids),
        "design": design,
        "points": {},
    }


def _keep(task: PartitionTask, entry: dict) -> None:
    """Keep ``entry`` in this process's cache when the task asks for it."""
    if task.cache > 0:
        _CACHE[task.key] = entry
        _CACHE.move_to_end(task.key)
        while len(_CACHE) > task.cache:
            _CACHE.popitem(last=False)


def _spill_entry(task: PartitionTask, entry: dict) -> None:
    """Write the entry's design to the disk cache (without the evaluations it has cached)."""
    design = replace(entry["design"], seen_cache={})
    _spill.save(task.spill, task.spill_name, {"problem": entry["problem"], "design": design})


def _entry(task: PartitionTask) -> dict | None:
    """The partition's {problem (_Plots), design, points} from the caches, or built (and cached as asked)."""
    hit = _CACHE.get(task.key)
    if hit is not None:
        _CACHE.move_to_end(task.key)
        return hit
    entry = None
    if task.spill is not None:
        found = _spill.load(task.spill, task.spill_name)
        if found is not None:
            entry = {**found, "points": {}}
    if entry is None:
        problem = partition_problem(task)
        if problem is not None:
            entry = _new_entry(problem, _design(task, problem))
            if task.spill is not None:
                _spill_entry(task, entry)
    _keep(task, entry)
    return entry


#: The spill files of a partition's points: the current point (reduce pass) and the latest trial
#: (step pass), which is the next current point when the step is accepted.
_SLOTS = ("point", "trial")


def _point_digest(x: np.ndarray, coef: np.ndarray) -> str:
    return _spill.digest(x.tobytes(), coef.tobytes(), str(coef.shape))


def _point(
    task: PartitionTask,
    entry: dict,
    x: np.ndarray,
    coef: np.ndarray,
    with_normal: bool = True,
    with_ev: bool = False,
) -> dict:
    """{ev, cost, normal, reduced: {lam: Reduced}} at (x, coef), computed as asked (the latest two
    points are kept in the entry; the normal equations and cost of the latest one on disk too)."""
    key = (x.tobytes(), coef.tobytes())
    points = entry["points"]
    pt = points.get(key)
    if pt is None:
        pt = {"ev": None, "cost": None, "normal": None, "reduced": {}}
        points[key] = pt
        while len(points) > 2:
            points.pop(next(iter(points)))
    design = entry["design"]
    if with_normal and pt["normal"] is None and task.spill is not None and not with_ev:
        digest = _point_digest(x, coef)
        for slot in _SLOTS:
            found = _spill.load(task.spill, f"{task.spill_name}-{slot}", digest)
            if found is not None:
                pt["normal"], pt["cost"], pt["reduced"] = found["normal"], found["cost"], found["reduced"]
                break
    if pt["ev"] is None and (with_ev or pt["cost"] is None or (with_normal and pt["normal"] is None)):
        pt["ev"] = evaluate(design, x, coef)
        pt["cost"] = pt["ev"].cost
    if with_normal and pt["normal"] is None:
        pt["normal"] = normal_equations(design, pt["ev"])
    return pt


def _spill_point(task: PartitionTask, x: np.ndarray, coef: np.ndarray, pt: dict, slot: str = "point") -> None:
    """Write a point's normal equations, cost and latest reduction to the disk cache (if the task has one)."""
    if task.spill is not None:
        _spill.save(
            task.spill,
            f"{task.spill_name}-{slot}",
            {"normal": pt["normal"], "cost": pt["cost"], "reduced": pt["reduced"]},
            _point_digest(x, coef),
        )


def _reduced(entry: dict, pt: dict, lam: float):
    red = pt["reduced"].get(lam)
    if red is None:
        normal = pt["normal"]
        red = reduce(entry["design"].blocks, replace(normal, U=np.zeros_like(normal.U)), lam)
        pt["reduced"] = {lam: red}
    return red


def setup_pass(task: PartitionTask, x0: np.ndarray) -> dict | None:
    """The windows whose position their plots do not determine (as determined_design finds them,
    with the archive's windows) and the starting coefficients at states ``x0`` (n,): {dropped
    ((K, 2) target and window index), exclusions, coef (B, n_coef, 3), plots}; None: no plot.
    The partition's design and its normal equations at the start go to the task's caches."""
    dropped = [task.dropped]
    exclusions = []
    while True:
        task_k = replace(task, dropped=np.concatenate(dropped))
        problem = partition_problem(task_k)
        if problem is None:
            return (
                None
                if not exclusions
                else {"dropped": task_k.dropped, "exclusions": exclusions, "coef": None, "plots": 0}
            )
        design = _design(task_k, problem)
        coef = initial_coefficients(design, x0)
        ev = evaluate(design, x0, coef)
        normal = normal_equations(design, ev)
        bad = singular_blocks(design, normal)
        if bad.size == 0:
            if task.cache > 0 or task.spill is not None:
                entry = _new_entry(problem, design)
                if task.spill is not None:
                    _spill_entry(task_k, entry)
                pt = {"ev": ev, "cost": ev.cost, "normal": normal, "reduced": {}}
                entry["points"][(x0.tobytes(), coef.tobytes())] = pt
                _spill_point(task_k, x0, coef, pt)
                _keep(task_k, entry)
            return {
                "dropped": task_k.dropped,
                "exclusions": exclusions,
                "coef": coef,
                "plots": problem.n_plots,
            }
        blk = design.blocks
        first = blk.order[blk.block_start[bad]]
        w = window_index(task.plan, problem.target[first], problem.time[first])[0]
        dropped.append(np.stack([problem.target[first], w], axis=1))
        for b in bad:
            plots = blk.order[blk.block == b]
            t = problem.time[plots]
            sensors = sorted({problem.sensor_ids[s] for s in problem.sensor[plots]})
            exclusions.append(
                Exclusion(
                    problem.target_ids[blk.block_target[b]],
                    "singular geometry: its position is "
                    f"not determined by the plots of {', '.join(sensors)} in this window",
                    int(plots.size),
                    float(t.min()),
                    float(t.max()),
                )
            )


def reduce_pass(task: PartitionTask, x: np.ndarray, coef: np.ndarray, lams: tuple) -> dict:
    """At (x, coef): {cost (plots and references), U (n+1, n+1), b_x (n+1,), S: [S_p per lam], r: [r_p per lam]}."""
    entry = _entry(task)
    pt = _point(task, entry, x, coef)
    known = set(pt["reduced"])
    out = _reduce_terms(entry, pt, lams)
    if set(pt["reduced"]) != known:
        _spill_point(task, x, coef, pt)
    return out


def _reduce_terms(entry: dict, pt: dict, lams: tuple) -> dict:
    """The reduce pass's result: copies, so that the caller, who keeps every partition's, does not
    keep alive the buffer of a whole spill file the arrays may view."""
    normal = pt["normal"]
    reds = [_reduced(entry, pt, lam) for lam in lams]
    return {
        "cost": pt["cost"],
        "U": normal.U.copy(),
        "b_x": normal.b_x.copy(),
        "S": [r.S.copy() for r in reds],
        "r": [r.r.copy() for r in reds],
    }


def step_pass(task: PartitionTask, x: np.ndarray, coef: np.ndarray, dx: np.ndarray, lam: float) -> dict:
    """The damped step's coefficients for states step ``dx`` (n + 1,; sink last) and the trial:
    {dc (B, n_coef, 3), b_dot (sum dc . b_c), damp (sum diag(V) dc^2), cost (at x + dx, coef + dc)}."""
    entry = _entry(task)
    pt = _point(task, entry, x, coef)
    blk, normal = entry["design"].blocks, pt["normal"]
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
    return {
        "dc": dc3,
        "b_dot": float(np.sum(dc * normal.b_c)),
        "damp": float(np.sum(diag_V * dc**2)),
        "cost": trial["cost"],
    }


def final_pass(task: PartitionTask, x: np.ndarray, coef: np.ndarray) -> dict:
    """At the solution: reduce_pass at lam = 0 and {parts (chi_square_parts), n_coef (coefficients
    used), singular (windows undetermined there), outside (plots seen outside their navigation),
    exclusions (of those plots), empty (windows those would empty)}."""
    entry = _entry(task)
    problem, design = entry["problem"], entry["design"]
    pt = _point(task, entry, x, coef, with_ev=True)
    out = _reduce_terms(entry, pt, (0.0,))
    outside = outside_when_seen(design, x)
    rows = np.zeros(design.weight.shape[0], dtype=bool)
    rows[design.slot] = outside[design.blocks.order]
    weight = np.where(rows[:, None], 0.0, design.weight)
    empty = np.add.reduceat(weight.any(axis=1).astype(np.int64), design.block_start) == 0
    exclusions = []
    for k in np.unique(problem.target[outside]):
        sel = outside & (problem.target == k)
        t = problem.time[sel]
        exclusions.append(
            Exclusion(
                problem.target_ids[k],
                "seen outside its platform's navigation once its "
                "sensor's time bias is applied (reported time - time bias)",
                int(sel.sum()),
                float(t.min()),
                float(t.max()),
            )
        )
    out.update(
        parts=chi_square_parts(replace(design, weight=weight), pt["ev"]),
        n_coef=int(design.blocks.coef_mask.sum()),
        singular=int(singular_blocks(design, pt["normal"]).size),
        outside=int(outside.sum()),
        exclusions=exclusions,
        empty=int(empty.sum()),
    )
    return out
