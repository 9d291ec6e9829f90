"""Register recorded files: streaming, resumable, nothing lost (issue 6).

:func:`run_register` is what ``registration register`` runs. Stages:

1. **Pairing** (asynchronous form only, :mod:`registration.pairing`): two plot files (+ navigation)
   become a synchronous table ``OUT/paired.csv`` (or ``.parquet``). It is all-or-nothing: written
   under a temporary name and published with ``pairing.json``; an interrupted pairing starts again
   (it is deterministic and much cheaper than the filter).
2. **Filter**: the synchronous table is read in blocks of ``chunk_rows`` rows aligned on absolute
   row numbers, validated (:mod:`registration.rowcheck`) and run through
   :meth:`registration.online.OnlineRegistrar.update_block` (one compiled loop per block with fixed
   Q, carrying x, P and the information). Per block it appends the estimates (degrees and metres,
   with 1 sigma) and the corrected ECEF positions, and accumulates the before/after statistics.
3. **Observability** (default ``final``): a second pass evaluates the information matrix
   sum H^T R^-1 H at the final estimate, exactly like :func:`registration.online.register`;
   ``filter`` uses the information the filter accumulated at its own linearisation points instead
   (one pass, but at the raw measurements it can make inseparable states look separable).
4. **Summary**: ``summary.json``, the plots, and a final checkpoint marked ``done``.

Checkpoints (``checkpoint=FILE``) hold the filter state, the validator's last time, the
statistics, the counters and the byte length (CSV) or part count (Parquet) of every output, plus a
fingerprint (sha256 of the input files' contents and of every option that changes the results).
They are written at block boundaries every ``checkpoint_every`` rows, after the outputs have been
flushed and fsync'ed. A rerun of the same command resumes: outputs are cut back to the recorded
lengths (so rows written after the checkpoint are rewritten once, never duplicated) and the
blocks after the checkpoint are the same blocks an uninterrupted run sees, so every number comes
out bit-for-bit identical.
"""

from __future__ import annotations

import hashlib
import json
import os
import sys
import time as _time
from dataclasses import dataclass, field
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from registration import _codegen as _loader
from registration.recorded.checkpoint import CheckpointError, load_checkpoint, save_checkpoint
from registration.recorded.formats import SYNC_COLUMNS, CsvAppender, FileFormatError, PartsWriter, file_format, iter_frames, read_columns
from registration.core.observability import observability_report
from registration.online.filter import (
    OnlineRegistrar, RegistrationConfig, RegistrationResult, _corrected_rows, _target_positions, information_at_estimate,
)
from registration.recorded.rowcheck import BadRowError, Rejection, check_frame, sync_layout
from registration.online.contract import IS_ANGLE, N_STATE, STATE_LABELS, STATE_NAMES, STATE_UNITS

__all__ = ["RunOptions", "run_register", "ESTIMATE_COLUMNS", "POSITION_COLUMNS", "REJECTED_COLUMNS", "UNPAIRED_COLUMNS"]

ESTIMATE_COLUMNS = ["row", "time_s"] + [
    c for i, n in enumerate(STATE_NAMES) for c in (f"{n}_{'deg' if IS_ANGLE[i] else 'm'}", f"{n}_sigma_{'deg' if IS_ANGLE[i] else 'm'}")
] + ["nis"]
POSITION_COLUMNS = ["row", "time_s", "a_ecef_x_m", "a_ecef_y_m", "a_ecef_z_m", "b_ecef_x_m", "b_ecef_y_m", "b_ecef_z_m",
                    "diff_raw_x_m", "diff_raw_y_m", "diff_raw_z_m", "diff_x_m", "diff_y_m", "diff_z_m"]
REJECTED_COLUMNS = ["file", "row", "column", "reason_code", "reason", "values"]
UNPAIRED_COLUMNS = ["time_s", "file", "row", "reason"]
_PLOT_POINTS = 4000


