"""The state of a recorded-data run between blocks (:class:`RunState`), and its checkpoints.

A checkpoint payload is ``{"fingerprint", "phase", "filter": OnlineRegistrar.state_dict(),
"state": {counters}, "stats": {"raw", "corrected"}, "outputs": Outputs.marks()}``; restoring it
gives the state bit for bit, so a resumed run writes what an uninterrupted one writes.
:class:`Checkpointer` saves one at the start, every ``every`` rows of a pass and at the end of
each pass, after the outputs are fsync'ed.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from registration.io.output.checkpoint import load_checkpoint, save_checkpoint
from registration.online.config import RegistrationConfig
from registration.online.contract import N_STATE
from registration.online.filter import OnlineRegistrar
from registration.recorded.output.outputs import DifferenceStats, Outputs
from registration.recorded.output.plotseries import PlotSeries

__all__ = ["PassPosition", "RunState", "Checkpointer", "mark_done", "PHASES"]

#: A run goes through these phases in order ("observability" only with observability="final").
PHASES = ("filter", "observability", "summary", "done")


@dataclass
class PassPosition:
    """Where a pass over the table stands: rows done (the next block starts there) and the time
    (s) of the last row the validator accepted (None before the first)."""

    rows_done: int = 0
    last_time: float | None = None


@dataclass
class RunState:
    """Everything a run carries from block to block (counts in rows, times in s, SI units)."""

    registrar: OnlineRegistrar
    phase: str = "filter"
    filter_pass: PassPosition = field(default_factory=PassPosition)
    obs_pass: PassPosition = field(default_factory=PassPosition)
    rows_read: int = 0
    rows_accepted: int = 0
    rejected: dict = field(default_factory=dict)  # reason code -> rows
    first_rejection: str | None = None  # "row R, column 'C': reason" of the first rejected row
    filter_rejected: set = field(default_factory=set)  # rows whose filter step was not finite
    nis_sum: float = 0.0
    first_time: float | None = None  # time span of the registered rows
    last_time: float | None = None
    raw: DifferenceStats = field(default_factory=DifferenceStats)  # X_A - X_B from the measurements
    corrected: DifferenceStats = field(default_factory=DifferenceStats)  # X_A - X_B after correction
    obs_info: np.ndarray = field(
        default_factory=lambda: np.zeros((N_STATE, N_STATE))
    )  # information at the final estimate
    obs_used: int = 0  # rows in obs_info
    plot_series: PlotSeries | None = None  # points for the plots (not checkpointed: None after a resume)

    def add_rejections(self, rejections: list) -> None:
        """Count rejected rows by reason (in the order given) and remember the first one."""
        for r in rejections:
            self.rejected[r.code] = self.rejected.get(r.code, 0) + 1
        if rejections and self.first_rejection is None:
            self.first_rejection = (
                f"row {rejections[0].row}, column {rejections[0].column!r}: {rejections[0].reason}"
            )

    def add_registered(
        self, times: np.ndarray, nis: np.ndarray, raw_diff: np.ndarray, corrected_diff: np.ndarray
    ) -> None:
        """Take in one run of registered rows for the statistics:
        their times (s), NIS and ECEF differences (m)."""
        self.raw.add(raw_diff)
        self.corrected.add(corrected_diff)
        self.nis_sum = self.nis_sum + float(np.sum(nis))
        if self.first_time is None:
            self.first_time = float(times[0])
        self.last_time = float(times[-1])

    def to_checkpoint(self, fingerprint: str, marks: dict) -> dict:
        """The checkpoint payload for this state and the outputs' ``marks``."""
        counters = {
            "rows_done": self.filter_pass.rows_done,
            "last_time": self.filter_pass.last_time,
            "obs_rows_done": self.obs_pass.rows_done,
            "obs_last_time": self.obs_pass.last_time,
            "rows_total": self.rows_read,
            "accepted": self.rows_accepted,
            "rejected": self.rejected,
            "first_rejection": self.first_rejection,
            "filter_rejected": sorted(self.filter_rejected),
            "nis_sum": self.nis_sum,
            "first_time": self.first_time,
            "time": self.last_time,
            "obs_info": self.obs_info,
            "obs_used": self.obs_used,
        }
        return {
            "fingerprint": fingerprint,
            "phase": self.phase,
            "filter": self.registrar.state_dict(),
            "state": counters,
            "stats": {"raw": self.raw.state(), "corrected": self.corrected.state()},
            "outputs": marks,
        }

    @classmethod
    def from_checkpoint(cls, payload: dict, config: RegistrationConfig) -> "RunState":
        """Inverse of :meth:`to_checkpoint` (the outputs' marks are read by :class:`Outputs`)."""
        c = payload["state"]
        return cls(
            registrar=OnlineRegistrar.from_state_dict(payload["filter"], config),
            phase=payload["phase"],
            filter_pass=PassPosition(c["rows_done"], c["last_time"]),
            obs_pass=PassPosition(c["obs_rows_done"], c["obs_last_time"]),
            rows_read=c["rows_total"],
            rows_accepted=c["accepted"],
            rejected=dict(c["rejected"]),
            first_rejection=c.get("first_rejection"),
            filter_rejected={int(r) for r in c["filter_rejected"]},
            nis_sum=c["nis_sum"],
            first_time=c["first_time"],
            last_time=c["time"],
            raw=DifferenceStats(payload["stats"]["raw"]),
            corrected=DifferenceStats(payload["stats"]["corrected"]),
            obs_info=c["obs_info"],
            obs_used=c["obs_used"],
        )


class Checkpointer:
    """Saves the run state to ``path`` (None: never) every ``every`` rows of a pass."""

    def __init__(self, path: Path | None, fingerprint: str, every: int):
        self.path, self.fingerprint, self.every = path, fingerprint, int(every)
        self._last_saved = 0

    def start_pass(self, rows_done: int) -> None:
        """A pass starts (or resumes) at ``rows_done``: the next periodic save is ``every`` rows later."""
        self._last_saved = rows_done

    def save_every(self, state: RunState, outputs: Outputs, rows_done: int) -> None:
        """Save if the pass has moved ``every`` rows or more since the last save."""
        if rows_done - self._last_saved >= self.every:
            self.save(state, outputs)
            self._last_saved = rows_done

    def save(self, state: RunState, outputs: Outputs) -> None:
        """Make the outputs durable, then write the checkpoint atomically."""
        if self.path is None:
            return
        outputs.sync()
        save_checkpoint(self.path, state.to_checkpoint(self.fingerprint, outputs.marks()))


def mark_done(path: Path) -> None:
    """Mark the checkpoint at ``path`` as the one of a finished run."""
    payload = load_checkpoint(path)
    payload["phase"] = "done"
    save_checkpoint(path, payload)
