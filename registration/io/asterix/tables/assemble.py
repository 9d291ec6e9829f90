"""One decoded file turned into rows: its records placed on the time axis, CAT048 and CAT001 plots and
CAT021 reference positions kept or set aside, CAT034 and CAT002 service messages of the known radars
kept for the scan periods and the clock check, and the sources seen. CAT001's truncated times are
made whole first (:mod:`registration.io.asterix.tables.truncated`)."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

import numpy as np

from registration.io.asterix.decode.decode34 import NORTH_MARKER, SECTOR_LSB_DEG
from registration.io.asterix.decode.reader import DecodedFile
from registration.io.asterix.tables.adsb21 import reference_columns, reference_verdicts
from registration.io.asterix.tables.duplicates import StreamChecks
from registration.io.asterix.tables.plots01 import plot_columns01, plot_verdicts01
from registration.io.asterix.tables.plots48 import plot_columns, plot_verdicts, unknown_source_texts
from registration.io.asterix.tables.timeofday import Unwrapper, midnight_utc, recorder_times
from registration.io.asterix.tables.truncated import TruncatedClock
from registration.io.asterix.tables.verdicts import Verdicts
from registration.io.files.ledger import RejectedLedger

__all__ = ["FileRows", "SiteLookup", "assemble_file"]


class SiteLookup:
    """SAC/SIC -> row of SITES (-1: not there)."""

    def __init__(self, sac: np.ndarray, sic: np.ndarray) -> None:
        self.table = np.full(1 << 16, -1, dtype=np.int64)
        self.table[np.asarray(sac, dtype=np.int64) * 256 + np.asarray(sic, dtype=np.int64)] = np.arange(
            len(sac)
        )

    def __call__(self, fields: dict) -> np.ndarray:
        return np.where(fields["has_010"], self.table[(fields["sac"] * 256 + fields["sic"]) & 0xFFFF], -1)


@dataclass
class FileRows:
    """Rows of one file: ``plots`` and ``reference`` (file columns, kept rows; plots also ``kind``
    and ``capture_lag_s``), ``service`` (CAT034 and CAT002 of known radars: ``sensor`` index,
    ``category``, ``msg_type``, ``time_s``, ``azimuth_deg`` (NaN: none), ``rotation_s`` (NaN:
    none)), ``decoded`` (category -> records per SITES row), ``unknown`` (category, sac, sic) ->
    records, ``adsb_sources`` (sac, sic) -> reports kept, ``times`` all record times (s)."""

    plots: dict
    reference: dict
    service: dict
    decoded: dict = field(default_factory=dict)
    unknown: Counter = field(default_factory=Counter)
    adsb_sources: Counter = field(default_factory=Counter)
    times: np.ndarray = field(default_factory=lambda: np.zeros(0))


def _record_times(dec: DecodedFile, unwrapper: Unwrapper) -> dict:
    """Category -> (R,) seconds since midnight of the reference day (NaN: no valid time of day)."""
    tods, offsets, captures, cats = [], [], [], []
    for cat, rec in dec.records.items():
        f = rec.fields
        if rec.size == 0:
            continue
        if cat == 21:
            given = f["time_item"] != ""
        else:
            given = f["time_base"] > 0 if cat == 1 else f["has_140" if cat == 48 else "has_030"]
        tod = np.where(given & (f["tod"] < 86400 * 128), f["tod"] / 128.0, np.nan)
        tods.append(tod)
        offsets.append(rec.offset)
        recorder_tod = dec.capture.clock == "time_of_day"  # no date: not for placing the file's day
        captures.append(np.full(rec.size, np.nan) if recorder_tod else rec.capture_time)
        cats.append(np.full(rec.size, cat))
    if not tods:
        return {cat: np.zeros(0) for cat in dec.records}
    tod, offset, capture, cat = (np.concatenate(a) for a in (tods, offsets, captures, cats))
    order = np.argsort(offset, kind="stable")
    times = np.empty_like(tod)
    times[order] = unwrapper.file_times(tod[order], capture[order])
    return {c: times[cat == c] if (cat == c).any() else np.zeros(0) for c in dec.records}


def _service(f: dict, t: np.ndarray, sensor: np.ndarray, v: Verdicts, cat: int) -> dict:
    for item, what in (("010", "data source identifier"), ("000", "message type"), ("030", "time of day")):
        v.rule(~f[f"has_{item}"], "missing_item", f"no I{cat:03d}/{item} ({what})")
    v.rule(f["tod"] >= 86400 * 128, "bad_time", f"I{cat:03d}/030 time of day is 24 h or more")
    v.rule(sensor < 0, "unknown_sac_sic", unknown_source_texts(f["sac"], f["sic"], sensor < 0))
    keep = v.kept()
    azimuth = np.where(
        f["msg_type"] == NORTH_MARKER, 0.0, np.where(f["has_020"], f["sector"] * SECTOR_LSB_DEG, np.nan)
    )
    return {
        "sensor": sensor[keep],
        "category": np.full(int(keep.sum()), cat, dtype=np.int64),
        "msg_type": f["msg_type"][keep],
        "time_s": t[keep],
        "azimuth_deg": azimuth[keep],
        "rotation_s": np.where(f["has_041"], f["rotation"] / 128.0, np.nan)[keep],
    }


def _joined(rows: dict, more: dict) -> dict:
    """The columns of ``rows`` (empty: none yet) followed by those of ``more``."""
    if not rows:
        return more
    return {k: np.concatenate([np.asarray(rows[k]), np.asarray(c)]) for k, c in more.items()}


def _unknown(counter: Counter, cat: int, f: dict, sensor: np.ndarray) -> None:
    m = (sensor < 0) & f["has_010"]
    pairs, n = np.unique(f["sac"][m] * 256 + f["sic"][m], return_counts=True)
    for p, k in zip(pairs.tolist(), n.tolist()):
        counter[(cat, p >> 8, p & 0xFF)] += k


def _once(
    checks: StreamChecks, path: str, cat: int, records: dict, times: dict, rejections: RejectedLedger
) -> None:
    """Check the category's records for time going back, and set aside its duplicates (in place
    in ``records`` and ``times``)."""
    rec, t = records[cat], times[cat]
    if rec.size == 0:
        return
    checks.time_steps(path, cat, rec, t)
    dup = checks.duplicates(path, cat, rec, t)
    if dup.any():
        rejections.add(
            path,
            "duplicate",
            f"CAT{cat:03d}: the same record (SAC/SIC, time of day and octets) came earlier in the stream "
            "(a duplicated feed or a replayed recording)",
            offset=rec.offset[dup],
            packet=rec.packet[dup],
            category=cat,
        )
        records[cat], times[cat] = rec.subset(~dup), t[~dup]


def assemble_file(
    dec: DecodedFile,
    unwrapper: Unwrapper,
    sites: SiteLookup,
    names: np.ndarray,
    editions: dict,
    rejections: RejectedLedger,
    checks: StreamChecks | None = None,
    clock: TruncatedClock | None = None,
) -> FileRows:
    """The rows of one decoded file; records set aside go to ``rejections``. ``names``: the SITES
    sensor names; ``editions``: category -> edition used; ``checks``: the duplicates and backward
    time steps of the import (None: a new one); ``clock``: the bases of the CAT001 times of the
    import (None: a new one)."""
    path = dec.capture.path
    (TruncatedClock() if clock is None else clock).place(dec.records)
    times = _record_times(dec, unwrapper)
    midnight = midnight_utc(unwrapper.reference) if unwrapper.reference is not None else np.nan
    rows = FileRows({}, {}, {}, times=np.concatenate([t for t in times.values()]) if times else np.zeros(0))
    checks = StreamChecks() if checks is None else checks
    records = dict(dec.records)
    for cat in records:
        _once(checks, path, cat, records, times, rejections)
    recorded = {cat: rec.capture_time - midnight for cat, rec in records.items()}
    if dec.capture.clock == "time_of_day":
        recorded = {cat: recorder_times(rec.capture_time, times[cat]) for cat, rec in records.items()}
        for cat, rec in records.items():
            rec.capture_time = recorded[cat] + midnight
    rec = records[48]
    f, sensor = rec.fields, sites(rec.fields) if rec.size else np.zeros(0, dtype=np.int64)
    if rec.size:
        v = plot_verdicts(f, sensor)
        v.report(rejections, path, rec.offset, rec.packet, 48)
        keep = v.kept()
        cols = plot_columns(f, times[48], names[np.maximum(sensor, 0)])
        cols["capture_lag_s"] = recorded[48] - times[48]
        rows.plots = {k: np.asarray(c)[keep] for k, c in cols.items()}
        rows.decoded[48] = np.bincount(sensor[sensor >= 0], minlength=names.size)
        _unknown(rows.unknown, 48, f, sensor)
    rec = records.get(1)
    if rec is not None and rec.size:
        f, sensor = rec.fields, sites(rec.fields)
        v = plot_verdicts01(f, sensor)
        v.report(rejections, path, rec.offset, rec.packet, 1)
        keep = v.kept()
        cols = plot_columns01(f, times[1], names[np.maximum(sensor, 0)])
        cols["capture_lag_s"] = rec.capture_time - midnight - times[1]
        rows.plots = _joined(rows.plots, {k: np.asarray(c)[keep] for k, c in cols.items()})
        rows.decoded[1] = np.bincount(sensor[sensor >= 0], minlength=names.size)
        _unknown(rows.unknown, 1, f, sensor)
    for cat in (34, 2):
        rec = records.get(cat)
        if rec is None or not rec.size:
            continue
        sensor = sites(rec.fields)
        v = Verdicts(rec.size)
        rows.service = _joined(rows.service, _service(rec.fields, times[cat], sensor, v, cat))
        v.report(rejections, path, rec.offset, rec.packet, cat)
        rows.decoded[cat] = np.bincount(sensor[sensor >= 0], minlength=names.size)
        _unknown(rows.unknown, cat, rec.fields, sensor)
    rec = records[21]
    if rec.size:
        v, epu = reference_verdicts(rec.fields, editions[21].startswith("0."))
        v.report(rejections, path, rec.offset, rec.packet, 21)
        keep = v.kept()
        rows.reference = {
            k: np.asarray(c)[keep] for k, c in reference_columns(rec.fields, times[21], epu).items()
        }
        src = rec.fields["sac"][keep] * 256 + rec.fields["sic"][keep]
        for p, k in zip(*[a.tolist() for a in np.unique(src, return_counts=True)]):
            rows.adsb_sources[(p >> 8, p & 0xFF)] += k
    return rows
