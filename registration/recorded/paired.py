"""The pairing stage of the asynchronous form: two plot files (+ navigation) become the
synchronous table ``OUT/paired.csv|parquet`` that the filter reads.

All or nothing: the table is written under a temporary name and published by a rename with
``pairing.json`` (its fingerprint, sha256 and report); a rerun with the same inputs and options
reuses a published table, an interrupted pairing starts again (it is deterministic and much
cheaper than the filter). Bad rows go to ``rejected.csv``, unpaired instants to ``unpaired.csv``.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

from registration.recorded.columns import PAIRED_COLUMNS, REJECTED_COLUMNS, SYNC_COLUMNS, UNPAIRED_COLUMNS
from registration.recorded.formats import scan_file
from registration.recorded.options import RunOptions
from registration.recorded.outputs import rejected_rows
from registration.recorded.pairing import Pairer
from registration.recorded.plan import RunPlan, Table, fingerprint, table_rows
from registration.recorded.sources import plan_sources
from registration.recorded.writers import CsvAppender, ParquetFileWriter, write_json_atomic

__all__ = ["pair_inputs"]


def pair_inputs(plan: RunPlan, options: RunOptions) -> Table:
    """The published paired table of ``plan``'s inputs (made now unless a matching one exists)."""
    paired = options.out / f"paired{options.output_suffix}"
    meta_path = options.out / "pairing.json"
    fp = fingerprint(plan.inputs_key)
    report = _published_report(paired, meta_path, fp)
    if report is not None:
        options.message(f"registration register: reusing the pairing in {paired}")
        return Table(paired, report["paired"], report)
    if plan.resume is not None:
        options.message("registration register: the pairing stage is redone (its result was missing or changed)")
    tmp = paired.with_name(paired.name + ".partial")
    report = _pair_into(tmp, plan, options)
    os.replace(tmp, paired)
    write_json_atomic(meta_path, {"fingerprint": fp, "paired_sha256": scan_file(paired)[0], "report": report})
    options.message(f"registration register: paired {report['paired']} of {report['instants']} instants "
                    f"({report['exact']} exact, {report['interpolated']} interpolated, {report['unpaired']} unpaired) into {paired}")
    return Table(paired, report["paired"], report)


def _published_report(paired: Path, meta_path: Path, fp: str) -> dict | None:
    """The report of a published pairing made from the same inputs and options, else None."""
    if not (meta_path.exists() and paired.exists()):
        return None
    try:
        meta = json.loads(meta_path.read_text())
    except json.JSONDecodeError:
        meta = {}
    if meta.get("fingerprint") == fp and meta.get("paired_sha256") == scan_file(paired)[0]:
        return meta["report"]
    return None


def _pair_into(tmp: Path, plan: RunPlan, options: RunOptions) -> dict:
    """Pair the inputs into the table file ``tmp``, rejected.csv and unpaired.csv; return the report."""
    sources = plan_sources(plan.inputs, plan.navs, plan.pairing)
    rejected = CsvAppender(options.out / "rejected.csv", REJECTED_COLUMNS)
    unpaired = CsvAppender(options.out / "unpaired.csv", UNPAIRED_COLUMNS)
    ref = next(s for s in sources if s.plots_of == plan.pairing.pair_at)
    bar = options.progress_bar(table_rows(ref.path, plan.newlines(ref.path)), 0, "pairing")
    table = CsvAppender(tmp, PAIRED_COLUMNS) if options.out_format == "csv" else ParquetFileWriter(tmp, SYNC_COLUMNS)
    pairer = Pairer(sources, plan.pairing, chunk_rows=options.block_rows, mode=options.on_bad_row)
    try:
        for block in pairer.blocks():
            for path, rejections in block.rejections:
                rejected.append_rows(rejected_rows(path, rejections))
            unpaired.append_rows(block.unpaired)
            if block.pairs is not None:
                table.append_frame(block.pairs)
            if block.rows_done is not None:
                bar.update(block.rows_done - bar.n)
    finally:
        bar.close()
        for w in (rejected, unpaired):
            w.sync()
            w.close()
    table.sync()
    table.close()
    return {**pairer.report(), "rejected_rows_written": rejected.rows}