@dataclass
class RunOptions:
    out: Path
    config: RegistrationConfig = field(default_factory=RegistrationConfig)
    on_bad_row: str = "stop"
    checkpoint: Path | None = None
    checkpoint_every: int = 100_000
    chunk_rows: int = 20_000
    out_format: str = "csv"
    observability: str = "final"
    plots: bool = True
    progress: bool = True
    nav: list = field(default_factory=list)
    pairing: object = None  # pairing.PairingOptions for the asynchronous form
    log: object = None  # callable(str) for messages; default: print to stderr

    def __post_init__(self):
        if self.on_bad_row not in ("stop", "skip"):
            raise ValueError(f"on_bad_row: expected 'stop' or 'skip', got {self.on_bad_row!r}")
        if self.out_format not in ("csv", "parquet"):
            raise ValueError(f"out_format: expected 'csv' or 'parquet', got {self.out_format!r}")
        if self.observability not in ("final", "filter"):
            raise ValueError(f"observability: expected 'final' or 'filter', got {self.observability!r}")
        if int(self.chunk_rows) < 1 or int(self.checkpoint_every) < 1:
            raise ValueError("chunk_rows and checkpoint_every: must be >= 1 row")
        self.out = Path(self.out)

    @property
    def block_rows(self) -> int:
        """Rows per processing block: checkpoints fall on block boundaries."""
        if self.checkpoint is not None:
            return int(min(self.chunk_rows, self.checkpoint_every))
        return int(self.chunk_rows)


# --------------------------------------------------------------------------- helpers
def _scan_file(path) -> tuple[str, int]:
    """sha256 of a file's bytes and its number of newlines (a row estimate for CSV progress)."""
    h, lines = hashlib.sha256(), 0
    try:
        with open(path, "rb") as f:
            while chunk := f.read(1 << 22):
                h.update(chunk)
                lines += chunk.count(b"\n")
    except OSError as exc:
        raise FileFormatError(f"{path}: {exc}") from exc
    return h.hexdigest(), lines


def _total_rows(path, newlines: int) -> int | None:
    if file_format(path) == "parquet":
        from registration.recorded.formats import count_rows

        return count_rows(path)
    return max(newlines - 1, 0)


class _Stats:
    """Streaming max |.|, mean and sample std per axis (Chan et al. pairwise merge), exact to save."""

    def __init__(self, state: dict | None = None):
        if state is None:
            self.n, self.mean, self.m2, self.maxabs = 0, np.zeros(3), np.zeros(3), np.zeros(3)
        else:
            self.n = int(state["n"])
            self.mean, self.m2, self.maxabs = (np.asarray(state[k], dtype=float).reshape(3) for k in ("mean", "m2", "maxabs"))

    def add(self, z: np.ndarray) -> None:
        if not len(z):
            return
        nb = len(z)
        mb = z.mean(axis=0)
        m2b = ((z - mb) ** 2).sum(axis=0)
        n = self.n + nb
        delta = mb - self.mean
        self.mean = self.mean + delta * (nb / n)
        self.m2 = self.m2 + m2b + delta**2 * (self.n * nb / n)
        self.maxabs = np.maximum(self.maxabs, np.abs(z).max(axis=0))
        self.n = n

    def state(self) -> dict:
        return {"n": self.n, "mean": self.mean, "m2": self.m2, "maxabs": self.maxabs}

    def summary(self) -> dict:
        std = np.sqrt(self.m2 / (self.n - 1)) if self.n > 1 else np.zeros(3)
        return {"max": self.maxabs.tolist(), "mean": self.mean.tolist(), "std": std.tolist()}


def _outputs(out: Path, fmt: str):
    ext = ".csv" if fmt == "csv" else ".parquet"
    return {"estimates": (out / f"estimates{ext}", ESTIMATE_COLUMNS), "positions": (out / f"positions{ext}", POSITION_COLUMNS)}


def _open_output(path, columns, fmt, resume):
    if fmt == "csv":
        return CsvAppender(path, columns, resume=resume)
    return PartsWriter(path, columns, resume=resume)


def _fingerprint(parts: dict) -> str:
    return hashlib.sha256(json.dumps(parts, sort_keys=True, default=str).encode()).hexdigest()


def _write_json_atomic(path: Path, obj) -> None:
    tmp = path.with_name(path.name + ".tmp")
    with open(tmp, "w") as f:
        f.write(json.dumps(obj, indent=2) + "\n")
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def _rejected_rows(path, rejections: list[Rejection]) -> list[list]:
    return [[str(path), r.row, r.column, r.code, r.reason, r.values] for r in rejections]


