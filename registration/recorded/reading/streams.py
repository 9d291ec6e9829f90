"""One input of the asynchronous form as a stream of accepted samples on the reference clock.

A :class:`SampleStream` reads its file block by block (validating every row; the rejections go
to a shared ``inbox`` in reading order), keeps only the samples around the current instants, and
evaluates its columns at given instants (s): the sample itself when one lies within
``exact_tol_s``, else the sliding-window fit of :func:`registration.core.alignment.align`, with
the reason when an instant cannot be served (extrapolation, gap, too few samples).
"""

from __future__ import annotations

import numpy as np

from registration.core.alignment import align
from registration.recorded.options import PairingOptions
from registration.recorded.reading.formats import iter_frames
from registration.recorded.reading.rowcheck import check_frame
from registration.recorded.reading.sources import Source

__all__ = ["SampleStream", "REASON_GAP", "REASON_NO_SAMPLES"]

REASON_GAP = "gap"
REASON_NO_SAMPLES = "no samples"


class SampleStream:
    """Accepted samples of one source: times ``t`` (s, reference clock), values ``y`` (SI units,
    radians; layout order without time) and their ``rows`` in the file."""

    def __init__(self, source: Source, chunk_rows: int, mode: str, options: PairingOptions, inbox: list):
        self.source = source
        self.name = source.role
        self._inbox = inbox
        self._blocks = self._read(chunk_rows, mode)
        self.t = np.empty(0)
        self.y = np.empty((0, len(source.layout.fields) - 1))
        self.rows = np.empty(0, dtype=np.int64)
        self.eof = False
        self.max_gap = options.max_gap_s
        self._gap_factor = options.gap_factor
        self.n_read = 0
        self.n_accepted = 0

    def _read(self, chunk_rows, mode):
        src = self.source
        last = None
        for first, frame in iter_frames(src.path, src.layout.columns, chunk_rows):
            blk = check_frame(frame, src.layout, str(src.path), first_row=first, mode=mode, last_time=last)
            last = blk.last_time
            self.n_read += blk.n_rows
            self.n_accepted += int(blk.accepted.sum())
            self._inbox.append((src.path, blk.rejections))
            acc = blk.accepted
            yield blk.values[acc, 0] - src.clock_offset, blk.values[acc, 1:], first + np.flatnonzero(acc)

    def load_block(self) -> bool:
        """Read the next block's accepted samples into the buffer; False at the end of the file."""
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

    def take(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Hand over the buffered (t, y, rows) and empty the buffer."""
        out = (self.t, self.y, self.rows)
        self.t, self.y, self.rows = np.empty(0), np.empty((0, self.y.shape[1])), np.empty(0, dtype=np.int64)
        return out

    def ensure(self, tau_max: float, need: int) -> None:
        """Load until ``need`` samples lie after tau_max (or the file ends)."""
        while not self.eof and (self.t.size - np.searchsorted(self.t, tau_max, side="right")) < need:
            self.load_block()

    def trim(self, tau_min_next: float, keep: int) -> None:
        """Forget the samples before ``tau_min_next`` except the last ``keep`` of them."""
        cut = max(0, int(np.searchsorted(self.t, tau_min_next)) - keep)
        if cut:
            self.t, self.y, self.rows = self.t[cut:], self.y[cut:], self.rows[cut:]

    def drain(self) -> None:
        """Read (and validate) the rest of the file, keeping only its last sample."""
        while not self.eof:
            self.load_block()
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
            fit = align(
                self.t,
                self.y[:, cols],
                tau[todo],
                degree=d,
                n_nearest=d + 1,
                max_extrapolation_s=options.max_extrapolation_s,
                angle_columns=angle_cols,
                strict=False,
            )
            vals[todo] = fit.y
            reason[todo] = fit.reason
            self._mark_gaps(i[todo], inext[todo], iprev[todo], reason, todo)
            ok = reason[todo] == ""
            vals[todo[~ok]] = np.nan
        return vals, exact, reason

    def _mark_gaps(self, i, inext, iprev, reason, todo) -> None:
        """Give the reason 'gap' to fitted instants between two samples further apart than max_gap."""
        inside = (i > 0) & (i < self.t.size)
        gap = np.where(inside, self.t[inext] - self.t[iprev], 0.0)
        limit = np.inf if self.max_gap is None else self.max_gap
        wide = inside & (gap > limit)
        for j in np.flatnonzero(wide):
            reason[todo[j]] = f"{REASON_GAP} of {gap[j]:.6g} s between samples (limit {limit:.6g} s)"
