"""Pair two radars' asynchronous plots of a common target at common instants (issue 6).

Input: two per-sensor plot files, each with its own timestamps and rate, and each ship's
navigation either in its plot file or in a navigation file at its own rate. Output: a
synchronous table (the file form of the data contract, :data:`registration.io.SYNC_COLUMNS`)
that the registration filter reads like any other.

Rules (documented in docs/register.md):

* **Clocks.** Radar A's clock reads reference time + ``clock_offset_a`` (likewise B); a
  navigation file is on the reference clock, navigation inside a plot file on that radar's clock.
  Every timestamp is moved onto the reference clock before anything else.
* **Instants.** The common instants are the plot times of one radar, ``pair_at`` (A by default;
  choose the radar with the lower rate so that no plot of the other is used twice more than
  necessary). That radar's plots are used as measured.
* **The other radar's plot** at an instant: its own plot when one lies within ``exact_tol_s`` of
  the instant (**paired**), otherwise the sliding-window least-squares fit of
  :func:`registration.alignment.align` over its ``degree + 1`` nearest plots (**interpolated**;
  degree 1 = linear interpolation between the two neighbours, angles unwrapped).
* **Navigation** (lat, lon, alt, heading, pitch, roll) at an instant: exact when it comes with
  the instant's own plot, otherwise fitted the same way from its source.
* **Unpaired** instants, each with its reason, written to ``unpaired.csv``: the instant lies
  before the first or after the last sample of a stream (``extrapolation beyond limit``; allowed
  up to ``max_extrapolation_s``, 0 by default), in a ``gap`` between two samples wider than
  ``max_gap_s`` (default 2.5 times the stream's median sample interval), or its window holds too
  few samples or is ill-conditioned (the reasons of ``align``).

Noise. An interpolated plot is a weighted mean of measured plots, so its noise variance is at most
that of one plot (``variance_factor`` <= 1 for linear interpolation): the filter keeps the radar's
nominal sigma, a conservative choice that ignores the correlation between neighbouring instants
that share a plot.

Streaming: each file is read in blocks; a stream keeps only the samples around the current
instants, so memory does not grow with the file length.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from registration.core.alignment import REASON_EXTRAPOLATION, align
from registration.recorded.formats import NAV_FIELDS, NAV_KINDS, PLOT_KINDS, SYNC_COLUMNS, iter_frames, read_columns
from registration.recorded.rowcheck import CheckedBlock, check_frame, nav_layout, plot_layout

__all__ = ["PairingOptions", "Source", "plan_sources", "pair_streams"]

REASON_GAP = "gap"
REASON_NO_SAMPLES = "no samples"


@dataclass
class PairingOptions:
    clock_offset_a: float = 0.0
    clock_offset_b: float = 0.0
    pair_at: str = "a"
    degree: int = 1
    max_extrapolation_s: float = 0.0
    max_gap_s: float | None = None  # None: 2.5 x the stream's median sample interval
    gap_factor: float = 2.5
    exact_tol_s: float = 1e-6

    def __post_init__(self):
        if self.pair_at not in ("a", "b"):
            raise ValueError(f"pair_at: expected 'a' or 'b', got {self.pair_at!r}")
        if not isinstance(self.degree, int) or not 0 <= self.degree <= 5:
            raise ValueError(f"degree: expected an integer in [0, 5], got {self.degree!r}")
        for name in ("clock_offset_a", "clock_offset_b", "max_extrapolation_s", "exact_tol_s"):
            if not np.isfinite(getattr(self, name)):
                raise ValueError(f"{name}: expected a finite number of seconds")
        if self.max_extrapolation_s < 0:
            raise ValueError("max_extrapolation_s: must be >= 0 s")
        if self.max_gap_s is not None and not (np.isfinite(self.max_gap_s) and self.max_gap_s > 0):
            raise ValueError("max_gap_s: must be a finite number > 0 s")

    def to_json(self) -> dict:
        return asdict(self)


@dataclass
class Source:
    """One input file of the asynchronous form and what it provides."""

    path: Path
    layout: object  # rowcheck.Layout
    clock_offset: float
    plots_of: str | None  # 'a'/'b' if the file holds that radar's plots
    nav_of: tuple[str, ...]  # ships whose navigation the file holds
    role: str  # human-readable

    def columns_for(self, sensor: str, kinds) -> list[int]:
        """Indices into the layout's non-time fields of ``sensor``'s ``kinds``."""
        out = []
        for kind in kinds:
            for j, f in enumerate(self.layout.fields[1:]):
                if f.kind == kind and (f.prefix == sensor or (f.prefix == "" and self.plots_of == sensor)):
                    out.append(j)
        return out


def _sensor_of_plot_file(cols: set[str]) -> str | None:
    has = [s for s in ("a", "b") if any(f"{s}_{k}_{u}" in cols for k, u in (("range", "m"), ("bearing", "deg"), ("elevation", "deg")))]
    return has[0] if len(has) == 1 else None


def plan_sources(inputs: list[Path], navs: list[Path], options: PairingOptions) -> list[Source]:
    """Work out which file gives which radar's plots and which ship's navigation; refuse ambiguity."""
    if len(inputs) != 2:
        raise ValueError("the asynchronous form takes exactly two plot files (radar A, radar B)")
    cols = [set(read_columns(p)) for p in inputs]
    sensors = [_sensor_of_plot_file(c) for c in cols]
    if sensors[0] is None and sensors[1] is None:
        sensors = ["a", "b"]
    elif sensors[0] is None:
        sensors[0] = "a" if sensors[1] == "b" else "b"
    elif sensors[1] is None:
        sensors[1] = "a" if sensors[0] == "b" else "b"
    if sensors[0] == sensors[1]:
        raise ValueError(f"both plot files {inputs[0]} and {inputs[1]} hold radar {sensors[0].upper()}'s plots (column prefix)")
    nav_kinds = [f.file_name for f in NAV_FIELDS]
    sources = []
    for path, c, s in zip(inputs, cols, sensors):
        prefixed = f"{s}_range_m" in c or f"{s}_bearing_deg" in c or f"{s}_elevation_deg" in c
        lead = f"{s}_" if prefixed else ""
        with_nav = any(f"{lead}{n}" in c for n in nav_kinds)
        offset = options.clock_offset_a if s == "a" else options.clock_offset_b
        sources.append(Source(path, plot_layout(s, prefixed, with_nav), offset, s, (s,) if with_nav else (),
                              f"plots of radar {s.upper()}" + (" with navigation" if with_nav else "")))
    for path in navs:
        c = set(read_columns(path))
        ships = tuple(s for s in ("a", "b") if any(f"{s}_{n}" in c for n in nav_kinds))
        if not ships:
            raise ValueError(f"navigation file {path}: no navigation columns; expected time_s and a_lat_deg ... a_roll_deg and/or b_lat_deg ... b_roll_deg")
        sources.append(Source(path, nav_layout(ships), 0.0, None, ships, "navigation of ship(s) " + ", ".join(x.upper() for x in ships)))
    for s in ("a", "b"):
        given = [src for src in sources if s in src.nav_of]
        if not given:
            raise ValueError(f"no navigation for ship {s.upper()}: give it in its plot file ({', '.join(f.file_name for f in NAV_FIELDS)}) or in a --nav file (prefixed {s}_)")
        if len(given) > 1:
            raise ValueError(f"navigation of ship {s.upper()} is given twice ({given[0].path} and {given[1].path}); give it once")
    return sorted(sources[:2], key=lambda src: src.plots_of) + sources[2:]


class _Stream:
    """Accepted samples of one source on the reference clock, read block by block."""

    def __init__(self, source: Source, chunk_rows: int, mode: str, on_reject, options: PairingOptions):
        self.source = source
        self.name = source.role
        self._blocks = self._read(chunk_rows, mode, on_reject)
        self.t = np.empty(0)
        self.y = np.empty((0, len(source.layout.fields) - 1))
        self.rows = np.empty(0, dtype=np.int64)
        self.eof = False
        self.max_gap = options.max_gap_s
        self._gap_factor = options.gap_factor
        self.n_read = 0
        self.n_accepted = 0

    def _read(self, chunk_rows, mode, on_reject):
        src = self.source
        last = None
        for first, frame in iter_frames(src.path, src.layout.columns, chunk_rows):
            blk: CheckedBlock = check_frame(frame, src.layout, str(src.path), first_row=first, mode=mode, last_time=last)
            last = blk.last_time
            self.n_read += blk.n_rows
            self.n_accepted += int(blk.accepted.sum())
            on_reject(src.path, blk.rejections)
            acc = blk.accepted
            yield blk.values[acc, 0] - src.clock_offset, blk.values[acc, 1:], first + np.flatnonzero(acc)

    def _load_one(self) -> bool:
        try:
            t, y, rows = next(self._blocks)
        except StopIteration:
            self.eof = True
            return False
        self.t = np.concatenate([self.t, t])
        self.y = np.concatenate([self.y, y])
        self.rows = np.concatenate([self.rows, rows])
        if self.max_gap is None and self.t.size >= 2:
            self.max_gap = self._gap_factor * float(np.median(np.diff(self.t)))
        return True

    def ensure(self, tau_max: float, need: int) -> None:
        """Load until ``need`` samples lie after tau_max (or the file ends)."""
        while not self.eof and (self.t.size - np.searchsorted(self.t, tau_max, side="right")) < need:
            self._load_one()

    def trim(self, tau_min_next: float, keep: int) -> None:
        cut = max(0, int(np.searchsorted(self.t, tau_min_next)) - keep)
        if cut:
            self.t, self.y, self.rows = self.t[cut:], self.y[cut:], self.rows[cut:]

    def drain(self) -> None:
        while not self.eof:
            self._load_one()
            self.t, self.y, self.rows = self.t[-1:], self.y[-1:], self.rows[-1:]

    def evaluate(self, tau: np.ndarray, cols: list[int], angle_cols: list[int], options: PairingOptions):
        """Values of columns ``cols`` at instants ``tau``: (values (M, C), exact (M,), reason (M,) object)."""
        m = tau.size
        vals = np.full((m, len(cols)), np.nan)
        reason = np.full(m, "", dtype=object)
        exact = np.zeros(m, dtype=bool)
        if self.t.size == 0:
            reason[:] = REASON_NO_SAMPLES
            return vals, exact, reason
        i = np.searchsorted(self.t, tau)
        inext = np.minimum(i, self.t.size - 1)
        iprev = np.maximum(i - 1, 0)
        dn, dp = np.abs(self.t[inext] - tau), np.abs(tau - self.t[iprev])
        near = np.where(dn <= dp, inext, iprev)
        exact = np.minimum(dn, dp) <= options.exact_tol_s
        vals[exact] = self.y[near[exact]][:, cols]
        todo = np.flatnonzero(~exact)
        if todo.size:
            d = options.degree
            fit = align(self.t, self.y[:, cols], tau[todo], degree=d, n_nearest=d + 1,
                        max_extrapolation_s=options.max_extrapolation_s, angle_columns=angle_cols, strict=False)
            vals[todo] = fit.y
            reason[todo] = fit.reason
            inside = (i[todo] > 0) & (i[todo] < self.t.size)
            gap = np.where(inside, self.t[inext[todo]] - self.t[iprev[todo]], 0.0)
            limit = np.inf if self.max_gap is None else self.max_gap
            wide = inside & (gap > limit)
            for j in np.flatnonzero(wide):
                reason[todo[j]] = f"{REASON_GAP} of {gap[j]:.6g} s between samples (limit {limit:.6g} s)"
            ok = reason[todo] == ""
            vals[todo[~ok]] = np.nan
        return vals, exact, reason


def pair_streams(sources: list[Source], options: PairingOptions, *, chunk_rows: int, mode: str,
                 on_reject, write_pairs, write_unpaired, progress=None) -> dict:
    """Stream the sources and emit paired rows.

    ``write_pairs(frame)``: a DataFrame with :data:`SYNC_COLUMNS` (file units) plus ``pair_row``
    (row of the instant in the reference plot file) and ``pair_interpolated`` (0/1).
    ``write_unpaired(rows)``: lists ``[time_s, file, row, reason]``. ``on_reject(path, rejections)``
    receives the bad rows of every file. Returns the pairing report (counts and reasons).
    """
    import pandas as pd

    ref_s = options.pair_at
    oth_s = "b" if ref_s == "a" else "a"
    by_plot = {src.plots_of: src for src in sources if src.plots_of}
    ref_src, oth_src = by_plot[ref_s], by_plot[oth_s]
    streams = {id(src): _Stream(src, chunk_rows, mode, on_reject, options) for src in sources}
    ref = streams[id(ref_src)]
    need = options.degree + 2
    counts = {"instants": 0, "paired": 0, "exact": 0, "interpolated": 0, "unpaired": 0, "unpaired_reasons": {}}
    angle_kinds = ("lon", "heading", "bearing")

    def plan(sensor: str, kinds):
        """For each kind of ``sensor``: which stream holds it and which column."""
        for src in sources:
            cols = src.columns_for(sensor, kinds)
            if len(cols) == len(kinds) and (sensor == src.plots_of or sensor in src.nav_of):
                return streams[id(src)], cols
        raise AssertionError("plan_sources guarantees a source")

    wanted = []  # (stream, cols, angle_cols, target slice in the 18-row, is_other_plot)
    for sensor in ("a", "b"):
        base = 0 if sensor == "a" else 9
        nav_src = next(src for src in sources if sensor in src.nav_of)
        s_nav = streams[id(nav_src)]
        cols = nav_src.columns_for(sensor, NAV_KINDS)
        wanted.append((s_nav, cols, [i for i, k in enumerate(NAV_KINDS) if k in angle_kinds], slice(base, base + 6), False))
        s_plot, pcols = plan(sensor, PLOT_KINDS)
        wanted.append((s_plot, pcols, [i for i, k in enumerate(PLOT_KINDS) if k in angle_kinds], slice(base + 6, base + 9), sensor == oth_s))
    others = [s for s in streams.values() if s is not ref]
    ref_cols_all = list(range(len(ref_src.layout.fields) - 1))
    while True:
        if not ref._load_one():
            break
        tau, rows_ref = ref.t, ref.rows
        ref_y = ref.y
        ref.t, ref.y, ref.rows = np.empty(0), np.empty((0, len(ref_cols_all))), np.empty(0, dtype=np.int64)
        if tau.size == 0:
            continue
        if progress is not None:
            progress(int(rows_ref[-1]) + 1)
        for s in others:
            s.ensure(float(tau[-1]), need)
        m = tau.size
        out = np.full((m, 18), np.nan)
        fail = np.full(m, "", dtype=object)
        interpolated = np.zeros(m, dtype=bool)
        for stream, cols, acols, slot, is_other_plot in wanted:
            if stream is ref:
                out[:, slot] = ref_y[:, cols]
                continue
            vals, exact, reason = stream.evaluate(tau, cols, acols, options)
            out[:, slot] = vals
            bad = (reason != "") & (fail == "")
            for j in np.flatnonzero(bad):
                fail[j] = f"{stream.name}: {reason[j]}"
            if is_other_plot:
                interpolated |= ~exact
        for s in others:
            s.trim(float(tau[-1]), need)
        ok = fail == ""
        counts["instants"] += m
        counts["paired"] += int(ok.sum())
        counts["interpolated"] += int((ok & interpolated).sum())
        counts["exact"] += int((ok & ~interpolated).sum())
        counts["unpaired"] += int((~ok).sum())
        if (~ok).any():
            rec = []
            for j in np.flatnonzero(~ok):
                stream_name, _, why = fail[j].partition(": ")
                key = f"{stream_name}: {REASON_GAP if why.startswith(REASON_GAP) else why}"
                counts["unpaired_reasons"][key] = counts["unpaired_reasons"].get(key, 0) + 1
                rec.append([repr(float(tau[j])), str(ref_src.path), int(rows_ref[j]), fail[j]])
            write_unpaired(rec)
        if ok.any():
            o = out[ok]
            frame = {"time_s": tau[ok]}
            for k, name in enumerate(SYNC_COLUMNS[1:]):
                frame[name] = np.degrees(o[:, k]) if name.endswith("_deg") else o[:, k]
            frame["pair_row"] = rows_ref[ok]
            frame["pair_interpolated"] = interpolated[ok].astype(np.int64)
            write_pairs(pd.DataFrame(frame))
    for s in others:  # read to the end: every row of every file is validated and accounted for
        s.drain()
    counts["extrapolation_reason"] = REASON_EXTRAPOLATION
    counts["max_gap_s"] = {s.name: s.max_gap for s in streams.values()}
    counts["files"] = {str(s.source.path): {"role": s.name, "rows": s.n_read, "accepted": s.n_accepted,
                                            "rejected": s.n_read - s.n_accepted} for s in streams.values()}
    return counts