def _progress(total, initial, desc, enabled):
    from tqdm import tqdm

    return tqdm(total=total, initial=initial, desc=desc, unit="row", unit_scale=True, disable=not enabled,
                file=sys.stderr, dynamic_ncols=True, mininterval=0.5)


# --------------------------------------------------------------------------- the run
def run_register(inputs, options: RunOptions) -> dict:
    """Register recorded data: one synchronous table, or two per-sensor plot files (+ navigation).

    Writes into ``options.out``: ``estimates.csv|parquet``, ``positions.csv|parquet``,
    ``rejected.csv``, ``summary.json``, the plots and, for the asynchronous form, ``paired.*``,
    ``unpaired.csv`` and ``pairing.json``. Returns the summary (also in ``summary.json``).

    Raises ValueError subclasses for bad input: :class:`registration.io.FileFormatError`,
    :class:`registration.rowcheck.BadRowError` (``stop`` mode), :class:`CheckpointError`.
    """
    inputs = [Path(p) for p in inputs]
    navs = [Path(p) for p in options.nav]
    log = options.log or (lambda msg: print(msg, file=sys.stderr))
    if not inputs or len(inputs) > 2:
        raise ValueError("give one synchronous table, or two per-sensor plot files (radar A, radar B)")
    if len(inputs) == 1 and navs:
        raise ValueError("--nav is for the asynchronous form (two plot files); a synchronous table carries its navigation")
    for p in inputs + navs:
        file_format(p)
        if not p.is_file():
            raise FileFormatError(f"{p}: no such file")
    form = "synchronous" if len(inputs) == 1 else "asynchronous"
    out = options.out
    out.mkdir(parents=True, exist_ok=True)
    t0 = _time.perf_counter()

    scans = {str(p): _scan_file(p) for p in inputs + navs}
    if form == "asynchronous":
        from registration.recorded.pairing import PairingOptions

        options.pairing = options.pairing or PairingOptions()
    common = {
        "inputs": [scans[str(p)][0] for p in inputs], "nav": [scans[str(p)][0] for p in navs], "form": form,
        "on_bad_row": options.on_bad_row, "format": options.out_format, "block_rows": options.block_rows,
        "pairing": options.pairing.to_json() if options.pairing else None,
    }
    fingerprint = _fingerprint({**common, "config": options.config.to_json(), "observability": options.observability})

    ckpt = None
    if options.checkpoint is not None and Path(options.checkpoint).exists():
        ckpt = load_checkpoint(options.checkpoint)
        if ckpt.get("fingerprint") != fingerprint:
            raise CheckpointError(
                f"checkpoint {options.checkpoint} was written for other input files or options (its fingerprint does not "
                "match these inputs' contents and options); rerun the exact command that wrote it, or delete it to start over"
            )
        if ckpt.get("phase") == "done":
            summary_path = out / "summary.json"
            if not summary_path.exists():
                raise CheckpointError(f"checkpoint {options.checkpoint} says the run is complete but {summary_path} is missing; delete the checkpoint to recompute")
            log(f"registration register: run already complete (checkpoint {options.checkpoint}); delete it to recompute")
            return json.loads(summary_path.read_text())

    pairing_report = None
    if form == "asynchronous":
        sync_path, pairing_report = _ensure_pairing(inputs, navs, scans, common, options, log, resuming=ckpt is not None)
        table_total = pairing_report["paired"]
    else:
        sync_path = inputs[0]
        table_total = _total_rows(sync_path, scans[str(sync_path)][1])

    summary = _run_filter(sync_path, table_total, form, fingerprint, ckpt, options, log,
                          keep_rejected=form == "asynchronous")
    summary["form"] = form
    summary["inputs"] = [{"path": str(p), "sha256": scans[str(p)][0]} for p in inputs + navs]
    if pairing_report is not None:
        summary["pairing"] = pairing_report
    summary["elapsed_s"] = round(_time.perf_counter() - t0, 3)
    _write_json_atomic(out / "summary.json", summary)
    if options.plots:
        summary["plots"] = _plots(sync_path, out, options, summary)
        _write_json_atomic(out / "summary.json", summary)
    if options.checkpoint is not None:
        state = load_checkpoint(options.checkpoint)
        state["phase"] = "done"
        save_checkpoint(options.checkpoint, state)
    return summary


