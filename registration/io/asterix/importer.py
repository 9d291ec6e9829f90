"""``import_asterix``: ASTERIX recordings and captures -> the fleet tables in file form (degrees
and metres), the records set aside, and a summary (docs/howto/import-asterix.md)."""

from __future__ import annotations

import datetime as dt
from collections import Counter
from pathlib import Path
from typing import TYPE_CHECKING, Iterable, Mapping, Sequence

import numpy as np

from registration.core.progress import progress_bar
from registration.io.asterix.capture.unwrap import check_framing
from registration.io.asterix.decode.reader import decode_file
from registration.io.asterix.decode.uap import check_editions
from registration.io.asterix.errors import LEDGER_COLUMNS, REASONS
from registration.io.asterix.tables.assemble import FileRows, SiteLookup, assemble_file
from registration.io.asterix.tables.duplicates import StreamChecks
from registration.io.asterix.tables.fleetfiles import PLOT_COLUMNS, REFERENCE_COLUMNS, site_tables
from registration.io.asterix.tables.flightlevels import height_rows, learn_relation
from registration.io.asterix.tables.plots48 import file_kinds
from registration.io.asterix.tables.sites import channel_sensors, check_sites, read_sites
from registration.io.asterix.tables.summary import (
    file_summary,
    sensor_summary,
    sources_not_in_sites,
    time_summary,
)
from registration.io.asterix.tables.timeofday import Unwrapper, capture_day
from registration.io.asterix.tables.truncated import TruncatedClock
from registration.io.files.ledger import RejectedLedger
from registration.io.files.limits import (
    DEFAULT_MAX_BYTES,
    DEFAULT_MAX_RECORDS,
    DEFAULT_MAX_REJECTED_ROWS,
    BoundedLedger,
    Limits,
)
from registration.io.imports import ImportResult

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["AsterixImport", "import_asterix", "REFERENCE_TARGETS"]

#: Which ADS-B targets go into the reference table: those named by a plot, or all.
REFERENCE_TARGETS = ("plotted", "all")


class AsterixImport(ImportResult):
    """What :func:`import_asterix` gives (:class:`~registration.io.imports.ImportResult`): the fleet
    tables as DataFrames in their file form (docs/reference/fleet-files.md: ``plots``, ``navigation``,
    ``sensors``, ``platforms``, ``reference``; no ``targets``), the records set aside
    (``rejected``: ``file``, ``offset``, ``packet``, ``category``, ``reason_code``, ``reason``) and
    the ``summary`` (a JSON-able dict); :meth:`write` writes them into a folder."""


class _Progress:
    """A bar (:func:`registration.core.progress.progress_bar`) over the files' sizes on disk,
    advanced by the octets of the blocks walked, scaled by on-disk over decompressed size (gzip
    files); ``bar`` None when it does not show."""

    def __init__(self, paths: list, enabled: bool) -> None:
        self.bar, self.on_disk, self.scale, self.done = None, 0, 1.0, 0
        if enabled:
            total = sum(Path(p).stat().st_size for p in paths if Path(p).is_file())
            bar = progress_bar(enabled, "ASTERIX", total=total, unit="B", unit_scale=True)
            self.bar = None if bar.disable else bar

    def start(self, path: str | Path) -> None:
        self.on_disk = Path(path).stat().st_size if Path(path).is_file() else 0

    def file_size(self, octets: int) -> None:
        self.scale = self.on_disk / max(octets, 1)

    def update(self, octets: int) -> None:
        if self.bar is not None:
            self.bar.update(octets * self.scale)

    def finish_file(self) -> None:
        if self.bar is not None:
            self.done += self.on_disk
            self.bar.n = self.done
            self.bar.refresh()

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()


def _as_date(date: dt.date | str | None) -> dt.date | None:
    if date is None or isinstance(date, dt.date):
        return date.date() if isinstance(date, dt.datetime) else date
    try:
        return dt.date.fromisoformat(str(date))
    except ValueError:
        raise ValueError(f"date: {date!r} is not a date; give a datetime.date or 'YYYY-MM-DD'") from None


