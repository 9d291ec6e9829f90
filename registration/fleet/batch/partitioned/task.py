"""One partition of an archive (:mod:`registration.fleet.batch.partitioned.plan`) as the passes of
the partitioned solver take it (:mod:`registration.fleet.batch.partitioned.partition_passes`): its
task, its problem read from the source, its design, and the caches that keep them between passes
(module docstring of partition_passes).
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from registration.fleet.batch.blocks import make_blocks
from registration.fleet.batch.design import Design, make_design
from registration.fleet.batch.normal import Evaluation, Normal
from registration.fleet.batch.partitioned import spill
from registration.fleet.batch.partitioned.plan import ArchivePlan, partition_of, window_index
from registration.fleet.batch.schur import Reduced
from registration.fleet.batch.solver import BatchOptions
from registration.fleet.data.known_targets import read_references, read_surface
from registration.fleet.data.layout import StateLayout, make_layout
from registration.fleet.data.navigation import navigation_at, platform_navigation
from registration.fleet.data.plot_rows import read_plots
from registration.fleet.data.problem import FleetProblem
from registration.fleet.data.sensor_specs import read_platforms, read_sensors
from registration.fleet.data.tables import index_of, read_table

__all__ = [
    "PartitionEntry",
    "PartitionPlots",
    "PartitionTask",
    "PointTerms",
    "archive_layout",
    "archive_sensors",
    "keep_entry",
    "new_entry",
    "partition_design",
    "partition_entry",
    "partition_problem",
    "read_source",
    "spill_entry",
    "spilled_problem",
]


@dataclass(frozen=True)
class PartitionTask:
    """Partition ``index`` of ``plan`` read from ``source``, windows ``dropped`` ((K, 2) target index
    and window index) set aside; ``cache``: partitions whose design this process keeps in memory;
    ``spill``: folder of the disk cache (None: none; module docstring)."""

    source: Any  # a partition source (module docstring of plan)
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
        return f"p{self.index}-{spill.digest(*self.key)}"


_CACHE: OrderedDict[tuple, PartitionEntry | None] = OrderedDict()


def read_source(source, what: str, read, *args):
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
        src.name("plots"), read_source(src, "plots", src.read_plots, lo, hi), ("time", "sensor", "target")
    )
    cols = read_plots(plots_t, specs)
    target = index_of(cols.target, plan.target_ids)
    keep = target >= 0
    keep[keep] = partition_of(plan, target[keep], cols.time[keep]) == k
    if task.dropped.size:
        w = window_index(plan, np.maximum(target, 0), cols.time)[0]
        gone = np.isin(target * (1 << 32) + w, task.dropped[:, 0] * (1 << 32) + task.dropped[:, 1])
        keep &= ~gone
    rows = np.flatnonzero(keep)
    if rows.size == 0:
        return None
    sensor, time = cols.sensor[rows], cols.time[rows]
    refs = read_references(read_source(src, "reference", src.read_references, lo, hi), plan.all_targets)
    ref_target = index_of(refs.target, plan.target_ids)
    ref_keep = ref_target >= 0
    ref_keep[ref_keep] = partition_of(plan, ref_target[ref_keep], refs.time[ref_keep]) == k
    refs = refs.subset(ref_keep)
    nav_t = read_table(
        src.name("navigation"),
        read_source(src, "navigation", src.read_navigation, plan.nav_ranges[k]),
        ("platform",),
    )
    tracks = platform_navigation(nav_t, platform_ids)

    def describe(i: int) -> str:
        return f"plot at {time[i]:g} s of sensor {str(specs.ids[sensor[i]])!r}"

    nav = navigation_at(tracks, platform_ids, specs.platform[sensor], time, describe)
    layout = make_layout(
        platform_ids,
        platform_priors,
        specs.ids,
        specs.channels,
        specs.prior,
        specs.extended_prior,
        specs.eccentricity_prior,
        specs.channel_of,
        plan.height_offset_prior,
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
        target=target[rows],
        meas=cols.meas[rows],
        mask=cols.mask[rows],
        nav=nav,
        row=rows,
        n_input_plots=int(cols.time.shape[0]),
        references=refs,
        ref_target=index_of(refs.target, plan.target_ids),
        tracks=tracks,
        surface=read_surface(getattr(src, "targets", None)),
    )


def archive_layout(source, height_offset_prior: float | None = None) -> StateLayout:
    """The state layout of a source's sensors and platforms tables (as build_problem lays it out),
    with the flight levels' common height offset when ``height_offset_prior`` (m) is given
    (:attr:`ArchivePlan.height_offset_prior`)."""
    return archive_sensors(source, height_offset_prior)[0]


def archive_sensors(source, height_offset_prior: float | None = None) -> tuple:
    """(layout, platform ids, sensor ids, each sensor's platform index) of a source's sensors and
    platforms tables, as build_problem reads them; the layout with the flight levels' common height
    offset when ``height_offset_prior`` (m) is given (:attr:`ArchivePlan.height_offset_prior`)."""
    sensors_t = read_table("sensors", source.sensors, ("sensor", "platform"))
    platform_ids, platform_priors = read_platforms(source.platforms, sensors_t.ids("platform"))
    specs = read_sensors(sensors_t, platform_ids)
    layout = make_layout(
        platform_ids,
        platform_priors,
        specs.ids,
        specs.channels,
        specs.prior,
        specs.extended_prior,
        specs.eccentricity_prior,
        specs.channel_of,
        height_offset_prior,
    )
    return layout, tuple(platform_ids), tuple(specs.ids), specs.platform


def partition_design(task: PartitionTask, problem: FleetProblem) -> Design:
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
class PartitionPlots:
    """What the passes need of a partition's problem once its design is built (problem order)."""

    target: np.ndarray  # (N,) index into target_ids
    time: np.ndarray  # (N,) reported time, s
    target_ids: tuple[str, ...]


@dataclass
class PointTerms:
    """A partition's terms at one point (x, coef), filled as the passes ask: its evaluation, its sum
    of squares (plots, references, surface; no priors), its normal equations and its latest
    reduction per damping ``lam``."""

    evaluation: Evaluation | None = None
    cost: float | None = None
    normal: Normal | None = None
    reduced: dict[float, Reduced] = field(default_factory=dict)


@dataclass
class PartitionEntry:
    """A partition's plots, its design (without priors) and its terms at its latest points (up to
    two (x, coef), by their bytes)."""

    plots: PartitionPlots
    design: Design
    points: dict[tuple[bytes, bytes], PointTerms] = field(default_factory=dict)


def new_entry(problem: FleetProblem, design: Design) -> PartitionEntry:
    return PartitionEntry(PartitionPlots(problem.target, problem.time, problem.target_ids), design)


def keep_entry(task: PartitionTask, entry: PartitionEntry | None) -> None:
    """Keep ``entry`` in this process's cache when the task asks for it."""
    if task.cache > 0:
        _CACHE[task.key] = entry
        _CACHE.move_to_end(task.key)
        while len(_CACHE) > task.cache:
            _CACHE.popitem(last=False)


def spill_entry(task: PartitionTask, entry: PartitionEntry, problem: FleetProblem | None = None) -> None:
    """Write the entry's design to the disk cache (without the evaluations it has cached) and, when
    given, the partition's problem (for the output pass: :func:`spilled_problem`)."""
    assert task.spill is not None
    design = replace(entry.design, seen_cache={})
    spill.save(task.spill, task.spill_name, {"plots": entry.plots, "design": design})
    if problem is not None:
        spill.save(task.spill, f"{task.spill_name}-problem", problem)


def spilled_problem(task: PartitionTask) -> tuple[FleetProblem, Design] | None:
    """The partition's problem and design from the disk cache (None: not there, or no cache)."""
    if task.spill is None:
        return None
    problem = spill.load(task.spill, f"{task.spill_name}-problem")
    found = spill.load(task.spill, task.spill_name) if problem is not None else None
    return None if found is None else (problem, found["design"])


def partition_entry(task: PartitionTask) -> PartitionEntry | None:
    """The partition's entry from the caches, or built (and cached as asked); None: no plot."""
    hit = _CACHE.get(task.key)
    if hit is not None:
        _CACHE.move_to_end(task.key)
        return hit
    entry = None
    if task.spill is not None:
        found = spill.load(task.spill, task.spill_name)
        if found is not None:
            entry = PartitionEntry(found["plots"], found["design"])
    if entry is None:
        problem = partition_problem(task)
        if problem is not None:
            entry = new_entry(problem, partition_design(task, problem))
            if task.spill is not None:
                spill_entry(task, entry)
    keep_entry(task, entry)
    return entry
