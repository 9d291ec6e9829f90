"""First stage of a run: check the inputs, fingerprint them, find the checkpoint to resume from.

:func:`plan_run` returns a :class:`RunPlan`: the form (one synchronous table, or two plot files
of the asynchronous form), each input's sha256, the fingerprint (sha256 of the inputs' contents
and of every option that changes the results), the folder the run writes into
(:mod:`registration.io.output.outfolder`: a new one inside ``--out``, or the one the checkpoint
records) and, when ``options.checkpoint`` exists and was written for the same fingerprint, its
payload or, for a finished run, its summary.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from pathlib import Path

from registration.io.files.tablefile import FileFormatError, file_format
from registration.io.output.checkpoint import CheckpointError, load_checkpoint
from registration.io.output.outfolder import RunFolder, mark_in_place, new_run_folder, prepare_out, publish
from registration.recorded.options import PairingOptions, RunOptions
from registration.recorded.reading.formats import count_rows, iter_frames, read_columns, scan_file
from registration.recorded.reading.rowcheck import sync_layout
from registration.recorded.reading.sources import plan_sources
from registration.recorded.reading.unitcheck import angle_unit_warnings

__all__ = ["Table", "RunPlan", "plan_run", "fingerprint", "table_rows", "input_warnings"]


@dataclass
class Table:
    """The synchronous table the filter reads: its path, its rows (None: unknown), for the
    asynchronous form the pairing report, and the path messages and rejected.csv name it by
    (``published``: where it will be in ``--out``; default ``path``)."""

    path: Path
    rows: int | None
    pairing: dict | None = None
    published: Path | None = None

    @property
    def label(self) -> str:
        return str(self.path if self.published is None else self.published)


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
    folder: RunFolder | None = None  # where the run writes (None for a finished run)

    def working_folder(self) -> RunFolder:
        """The folder the run writes into (the plan of every run but a finished one has it)."""
        if self.folder is None:
            raise RuntimeError("the plan of a finished run has no folder to write into")
        return self.folder

    def async_pairing(self) -> PairingOptions:
        """The pairing options of the asynchronous form (the synchronous form has none)."""
        if self.pairing is None:
            raise RuntimeError("the synchronous form has no pairing options")
        return self.pairing

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
        raise ValueError(
            "--nav is for the asynchronous form (two plot files); a synchronous table carries its navigation"
        )
    for p in inputs + navs:
        file_format(p)
        if not p.is_file():
            raise FileFormatError(f"{p}: no such file")
    return "synchronous" if len(inputs) == 1 else "asynchronous"


def _check_has_rows(path: Path, newlines: int) -> None:
    """Refuse a table with a header and no data rows, naming it."""
    if file_format(path) == "parquet":
        empty = count_rows(path) == 0
    else:  # a CSV of more than two lines has rows; shorter ones are read to make sure
        empty = newlines <= 2 and next(iter_frames(path, read_columns(path), 1), None) is None
    if empty:
        raise FileFormatError(f"{path}: no data rows (the file holds only a header)")


def plan_run(inputs, options: RunOptions) -> RunPlan:
    """Check the inputs and ``options.out``, hash the inputs, look up the checkpoint, and choose
    (usually: create) the folder the run writes into."""
    inputs = [Path(p) for p in inputs]
    navs = [Path(p) for p in options.nav]
    form = _check_inputs(inputs, navs)
    scans = {str(p): scan_file(p) for p in inputs + navs}
    for p in inputs + navs:
        _check_has_rows(p, scans[str(p)][1])
    prepare_out(options.out)
    pairing = options.pairing or (PairingOptions() if form == "asynchronous" else None)
    inputs_key = {
        "inputs": [scans[str(p)][0] for p in inputs],
        "nav": [scans[str(p)][0] for p in navs],
        "form": form,
        "on_bad_row": options.on_bad_row,
        "format": options.out_format,
        "block_rows": options.block_rows,
        "pairing": pairing.to_json() if pairing else None,
    }
    fp = fingerprint(
        {**inputs_key, "config": options.config.to_json(), "observability": options.observability}
    )
    plan = RunPlan(inputs, navs, form, pairing, scans, inputs_key, fp)
    if options.checkpoint is not None and Path(options.checkpoint).exists():
        plan.resume = _matching_checkpoint(options, fp)
        if plan.resume.get("phase") == "done":
            plan.finished = _finished_summary(options, plan.resume)
            return plan
        plan.folder = _resume_folder(options, plan.resume, fp)
    else:
        plan.folder = new_run_folder(options.out, options.checkpoint)
    return plan


def _matching_checkpoint(options: RunOptions, fp: str) -> dict:
    payload = load_checkpoint(options.checkpoint)
    if payload.get("fingerprint") != fp:
        raise CheckpointError(
            f"checkpoint {options.checkpoint} was written for other input files or options (its fingerprint "
            "does not match these inputs' contents and options); rerun the exact command that wrote it, or "
            "delete it to start over"
        )
    return payload


def _recorded_folder(options: RunOptions, payload: dict) -> Path | None:
    name = payload.get("outputs", {}).get("folder")
    return None if name is None else options.out / name


def _resume_folder(options: RunOptions, payload: dict, fp: str) -> RunFolder:
    """The folder the checkpoint's run writes into. A checkpoint without one (older versions), or
    whose folder is gone while ``--out`` holds a summary of the same fingerprint, resumes in ``--out``."""
    path = _recorded_folder(options, payload)
    if path is not None and path.is_dir():
        return RunFolder(options.out, path)
    if path is not None and _summary_fingerprint(options.out) != fp:
        raise CheckpointError(
            f"checkpoint {options.checkpoint} continues a run whose unfinished outputs were in {path}, which "
            "no longer exists; delete the checkpoint to start over"
        )
    folder = RunFolder(options.out, options.out)
    mark_in_place(folder, options.checkpoint)
    return folder


def _summary_fingerprint(out: Path) -> str | None:
    try:
        return json.loads((out / "summary.json").read_text()).get("fingerprint")
    except (OSError, ValueError, AttributeError):
        return None


def _finished_summary(options: RunOptions, payload: dict) -> dict:
    """The summary of a finished run, published now if a kill came between the end and the publication."""
    path = _recorded_folder(options, payload)
    if path is not None and path.is_dir():
        publish(RunFolder(options.out, path))
    summary_path = options.out / "summary.json"
    if not summary_path.exists():
        raise CheckpointError(
            f"checkpoint {options.checkpoint} says the run is complete but {summary_path} is missing; delete "
            "the checkpoint to recompute"
        )
    options.message(
        f"registration register: run already complete (checkpoint {options.checkpoint}); delete it to "
        "recompute"
    )
    return json.loads(summary_path.read_text())


def input_warnings(plan: RunPlan) -> list[str]:
    """The warnings of :func:`~registration.recorded.reading.unitcheck.angle_unit_warnings` for
    every input file of ``plan`` (angle columns that seem to hold radians), in reading order."""
    if plan.form == "synchronous":
        jobs = [(plan.inputs[0], sync_layout())]
    else:
        jobs = [(s.path, s.layout) for s in plan_sources(plan.inputs, plan.navs, plan.async_pairing())]
    return [w for path, layout in jobs for w in angle_unit_warnings(path, layout)]