def _concat(parts: list, columns: tuple) -> dict:
    return {c: np.concatenate([p[c] for p in parts if p]) if any(parts) else np.zeros(0) for c in columns}


def _frame(columns: dict, order_by: str = "time_s") -> pd.DataFrame:
    import pandas as pd

    frame = pd.DataFrame(columns)
    if len(frame):
        frame = frame.sort_values(order_by, kind="stable").reset_index(drop=True)
    return frame


def _reference(rows: list, plot_targets: set, which: str) -> tuple[dict, dict]:
    ref = _concat([r.reference for r in rows], (*REFERENCE_COLUMNS, "pressure_alt_m"))
    targets = ref["target"].astype(str) if ref["target"].size else np.zeros(0, dtype=str)
    plotted = np.isin(targets, list(plot_targets)) if targets.size else np.zeros(0, dtype=bool)
    info = {
        "reports": int(targets.size),
        "targets": int(np.unique(targets).size),
        "targets_without_plots": int(np.unique(targets[~plotted]).size),
        "reports_of_targets_without_plots": int((~plotted).sum()),
        "kept": which,
    }
    if which == "plotted":
        ref = {c: v[plotted] for c, v in ref.items()}
    return ref, info


def _flight_levels(plots: dict, sites: pd.DataFrame, reference: dict) -> tuple[dict, dict]:
    """The reference rows of the plots' flight levels and their summary
    (:mod:`registration.io.asterix.tables.flightlevels`), the relation learned from every ADS-B
    report kept (``reference`` before the plotted targets are chosen)."""
    relation = learn_relation(
        np.asarray(reference["pressure_alt_m"], dtype=float),
        np.asarray(reference["alt_m"], dtype=float),
        np.asarray(reference["target"]).astype(str),
    )
    row = _site_rows(sites["sensor"].astype(str).to_numpy(), np.asarray(plots["sensor"]).astype(str))
    site_lla = np.stack(
        [
            np.radians(sites["lat_deg"].to_numpy(float))[row],
            np.radians(sites["lon_deg"].to_numpy(float))[row],
            sites["alt_m"].to_numpy(float)[row],
        ],
        axis=1,
    ).reshape(-1, 3)
    return height_rows(plots, site_lla, relation, set(np.asarray(reference["target"]).astype(str).tolist()))


def _site_rows(names: np.ndarray, values: np.ndarray) -> np.ndarray:
    """Index of each of ``values`` in ``names`` (every value is there)."""
    lookup = {n: k for k, n in enumerate(names.tolist())}
    unique, inverse = np.unique(values, return_inverse=True) if values.size else (values, values)
    return np.array([lookup[u] for u in unique.tolist()], dtype=np.int64)[inverse.astype(np.int64)]


