"""The filter stage: the synchronous table through the online filter, then the information
matrix at the final estimate.

Pass 1 reads the table in blocks of ``block_rows`` rows aligned on absolute row numbers,
validates them (:mod:`registration.recorded.reading.rowcheck`) and runs the accepted rows through
:meth:`registration.online.filter.OnlineRegistrar.update_block`; per block it appends the
estimates, the corrected ECEF positions and the rejected rows, and accumulates the statistics.
Pass 2 (``observability="final"``) sums H^T R^-1 H at the final estimate over the same rows.
The run state is checkpointed at block boundaries (:mod:`registration.recorded.run.runstate`).
"""

from __future__ import annotations

import numpy as np

from registration.io.files.tablefile import FileFormatError, NoValidRowsError
from registration.online.contract import correct_rows
from registration.online.filter import OnlineRegistrar
from registration.online.information import information_at_estimate, target_positions
from registration.recorded.options import RunOptions
from registration.recorded.output.outputs import Outputs, estimate_frame, position_frame, rejected_rows
from registration.recorded.output.plotseries import PLOT_POINTS, PlotSeries
from registration.recorded.reading.columns import SYNC_COLUMNS
from registration.recorded.reading.formats import iter_frames
from registration.recorded.reading.rowcheck import (
    BadRowError,
    CheckedBlock,
    Rejection,
    check_frame,
    sync_layout,
)
from registration.recorded.run.plan import RunPlan, Table
from registration.recorded.run.runstate import Checkpointer, RunState

__all__ = ["filter_table"]


_NON_FINITE_STEP = "the filter step for this row produced non-finite values (extreme geometry or values)"


def filter_table(table: Table, plan: RunPlan, options: RunOptions) -> RunState:
    """Run (or resume) both passes over ``table``; return the final run state."""
    state, outputs = _start(plan, options)
    saver = Checkpointer(options.checkpoint, plan.fingerprint, options.checkpoint_every)
    if plan.resume is None:
        saver.save(state, outputs)  # a kill before the first periodic checkpoint resumes from a clean start
    try:
        if state.phase == "filter":
            _filter_pass(table, state, outputs, options, saver)
            if state.rows_accepted == 0:
                raise _nothing_to_register(table, plan, state, options)
            state.phase = "observability" if options.observability == "final" else "summary"
            saver.save(state, outputs)
        if state.phase == "observability":
            _observability_pass(table, state, outputs, options, saver)
            state.phase = "summary"
            saver.save(state, outputs)
    finally:
        outputs.close()
    return state


def _nothing_to_register(table: Table, plan: RunPlan, state: RunState, options: RunOptions) -> ValueError:
    """The error of a pass 1 that accepted no row: no rows at all, or every row rejected."""
    if state.rows_read == 0 and plan.form == "synchronous":
        return FileFormatError(f"{table.label}: no data rows (the file holds only a header)")
    if state.rows_read == 0:
        return NoValidRowsError(
            f"no instant of the two plot files could be paired, so there is nothing to register; "
            f"see {options.out / 'unpaired.csv'} and {options.out / 'rejected.csv'}"
        )
    codes = ", ".join(f"{n} {code}" for code, n in sorted(state.rejected.items()))
    return NoValidRowsError(
        f"{table.label}: no valid rows to register: all {state.rows_read} rows rejected ({codes}), the "
        f"first at {state.first_rejection}; see {options.out / 'rejected.csv'}"
    )


def _start(plan: RunPlan, options: RunOptions) -> tuple[RunState, Outputs]:
    """A new state and fresh outputs, or the checkpoint's state and outputs cut back to its marks."""
    if plan.resume is None:
        state = RunState(
            OnlineRegistrar(options.config), plot_series=PlotSeries(PLOT_POINTS) if options.plots else None
        )
        return state, Outputs(options, plan.working_folder(), keep_rejected=plan.form == "asynchronous")
    payload = plan.resume
    options.message(
        f"registration register: resuming from checkpoint {options.checkpoint} at row "
        f"{payload['state']['rows_done']} (phase {payload['phase']})"
    )
    state = RunState.from_checkpoint(payload, options.config)
    return state, Outputs(options, plan.working_folder(), payload["outputs"])


