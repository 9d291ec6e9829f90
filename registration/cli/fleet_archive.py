"""``registration fleet register`` on an archive too large for memory: the partitioned batch solver
(:func:`registration.fleet.batch.partitioned.solve_batch_partitioned`, docs/archive.md) on a
folder of Parquet tables, in this process or on Dask workers.

Options (:func:`add_archive_arguments`): ``--partition-s S`` (the archive is read and solved in
partitions of S seconds of target windows; this switches the archive path on), ``--workers N`` (a
local Dask cluster of N worker processes), ``--scheduler ADDRESS`` (a running dask.distributed
scheduler). The estimates equal the in-process run's for any number of workers. Outputs, replacing
an earlier run's in ``--out`` only once all are written (a partition that cannot be read leaves
``--out`` as it was, with a one-line error naming the file): ``estimates.csv`` (state, unit in file
units, estimate, sigma) and ``summary.json`` (the partitions, iterations, chi-square, exclusions).
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

__all__ = ["ARCHIVE_OUTPUTS", "add_archive_arguments", "archive_requested", "run_archive"]

#: The files an archive run writes into --out.
ARCHIVE_OUTPUTS = frozenset({"estimates.csv", "summary.json"})


def add_archive_arguments(p: argparse.ArgumentParser) -> None:
    """The archive options, in their own group of ``p`` (the ``fleet register`` parser)."""
    g = p.add_argument_group("archives too large for memory (Parquet tables in --tables DIR)")
    g.add_argument("--partition-s", type=float, default=None, metavar="S",
                   help="solve partition by partition, S seconds of target windows each (memory bounded by a "
                        "partition; default: not partitioned, the whole archive in memory)")
    g.add_argument("--workers", type=int, default=None, metavar="N",
                   help="map the partitions on a local Dask cluster of N worker processes (with --partition-s)")
    g.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="map the partitions on the dask.distributed scheduler at ADDRESS, e.g. tcp://host:8786 "
                        "(with --partition-s)")


def archive_requested(args: argparse.Namespace) -> bool:
    """True when the options ask for the archive path (ValueError for --workers/--scheduler alone)."""
    if getattr(args, "partition_s", None) is None:
        if getattr(args, "workers", None) is not None or getattr(args, "scheduler", None):
            raise ValueError("--workers and --scheduler map the partitions of an archive: give --partition-s S too")
        return False
    return True


def _estimate_lines(result) -> list[str]:
    from registration.fleet.data.layout import FILE_UNITS

    lines = ["state,unit,estimate,sigma"]
    for i, name in enumerate(result.layout.names):
        unit, factor, _, _ = FILE_UNITS[result.layout.units[i]]
        lines.append(f"{name},{unit},{float(result.estimate[i] * factor)!r},{float(result.sigma[i] * factor)!r}")
    return lines


def _summary(result, args: argparse.Namespace) -> dict:
    chi = result.chi_square
    return {"tables": str(args.tables), "window_s": args.window_s, "partition_s": args.partition_s,
            "partitions": result.plan.n_partitions, "plots_used": result.n_plots,
            "plots_read": result.plan.n_input_plots, "converged": result.converged, "iterations": result.iterations,
            "chi_square": {"chi2": chi.chi2, "dof": chi.dof, "mean": chi.mean,
                           "parts": {k: list(v) for k, v in chi.parts.items()}},
            "excluded": [e.text() for e in result.excluded], "warnings": list(result.warnings),
            "workers": args.workers, "scheduler": args.scheduler}


def run_archive(args: argparse.Namespace) -> int:
    """Register the Parquet archive ``--tables DIR`` partition by partition and write the outputs."""
    from registration.cli.errors import prepare_out
    from registration.cli.staging import staged_outputs
    from registration.core.parallel import dask_client
    from registration.fleet import BatchOptions
    from registration.fleet.batch.archive import ParquetSource
    from registration.fleet.batch.partitioned import solve_batch_partitioned
    from registration.io.fleet.cells import FILE_COLUMNS

    if args.tables is None:
        raise ValueError("--partition-s: give the archive as --tables DIR (Parquet files or folders of them)")
    out = prepare_out(args.out)
    source = ParquetSource(Path(args.tables), FILE_COLUMNS)
    with dask_client(args.scheduler, args.workers) as client:
        result = solve_batch_partitioned(source, BatchOptions(window_s=args.window_s), partition_s=args.partition_s,
                                         client=client, progress=True)
    with staged_outputs(out, "registration fleet register", ARCHIVE_OUTPUTS) as folder:
        (folder.path / "estimates.csv").write_text("\n".join(_estimate_lines(result)) + "\n")
        (folder.path / "summary.json").write_text(json.dumps(_summary(result, args), indent=2) + "\n")
    print(f"{result.n_plots} plots in {result.plan.n_partitions} partitions, {result.iterations} iterations, "
          f"chi-square/dof {result.chi_square.mean:.3f}")
    for w in result.warnings:
        print(f"warning: {w}")
    print("wrote " + ", ".join(str(out / n) for n in sorted(ARCHIVE_OUTPUTS)))
    return 0
