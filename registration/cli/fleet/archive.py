"""``registration fleet register`` on an archive too large for memory: the partitioned batch solver
(:func:`registration.fleet.batch.partitioned.solve_batch_partitioned`, docs/howto/register-an-archive.md) on a
folder of Parquet tables, or of CSV files converted block by block into a temporary Parquet folder
(:mod:`registration.io.fleet.archive.csvfolder`), in this process or on Dask workers.

Options (:func:`add_archive_arguments`): ``--partition-s S`` (the archive is read and solved in
partitions of S seconds of target windows; this switches the archive path on), ``--memory-limit
SIZE`` (without ``--partition-s``: tables whose registration in memory would need more are
registered by partitions, of a length chosen from the plot rate, :mod:`registration.cli.fleet.memory`),
``--workers N`` (a local Dask cluster of N worker processes), ``--scheduler ADDRESS`` (a running
dask.distributed scheduler). A table whose row groups do not follow time is first copied by time
buckets into a temporary folder (:mod:`registration.io.fleet.archive.timeorder`), so every process reads
only its partition. The estimates equal the in-process run's for any number of workers. Outputs, replacing
an earlier run's in ``--out`` only once all are written (a partition that cannot be read, or a bad
CSV row, leaves ``--out`` as it was, with a one-line error naming the file): ``estimates.csv``
(state, unit in file units, estimate, sigma), ``fused_targets/`` (Parquet parts, one per
partition, written by the workers, or with ``--scheduler`` returned to this process and written
here), ``residuals.csv`` (per sensor and channel: count, mean, RMS of the whitened residuals),
``summary.json`` (the partitions, iterations, chi-square, exclusions, residual checks, the
association's figures), ``labelled_plots/`` (when plots lacked target ids: the plots the
association labelled, Parquet parts, the label as ``target``) and the PNGs
of :mod:`registration.cli.fleet.archive_output` (docs/howto/register-an-archive.md, "Outputs of an archive
run").
"""

from __future__ import annotations

import argparse
from pathlib import Path

from registration.cli.errors import writing
from registration.cli.fleet.archive_output import PNG_OUTPUTS
from registration.cli.fleet.memory import choose_partitions, memory_limit, parse_size, too_large
from registration.io.files.jsonfile import json_text

__all__ = [
    "ARCHIVE_FOLDERS",
    "ARCHIVE_OUTPUTS",
    "FUSED_FOLDER",
    "add_archive_arguments",
    "archive_requested",
    "run_archive",
]

#: The folder of the fused targets' Parquet parts.
FUSED_FOLDER = "fused_targets"
#: The files an archive run writes into --out (the PNGs unless --no-plots), and its folders.
ARCHIVE_OUTPUTS = frozenset({"estimates.csv", "residuals.csv", "summary.json", *PNG_OUTPUTS})
#: The folder of the plots the association labelled (Parquet parts: the plots with their targets).
LABELLED_FOLDER = "labelled_plots"
ARCHIVE_FOLDERS = frozenset({FUSED_FOLDER, LABELLED_FOLDER})


def add_archive_arguments(p: argparse.ArgumentParser) -> None:
    """The archive options, in their own group of ``p`` (the ``fleet register`` parser)."""
    g = p.add_argument_group("archives too large for memory (Parquet or CSV tables in --tables DIR)")
    g.add_argument(
        "--partition-s",
        type=float,
        default=None,
        metavar="S",
        help="solve partition by partition, S seconds of target windows each (memory bounded by a "
        "partition; default: chosen from --memory-limit: in memory when the tables fit, else "
        "partitions whose length follows from the plot rate); plots without target ids are "
        "associated partition by partition first",
    )
    g.add_argument(
        "--memory-limit",
        type=parse_size,
        default=None,
        metavar="SIZE",
        help="the memory a process of the run may use, e.g. 1GiB or 512MiB (default: a quarter of "
        "this machine's memory): tables that need more in memory are registered by partitions short "
        "enough for it; a limit below what one partition needs stops the run, naming the smallest "
        "that works",
    )
    g.add_argument(
        "--workers",
        type=int,
        default=None,
        metavar="N",
        help="map the partitions on a local Dask cluster of N worker processes (the partition length: "
        "--partition-s, else chosen from --memory-limit)",
    )
    g.add_argument(
        "--scheduler",
        default=None,
        metavar="ADDRESS",
        help="map the partitions on the dask.distributed scheduler at ADDRESS, e.g. tcp://host:8786 "
        "(the partition length: --partition-s, else chosen from --memory-limit)",
    )


