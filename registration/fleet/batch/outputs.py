"""The outputs of a partitioned solve (:mod:`registration.fleet.batch.partitioned`,
docs/howto/register-an-archive.md),
made by one more pass over the partitions at the solution: :func:`archive_outputs`.

Each partition, with the states ``x``, its windows' coefficients and the states' covariance ``P``,
evaluates (a pure function, :func:`output_pass`, run by ``run_pass`` here or on Dask workers; its
problem and design read from the solve's spill folder when the solve kept it, ``keep_spill``, else
read from the source and built again, the same bits either way):

* its **fused targets**, as :func:`registration.fleet.batch.covariance.fused_targets` makes them for
  ``solve_batch``: per measured instant of each target (time corrected by any time bias) the
  fitted position (ECEF m), its covariance (m^2; coefficients' ``V_b^-1 + Y_b P Y_b^T``) and the
  plots at that instant, sorted by target then time. They are written as one Parquet file per
  partition, ``part-00000.parquet``, ... (columns :data:`FUSED_COLUMNS`) into a folder, written
  under a temporary name and renamed, so a task run again after a lost worker writes the same file;
  or (``parts=None``) returned, for the caller to write (a remote cluster without a shared disk).
* the **sums of its whitened residuals** ``(measured - predicted) / sigma``: per sensor and channel
  (range, bearing, elevation) their count, sum and sum of squares; per target and per reference
  target their sum of squares and count; a histogram of each channel (clipped to +-HIST_LIMIT);
  the chi-square parts of :func:`~registration.fleet.batch.residuals.chi_square_parts` (plots seen
  outside their navigation under a time bias left out, as the solver's final pass does).
* a **sample** of its plots for figures: every ``every``-th plot of the partition (in file order),
  with its time, sensor, target, residuals and (with a range) its position as measured and as
  corrected (latitude, longitude, rad).

The caller adds the sums in partition order, so the outputs do not depend on where the partitions
ran or on the number of workers.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, replace
from types import SimpleNamespace

import numpy as np

from registration.core.frames import ecef2geodetic
from registration.fleet.batch.covariance import fused_targets
from registration.fleet.batch.normal import evaluate, normal_equations
from registration.fleet.batch.partitioned.equations import run_pass
from registration.fleet.batch.partitioned.task import (
    PartitionTask,
    partition_design,
    partition_problem,
    spilled_problem,
)
from registration.fleet.batch.residuals import chi_square_parts
from registration.fleet.batch.schur import reduce
from registration.fleet.batch.set_aside import outside_weight
from registration.fleet.corrected import corrected_plot_positions

__all__ = [
    "CHANNELS",
    "FUSED_COLUMNS",
    "HIST_BINS",
    "HIST_LIMIT",
    "SAMPLE_PLOTS",
    "ArchiveOutputs",
    "PartitionOutputs",
    "ResidualSums",
    "archive_outputs",
    "output_pass",
    "part_name",
    "write_part",
]

#: The channels of a plot, in the order of the residuals' columns.
CHANNELS = ("range", "bearing", "elevation")
#: The columns of a fused targets part file.
FUSED_COLUMNS = (
    "target",
    "time_s",
    "x_m",
    "y_m",
    "z_m",
    "cov_xx_m2",
    "cov_xy_m2",
    "cov_xz_m2",
    "cov_yy_m2",
    "cov_yz_m2",
    "cov_zz_m2",
    "n_plots",
)
#: The most plots the figures' sample holds.
SAMPLE_PLOTS = 20_000
#: The residual histogram: HIST_BINS bins over [-HIST_LIMIT, HIST_LIMIT] (values clipped to it).
HIST_BINS, HIST_LIMIT = 60, 6.0
_COV = ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))


def part_name(k: int) -> str:
    """The file name of the ``k``-th part (the partitions with plots, counted in order)."""
    return f"part-{k:05d}.parquet"


def write_part(folder, k: int, table: dict) -> None:
    """Write ``table`` (FUSED_COLUMNS) as part ``k`` of ``folder``: a temporary file renamed, so a
    part written twice (a task run again) is whole either time."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    path = os.path.join(str(folder), part_name(k))
    tmp = f"{path}.{os.getpid()}.tmp"
    pq.write_table(pa.table({c: table[c] for c in FUSED_COLUMNS}), tmp)
    os.replace(tmp, path)


