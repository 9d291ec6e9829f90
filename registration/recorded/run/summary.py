"""The summary of a recorded-data run (``summary.json``): rows, before/after statistics (m), final
estimates with 1 sigma (SI units and display units), observability, mean NIS and its consistency
gate, warnings about the inputs, outputs (where they are once published in ``--out``)."""

from __future__ import annotations

from typing import Sequence

import numpy as np

from registration.core.consistency import ConsistencyReport
from registration.core.observability import observability_report
from registration.online.contract import STATE_LABELS, STATE_NAMES, STATE_UNITS
from registration.online.result import estimate_rows
from registration.recorded.options import RunOptions
from registration.recorded.output.outputs import output_paths
from registration.recorded.run.plan import RunPlan, Table
from registration.recorded.run.runstate import RunState

__all__ = ["build_summary", "summary_consistency", "NIS_DOF"]

#: Degrees of freedom of one normalised innovation: the 3 ECEF components of X_A - X_B.
NIS_DOF = 3


def summary_consistency(summary: dict) -> ConsistencyReport | None:
    """The consistency gate of a run from its summary: the mean NIS over the registered rows
    against its chi-square band (None when no row was registered)."""
    accepted = summary["rows"]["accepted"]
    if summary.get("mean_nis") is None or not accepted:
        return None
    return ConsistencyReport.from_mean(summary["mean_nis"], accepted, NIS_DOF, "NIS")


def build_summary(
    table: Table,
    plan: RunPlan,
    state: RunState,
    options: RunOptions,
    elapsed_s: float,
    warnings: Sequence[str] = (),
) -> dict:
    """The summary dict of a finished run that took ``elapsed_s`` seconds; ``warnings``: about its inputs."""
    final = options.observability == "final"
    info = state.obs_info if final else state.registrar.info
    report = observability_report(
        info, np.array(options.config.prior_sigma), STATE_NAMES, STATE_LABELS, STATE_UNITS
    )
    accepted = state.rows_accepted
    summary = {
        "table": table.label,
        "state_names": list(STATE_NAMES),
        "config": options.config.to_json(),
        "options": _options_json(options),
        "rows": {
            "read": state.rows_read,
            "accepted": accepted,
            "rejected": sum(state.rejected.values()),
            "rejected_by_reason": dict(sorted(state.rejected.items())),
            "used_for_observability": state.obs_used,
        },
        "time_span_s": [state.first_time, state.last_time],
        "before": state.raw.summary(),
        "after": state.corrected.summary(),
        "estimates": _final_estimates(state, report),
        "observability": {
            **report.to_json(),
            "information": "at the final estimate (second pass)"
            if final
            else "accumulated by the filter at its linearisation points",
        },
        "mean_nis": state.nis_sum / accepted if accepted else None,
        "outputs": {k: str(p) for k, p in output_paths(options).items()},
        "form": plan.form,
        "inputs": plan.input_list(),
        "fingerprint": plan.fingerprint,
        "warnings": list(warnings),
    }
    gate = summary_consistency(summary)
    summary["consistency"] = None if gate is None else gate.to_json()
    if table.pairing is not None:
        summary["pairing"] = table.pairing
    summary["elapsed_s"] = elapsed_s
    return summary


def _options_json(options: RunOptions) -> dict:
    return {
        "on_bad_row": options.on_bad_row,
        "format": options.out_format,
        "chunk_rows": options.chunk_rows,
        "block_rows": options.block_rows,
        "checkpoint": None if options.checkpoint is None else str(options.checkpoint),
        "checkpoint_every": options.checkpoint_every,
        "observability": options.observability,
    }


def _final_estimates(state: RunState, report) -> list[dict]:
    """:func:`registration.online.result.estimate_rows` with the values also in degrees or metres."""
    rows = estimate_rows(state.registrar.x, state.registrar.P, report)
    for r in rows:
        k = np.degrees(1.0) if r["unit"] == "rad" else 1.0
        r["display_unit"] = "deg" if r["unit"] == "rad" else "m"
        r["estimate_display"], r["sigma_display"] = r["estimate"] * k, r["sigma"] * k
    return rows
