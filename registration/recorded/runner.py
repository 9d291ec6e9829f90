"""``registration register`` as a pipeline: plan -> pair (asynchronous form) -> filter -> report.

Each stage is a module of its own and hands its result to the next:

1. :func:`~registration.recorded.plan.plan_run`: check the inputs, fingerprint them, find the
   checkpoint to resume from;
2. :func:`~registration.recorded.paired.pair_inputs` (two plot files only): the published
   synchronous table ``paired.csv|parquet``;
3. :func:`~registration.recorded.filtering.filter_table`: read, check and filter the table block
   by block, writing estimates, positions and rejected rows, then the information matrix at the
   final estimate; checkpointed and resumable bit for bit;
4. :func:`~registration.recorded.report.build_summary`, ``summary.json``, the plots, and the
   checkpoint marked ``done``.
"""

from __future__ import annotations

import time

from registration.recorded.filtering import filter_table
from registration.recorded.options import RunOptions
from registration.recorded.paired import pair_inputs
from registration.recorded.plan import plan_run
from registration.recorded.plots import write_plots
from registration.recorded.report import build_summary
from registration.recorded.runstate import mark_done
from registration.recorded.writers import write_json_atomic

__all__ = ["run_register"]


def run_register(inputs, options: RunOptions) -> dict:
    """Register recorded data: one synchronous table, or two per-sensor plot files (+ navigation).

    Writes into ``options.out``: ``estimates`` and ``positions`` (.csv or .parquet),
    ``rejected.csv``, ``summary.json``, the plots and, for the asynchronous form, ``paired.*``,
    ``unpaired.csv`` and ``pairing.json``. Returns the summary. Raises ValueError subclasses for
    bad input: FileFormatError, BadRowError (``on_bad_row="stop"``), CheckpointError.
    """
    started = time.perf_counter()
    plan = plan_run(inputs, options)
    if plan.finished is not None:
        return plan.finished
    table = pair_inputs(plan, options) if plan.form == "asynchronous" else plan.sync_table()
    state = filter_table(table, plan, options)
    summary = build_summary(table, plan, state, options, elapsed_s=round(time.perf_counter() - started, 3))
    write_json_atomic(options.out / "summary.json", summary)
    if options.plots:
        summary["plots"] = write_plots(table.path, options, summary)
        write_json_atomic(options.out / "summary.json", summary)
    if options.checkpoint is not None:
        mark_done(options.checkpoint)
    return summary