def _fused_table(problem, design, x: np.ndarray, coef: np.ndarray, normal, P_sink: np.ndarray) -> dict:
    normal0 = replace(normal, U=np.zeros_like(normal.U))
    red = reduce(design.blocks, normal0, 0.0)
    fused = fused_targets(SimpleNamespace(design=design, problem=problem, x=x, coef=coef), red, P_sink)
    table = {"target": fused.target.astype(str), "time_s": fused.time}
    for j, axis in enumerate("xyz"):
        table[f"{axis}_m"] = fused.p_ecef[:, j]
    for (a, b), name in zip(_COV, FUSED_COLUMNS[5:11]):
        table[name] = fused.covariance[:, a, b]
    table["n_plots"] = fused.n_plots.astype(np.int64)
    return table


@dataclass(frozen=True)
class ResidualSums:
    """A partition's residual sums (S sensors, 3 channels: :data:`CHANNELS`): ``count`` (S, 3) values,
    ``total`` (S, 3) and ``squares`` (S, 3) sums of the whitened residuals and of their squares,
    ``hist`` (3, HIST_BINS) counts; ``by_target`` (target indices (K,), sums of squares (K,), values
    (K,)) and ``by_reference`` (reference target ids (K,), sums of squares (K,), values (K,))."""

    count: np.ndarray
    total: np.ndarray
    squares: np.ndarray
    hist: np.ndarray
    by_target: tuple[np.ndarray, np.ndarray, np.ndarray]
    by_reference: tuple[np.ndarray, np.ndarray, np.ndarray]


@dataclass(frozen=True)
class PartitionOutputs:
    """The output pass of one partition: its residual ``sums``, chi-square ``parts`` {name: (sum of
    squares, values)}, fused ``rows``, its ``sample`` of plots (columns), its ``sensor_ids`` and,
    when not written as a part, the ``fused`` table (columns)."""

    sums: ResidualSums
    parts: dict[str, tuple[float, int]]
    rows: int
    sample: dict[str, np.ndarray]
    sensor_ids: tuple[str, ...]
    fused: dict[str, np.ndarray] | None


def _sums(problem, design, ev, residual: np.ndarray) -> ResidualSums:
    """The residual sums of the partition (module docstring); ``residual`` (N, 3) per problem plot,
    NaN where not measured or left out."""
    S = len(problem.sensor_ids)
    given = np.isfinite(residual)
    r0 = np.where(given, residual, 0.0)
    count = np.zeros((S, 3), dtype=np.int64)
    total, squares = np.zeros((S, 3)), np.zeros((S, 3))
    for c in range(3):
        count[:, c] = np.bincount(problem.sensor, given[:, c], minlength=S).astype(np.int64)
        total[:, c] = np.bincount(problem.sensor, r0[:, c], minlength=S)
        squares[:, c] = np.bincount(problem.sensor, r0[:, c] ** 2, minlength=S)
    targets, inv = np.unique(problem.target, return_inverse=True)
    by_target = (targets, np.bincount(inv, np.sum(r0**2, axis=1)), np.bincount(inv, np.sum(given, axis=1)))
    refs = problem.references.target[design.blocks.ref_index].astype(str)
    ref_ids, ref_inv = np.unique(refs, return_inverse=True)
    e_ref = np.asarray(ev.e_ref, dtype=np.float64).reshape(-1, 3)
    by_reference = (
        ref_ids,
        np.bincount(ref_inv, np.sum(e_ref**2, axis=1), minlength=ref_ids.size),
        np.full(ref_ids.size, 3) * np.bincount(ref_inv, minlength=ref_ids.size),
    )
    hist = np.stack(
        [
            np.histogram(
                np.clip(residual[given[:, c], c], -HIST_LIMIT, HIST_LIMIT),
                HIST_BINS,
                (-HIST_LIMIT, HIST_LIMIT),
            )[0]
            for c in range(3)
        ]
    )
    return ResidualSums(count, total, squares, hist.astype(np.int64), by_target, by_reference)