def archive_requested(args: argparse.Namespace) -> bool:
    """True when the run takes the archive path: --partition-s, --workers or --scheduler given, or
    tables too large for --memory-limit in memory (:func:`registration.cli.fleet.memory.too_large`)."""
    if getattr(args, "partition_s", None) is not None:
        return True
    if getattr(args, "workers", None) is not None or getattr(args, "scheduler", None):
        if getattr(args, "tables", None) is None:
            raise ValueError(
                "--workers and --scheduler map the partitions of an archive: give it as --tables DIR"
            )
        return True
    return too_large(args)


def _summary(result, args: argparse.Namespace) -> dict:
    from registration.cli.fleet.output import estimates_json
    from registration.io.fleet.estimates import estimate_rows

    chi = result.chi_square
    return {
        "estimates": estimates_json(estimate_rows(result)),
        "observability": result.observability.to_json(),
        "tables": str(args.tables),
        "window_s": args.window_s,
        "partition_s": args.partition_s,
        "partition_s_chosen": bool(getattr(args, "partition_chosen", False)),
        "memory_limit_bytes": memory_limit(args),
        "partitions": result.plan.n_partitions,
        "plots_used": result.n_plots,
        "plots_read": result.plan.n_input_plots,
        "converged": result.converged,
        "iterations": result.iterations,
        "chi_square": {
            "chi2": chi.chi2,
            "dof": chi.dof,
            "mean": chi.mean,
            "parts": {k: list(v) for k, v in chi.parts.items()},
        },
        "excluded": [e.text() for e in result.excluded],
        "warnings": list(result.warnings),
        "workers": args.workers,
        "scheduler": args.scheduler,
        "association": getattr(args, "association_summary", None),
    }


def _write_parts(parts: Path, tables: list) -> None:
    from registration.fleet.batch.outputs import write_part

    for k, table in enumerate(tables):
        with writing(parts):
            write_part(parts, k, table)


def _write_outputs(folder: Path, args: argparse.Namespace, result, outputs, written_by: str) -> None:
    from registration.cli.fleet.archive_output import residual_lines, residual_summary, write_figures
    from registration.fleet.batch.outputs import FUSED_COLUMNS

    summary = {
        **_summary(result, args),
        **residual_summary(outputs),
        "fused_targets": {
            "folder": f"{FUSED_FOLDER}/",
            "parts": outputs.n_parts,
            "rows": outputs.fused_rows,
            "columns": list(FUSED_COLUMNS),
            "written_by": written_by,
        },
        "figures_sample": {"plots": int(outputs.sample["time"].size), "every": outputs.sample_every},
    }
    import pandas as pd

    from registration.io.files.tablefile import write_frame
    from registration.io.fleet.estimates import estimate_rows

    with writing(
        folder / "estimates.csv"
    ):  # the in-memory run's layout: object, state, unit, estimate, sigma, status
        write_frame(pd.DataFrame(estimate_rows(result)), folder / "estimates.csv", "csv")
    for name, text in (
        ("residuals.csv", "\n".join(residual_lines(outputs))),
        ("summary.json", json_text(summary).rstrip("\n")),
    ):
        with writing(folder / name):
            (folder / name).write_text(text + "\n")
    if not getattr(args, "no_plots", False):
        write_figures(folder, outputs, result)


def _solve_and_write(args: argparse.Namespace, out: Path, source) -> tuple:
    import tempfile

    with tempfile.TemporaryDirectory(prefix="registration-archive-") as work:
        ordered = source.time_ordered(work)  # tables out of time order copied by time buckets
        for name in ordered.copies:
            print(f"{source.name(name)}: its row groups do not follow time; read through a copy by time")
        return _solve_in(args, out, ordered, work)


