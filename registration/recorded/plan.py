"""First stage of a run: check the inputs, fingerprint them, find the checkpoint to resume from.

:func:`plan_run` returns a :class:`RunPlan`: the form (one synchronous table, or two plot files
of the asynchronous form), each input's sha256, the fingerprint (sha256 of the inputs' contents
and of every option that changes the results) and, when ``options.checkpoint`` exists and was
written for the same fingerprint, its payload or, for a finished run, its summary.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from pathlib import Path

from registration.recorded.checkpoint import CheckpointError, load_checkpoint
from registration.recorded.columns import FileFormatError
from registration.recorded.formats import count_rows, file_format, scan_file
from registration.recorded.options import PairingOptions, RunOptions

__all__ = ["Table", "RunPlan", "plan_run", "fingerprint", "table_rows"]


@dataclass
class Table:
    """The synchronous table the filter reads: its path, its rows (None: unknown) and, for the
    asynchronous form, the pairing report."""

    path: Path
    rows: int | None
    pairing: dict | None = None


@dataclass
class RunPlan:
    """What a run works on; ``resume`` is the checkpoint payload to continue from (None: start),
    ``finished`` the summary of a run the checkpoint marks as done."""

    inputs: list[Path]
    navs: list[Path]
    form: str  # "synchronous" or "asynchronous"
    pairing: PairingOptions | None
    scans: dict  # str(path) -> (sha256, newlines)
    inputs_key: dict  # what the pairing's fingerprint covers
    fingerprint: str
    resume: dict | None = None
    finished: dict | None = None

    def newlines(self, path: Path) -> int:
        return self.scans[str(path)][1]

    def sync_table(self) -> Table:
        """The table of the synchronous form: the one input."""
        return Table(self.inputs[0], table_rows(self.inputs[0], self.newlines(self.inputs[0])))

    def input_list(self) -> list[dict]:
        """``[{"path", "sha256"}]`` of every input and navigation file."""
        return [{"path": str(p), "sha256": self.scans[str(p)][0]} for p in self.inputs + self.navs]


def fingerprint(parts: dict) -> str:
    """sha256 (hex) of a JSON dict of the things a result depends on."""
    return hashlib.sha256(json.dumps(parts, sort_keys=True, default=str).encode()).hexdigest()


def table_rows(path: Path, newlines: int) -> int | None:
    """Rows of a table: from the Parquet metadata, or the newlines of a CSV less its header."""
    if file_format(path) == "parquet":
        return count_rows(path)
    return max(newlines - 1, 0)


def _check_inputs(inputs: list[Path], navs: list[Path]) -> str:
    if not inputs or len(inputs) > 2:
        raise ValueError("give one synchronous table, or two per-sensor plot files (radar A, radar B)")
    if len(inputs) == 1 and navs:
        raise ValueError("--nav is for the asynchronous form (two plot files); a synchronous table carries its navigation")
    for p in inputs + navs:
        file_format(p)
        if not p.is_file():
            raise FileFormatError(f"{p}: no such file")
    return "synchronous" if len(inputs) == 1 else "asynchronous"


def plan_run(inputs, options: RunOptions) -> RunPlan:
    """Check the inputs, create ``options.out``, hash the inputs and look up the checkpoint."""
    inputs = [Path(p) for p in inputs]
    navs = [Path(p) for p in options.nav]
    form = _check_inputs(inputs, navs)
    options.out.mkdir(parents=True, exist_ok=True)
    scans = {str(p): scan_file(p) for p in inputs + navs}
    pairing = options.pairing or (PairingOptions() if form == "asynchronous" else None)
    inputs_key = {
        "inputs": [scans[str(p)][0] for p in inputs], "nav": [scans[str(p)][0] for p in navs], "form": form,
        "on_bad_row": options.on_bad_row, "format": options.out_format, "block_rows": options.block_rows,
        "pairing": pairing.to_json() if pairing else None,
    }
    fp = fingerprint({**inputs_key, "config": options.config.to_json(), "observability": options.observability})
    plan = RunPlan(inputs, navs, form, pairing, scans, inputs_key, fp)
    if options.checkpoint is not None and Path(options.checkpoint).exists():
        plan.resume = _matching_checkpoint(options, fp)
        if plan.resume.get("phase") == "done":
            plan.finished = _finished_summary(options)
    return plan


def _matching_checkpoint(options: RunOptions, fp: str) -> dict:
    payload = load_checkpoint(options.checkpoint)
    if payload.get("fingerprint") != fp:
        raise CheckpointError(
            f"checkpoint {options.checkpoint} was written for other input files or options (its fingerprint does not "
            "match these inputs' contents and options); rerun the exact command that wrote it, or delete it to start over"
        )
    return payload


def _finished_summary(options: RunOptions) -> dict:
    summary_path = options.out / "summary.json"
    if not summary_path.exists():
        raise CheckpointError(f"checkpoint {options.checkpoint} says the run is complete but {summary_path} is missing; delete the checkpoint to recompute")
    options.message(f"registration register: run already complete (checkpoint {options.checkpoint}); delete it to recompute")
    return json.loads(summary_path.read_text())