def import_asterix(
    paths: str | Path | Sequence[str | Path],
    sites: pd.DataFrame | str | Path,
    date: dt.date | str | None = None,
    progress: bool = False,
    *,
    editions: Mapping[int, str] | None = None,
    ports: Iterable[int] | None = None,
    reference_targets: str = "plotted",
    max_bytes: int = DEFAULT_MAX_BYTES,
    max_records: int = DEFAULT_MAX_RECORDS,
    max_rejected_rows: int = DEFAULT_MAX_REJECTED_ROWS,
    keep_duplicates: bool = False,
    framing: str = "auto",
) -> AsterixImport:
    """Import ASTERIX recordings (raw data blocks, pcap, pcapng; gzip or not; told apart by content).

    ``paths``: one path or a list, read in order as one stream (time of day carried across files).
    ``sites``: the SITES table (DataFrame, or a path read with
    :func:`~registration.io.asterix.tables.sites.read_sites`). ``date``: the UTC day (datetime.date or
    'YYYY-MM-DD') that ``time_s`` counts from; None: the first capture's packet date, else the
    recording's first day (the summary says which). ``progress``: a bar over the bytes read
    (:func:`registration.core.progress.progress_bar`). ``editions``:
    category -> edition (default the latest of each, e.g. ``{21: "0.26"}`` for an old ADS-B
    feed). ``ports``: UDP destination ports to read from captures (None: all).
    ``reference_targets``: 'plotted' (default) keeps the ADS-B reports of targets that some plot
    names (the fleet reader refuses reference targets without plots), 'all' keeps all.
    ``max_bytes``, ``max_records``: the decompressed octets read and the records decoded per input;
    ``max_rejected_rows``: the rows ``rejected`` lists (the rest are counted in the summary, and one
    last row says how many). Beyond a bound the rest is set aside as ``over_limit``
    (:mod:`registration.io.files.limits`; defaults 8 GiB, 2*10^6 records, 10^5 rows).
    ``keep_duplicates``: keep records that repeat an earlier one (same category, octets and day);
    by default they are set aside as ``duplicate`` and counted
    (:mod:`registration.io.asterix.tables.duplicates`). ``framing``: how a file that is no capture
    wraps its data blocks: 'auto' (default: told by content), 'netto' (raw data blocks end to end),
    or a recorder framing, 'gps', 'rff', 'ioss' ('final'), 'ioss_seq', 'oradis', 'hdlc'
    (docs/reference/asterix-framings.md).

    Raises :class:`~registration.io.asterix.errors.AsterixImportError` (a ValueError) naming the
    file for a file that is neither ASTERIX nor a capture, ValueError for bad arguments or SITES;
    anything bad inside a file is set aside in ``rejected``.
    """
    paths = [paths] if isinstance(paths, (str, Path)) else list(paths)
    if not paths:
        raise ValueError("paths: no file given")
    if reference_targets not in REFERENCE_TARGETS:
        raise ValueError(f"reference_targets: {reference_targets!r}; expected one of {REFERENCE_TARGETS}")
    sites = read_sites(sites) if isinstance(sites, (str, Path)) else check_sites(sites, "sites")
    editions = check_editions(editions)
    framing = check_framing(framing)
    date = _as_date(date)
    limits = Limits(max_bytes, max_records, max_rejected_rows)
    rejections, bar = BoundedLedger(LEDGER_COLUMNS, max_rejected_rows), _Progress(paths, progress)
    decoded = []
    try:
        for path in paths:
            bar.start(path)
            decoded.append(
                decode_file(
                    path, editions, rejections, ports, bar if bar.bar is not None else None, limits, framing
                )
            )
            decoded[-1].capture.buf = np.zeros(0, dtype=np.uint8)  # fields decoded: the file's bytes can go
            bar.finish_file()
    finally:
        bar.close()
    return _build(
        decoded, sites, date, editions, rejections, reference_targets, StreamChecks(keep_duplicates)
    )