def _ensure_pairing(inputs, navs, scans, common, options: RunOptions, log, *, resuming: bool):
    from registration.recorded.pairing import pair_streams, plan_sources

    out = options.out
    ext = ".csv" if options.out_format == "csv" else ".parquet"
    paired = out / f"paired{ext}"
    meta_path = out / "pairing.json"
    fp = _fingerprint(common)
    if meta_path.exists() and paired.exists():
        try:
            meta = json.loads(meta_path.read_text())
        except json.JSONDecodeError:
            meta = {}
        if meta.get("fingerprint") == fp and meta.get("paired_sha256") == _scan_file(paired)[0]:
            log(f"registration register: reusing the pairing in {paired}")
            return paired, meta["report"]
    if resuming:
        log("registration register: the pairing stage is redone (its result was missing or changed)")
    sources = plan_sources(inputs, navs, options.pairing)
    rejected = CsvAppender(out / "rejected.csv", REJECTED_COLUMNS)
    unpaired = CsvAppender(out / "unpaired.csv", UNPAIRED_COLUMNS)
    tmp = paired.with_name(paired.name + ".partial")
    ref = next(s for s in sources if s.plots_of == options.pairing.pair_at)
    total = _total_rows(ref.path, scans[str(ref.path)][1])
    bar = _progress(total, 0, "pairing", options.progress)
    if options.out_format == "csv":
        writer = CsvAppender(tmp, list(SYNC_COLUMNS) + ["pair_row", "pair_interpolated"])
        write_pairs = writer.append_frame
    else:
        import pyarrow as pa
        import pyarrow.parquet as pq

        holder = {}

        def write_pairs(frame):
            table = pa.Table.from_pandas(frame, preserve_index=False)
            if "w" not in holder:
                holder["w"] = pq.ParquetWriter(str(tmp), table.schema)
            holder["w"].write_table(table)

    def on_reject(path, rejections):
        rejected.append_rows(_rejected_rows(path, rejections))

    def progress(rows_done):
        bar.update(rows_done - bar.n)

    try:
        report = pair_streams(sources, options.pairing, chunk_rows=options.block_rows, mode=options.on_bad_row,
                              on_reject=on_reject, write_pairs=write_pairs, write_unpaired=unpaired.append_rows, progress=progress)
    finally:
        bar.close()
        rejected.sync()
        rejected.close()
        unpaired.sync()
        unpaired.close()
    if options.out_format == "csv":
        writer.sync()
        writer.close()
    else:
        if "w" in holder:
            holder["w"].close()
        else:  # no pair at all: an empty table with the right columns
            import pandas as pd

            pq.write_table(pa.Table.from_pandas(pd.DataFrame({c: np.empty(0) for c in SYNC_COLUMNS}), preserve_index=False), str(tmp))
        with open(tmp, "rb") as f:
            os.fsync(f.fileno())
    os.replace(tmp, paired)
    report["rejected_rows_written"] = rejected.rows
    _write_json_atomic(meta_path, {"fingerprint": fp, "paired_sha256": _scan_file(paired)[0], "report": report})
    log(f"registration register: paired {report['paired']} of {report['instants']} instants "
        f"({report['exact']} exact, {report['interpolated']} interpolated, {report['unpaired']} unpaired) into {paired}")
    return paired, report


