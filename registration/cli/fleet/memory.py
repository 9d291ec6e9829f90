"""``fleet register --memory-limit SIZE``: in memory or by partitions, as the tables' size asks
(docs/howto/register-an-archive.md, "Memory").

Without ``--partition-s``, the plots of ``--tables DIR`` are counted from the files' metadata (a
CSV file: one streamed pass over its ``target`` column) and the memory of a registration in memory
estimated (:func:`registration.fleet.batch.partitioned.sizing.in_memory_bytes`). Above the limit
(default: a quarter of this machine's memory) the run takes the archive path, and the partition
length is chosen from the plot rate so that the busiest partition fits
(:func:`~registration.fleet.batch.partitioned.sizing.choose_partition_s`); the run says what it
chose (plots without target ids are associated by partitions too). A run that cannot take the
archive path (``--on-bad-row skip``,
``--method online``, ...) is registered in memory all the same, with a warning. A limit below what
one partition needs (the chosen length, or ``--partition-s``) stops the run with exit 2 before
the solve, naming the smallest limit that works.
"""

from __future__ import annotations

import argparse
import os
import re
import sys

__all__ = ["choose_partitions", "default_limit", "memory_limit", "parse_size", "too_large"]

_UNITS = {
    "": 1,
    "b": 1,
    "k": 1 << 10,
    "kib": 1 << 10,
    "m": 1 << 20,
    "mib": 1 << 20,
    "g": 1 << 30,
    "gib": 1 << 30,
    "t": 1 << 40,
    "tib": 1 << 40,
    "kb": 10**3,
    "mb": 10**6,
    "gb": 10**9,
    "tb": 10**12,
}


def parse_size(text: str) -> int:
    """A memory size as bytes: a number and a unit (B, KiB, MiB, GiB, TiB, or K, M, G, T, also
    binary; KB, MB, GB, TB decimal), e.g. ``1GiB``, ``512MiB``, ``1.5G``."""
    m = re.fullmatch(r"\s*([0-9]*\.?[0-9]+(?:[eE][0-9]+)?)\s*([A-Za-z]*)\s*", str(text))
    unit = m.group(2).lower() if m else None
    if m is None or unit not in _UNITS or float(m.group(1)) <= 0:
        raise argparse.ArgumentTypeError(
            f"{text!r}: expected a size > 0 with its unit, such as 1GiB, 512MiB or 2G"
        )
    return int(float(m.group(1)) * _UNITS[unit])


def default_limit() -> int:
    """A quarter of this machine's physical memory (bytes; 1 GiB where it cannot be told)."""
    try:
        return int(os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")) // 4
    except (ValueError, OSError, AttributeError):
        return 1 << 30


def memory_limit(args: argparse.Namespace) -> int:
    """The run's memory limit in bytes: --memory-limit, else :func:`default_limit`."""
    given = getattr(args, "memory_limit", None)
    return int(given) if given is not None else default_limit()


def _size(n: float) -> str:
    return f"{n / (1 << 30):.1f} GiB" if n >= 1 << 30 else f"{n / (1 << 20):.0f} MiB"


def _in_memory_only(args: argparse.Namespace) -> str | None:
    """Why the run cannot take the archive path (None: it can)."""
    from registration.io.fleet.folder import TABLE_NAMES

    reasons = (
        (getattr(args, "on_bad_row", "stop") != "stop", "--on-bad-row skip"),
        (getattr(args, "method", "batch") != "batch", "--method online"),
        (getattr(args, "targets", None) is not None, "--targets"),
        (getattr(args, "cat063", None) is not None, "--cat063"),
        (getattr(args, "bias_period_s", None) is not None, "--bias-period-s"),
        (any(getattr(args, n, None) is not None for n in TABLE_NAMES), "a table given by its own option"),
    )
    found = [text for cond, text in reasons if cond]
    return f"{found[0]} is for a registration in memory" if found else None


def too_large(args: argparse.Namespace) -> bool:
    """True when the tables of --tables DIR would need more than the memory limit in memory and the
    run can take the archive path (module docstring); a warning on stderr when it cannot."""
    if getattr(args, "tables", None) is None:
        return False
    from registration.fleet.batch.partitioned.sizing import in_memory_bytes
    from registration.io.fleet.sources import plot_count

    try:
        rows, ids = plot_count(args.tables)
    except ValueError:  # a folder or file the reader will name with its own error
        return False
    need, limit = in_memory_bytes(rows, association=not ids), memory_limit(args)
    if need <= limit:
        return False
    why = _in_memory_only(args)
    head = f"{rows} plots need about {_size(need)} in memory, above the memory limit of {_size(limit)}"
    if why is not None:
        print(f"warning: {head}; registering in memory all the same: {why}", file=sys.stderr)
        return False
    print(f"{head}: registering the archive by partitions")
    args.partition_chosen = True
    return True


def _lacks_ids(args: argparse.Namespace) -> bool:
    """True when some plot of --tables DIR has no target id (they are associated by partitions)."""
    from registration.io.fleet.sources import plot_count

    try:
        return not plot_count(args.tables)[1]
    except ValueError:  # a folder or file the reader names with its own error
        return False


def choose_partitions(args: argparse.Namespace, source) -> None:
    """Set ``args.partition_s`` from the memory limit and the plot rate when it is not given, and say
    so; with --memory-limit and --partition-s both given, check that one partition fits.
    MemoryLimitError (a ValueError: exit 2) naming the smallest limit that works."""
    from registration.fleet.association.partitioned.parts import DEFAULT_OVERLAP_S
    from registration.fleet.batch.partitioned.sizing import (
        MemoryLimitError,
        association_bytes,
        choose_partition_s,
        in_memory_bytes,
        partition_bytes,
    )

    given = getattr(args, "partition_s", None)
    if given is not None and getattr(args, "memory_limit", None) is None:
        return
    profile = source.plot_profile()
    limit = memory_limit(args)
    overlap = DEFAULT_OVERLAP_S if _lacks_ids(args) else None
    if given is None:
        try:
            choice = choose_partition_s(
                profile.most_rows, profile.rows, profile.t1 - profile.t0, limit, args.window_s, overlap
            )
        except MemoryLimitError as exc:
            whole = in_memory_bytes(profile.rows, association=overlap is not None)
            if whole >= exc.smallest:
                raise
            raise MemoryLimitError(  # in memory needs less than one partition: that is the smallest
                f"--memory-limit {_size(limit)}: the {profile.rows} plots need about {_size(whole)} in "
                f"memory, and one partition at least {_size(exc.smallest)}; the smallest limit that "
                f"works is {-(-whole // (1 << 20))}MiB",
                whole,
            ) from None
        args.partition_s = choice.partition_s
        args.partition_chosen = True
        print(f"memory limit {_size(limit)}: {choice.text()}")
        return
    need = partition_bytes(profile.most_rows(float(given) + 2.0 * args.window_s))
    if overlap is not None:
        need = max(need, association_bytes(profile.most_rows(float(given) + 2.0 * overlap)))
    if need > limit:
        raise MemoryLimitError(
            f"--memory-limit {_size(limit)}: a partition of --partition-s {given:g} s needs about "
            f"{_size(need)}; the smallest limit that works is {-(-need // (1 << 20))}MiB (or give a "
            "shorter --partition-s, or none and let the run choose)",
            need,
        )
