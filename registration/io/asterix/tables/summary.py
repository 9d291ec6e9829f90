"""The import summary, a JSON-able dict: the files read, the editions, the time axis, counts per
sensor and category, each radar's scan period and clock check, the SAC/SIC values seen that
SITES lacks, the reference reports, and the records set aside per reason."""

from __future__ import annotations

import datetime as dt
from collections import Counter
from typing import TYPE_CHECKING

import numpy as np

from registration.io.asterix.decode.decode34 import NORTH_MARKER
from registration.io.asterix.decode.reader import DecodedFile
from registration.io.asterix.tables.service import antenna_track, clock_check, scan_period

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["file_summary", "sensor_summary", "sources_not_in_sites", "time_summary"]


def _median(values: np.ndarray) -> float | None:
    values = np.asarray(values, dtype=float)
    values = values[np.isfinite(values)]
    return float(np.median(values)) if values.size else None


def file_summary(dec: DecodedFile, blocks_seen: dict) -> dict:
    """One file: name, format, framing, gzip, octets, packet counts (captures) or records (recorder
    framings), data blocks per category."""
    cap = dec.capture
    out = {
        "file": cap.path,
        "format": cap.kind,
        "framing": cap.framing,
        "gzip": cap.gzip,
        "bytes": cap.size,
        "data_blocks": {f"{c:03d}": n for c, n in sorted(blocks_seen.items())},
        "records": {f"{c:03d}": rec.size for c, rec in dec.records.items()},
    }
    out.update({k: v for k, v in cap.counts.items() if k != "first_packet_time"})
    if cap.notes:
        out["notes"] = list(cap.notes)
    return out


def time_summary(reference: dt.date | None, source: str, times: np.ndarray, placed_by_capture: int) -> dict:
    """What ``time_s`` counts from and the span of the records' times (s)."""
    meaning = {
        "argument": "the date given",
        "capture": "the UTC date of the first packet of the first capture",
        "recording": "the first day of the recording (raw file(s), no date given: the date is not known)",
    }[source]
    finite = times[np.isfinite(times)]
    return {
        "reference_date": None if reference is None else reference.isoformat(),
        "time_s": f"seconds since midnight UTC of {meaning}",
        "span_s": [float(finite.min()), float(finite.max())] if finite.size else None,
        "files_placed_by_packet_times": placed_by_capture,
    }


def _service_of(service: dict, k: int, plots_t: np.ndarray, plots_b: np.ndarray) -> dict:
    mine = service["sensor"] == k if service else np.zeros(0, dtype=bool)
    t, kind = service["time_s"][mine], service["msg_type"][mine]
    out = scan_period(t[kind == NORTH_MARKER])
    category = service["category"][mine] if service else np.zeros(0, dtype=np.int64)
    out["cat034_messages"] = int((category == 34).sum())
    if (category == 2).any():
        out["cat002_messages"] = int((category == 2).sum())
    out["sector_messages"] = int((kind == 2).sum())
    out["antenna_rotation_period_s"] = _median(service["rotation_s"][mine]) if mine.any() else None
    az = service["azimuth_deg"][mine]
    has_az = np.isfinite(az) & np.isfinite(t)
    track = antenna_track(t[has_az], az[has_az], out["scan_period_s"] or out["antenna_rotation_period_s"])
    out["clock_check"] = clock_check(*track, plots_t, plots_b)
    return out


def sensor_summary(sites: pd.DataFrame, plots: dict, service: dict, decoded: dict) -> dict:
    """Per SITES sensor: SAC/SIC, records decoded per category, plots kept by kind of id, CAT034
    (and CAT002, when any) counts, scan period, antenna rotation period (I034/041, I002/041),
    clock check, and the median of capture time - plot time (captures with a known date;
    transport delay plus the radar's clock offset)."""
    out = {}
    for k, row in enumerate(sites.itertuples(index=False)):
        mine = plots["sensor"] == row.sensor
        kind = plots["kind"][mine]
        entry = {
            "sac": int(row.sac),
            "sic": int(row.sic),
            "records": {f"{c:03d}": int(v[k]) for c, v in sorted(decoded.items())},
            "plots": int(mine.sum()),
            "plots_mode_s": int((kind == "mode_s").sum()),
            "plots_mode_a": int((kind == "mode_a").sum()),
            "plots_without_id": int((kind == "none").sum()),
        }
        entry.update(_service_of(service, k, plots["time_s"][mine], plots["bearing_deg"][mine]))
        entry["capture_minus_plot_time_s"] = _median(plots["capture_lag_s"][mine])
        out[row.sensor] = entry
    return out


def sources_not_in_sites(unknown: Counter) -> list:
    """[{category, sac, sic, records}] of the CAT048/CAT034 sources not in SITES, most records first."""
    return [
        {"category": f"{c:03d}", "sac": s, "sic": i, "records": n}
        for (c, s, i), n in sorted(unknown.items(), key=lambda kv: (-kv[1], kv[0]))
    ]