def _run_filter(path: Path, total_rows, form, fingerprint, ckpt, options: RunOptions, log, *, keep_rejected: bool) -> dict:
    out = options.out
    cfg = options.config
    layout = sync_layout()
    outs_spec = _outputs(out, options.out_format)
    block = options.block_rows
    every = int(options.checkpoint_every)
    skip = options.on_bad_row == "skip"

    if ckpt is None:
        reg = OnlineRegistrar(cfg)
        outputs = {k: _open_output(p, cols, options.out_format, None) for k, (p, cols) in outs_spec.items()}
        rejected = CsvAppender(out / "rejected.csv", REJECTED_COLUMNS, keep_existing=keep_rejected)
        st = {
            "phase": "filter", "rows_done": 0, "last_time": None, "rows_total": 0, "accepted": 0,
            "rejected": {}, "filter_rejected": [], "nis_sum": 0.0, "first_time": None, "time": None,
            "obs_rows_done": 0, "obs_last_time": None, "obs_info": np.zeros((N_STATE, N_STATE)), "obs_used": 0, "first_rejection": None,
        }
        raw_stats, cor_stats = _Stats(), _Stats()
    else:
        log(f"registration register: resuming from checkpoint {options.checkpoint} at row {ckpt['state']['rows_done']} "
            f"(phase {ckpt['phase']})")
        reg = OnlineRegistrar.from_state_dict(ckpt["filter"], cfg)
        o = ckpt["outputs"]
        outputs = {k: _open_output(p, cols, options.out_format, tuple(o[k])) for k, (p, cols) in outs_spec.items()}
        rejected = CsvAppender(out / "rejected.csv", REJECTED_COLUMNS, resume=tuple(o["rejected"]))
        st = dict(ckpt["state"])
        st["phase"] = ckpt["phase"]
        raw_stats, cor_stats = _Stats(ckpt["stats"]["raw"]), _Stats(ckpt["stats"]["corrected"])

    def save():
        if options.checkpoint is None:
            return
        for w in list(outputs.values()) + [rejected]:
            w.sync()
        save_checkpoint(options.checkpoint, {
            "fingerprint": fingerprint, "phase": st["phase"], "filter": reg.state_dict(),
            "state": {k: v for k, v in st.items() if k != "phase"},
            "stats": {"raw": raw_stats.state(), "corrected": cor_stats.state()},
            "outputs": {**{k: [w.size, w.rows] for k, w in outputs.items()}, "rejected": [rejected.size, rejected.rows]},
        })

    if ckpt is None:
        save()  # a kill before the first periodic checkpoint resumes from a clean start
    last_saved = st["rows_done"] if st["phase"] == "filter" else st["obs_rows_done"]
    filter_rejected = set(int(r) for r in st["filter_rejected"])

    try:
        # ---------------------------------------------------------------- pass 1: the filter
        if st["phase"] == "filter":
            bar = _progress(total_rows, st["rows_done"], "registering", options.progress)
            try:
                for first, frame in iter_frames(path, SYNC_COLUMNS, block, start_row=st["rows_done"]):
                    blk = check_frame(frame, layout, str(path), first_row=first, mode=options.on_bad_row, last_time=st["last_time"])
                    st["last_time"] = blk.last_time
                    rej = list(blk.rejections)
                    acc = np.flatnonzero(blk.accepted)
                    rows18 = blk.values[acc, 1:]
                    times = blk.values[acc, 0]
                    s = 0
                    while s < len(acc):
                        res = reg.update_block(rows18[s:], times[s:], partial=True)
                        n = res["n"]
                        if n:
                            _emit(outputs, acc[s:s + n] + first, times[s:s + n], rows18[s:s + n], res, cfg, raw_stats, cor_stats, st)
                        s += n
                        if s < len(acc):  # this row's step would not be finite: never committed
                            row = int(first + acc[s])
                            reason = "the filter step for this row produced non-finite values (extreme geometry or values)"
                            if not skip:
                                raise BadRowError(str(path), row, "*", "filter_non_finite", reason)
                            rej.append(Rejection(row, "*", "filter_non_finite", reason, "{}"))
                            filter_rejected.add(row)
                            st["filter_rejected"] = sorted(filter_rejected)
                            s += 1
                    rejected.append_rows(_rejected_rows(path, sorted(rej, key=lambda r: r.row)))
                    for r in rej:
                        st["rejected"][r.code] = st["rejected"].get(r.code, 0) + 1
                    if rej and st.get("first_rejection") is None:
                        st["first_rejection"] = f"row {rej[0].row}, column {rej[0].column!r}: {rej[0].reason}"
                    st["rows_total"] += blk.n_rows
                    st["accepted"] += blk.n_rows - len(rej)
                    st["rows_done"] = first + blk.n_rows
                    bar.update(blk.n_rows)
                    if st["rows_done"] - last_saved >= every:
                        save()
                        last_saved = st["rows_done"]
            finally:
                bar.close()
            if st["accepted"] == 0:
                raise ValueError(
                    f"{path}: no valid rows to register: all {st['rows_total']} rows rejected {st['rejected']}, the first "
                    f"at {st.get('first_rejection')}; see {out / 'rejected.csv'}")
            st["phase"] = "observability" if options.observability == "final" else "summary"
            last_saved = 0
            save()

        # ---------------------------------------------------------------- pass 2: information at the final estimate
        if st["phase"] == "observability":
            x_final = reg.x.copy()
            bar = _progress(total_rows, st["obs_rows_done"], "observability", options.progress)
            try:
                for first, frame in iter_frames(path, SYNC_COLUMNS, block, start_row=st["obs_rows_done"]):
                    blk = check_frame(frame, layout, str(path), first_row=first, mode="skip", last_time=st["obs_last_time"])
                    st["obs_last_time"] = blk.last_time
                    acc = np.flatnonzero(blk.accepted)
                    if filter_rejected:
                        acc = np.array([i for i in acc if int(first + i) not in filter_rejected], dtype=np.int64)
                    if len(acc):
                        rows18 = blk.values[acc, 1:]
                        J, used = information_at_estimate(np.ascontiguousarray(rows18), x_final, cfg)
                        st["obs_info"] = st["obs_info"] + J
                        st["obs_used"] += used
                    st["obs_rows_done"] = first + blk.n_rows
                    bar.update(blk.n_rows)
                    if st["obs_rows_done"] - last_saved >= every:
                        save()
                        last_saved = st["obs_rows_done"]
            finally:
                bar.close()
            st["phase"] = "summary"
            save()
    finally:
        for w in list(outputs.values()) + [rejected]:
            w.close()

    info = st["obs_info"] if options.observability == "final" else reg.info
    report = observability_report(info, np.array(cfg.prior_sigma), STATE_NAMES, STATE_LABELS, STATE_UNITS)
    return _summary(path, reg, report, raw_stats, cor_stats, st, options, outs_spec)


