"""Check every row of recorded inputs without estimating (``registration register --validate-only``)."""

from __future__ import annotations

from pathlib import Path

from registration.recorded.options import PairingOptions, RunOptions
from registration.recorded.reading.formats import iter_frames
from registration.recorded.reading.rowcheck import Layout, check_frame, sync_layout
from registration.recorded.reading.sources import plan_sources

__all__ = ["validate_files"]


def validate_files(inputs, options: RunOptions, max_listed: int = 20) -> dict:
    """Check every row of the inputs; return counts per file and reason.

    Uses the same layouts and rules as :func:`registration.recorded.run_register` (all rows are
    read, whatever ``on_bad_row`` says). Returns ``{"files": {path: {"layout", "rows", "accepted",
    "rejected_by_reason"}}, "problems": [the first max_listed rejections]}``.
    """
    inputs = [Path(p) for p in inputs]
    navs = [Path(p) for p in options.nav]
    if len(inputs) == 1:
        jobs = [(inputs[0], sync_layout())]
    else:
        jobs = [
            (src.path, src.layout) for src in plan_sources(inputs, navs, options.pairing or PairingOptions())
        ]
    files: dict[str, dict] = {}
    problems: list[dict] = []
    for path, layout in jobs:
        files[str(path)] = _validate_file(path, layout, options.chunk_rows, problems, max_listed)
    return {"files": files, "problems": problems}


def _validate_file(path: Path, layout: Layout, chunk_rows: int, problems: list, max_listed: int) -> dict:
    """Counts of one file; appends its rejections to ``problems`` while fewer than ``max_listed``."""
    last, rows, acc = None, 0, 0
    by: dict[str, int] = {}
    for first, frame in iter_frames(path, layout.columns, chunk_rows):
        blk = check_frame(frame, layout, str(path), first_row=first, mode="skip", last_time=last)
        last = blk.last_time
        rows += blk.n_rows
        acc += int(blk.accepted.sum())
        for r in blk.rejections:
            by[r.code] = by.get(r.code, 0) + 1
            if len(problems) < max_listed:
                problems.append(
                    {"file": str(path), "row": r.row, "column": r.column, "code": r.code, "reason": r.reason}
                )
    return {"layout": layout.name, "rows": rows, "accepted": acc, "rejected_by_reason": by}
