"""The pairing stage of the asynchronous form: two plot files (+ navigation) become the
synchronous table ``paired.csv|parquet`` in the run's folder, which the filter reads.

All or nothing: the table is written under a temporary name and published by a rename with
``pairing.json`` (its fingerprint, sha256, report, and the sha256 of the pairing's part of
``rejected.csv`` and of ``unpaired.csv``). A resumed run reuses the table in its folder; a new run
with the same inputs and options takes over the one an earlier run left in ``--out`` (the table
hard-linked, its rejected rows and unpaired instants copied); an interrupted pairing starts again
(it is deterministic and much cheaper than the filter). Bad rows go to ``rejected.csv``, unpaired
instants to ``unpaired.csv``.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
from pathlib import Path

from registration.io.output.outfolder import RunFolder
from registration.recorded.options import RunOptions
from registration.recorded.output.outputs import rejected_rows
from registration.recorded.output.writers import CsvAppender, ParquetFileWriter, write_json_atomic
from registration.recorded.pairing.pairs import Pairer
from registration.recorded.reading.columns import (
    PAIRED_COLUMNS,
    REJECTED_COLUMNS,
    SYNC_COLUMNS,
    UNPAIRED_COLUMNS,
)
from registration.recorded.reading.formats import scan_file
from registration.recorded.reading.sources import plan_sources
from registration.recorded.run.plan import RunPlan, Table, fingerprint, table_rows

__all__ = ["pair_inputs"]


def pair_inputs(plan: RunPlan, options: RunOptions) -> Table:
    """The published paired table of ``plan``'s inputs in
    the run folder (made now unless a matching one exists)."""
    folder = plan.working_folder()
    paired = folder.path / f"paired{options.output_suffix}"
    meta_path = folder.path / "pairing.json"
    fp = fingerprint(plan.inputs_key)
    meta = _published_meta(paired, meta_path, fp)
    if meta is None and not folder.in_place:
        meta = _take_over(folder, paired.name, fp)
    if meta is not None:
        options.message(f"registration register: reusing the pairing in {folder.final(paired)}")
        return Table(paired, meta["report"]["paired"], meta["report"], folder.final(paired))
    if plan.resume is not None:
        options.message(
            "registration register: the pairing stage is redone (its result was missing or changed)"
        )
    tmp = paired.with_name(paired.name + ".partial")
    report = _pair_into(tmp, plan, options)
    os.replace(tmp, paired)
    rejected = folder.path / "rejected.csv"
    write_json_atomic(
        meta_path,
        {
            "fingerprint": fp,
            "paired_sha256": scan_file(paired)[0],
            "report": report,
            "rejected_size": rejected.stat().st_size,
            "rejected_sha256": scan_file(rejected)[0],
            "unpaired_sha256": scan_file(folder.path / "unpaired.csv")[0],
        },
    )
    options.message(
        f"registration register: paired {report['paired']} of {report['instants']} instants "
        f"({report['exact']} exact, {report['interpolated']} interpolated, {report['unpaired']} unpaired) "
        f"into {folder.final(paired)}"
    )
    return Table(paired, report["paired"], report, folder.final(paired))


def _published_meta(paired: Path, meta_path: Path, fp: str) -> dict | None:
    """``pairing.json`` of a published pairing made from the same inputs and options, else None."""
    if not (meta_path.exists() and paired.exists()):
        return None
    try:
        meta = json.loads(meta_path.read_text())
    except json.JSONDecodeError:
        meta = {}
    if (
        isinstance(meta, dict)
        and meta.get("fingerprint") == fp
        and meta.get("paired_sha256") == scan_file(paired)[0]
    ):
        return meta
    return None


def _take_over(folder: RunFolder, name: str, fp: str) -> dict | None:
    """Bring the pairing an earlier run left in ``--out`` into the run folder if it was made from
    the same inputs and options and its rejected rows and unpaired instants are intact."""
    out, work = folder.out, folder.path
    meta = _published_meta(out / name, out / "pairing.json", fp)
    if meta is None or "rejected_size" not in meta or not (out / "unpaired.csv").exists():
        return None
    if scan_file(out / "unpaired.csv")[0] != meta["unpaired_sha256"]:
        return None
    if (
        _copy_prefix(out / "rejected.csv", work / "rejected.csv", meta["rejected_size"])
        != meta["rejected_sha256"]
    ):
        (work / "rejected.csv").unlink(missing_ok=True)
        return None
    shutil.copyfile(out / "unpaired.csv", work / "unpaired.csv")
    try:
        os.link(out / name, work / name)  # never written in place: a new pairing replaces it by a rename
    except OSError:
        shutil.copyfile(out / name, work / name)
    write_json_atomic(work / "pairing.json", meta)
    return meta


def _copy_prefix(src: Path, dst: Path, size: int) -> str | None:
    """Copy the first ``size`` bytes of ``src`` to ``dst``; their sha256 (None if ``src`` is shorter)."""
    h, left = hashlib.sha256(), int(size)
    try:
        with open(src, "rb") as fin, open(dst, "wb") as fout:
            while left > 0:
                chunk = fin.read(min(left, 1 << 22))
                if not chunk:
                    return None
                h.update(chunk)
                fout.write(chunk)
                left -= len(chunk)
    except FileNotFoundError:
        return None
    return h.hexdigest()


def _pair_into(tmp: Path, plan: RunPlan, options: RunOptions) -> dict:
    """Pair the inputs into the table file ``tmp``, rejected.csv and unpaired.csv; return the report."""
    pairing, folder = plan.async_pairing(), plan.working_folder()
    sources = plan_sources(plan.inputs, plan.navs, pairing)
    rejected = CsvAppender(folder.path / "rejected.csv", REJECTED_COLUMNS)
    unpaired = CsvAppender(folder.path / "unpaired.csv", UNPAIRED_COLUMNS)
    ref = next(s for s in sources if s.plots_of == pairing.pair_at)
    bar = options.progress_bar(table_rows(ref.path, plan.newlines(ref.path)), 0, "pairing")
    table = (
        CsvAppender(tmp, PAIRED_COLUMNS)
        if options.out_format == "csv"
        else ParquetFileWriter(tmp, SYNC_COLUMNS)
    )
    pairer = Pairer(sources, pairing, chunk_rows=options.block_rows, mode=options.on_bad_row)
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