def _build(
    decoded: list,
    sites: pd.DataFrame,
    date: dt.date | None,
    editions: dict,
    rejections: RejectedLedger,
    which: str,
    checks: StreamChecks,
) -> AsterixImport:
    first_capture = next(
        (d.capture.counts["first_packet_time"] for d in decoded if "first_packet_time" in d.capture.counts),
        None,
    )
    source = "argument" if date is not None else "capture" if first_capture is not None else "recording"
    reference_day = (
        date if date is not None else capture_day(first_capture) if first_capture is not None else None
    )
    unwrapper = Unwrapper(reference_day)
    names = sites["sensor"].astype(str).to_numpy()
    lookup = SiteLookup(sites["sac"].to_numpy(), sites["sic"].to_numpy())
    clock = TruncatedClock()
    rows: list[FileRows] = [
        assemble_file(d, unwrapper, lookup, names, editions, rejections, checks, clock) for d in decoded
    ]
    plots = _concat(
        [r.plots for r in rows], (*PLOT_COLUMNS, "kind", "primary", "capture_lag_s", "pressure_alt_m")
    )
    service = _concat(
        [r.service for r in rows], ("sensor", "category", "msg_type", "time_s", "azimuth_deg", "rotation_s")
    )
    reference, ref_info, level_info = _references_with_heights(rows, plots, sites, which)
    decoded_counts: dict[int, int] = {}
    for r in rows:
        for cat, counts in r.decoded.items():
            decoded_counts[cat] = decoded_counts.get(cat, 0) + counts
    times = np.concatenate([r.times for r in rows]) if rows else np.zeros(0)
    span = times[np.isfinite(times)]
    tables = site_tables(sites, float(span.min()) if span.size else 0.0)
    unknown, adsb = sum((r.unknown for r in rows), Counter()), sum((r.adsb_sources for r in rows), Counter())
    ref_info["sources"] = [{"sac": s, "sic": i, "reports": n} for (s, i), n in sorted(adsb.items())]
    summary = {
        "files": [file_summary(d, d.blocks_by_category) for d in decoded],
        "editions": {f"{c:03d}": e for c, e in sorted(editions.items())},
        "time": time_summary(reference_day, source, times, unwrapper.placed_by_capture),
        "plots": {
            "total": int(plots["time_s"].size),
            "mode_s": int((plots["kind"] == "mode_s").sum()),
            "mode_a": int((plots["kind"] == "mode_a").sum()),
            "without_id": int((plots["kind"] == "none").sum()),
        },
        "sensors": sensor_summary(sites, plots, service, decoded_counts),
        **({"cat001_time": clock.summary()} if decoded_counts.get(1) is not None else {}),
        "sac_sic_not_in_sites": sources_not_in_sites(unknown),
        "reference": ref_info,
        "flight_levels": level_info,
        **checks.summary(),
        "rejected": {"total": rejections.count(), "by_reason": rejections.by_code(tuple(REASONS))},
    }
    return AsterixImport(
        plots=_plot_frame(plots, sites),
        navigation=tables["navigation"],
        sensors=tables["sensors"],
        platforms=tables["platforms"],
        reference=_frame(reference),
        rejected=rejections.frame(),
        summary=summary,
    )


def _references_with_heights(
    rows: list, plots: dict, sites: pd.DataFrame, which: str
) -> tuple[dict, dict, dict]:
    """(reference columns, the reference summary, the flight levels' summary): the ADS-B reports
    ``which`` kept, then the heights of the flight levels of aircraft without ADS-B (height-only
    rows; with ``height_offset_prior_m`` where they share one offset state)."""
    every_adsb, _ = _reference(rows, set(), "all")
    reference, ref_info = _reference(
        rows, set(plots["target"].astype(str)) - {""} if plots["target"].size else set(), which
    )
    heights, level_info = _flight_levels(plots, sites, every_adsb)
    reference = {
        c: np.concatenate([np.asarray(reference[c]), np.asarray(heights[c])]) if heights else reference[c]
        for c in REFERENCE_COLUMNS
    }
    if "height_offset_prior_m" in heights:  # the ISA's heights, sharing one offset state
        n_adsb = reference["time_s"].size - heights["time_s"].size
        reference["height_offset_prior_m"] = np.r_[np.full(n_adsb, np.nan), heights["height_offset_prior_m"]]
    return reference, ref_info, level_info


def _plot_frame(plots: dict, sites: pd.DataFrame) -> pd.DataFrame:
    """The plots file's rows: the primary-only plots of radars whose PSR channel is their own
    sensor moved to ``<radar>.psr``."""
    plot_frame = _frame(
        {
            **{c: plots[c] for c in PLOT_COLUMNS},
            "kind": file_kinds(plots["kind"], plots["primary"]).astype(str),
            "primary": np.asarray(plots["primary"], dtype=bool),  # sorted with the rows, then dropped
        }
    )
    primary = plot_frame.pop("primary").to_numpy(bool)
    plot_frame["sensor"] = channel_sensors(sites, plot_frame["sensor"].to_numpy(), primary)
    plot_frame["target"] = plot_frame["target"].astype(str)
    return plot_frame