def _filter_pass(
    table: Table, state: RunState, outputs: Outputs, options: RunOptions, saver: Checkpointer
) -> None:
    """Pass 1 from ``state.filter_pass`` to the end of the table."""
    layout, where = sync_layout(), state.filter_pass
    saver.start_pass(where.rows_done)
    bar = options.progress_bar(table.rows, where.rows_done, "registering")
    try:
        for first, frame in iter_frames(
            table.path, SYNC_COLUMNS, options.block_rows, start_row=where.rows_done
        ):
            block = check_frame(
                frame,
                layout,
                table.label,
                first_row=first,
                mode=options.on_bad_row,
                last_time=where.last_time,
            )
            where.last_time = block.last_time
            rejections = list(block.rejections) + _register_block(block, table, state, outputs, options)
            outputs.rejected.append_rows(rejected_rows(table.label, sorted(rejections, key=lambda r: r.row)))
            state.add_rejections(rejections)
            state.rows_read += block.n_rows
            state.rows_accepted += block.n_rows - len(rejections)
            where.rows_done = first + block.n_rows
            bar.update(block.n_rows)
            saver.save_every(state, outputs, where.rows_done)
    finally:
        bar.close()


def _register_block(
    block: CheckedBlock, table: Table, state: RunState, outputs: Outputs, options: RunOptions
) -> list[Rejection]:
    """Filter the accepted rows of one block and write them; return the rows whose step was not finite."""
    accepted = np.flatnonzero(block.accepted)
    rows, times = block.values[accepted, 1:], block.values[accepted, 0]
    rejections = []
    s = 0
    while s < len(accepted):
        result = state.registrar.update_block(rows[s:], times[s:], partial=True)
        n = result["n"]
        if n:
            _write_registered(
                block.first_row + accepted[s : s + n],
                times[s : s + n],
                rows[s : s + n],
                result,
                state,
                outputs,
                options,
            )
        s += n
        if s < len(accepted):  # this row's step would not be finite: never committed
            row = int(block.first_row + accepted[s])
            if options.on_bad_row != "skip":
                raise BadRowError(table.label, row, "*", "filter_non_finite", _NON_FINITE_STEP)
            rejections.append(Rejection(table.label, row, "*", "filter_non_finite", _NON_FINITE_STEP, "{}"))
            state.filter_rejected.add(row)
            s += 1
    return rejections


def _write_registered(
    rows_abs, times, rows, result: dict, state: RunState, outputs: Outputs, options: RunOptions
) -> None:
    """Append the estimates and positions of registered rows (K, 18) and add them to the statistics."""
    x, t_variant = result["x"], options.config.t_variant
    outputs.estimates.append_frame(estimate_frame(rows_abs, times, x, result["P"], result["nis"]))
    raw_a, raw_b = target_positions(rows, t_variant)
    cor_a, cor_b = target_positions(correct_rows(rows, x), t_variant)
    raw_diff, cor_diff = raw_a - raw_b, cor_a - cor_b
    outputs.positions.append_frame(position_frame(rows_abs, times, cor_a, cor_b, raw_diff, cor_diff))
    state.add_registered(times, result["nis"], raw_diff, cor_diff)
    if state.plot_series is not None:
        state.plot_series.add(times, x, result["P"], raw_diff, cor_diff, cor_a, cor_b, rows)


def _observability_pass(
    table: Table, state: RunState, outputs: Outputs, options: RunOptions, saver: Checkpointer
) -> None:
    """Pass 2: add up the information at the final estimate over the rows the filter used."""
    layout, where = sync_layout(), state.obs_pass
    x_final, config = state.registrar.x.copy(), options.config
    saver.start_pass(where.rows_done)
    bar = options.progress_bar(table.rows, where.rows_done, "observability")
    try:
        for first, frame in iter_frames(
            table.path, SYNC_COLUMNS, options.block_rows, start_row=where.rows_done
        ):
            block = check_frame(
                frame, layout, table.label, first_row=first, mode="skip", last_time=where.last_time
            )
            where.last_time = block.last_time
            accepted = np.flatnonzero(block.accepted)
            if state.filter_rejected:
                accepted = np.array(
                    [i for i in accepted if int(first + i) not in state.filter_rejected], dtype=np.int64
                )
            if len(accepted):
                J, used = information_at_estimate(
                    np.ascontiguousarray(block.values[accepted, 1:]), x_final, config.sigma0, config.t_variant
                )
                state.obs_info = state.obs_info + J
                state.obs_used += used
            where.rows_done = first + block.n_rows
            bar.update(block.n_rows)
            saver.save_every(state, outputs, where.rows_done)
    finally:
        bar.close()
