"""How much memory a registration of an archive needs, and the partition length that keeps it under
a limit (docs/howto/register-an-archive.md, "Memory"): :func:`in_memory_bytes`,
:func:`choose_partition_s`.

The figures are measured peaks of the resident memory of ``fleet register --no-plots`` (the
archive of benchmarks/bench_archive_workers.py: 8 sensors, 3 navigation rows per plot): in memory, a base of
IN_MEMORY_BASE plus IN_MEMORY_PER_PLOT per plot; partitioned, a base of PARTITION_BASE (imports,
the plan, the windows' coefficients, the solver's sums) plus PARTITION_PER_PLOT per plot of the
largest partition (its rows read, its design, its normal equations and their reduction). Each
process of a run on workers holds one partition at a time, so the same figures bound each worker.
Plots without target ids are associated first, in memory or partition by partition
(:mod:`registration.fleet.association.partitioned`): a base of ASSOCIATION_BASE plus
ASSOCIATION_PER_PLOT per plot associated together (a partition's plots and its overlaps).
"""

from __future__ import annotations

from typing import Callable

import numpy as np

__all__ = [
    "ASSOCIATION_BASE",
    "ASSOCIATION_PER_PLOT",
    "IN_MEMORY_BASE",
    "IN_MEMORY_PER_PLOT",
    "MiB",
    "PARTITION_BASE",
    "PARTITION_PER_PLOT",
    "MemoryLimitError",
    "PartitionChoice",
    "association_bytes",
    "choose_partition_s",
    "in_memory_bytes",
    "partition_bytes",
]

MiB = 1 << 20
#: In memory (read_fleet_tables + solve_batch): bytes before the first plot and per plot (measured:
#: 616 MiB for 10^5 plots, 976 MiB for 2 * 10^5).
IN_MEMORY_BASE = 260 * MiB
IN_MEMORY_PER_PLOT = 3_800
#: Partitioned: bytes before the first partition and per plot of the largest partition (measured on
#: 10^6 plots in process: 502 MiB with partitions of 27 000 plots, 662 MiB with 99 000; rounded up).
PARTITION_BASE = 480 * MiB
PARTITION_PER_PLOT = 2_600
#: The association in memory (fleet register on imported ATC tables, 1.3 ADS-B reference rows per
#: plot): bytes before the first plot and per plot (measured: 246 MiB for 9 504 plots, 435 MiB for
#: 32 950; rounded up).
ASSOCIATION_BASE = 200 * MiB
ASSOCIATION_PER_PLOT = 10_000


class MemoryLimitError(ValueError):
    """A memory limit below what one partition needs; ``smallest``: the smallest limit that works (bytes)."""

    def __init__(self, text: str, smallest: int):
        super().__init__(text)
        self.smallest = int(smallest)


def in_memory_bytes(plots: int, association: bool = False) -> int:
    """The peak memory (bytes) of registering ``plots`` plots in memory (``association``: some lack
    target ids, so they are associated first)."""
    need = int(IN_MEMORY_BASE + IN_MEMORY_PER_PLOT * int(plots))
    return max(need, association_bytes(plots)) if association else need


def association_bytes(plots: int) -> int:
    """The peak memory (bytes) of associating ``plots`` plots together."""
    return int(ASSOCIATION_BASE + ASSOCIATION_PER_PLOT * int(plots))


def partition_bytes(plots: int) -> int:
    """The peak memory (bytes) of a partitioned run whose largest partition holds ``plots`` plots."""
    return int(PARTITION_BASE + PARTITION_PER_PLOT * int(plots))


def _text(n: float) -> str:
    """Bytes as MiB or GiB, rounded up."""
    return f"{np.ceil(n / (1 << 30) * 10) / 10:.1f} GiB" if n >= 1 << 30 else f"{int(np.ceil(n / MiB))} MiB"


class PartitionChoice:
    """A partition length ``partition_s`` (s), the most plots one partition may hold ``plots`` and the
    peak memory that gives ``bytes``."""

    def __init__(self, partition_s: float, plots: int, need: int | None = None):
        self.partition_s, self.plots = float(partition_s), int(plots)
        self.bytes = partition_bytes(plots) if need is None else int(need)

    def text(self) -> str:
        return (
            f"partitions of {self.partition_s:g} s (at most about {self.plots} plots each, "
            f"about {_text(self.bytes)} per process)"
        )


def _nice(seconds: float) -> float:
    """``seconds`` rounded down to 1, 2 or 5 times a power of ten."""
    p = 10.0 ** np.floor(np.log10(seconds))
    return float(max(m * p for m in (1.0, 2.0, 5.0) if m * p <= seconds))


def choose_partition_s(
    most_rows: Callable[[float], int],
    rows: int,
    span_s: float,
    limit: int,
    window_s: float,
    overlap_s: float | None = None,
) -> PartitionChoice:
    """The longest partition length (1, 2 or 5 times a power of ten seconds, at least ``window_s``)
    whose busiest partition fits in ``limit`` bytes (:func:`partition_bytes`); ``most_rows(L)``: the
    most plots in any L seconds, ``rows`` plots over ``span_s`` seconds. A partition reaches a
    window beyond its length on each side (the target windows that start in it). ``overlap_s``:
    the plots are associated first, each partition reading that much more on each side
    (:func:`association_bytes`). MemoryLimitError naming the smallest limit that works when even
    ``window_s`` is too long."""
    window_s = max(float(window_s), 1e-3)

    def plots_of(length: float) -> int:
        return int(most_rows(length + 2.0 * window_s))

    def need(length: float) -> int:
        solve = partition_bytes(plots_of(length))
        if overlap_s is None:
            return solve
        return max(solve, association_bytes(int(most_rows(length + 2.0 * float(overlap_s)))))

    smallest = need(window_s)
    if smallest > limit:
        raise MemoryLimitError(
            f"--memory-limit {_text(limit)}: one partition of the shortest length (a target window, "
            f"{window_s:g} s) needs about {_text(smallest)}; the smallest limit that works is "
            f"{int(np.ceil(smallest / MiB))}MiB",
            smallest,
        )
    rate = max(rows / span_s if span_s > 0 else float(rows), 1e-9)
    longest = (limit - PARTITION_BASE) / PARTITION_PER_PLOT / rate  # s, at the mean rate
    if overlap_s is not None:
        longest = min(longest, (limit - ASSOCIATION_BASE) / ASSOCIATION_PER_PLOT / rate - 2.0 * overlap_s)
    length = max(window_s, _nice(max(longest, window_s)))
    length = min(length, max(_nice(max(span_s, window_s)), window_s))
    while length > window_s and need(length) > limit:
        length = max(window_s, _nice(length * 0.999))
    return PartitionChoice(length, plots_of(length), need(length))
