"""The Monte Carlo in chunks of consecutive seeds, in this process or on a dask cluster.

Each run's data depend only on its seed (the tracks, true plots and Cramér-Rao bound are the same
in every run; per seed only the noise is drawn, and the compiled filter advances each run on its
own), so :func:`collect_runs` over ``seed0 .. seed0 + n - 1`` in chunks, merged in seed order by
:func:`merge_runs`, gives bit for bit the arrays and counts of one call over all the seeds, and
:func:`summarise_runs` then gives the same statistics. The chunk size is chosen by the caller,
never from the number of workers.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration.core.parallel import chunk_ranges, map_chunks
from registration.online.config import RegistrationConfig
from registration.online.mcresult import MonteCarloResult
from registration.online.montecarlo import collect_runs, parse_sum, summarise_runs

__all__ = [
    "DEFAULT_CHUNK_RUNS",
    "ChunkTask",
    "MonteCarloJob",
    "collect_chunk",
    "merge_runs",
    "run_montecarlo_chunked",
    "run_montecarlo_jobs",
]

#: Runs per chunk by default: large enough that one chunk's compiled batch dominates its overhead.
DEFAULT_CHUNK_RUNS = 100


@dataclass(frozen=True)
class ChunkTask:
    """Seeds ``start .. stop - 1`` of one Monte Carlo
    configuration (filter ``config``, scenario arguments)."""

    start: int
    stop: int
    config: RegistrationConfig | None
    scenario_kwargs: dict


def collect_chunk(task: ChunkTask) -> dict:
    """:func:`collect_runs` for the task's seeds (no progress bar: the chunks show progress)."""
    return collect_runs(task.stop - task.start, task.start, task.config, False, dict(task.scenario_kwargs))


def _add_counts(total: dict, part: dict) -> None:
    """Add ``part``'s counts into ``total``; keys keep the order of their first appearance."""
    for key, value in part.items():
        if isinstance(value, dict):
            _add_counts(total.setdefault(key, {}), value)
        else:
            total[key] = total.get(key, 0) + value


def merge_runs(parts: list[dict]) -> dict:
    """Chunks of :func:`collect_runs` output (in seed order) as one: runs concatenated, counts added.

    The shared parts (``time``, ``crlb``, ``description``, ``config``) are the first chunk's; they
    are checked to be the same in every chunk.
    """
    if not parts:
        raise ValueError("merge_runs: no chunks")
    first = parts[0]
    for p in parts[1:]:
        if not (np.array_equal(p["time"], first["time"]) and np.array_equal(p["crlb"], first["crlb"])):
            raise ValueError("merge_runs: the chunks simulate different scenarios")
    merged = {k: first[k] for k in ("time", "description", "crlb", "config")}
    for key in ("err", "P", "nis"):
        merged[key] = np.concatenate([p[key] for p in parts], axis=0) if len(parts) > 1 else first[key]
    for key in ("status_counts", "combo_counts"):
        merged[key] = {}
        for p in parts:
            _add_counts(merged[key], p[key])
    return merged


@dataclass
class MonteCarloJob:
    """One Monte Carlo configuration of :func:`run_montecarlo_jobs` (the arguments of
    :func:`run_montecarlo`)."""

    runs: int = 100
    seed0: int = 0
    config: RegistrationConfig | None = None
    include_weak: bool = False
    extra_sums: tuple = ()
    scenario_kwargs: dict = field(default_factory=dict)

    def tasks(self, chunk_runs: int) -> list[ChunkTask]:
        if int(self.runs) < 2:
            raise ValueError(f"runs: need at least 2 Monte Carlo runs, got {self.runs}")
        if "seed" in self.scenario_kwargs:
            raise ValueError("pass the first seed as seed0, not in the scenario arguments")
        return [
            ChunkTask(a, b, self.config, dict(self.scenario_kwargs))
            for a, b in chunk_ranges(int(self.runs), chunk_runs, int(self.seed0))
        ]

    def summarise(self, parts: list[dict]) -> MonteCarloResult:
        sums = [parse_sum(s) if isinstance(s, str) else parse_sum("+".join(s)) for s in self.extra_sums]
        return summarise_runs(
            merge_runs(parts),
            int(self.seed0),
            include_weak=self.include_weak,
            sums_requested=sums,
            scenario_kwargs=dict(self.scenario_kwargs),
        )


def run_montecarlo_jobs(
    jobs: list[MonteCarloJob], client=None, *, chunk_runs: int = DEFAULT_CHUNK_RUNS, progress: bool = False
) -> list[MonteCarloResult]:
    """Every job's :class:`MonteCarloResult`, all their chunks submitted as one batch.

    ``client``: a ``dask.distributed.Client`` or None (this process); ``chunk_runs``: seeds per
    chunk. Each result equals, bit for bit, :func:`run_montecarlo` with the job's arguments.
    """
    per_job = [job.tasks(chunk_runs) for job in jobs]
    flat = [t for tasks in per_job for t in tasks]
    results = map_chunks(collect_chunk, flat, client, progress=progress, desc="Monte Carlo")
    out, i = [], 0
    for job, tasks in zip(jobs, per_job):
        out.append(job.summarise(results[i : i + len(tasks)]))
        i += len(tasks)
    return out


def run_montecarlo_chunked(
    runs: int = 100,
    seed0: int = 0,
    config: RegistrationConfig | None = None,
    *,
    client=None,
    chunk_runs: int = DEFAULT_CHUNK_RUNS,
    include_weak: bool = False,
    extra_sums=(),
    progress: bool = False,
    **scenario_kwargs,
) -> MonteCarloResult:
    """:func:`run_montecarlo` in chunks of ``chunk_runs``
    seeds, on ``client``'s workers or in this process."""
    job = MonteCarloJob(runs, seed0, config, include_weak, tuple(extra_sums), scenario_kwargs)
    return run_montecarlo_jobs([job], client, chunk_runs=chunk_runs, progress=progress)[0]