def _emit(outputs, rows_abs, times, rows18, res, cfg, raw_stats, cor_stats, st) -> None:
    import pandas as pd

    x, P, nis = res["x"], res["P"], res["nis"]
    sig = np.sqrt(np.einsum("kii->ki", P))
    est = {"row": rows_abs.astype(np.int64), "time_s": times}
    deg = np.degrees(1.0)
    for i, name in enumerate(STATE_NAMES):
        unit = "deg" if IS_ANGLE[i] else "m"
        k = deg if IS_ANGLE[i] else 1.0
        est[f"{name}_{unit}"] = np.degrees(x[:, i]) if IS_ANGLE[i] else x[:, i]
        est[f"{name}_sigma_{unit}"] = sig[:, i] * k
    est["nis"] = nis
    outputs["estimates"].append_frame(pd.DataFrame(est, columns=ESTIMATE_COLUMNS))
    raw_a, raw_b = _target_positions(rows18, cfg)
    cor_a, cor_b = _target_positions(_corrected_rows(rows18, x), cfg)
    raw_z, cor_z = raw_a - raw_b, cor_a - cor_b
    pos = np.concatenate([cor_a, cor_b, raw_z, cor_z], axis=1)
    frame = pd.DataFrame(pos, columns=POSITION_COLUMNS[2:])
    frame.insert(0, "time_s", times)
    frame.insert(0, "row", rows_abs.astype(np.int64))
    outputs["positions"].append_frame(frame)
    raw_stats.add(raw_z)
    cor_stats.add(cor_z)
    st["nis_sum"] = st["nis_sum"] + float(np.sum(nis))
    if st["first_time"] is None:
        st["first_time"] = float(times[0])
    st["time"] = float(times[-1])