def _sample(problem, x: np.ndarray, residual: np.ndarray, every: int) -> dict:
    """Every ``every``-th plot of the partition: time (s, reported), sensor, target (indices), residual
    (3,), and lat/lon (rad) as measured and corrected (NaN without a range)."""
    pick = np.arange(0, problem.n_plots, max(1, int(every)))
    out = {
        "time": problem.time[pick],
        "sensor": problem.sensor[pick],
        "target": problem.target[pick],
        "residual": residual[pick],
    }
    has_range = problem.mask[pick, 0]
    layout = problem.layout
    for name, states in (("measured", np.zeros(layout.n)), ("corrected", np.asarray(x, dtype=np.float64))):
        lat, lon, _ = ecef2geodetic(corrected_plot_positions(problem, states, pick)[0])
        out[f"{name}_lat"] = np.full(pick.size, np.nan)
        out[f"{name}_lon"] = np.full(pick.size, np.nan)
        out[f"{name}_lat"][has_range], out[f"{name}_lon"][has_range] = lat, lon
    return out


def output_pass(
    task: PartitionTask, x: np.ndarray, coef: np.ndarray, P_sink: np.ndarray, part: int, parts, every: int
) -> PartitionOutputs:
    """The outputs of one partition at the solution (module docstring); the fused table written as
    part ``part`` into the folder ``parts`` (None: returned). ``P_sink`` (n + 1, n + 1): the states'
    covariance, the sink's row and column zero."""
    spilled = spilled_problem(task)  # the solve's spill folder, when kept: nothing read or built
    if spilled is not None:
        problem, design = spilled
    else:
        built = partition_problem(task)
        if built is None:
            raise ValueError(f"partition {task.index} holds no plot at the solution but has coefficients")
        problem, design = built, partition_design(task, built)
    if design.blocks.n_blocks != coef.shape[0]:
        raise ValueError(
            f"partition {task.index}: {design.blocks.n_blocks} windows, but {coef.shape[0]} "
            "windows' coefficients: the partitions are not the solve's"
        )
    ev = evaluate(design, x, coef)
    normal = normal_equations(design, ev)
    weight = outside_weight(design, x)[1]
    residual = np.full((problem.n_plots, 3), np.nan)
    residual[design.blocks.order] = np.where(weight > 0, ev.e, np.nan)[design.slot]
    table = _fused_table(problem, design, x, coef, normal, P_sink)
    if parts is not None:
        write_part(parts, part, table)
    return PartitionOutputs(
        sums=_sums(problem, design, ev, residual),
        parts=chi_square_parts(replace(design, weight=weight), ev),
        rows=int(table["time_s"].size),
        sample=_sample(problem, x, residual, every),
        sensor_ids=tuple(problem.sensor_ids),
        fused=table if parts is None else None,
    )


@dataclass(kw_only=True)
class ArchiveOutputs:
    """The outputs of :func:`archive_outputs`, summed over the partitions in partition order.

    ``sensor_ids``; ``count`` (S, 3) values per sensor and channel (:data:`CHANNELS`), ``mean`` and
    ``rms`` (S, 3) of their whitened residuals (NaN without values), ``squares`` (S, 3) their sums of
    squares; ``by_target`` and ``by_reference`` {id: (sum of squares, values)}; ``hist`` (3, HIST_BINS)
    counts per channel over [-HIST_LIMIT, HIST_LIMIT]; ``parts`` the chi-square parts {"plots",
    "references", with surface targets "surface": (sum of squares, values)}; ``fused_rows`` rows of fused
    targets in ``n_parts`` parts; ``sample`` the figures' plots (module docstring), at most
    ``sample_max``; ``tables`` the fused tables when they were returned rather than written (else None).
    """

    sensor_ids: tuple
    count: np.ndarray
    mean: np.ndarray
    rms: np.ndarray
    squares: np.ndarray
    by_target: dict
    by_reference: dict
    hist: np.ndarray
    parts: dict
    fused_rows: int
    n_parts: int
    sample: dict
    sample_every: int
    tables: list | None