def _solve_in(args: argparse.Namespace, out: Path, source, work: str) -> tuple:
    from registration.cli.fleet.archive_association import associated_source
    from registration.core.parallel import dask_client
    from registration.fleet import BatchOptions
    from registration.fleet.batch.partitioned import remove_spill, solve_batch_partitioned

    options = BatchOptions(window_s=args.window_s)
    with dask_client(args.scheduler, args.workers) as client:
        source, association = associated_source(args, source, work, client)
        args.association_summary = None if association is None else association.summary()
        result = solve_batch_partitioned(
            source,
            options,
            partition_s=args.partition_s,
            client=client,
            progress=True,
            spill_dir=work,
            keep_spill=True,  # the output pass reads each partition from it rather than building it again
        )
        try:
            outputs = _outputs(args, out, result, source, options, client)
        finally:
            if result.spill_folder is not None:
                remove_spill(result.spill_folder, client)
    return result, outputs


def _outputs(args: argparse.Namespace, out: Path, result, source, options, client):
    """The output pass and the outputs written into ``out`` (staged: all or none)."""
    from registration.cli.staging import staged_outputs
    from registration.fleet.batch.outputs import archive_outputs

    with staged_outputs(
        out, "registration fleet register", ARCHIVE_OUTPUTS, folders=ARCHIVE_FOLDERS
    ) as folder:
        parts = folder.path / FUSED_FOLDER
        with writing(parts):
            parts.mkdir()
        remote = bool(args.scheduler)  # a remote cluster may not see this disk: its workers return the parts
        outputs = archive_outputs(result, source, options, parts=None if remote else parts, client=client)
        if remote:
            _write_parts(parts, outputs.tables or [])
        _write_outputs(
            folder.path,
            args,
            result,
            outputs,
            "client" if remote else ("workers" if client is not None else "this process"),
        )
        if getattr(args, "association_summary", None) is not None:
            import shutil

            with writing(folder.path / LABELLED_FOLDER):
                shutil.copytree(source.paths["plots"], folder.path / LABELLED_FOLDER)
    return outputs


def run_archive(args: argparse.Namespace) -> int:
    """Register the archive ``--tables DIR`` partition by partition and write the outputs (module
    docstring); its tables are opened as the in-memory run's are (:mod:`registration.cli.fleet.tables`)."""
    from registration.cli.errors import consistency_gate, consistency_line, prepare_out

    if args.tables is None:
        raise ValueError(
            "--partition-s: give the archive as --tables DIR (Parquet or CSV files, or folders of "
            "Parquet files)"
        )
    if not args.window_s > 0:
        raise ValueError(
            f"--window-s {args.window_s:g}: the partitioned solver (--partition-s, --workers, --scheduler) "
            "needs windows of a length > 0 s"
        )
    if getattr(args, "on_bad_row", "stop") != "stop":
        raise ValueError(
            "--on-bad-row skip: not with --partition-s (an archive stops at its first bad row); "
            "register in memory to set bad rows aside"
        )
    if getattr(args, "method", "batch") != "batch":
        raise ValueError("--method online: not with --partition-s (the archive path is the batch solve)")
    if getattr(args, "targets", None) is not None:
        raise ValueError(
            "--targets: with --partition-s the surface targets are the --tables folder's targets file "
            "(targets.parquet or targets.csv)"
        )
    from registration.cli.fleet.tables import opened_tables

    out = prepare_out(args.out)
    with opened_tables(args, out, lazy=True) as source:
        choose_partitions(args, source)  # exit 2 before the solve when the limit is too small
        result, outputs = _solve_and_write(args, out, source)
    print(
        f"{result.n_plots} plots in {result.plan.n_partitions} partitions, {result.iterations} iterations, "
        f"chi-square/dof {result.chi_square.mean:.3f}"
    )
    print(f"fused targets: {outputs.fused_rows} rows in {outputs.n_parts} Parquet parts")
    for w in result.warnings:
        print(f"warning: {w}")
    from registration.cli.fleet.output import estimate_table
    from registration.io.fleet.estimates import estimate_rows

    print()
    for line in estimate_table(estimate_rows(result)):
        print(line)
    print("\nObservability:")
    for line in result.observability.lines():
        print(line)
    print()
    names = sorted(ARCHIVE_OUTPUTS - (set() if not getattr(args, "no_plots", False) else set(PNG_OUTPUTS)))
    print("wrote " + ", ".join(str(out / n) for n in [*names, FUSED_FOLDER + "/"]))
    report = (
        result.chi_square.report
    )  # the gate of the in-memory run: exit 3 when the data contradict the model
    print(consistency_line(report))
    return consistency_gate("registration fleet register", report, getattr(args, "allow_inconsistent", False))