def _summary(path, reg: OnlineRegistrar, report, raw_stats, cor_stats, st, options: RunOptions, outs_spec) -> dict:
    from registration.cli.simulate import estimate_rows

    ns = SimpleNamespace(final=reg.x, final_sigma=np.sqrt(np.diag(reg.P)), covariances=reg.P[None], observability=report)
    ns.identifiable_combinations = lambda: RegistrationResult.identifiable_combinations(ns)
    rows = estimate_rows(ns, None)
    for r in rows:
        k = np.degrees(1.0) if r["unit"] == "rad" else 1.0
        r["display_unit"] = "deg" if r["unit"] == "rad" else "m"
        r["estimate_display"], r["sigma_display"] = r["estimate"] * k, r["sigma"] * k
    accepted = st["accepted"]
    return {
        "table": str(path),
        "state_names": list(STATE_NAMES),
        "config": options.config.to_json(),
        "options": {"on_bad_row": options.on_bad_row, "format": options.out_format, "chunk_rows": options.chunk_rows,
                    "block_rows": options.block_rows, "checkpoint": None if options.checkpoint is None else str(options.checkpoint),
                    "checkpoint_every": options.checkpoint_every, "observability": options.observability},
        "rows": {"read": st["rows_total"], "accepted": accepted, "rejected": sum(st["rejected"].values()),
                 "rejected_by_reason": dict(sorted(st["rejected"].items())), "used_for_observability": st["obs_used"]},
        "time_span_s": [st["first_time"], st["time"]],
        "before": raw_stats.summary(),
        "after": cor_stats.summary(),
        "estimates": rows,
        "observability": {**report.to_json(), "information": "at the final estimate (second pass)" if options.observability == "final"
                          else "accumulated by the filter at its linearisation points"},
        "mean_nis": st["nis_sum"] / accepted if accepted else None,
        "outputs": {k: str(p) for k, (p, _) in outs_spec.items()} | {"rejected": str(options.out / "rejected.csv")},
    }


# --------------------------------------------------------------------------- plots
def _strided(path, columns, stride: int, fmt: str):
    """Every ``stride``-th row of a table (CSV/Parquet file or a folder of Parquet parts), streamed."""
    import pandas as pd

    files = sorted(Path(path).glob("part-*.parquet")) if Path(path).is_dir() else [Path(path)]
    pieces, pos = [], 0
    for f in files:
        for first, frame in iter_frames(f, columns, 50_000):
            off = (-pos) % stride
            pieces.append(frame.iloc[off::stride])
            pos += len(frame)
    return pd.concat(pieces, ignore_index=True) if pieces else pd.DataFrame(columns=columns)