def _add(total: dict, ids, ss, n) -> None:
    for key, a, b in zip(np.asarray(ids).tolist(), np.asarray(ss).tolist(), np.asarray(n).tolist()):
        s0, n0 = total.get(key, (0.0, 0))
        total[key] = (s0 + float(a), n0 + int(b))


def _reduce(
    found: list[PartitionOutputs], target_ids: tuple, sample_max: int, every: int, tables
) -> ArchiveOutputs:
    sensor_ids = found[0].sensor_ids
    S = len(sensor_ids)
    count, total, squares = np.zeros((S, 3), dtype=np.int64), np.zeros((S, 3)), np.zeros((S, 3))
    hist = np.zeros((3, HIST_BINS), dtype=np.int64)
    by_target: dict[str, tuple[float, int]] = {}
    by_reference: dict[str, tuple[float, int]] = {}
    parts = {
        key: (0.0, 0) for f in found for key in f.parts
    }  # plots, references and, with a surface, surface
    for f in found:  # in partition order
        s = f.sums
        count += s.count
        total += s.total
        squares += s.squares
        hist += s.hist
        g, ss, n = s.by_target
        _add(by_target, np.asarray(target_ids)[g], ss, n)
        _add(by_reference, *s.by_reference)
        for key, (part_ss, part_n) in f.parts.items():
            parts[key] = (parts[key][0] + part_ss, parts[key][1] + part_n)
    with np.errstate(invalid="ignore", divide="ignore"):
        mean, rms = total / count, np.sqrt(squares / count)
    sample = {k: np.concatenate([f.sample[k] for f in found])[:sample_max] for k in found[0].sample}
    order = sorted(by_target, key=list(target_ids).index)
    return ArchiveOutputs(
        sensor_ids=sensor_ids,
        count=count,
        mean=mean,
        rms=rms,
        squares=squares,
        by_target={k: by_target[k] for k in order},
        by_reference=by_reference,
        hist=hist,
        parts=parts,
        fused_rows=sum(f.rows for f in found),
        n_parts=len(found),
        sample=sample,
        sample_every=every,
        tables=tables,
    )


def archive_outputs(
    result, source, options, *, parts=None, client=None, sample_max: int = SAMPLE_PLOTS
) -> ArchiveOutputs:
    """The outputs of the partitioned solve ``result`` of ``source`` with ``options`` (module
    docstring), by one pass over its partitions (in this process or on ``client``'s workers): the
    fused targets written as parts into the folder ``parts`` (None: returned in ``.tables``),
    the residual sums and a sample of at most ``sample_max`` plots, every k-th of each partition
    with k = ceil(plots / (sample_max - partitions)). The partitions are the solve's
    (``result.tasks``, with the windows it set aside), read from ``source``."""
    layout = result.layout
    tasks = [replace(t, source=source, options=options) for t in result.tasks]
    coefs = list(result.coefficients)
    if len(tasks) != len(coefs):
        raise ValueError(
            f"{len(tasks)} partitions with plots but {len(coefs)} with coefficients: the partitions "
            "are not the solve's"
        )
    room = max(1, int(sample_max) - len(tasks))
    every = max(1, -(-int(result.n_plots) // room))
    P_sink = np.zeros((layout.n + 1, layout.n + 1))
    P_sink[: layout.n, : layout.n] = result.covariance
    folder = None if parts is None else str(parts)
    args = [(result.estimate, c, P_sink, j, folder, every) for j, c in enumerate(coefs)]
    found = run_pass(output_pass, tasks, args, client)
    tables = None if parts is not None else [f.fused for f in found]
    return _reduce(found, result.plan.target_ids, int(sample_max), every, tables)
