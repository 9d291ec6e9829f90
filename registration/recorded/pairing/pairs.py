"""Pair two radars' asynchronous plots of a common target at common instants.

Input: two per-sensor plot files, each with its own timestamps and rate, and each ship's
navigation either in its plot file or in a navigation file at its own rate
(:mod:`registration.recorded.reading.sources`). Output: blocks of the synchronous table
(:data:`registration.recorded.reading.columns.PAIRED_COLUMNS`) that the registration filter reads like
any other. Rules (documented in docs/howto/register-recorded-files.md):

* **Clocks.** Radar A's clock reads reference time + ``clock_offset_a`` (likewise B); a
  navigation file is on the reference clock, navigation inside a plot file on that radar's clock.
  Every timestamp is moved onto the reference clock before anything else.
* **Instants.** The common instants are the plot times of one radar, ``pair_at`` (A by default);
  that radar's plots are used as measured.
* **The other radar's plot** at an instant: its own plot when one lies within ``exact_tol_s`` of
  the instant (**paired**), otherwise the sliding-window least-squares fit over its
  ``degree + 1`` nearest plots (**interpolated**; degree 1 = linear interpolation, angles unwrapped).
* **Navigation** at an instant: exact when it comes with the instant's own plot, otherwise fitted
  the same way from its source.
* **Unpaired** instants, each with its reason: beyond the first or last sample of a stream
  (``extrapolation beyond limit``; allowed up to ``max_extrapolation_s``), in a ``gap`` wider than
  ``max_gap_s``, or a window with too few samples or ill-conditioned.

An interpolated plot is a weighted mean of measured plots, so its noise variance is at most that
of one plot: the filter keeps the radar's nominal sigma (conservative). Each file is read in
blocks and a stream keeps only the samples around the current instants, so memory does not grow
with the file length.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Iterator

import numpy as np

from registration.core.alignment import REASON_EXTRAPOLATION
from registration.online.contract import N_ROW, ROW_COLUMNS, SENSOR_ROW, SENSORS
from registration.recorded.options import PairingOptions
from registration.recorded.reading.columns import NAV_KINDS, PLOT_KINDS
from registration.recorded.reading.formats import to_file_frame
from registration.recorded.reading.sources import Source
from registration.recorded.reading.streams import REASON_GAP, SampleStream

__all__ = ["PairedBlock", "Pairer"]

_ANGLE_KINDS = ("lon", "heading", "bearing")


@dataclass
class PairedBlock:
    """What one block of reference instants gave: the paired rows (DataFrame of PAIRED_COLUMNS, or
    None), the unpaired instants (``[time_s, file, row, reason]``), the rejections read meanwhile
    (``[(path, [Rejection])]``) and the rows of the reference plot file read so far (None: unchanged)."""

    pairs: object
    unpaired: list
    rejections: list
    rows_done: int | None


@dataclass
class _Column:
    """Where columns ``cols`` of ``stream`` go in the 18-value row (``slot``)."""

    stream: SampleStream
    cols: list
    angle_cols: list
    slot: slice
    other_plot: bool  # the plots of the radar that is not pair_at


class Pairer:
    """Pairs the sources' samples; iterate :meth:`blocks`, then read :meth:`report`."""

    def __init__(self, sources: list[Source], options: PairingOptions, *, chunk_rows: int, mode: str):
        self.options = options
        self._inbox: list = []
        self._streams = [SampleStream(src, chunk_rows, mode, options, self._inbox) for src in sources]
        self._ref = next(s for s in self._streams if s.source.plots_of == options.pair_at)
        self._others = [s for s in self._streams if s is not self._ref]
        self._columns = self._plan_columns()
        self._need = options.degree + 2
        self._counts: dict[str, Any] = {
            "instants": 0,
            "paired": 0,
            "exact": 0,
            "interpolated": 0,
            "unpaired": 0,
            "unpaired_reasons": {},
        }

    def _plan_columns(self) -> list[_Column]:
        """For each sensor: the stream and columns of its navigation, then of its plot."""
        out = []
        for sensor in SENSORS:
            base = SENSOR_ROW[sensor].start
            nav = next(s for s in self._streams if sensor in s.source.nav_of)
            out.append(
                _Column(
                    nav,
                    nav.source.columns_for(sensor, NAV_KINDS),
                    [i for i, k in enumerate(NAV_KINDS) if k in _ANGLE_KINDS],
                    slice(base, base + len(NAV_KINDS)),
                    False,
                )
            )
            plot = next(
                s
                for s in self._streams
                if len(s.source.columns_for(sensor, PLOT_KINDS)) == len(PLOT_KINDS)
                and (sensor == s.source.plots_of or sensor in s.source.nav_of)
            )
            out.append(
                _Column(
                    plot,
                    plot.source.columns_for(sensor, PLOT_KINDS),
                    [i for i, k in enumerate(PLOT_KINDS) if k in _ANGLE_KINDS],
                    slice(base + len(NAV_KINDS), base + len(NAV_KINDS) + len(PLOT_KINDS)),
                    sensor != self.options.pair_at,
                )
            )
        return out

    def blocks(self) -> Iterator[PairedBlock]:
        """One :class:`PairedBlock` per block of the reference plot file, then one for the rest of
        the other files (read to the end: every row of every file is validated and accounted for)."""
        while self._ref.load_block():
            tau, ref_y, rows_ref = self._ref.take()
            if tau.size == 0:
                yield PairedBlock(None, [], self._take_rejections(), None)
                continue
            yield self._pair(tau, rows_ref, ref_y)
        for s in self._others:
            s.drain()
        yield PairedBlock(None, [], self._take_rejections(), None)

    def _take_rejections(self) -> list:
        out = list(self._inbox)
        self._inbox.clear()
        return out

    def _pair(self, tau: np.ndarray, rows_ref: np.ndarray, ref_y: np.ndarray) -> PairedBlock:
        for s in self._others:
            s.ensure(float(tau[-1]), self._need)
        values, fail, interpolated = self._values_at(tau, ref_y)
        for s in self._others:
            s.trim(float(tau[-1]), self._need)
        ok = fail == ""
        c = self._counts
        c["instants"] += tau.size
        c["paired"] += int(ok.sum())
        c["interpolated"] += int((ok & interpolated).sum())
        c["exact"] += int((ok & ~interpolated).sum())
        c["unpaired"] += int((~ok).sum())
        unpaired = self._unpaired(tau[~ok], rows_ref[~ok], fail[~ok])
        pairs = self._pairs_frame(tau[ok], values[ok], rows_ref[ok], interpolated[ok]) if ok.any() else None
        return PairedBlock(pairs, unpaired, self._take_rejections(), int(rows_ref[-1]) + 1)

    def _values_at(self, tau: np.ndarray, ref_y: np.ndarray):
        """18-value rows at the instants (SI units), the first failure per instant ('' if none),
        and whether the other radar's plot was interpolated."""
        m = tau.size
        out = np.full((m, N_ROW), np.nan)
        fail = np.full(m, "", dtype=object)
        interpolated = np.zeros(m, dtype=bool)
        for col in self._columns:
            if col.stream is self._ref:
                out[:, col.slot] = ref_y[:, col.cols]
                continue
            vals, exact, reason = col.stream.evaluate(tau, col.cols, col.angle_cols, self.options)
            out[:, col.slot] = vals
            bad = (reason != "") & (fail == "")
            for j in np.flatnonzero(bad):
                fail[j] = f"{col.stream.name}: {reason[j]}"
            if col.other_plot:
                interpolated |= ~exact
        return out, fail, interpolated

    def _unpaired(self, tau: np.ndarray, rows_ref: np.ndarray, fail: np.ndarray) -> list[list]:
        """unpaired.csv rows; counts each reason (a gap of any width under one key)."""
        rec = []
        reasons = self._counts["unpaired_reasons"]
        for t, row, why_full in zip(tau, rows_ref, fail):
            stream_name, _, why = why_full.partition(": ")
            key = f"{stream_name}: {REASON_GAP if why.startswith(REASON_GAP) else why}"
            reasons[key] = reasons.get(key, 0) + 1
            rec.append([repr(float(t)), str(self._ref.source.path), int(row), why_full])
        return rec

    @staticmethod
    def _pairs_frame(tau: np.ndarray, values: np.ndarray, rows_ref: np.ndarray, interpolated: np.ndarray):
        frame = to_file_frame({"time": tau, **{name: values[:, k] for k, name in enumerate(ROW_COLUMNS)}})
        frame["pair_row"] = rows_ref
        frame["pair_interpolated"] = interpolated.astype(np.int64)
        return frame

    def report(self) -> dict:
        """Counts of instants (paired, exact, interpolated, unpaired by reason), the gap limits (s)
        and, per file, its role and rows read, accepted and rejected."""
        streams = self._streams
        return {
            **self._counts,
            "extrapolation_reason": REASON_EXTRAPOLATION,
            "max_gap_s": {s.name: s.max_gap for s in streams},
            "files": {
                str(s.source.path): {
                    "role": s.name,
                    "rows": s.n_read,
                    "accepted": s.n_accepted,
                    "rejected": s.n_read - s.n_accepted,
                }
                for s in streams
            },
        }