def _plots(sync_path: Path, out: Path, options: RunOptions, summary: dict) -> list[str]:
    from registration.core.observability import ObservabilityReport
    from registration.online.plots import plot_differences, plot_estimates, plot_tracks

    n = max(int(summary["rows"]["accepted"]), 1)
    stride = max(1, -(-n // _PLOT_POINTS))
    outs = _outputs(out, options.out_format)
    est = _strided(outs["estimates"][0], ESTIMATE_COLUMNS, stride, options.out_format)
    pos = _strided(outs["positions"][0], POSITION_COLUMNS, stride, options.out_format)
    written = []
    x = np.stack([np.radians(est[c]) if IS_ANGLE[i] else est[c] for i, c in enumerate(ESTIMATE_COLUMNS[2:-1:2])], axis=1)
    s = np.stack([np.radians(est[c]) if IS_ANGLE[i] else est[c] for i, c in enumerate(ESTIMATE_COLUMNS[3:-1:2])], axis=1)
    cov = np.zeros((len(x), N_STATE, N_STATE))
    cov[:, np.arange(N_STATE), np.arange(N_STATE)] = s**2
    status = summary["observability"]["status"]
    res = SimpleNamespace(time=np.asarray(est["time_s"]), estimates=x, covariances=cov,
                          observability=ObservabilityReport(np.zeros(N_STATE), status=status),
                          raw_difference_ecef=pos[["diff_raw_x_m", "diff_raw_y_m", "diff_raw_z_m"]].to_numpy(),
                          corrected_difference_ecef=pos[["diff_x_m", "diff_y_m", "diff_z_m"]].to_numpy())
    res.time_pos = np.asarray(pos["time_s"])
    written.append(str(plot_estimates(res, None, out / "estimates.png")))
    res_d = SimpleNamespace(time=res.time_pos, raw_difference_ecef=res.raw_difference_ecef,
                            corrected_difference_ecef=res.corrected_difference_ecef)
    written.append(str(plot_differences(res_d, out / "differences.png")))
    nav_cols = ["a_lat_deg", "a_lon_deg", "b_lat_deg", "b_lon_deg"]
    total = summary["rows"]["read"]
    nav = _strided(sync_path, nav_cols, max(1, -(-total // _PLOT_POINTS)), file_format(sync_path))
    tracks = {}
    for c in nav_cols:
        v = pd_numeric(nav[c]) if c in nav else np.empty(0)
        tracks[c] = v
    ok = np.ones(len(tracks["a_lat_deg"]), dtype=bool)
    for c, v in tracks.items():
        ok &= np.isfinite(v) & (np.abs(v) <= (90 if "lat" in c else 360))
    targets = {s: _approx_lat_lon_deg(pos[[f"{s}_ecef_x_m", f"{s}_ecef_y_m", f"{s}_ecef_z_m"]].to_numpy()) for s in "ab"}
    if ok.sum() >= 2:
        written.append(str(_plot_recorded_tracks({k: v[ok] for k, v in tracks.items()}, targets, out / "tracks.png")))
    return written


def pd_numeric(col) -> np.ndarray:
    import pandas as pd

    return np.asarray(pd.to_numeric(col, errors="coerce"), dtype=float)


def _approx_lat_lon_deg(p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """ECEF -> geodetic latitude/longitude (deg) by Bowring's formula: for the track plot only
    (metre-level, the package has no generated inverse of geodetic2ecef)."""
    a, f = 6378137.0, 1 / 298.257223563
    b, e2 = a * (1 - f), f * (2 - f)
    ep2 = (a * a - b * b) / (b * b)
    x, y, z = p[:, 0], p[:, 1], p[:, 2]
    rho = np.hypot(x, y)
    th = np.arctan2(z * a, rho * b)
    lat = np.arctan2(z + ep2 * b * np.sin(th) ** 3, rho - e2 * a * np.cos(th) ** 3)
    return np.degrees(lat), np.degrees(np.arctan2(y, x))


def _plot_recorded_tracks(tracks: dict, targets: dict, path: Path) -> Path:
    """Ships' tracks and the target as each radar places it after registration (lon/lat, deg)."""
    from registration.online.plots import _pyplot

    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(7, 6))
    for s, colour in (("a", "tab:blue"), ("b", "tab:orange")):
        lon, lat = tracks[f"{s}_lon_deg"], tracks[f"{s}_lat_deg"]
        ax.plot(lon, lat, color=colour, lw=3, label=f"ship {s.upper()}")
        ax.plot(lon[0], lat[0], "o", color=colour)
    for s, colour in (("a", "tab:red"), ("b", "tab:purple")):
        lat, lon = targets[s]
        good = np.isfinite(lat) & np.isfinite(lon)
        if good.any():
            ax.plot(lon[good], lat[good], ".", ms=2, color=colour, label=f"target, corrected plots of radar {s.upper()}")
    ax.set_xlabel("longitude (deg E)")
    ax.set_ylabel("latitude (deg N)")
    ax.set_title("Ship tracks and the target (dots on tracks: start)")
    ax.set_aspect(1 / max(np.cos(np.radians(np.nanmean(tracks["a_lat_deg"]))), 0.05))
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


# --------------------------------------------------------------------------- validation only
def validate_files(inputs, options: RunOptions, max_listed: int = 20) -> dict:
    """Check every row of the inputs without estimating; return counts per file and reason.

    Uses the same layouts and rules as :func:`run_register` (all rows are read, whatever
    ``on_bad_row`` says). Returns ``{"files": {path: {"rows", "accepted", "rejected_by_reason"}},
    "problems": [first max_listed rejections]}``.
    """
    inputs = [Path(p) for p in inputs]
    navs = [Path(p) for p in options.nav]
    if len(inputs) == 1:
        jobs = [(inputs[0], sync_layout())]
    else:
        from registration.recorded.pairing import PairingOptions, plan_sources

        jobs = [(src.path, src.layout) for src in plan_sources(inputs, navs, options.pairing or PairingOptions())]
    report = {"files": {}, "problems": []}
    for path, layout in jobs:
        last, rows, acc, by = None, 0, 0, {}
        for first, frame in iter_frames(path, layout.columns, options.chunk_rows):
            blk = check_frame(frame, layout, str(path), first_row=first, mode="skip", last_time=last)
            last = blk.last_time
            rows += blk.n_rows
            acc += int(blk.accepted.sum())
            for r in blk.rejections:
                by[r.code] = by.get(r.code, 0) + 1
                if len(report["problems"]) < max_listed:
                    report["problems"].append({"file": str(path), "row": r.row, "column": r.column, "code": r.code, "reason": r.reason})
        report["files"][str(path)] = {"layout": layout.name, "rows": rows, "accepted": acc, "rejected_by_reason": by}
    return report
