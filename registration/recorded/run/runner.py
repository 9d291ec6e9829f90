"""``registration register`` as a pipeline: plan -> pair (asynchronous form) -> filter -> report -> publish.

Each stage is a module of its own and hands its result to the next:

1. :func:`~registration.recorded.run.plan.plan_run`: check the inputs and ``--out``, fingerprint the
   inputs, find the checkpoint to resume from, and choose the run's own folder inside ``--out``
   (:mod:`registration.io.output.outfolder`);
2. :func:`~registration.recorded.run.plan.input_warnings`: angle columns that seem to hold
   radians (printed at once, listed in the summary);
3. :func:`~registration.recorded.run.pairstage.pair_inputs` (two plot files only): the published
   synchronous table ``paired.csv|parquet``;
4. :func:`~registration.recorded.run.filtering.filter_table`: read, check and filter the table block
   by block, writing estimates, positions and rejected rows, then the information matrix at the
   final estimate; checkpointed and resumable bit for bit;
5. :func:`~registration.recorded.run.summary.build_summary` (with the consistency gate's figures),
   ``summary.json``, the plots (from the points kept while filtering,
   :mod:`registration.recorded.output.plotseries`), the checkpoint marked ``done``;
6. :func:`~registration.io.output.outfolder.publish`: the run's folder replaces the outputs of an
   earlier run in ``--out``.

A run that fails is not published, except when every row was rejected (``rejected.csv`` says
why); its folder is removed unless a checkpoint records it (then rerunning resumes in it).
"""

from __future__ import annotations

import time

from registration.io.files.tablefile import NoValidRowsError
from registration.io.output.outfolder import discard, publish, records_folder
from registration.recorded.options import RunOptions
from registration.recorded.output.plots import series_from_outputs, write_plots
from registration.recorded.output.writers import write_json_atomic
from registration.recorded.run.filtering import filter_table
from registration.recorded.run.pairstage import pair_inputs
from registration.recorded.run.plan import RunPlan, input_warnings, plan_run
from registration.recorded.run.runstate import mark_done
from registration.recorded.run.summary import build_summary

__all__ = ["run_register"]


def run_register(inputs, options: RunOptions) -> dict:
    """Register recorded data: one synchronous table, or two per-sensor plot files (+ navigation).

    Publishes into ``options.out``: ``estimates`` and ``positions`` (.csv or .parquet),
    ``rejected.csv``, ``summary.json``, the plots and, for the asynchronous form, ``paired.*``,
    ``unpaired.csv`` and ``pairing.json``, replacing what an earlier run wrote there. Returns the
    summary; its ``consistency`` says whether the data fit the model (the caller decides what a
    grossly inconsistent run means). Raises ValueError subclasses for bad input: FileFormatError,
    BadRowError (``on_bad_row="stop"``), CheckpointError, OutputFolderError, NoValidRowsError.
    """
    started = time.perf_counter()
    plan = plan_run(inputs, options)
    if plan.finished is not None:
        return plan.finished
    folder = plan.working_folder()
    try:
        summary = _run(plan, options, started)
    except NoValidRowsError:
        publish(folder)  # a complete answer: rejected.csv lists every row with its reason
        raise
    except BaseException:
        if not (options.checkpoint is not None and records_folder(options.checkpoint, folder.path.name)):
            discard(folder)
        raise
    if options.checkpoint is not None:
        # a kill from here on: the rerun publishes the folder the checkpoint records
        mark_done(options.checkpoint)
    publish(folder)  # an interrupted publication is completed by the next run into --out
    return summary


def _run(plan: RunPlan, options: RunOptions, started: float) -> dict:
    """The stages after the plan, in the run's folder, up to its summary.json and plots."""
    warnings = input_warnings(plan)
    for w in warnings:
        options.message(f"registration register: warning: {w}")
    table = pair_inputs(plan, options) if plan.form == "asynchronous" else plan.sync_table()
    state = filter_table(table, plan, options)
    summary = build_summary(
        table, plan, state, options, elapsed_s=round(time.perf_counter() - started, 3), warnings=warnings
    )
    folder = plan.working_folder()
    write_json_atomic(folder.path / "summary.json", summary)
    if options.plots:
        series = (
            state.plot_series.arrays()
            if state.plot_series is not None
            else series_from_outputs(table.path, options, folder.path, state.rows_accepted)
        )  # a resumed run
        paths = write_plots(series, summary["observability"]["status"], folder.path)
        summary["plots"] = [str(folder.final(p)) for p in paths]
        write_json_atomic(folder.path / "summary.json", summary)
    return summary
