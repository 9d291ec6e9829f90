"""The outputs of the filter pass: estimates, positions and rejected rows, and the streaming
before/after statistics of the ECEF differences.

:class:`Outputs` opens the three appendable files in the run's folder (new, or cut back to the
marks a checkpoint recorded); :func:`estimate_frame` and :func:`position_frame` turn one block
of filter results into rows in file units (degrees and metres); :class:`DifferenceStats`
accumulates max |.|, mean and standard deviation per ECEF axis (m) without keeping the rows.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from registration.io.output.outfolder import RunFolder
from registration.online.contract import IS_ANGLE, STATE_NAMES
from registration.recorded.options import RunOptions
from registration.recorded.output.writers import CsvAppender, open_appender
from registration.recorded.reading.columns import ESTIMATE_COLUMNS, POSITION_COLUMNS, REJECTED_COLUMNS

__all__ = ["DifferenceStats", "Outputs", "output_paths", "estimate_frame", "position_frame", "rejected_rows"]


def output_paths(options: RunOptions, folder: Path | None = None) -> dict[str, Path]:
    """Paths of the estimates, positions and rejected outputs
    of a run in ``folder`` (default: ``options.out``)."""
    out, ext = options.out if folder is None else Path(folder), options.output_suffix
    return {
        "estimates": out / f"estimates{ext}",
        "positions": out / f"positions{ext}",
        "rejected": out / "rejected.csv",
    }


class Outputs:
    """The filter pass's three outputs in the run folder ``folder``. ``marks`` (from a checkpoint):
    ``{name: [size, rows]}`` to cut each back to; ``keep_rejected``: append to an existing
    rejected.csv (the pairing's)."""

    def __init__(
        self,
        options: RunOptions,
        folder: RunFolder,
        marks: dict | None = None,
        *,
        keep_rejected: bool = False,
    ):
        paths, fmt = output_paths(options, folder.path), options.out_format
        self.folder = folder
        self.estimates = open_appender(
            paths["estimates"], ESTIMATE_COLUMNS, fmt, None if marks is None else tuple(marks["estimates"])
        )
        self.positions = open_appender(
            paths["positions"], POSITION_COLUMNS, fmt, None if marks is None else tuple(marks["positions"])
        )
        if marks is None:
            self.rejected = CsvAppender(paths["rejected"], REJECTED_COLUMNS, keep_existing=keep_rejected)
        else:
            self.rejected = CsvAppender(paths["rejected"], REJECTED_COLUMNS, resume=tuple(marks["rejected"]))

    def _all(self):
        return (self.estimates, self.positions, self.rejected)

    def marks(self) -> dict:
        """``{name: [size, rows]}`` and the run folder's name: what a checkpoint records to resume
        these outputs (no folder for a run resumed in ``--out`` itself)."""
        marks: dict[str, list | str] = {
            name: [w.size, w.rows] for name, w in zip(("estimates", "positions", "rejected"), self._all())
        }
        if not self.folder.in_place:
            marks["folder"] = self.folder.path.name
        return marks

    def sync(self) -> None:
        for w in self._all():
            w.sync()

    def close(self) -> None:
        for w in self._all():
            w.close()


def estimate_frame(rows: np.ndarray, times: np.ndarray, x: np.ndarray, P: np.ndarray, nis: np.ndarray):
    """DataFrame of :data:`ESTIMATE_COLUMNS`: input rows, times (s), estimates x (K, 12) and the
    1 sigma of covariances P (K, 12, 12) in degrees or metres, and the NIS (K,)."""
    import pandas as pd

    sig = np.sqrt(np.einsum("kii->ki", P))
    est = {"row": rows.astype(np.int64), "time_s": times}
    deg = np.degrees(1.0)
    for i, name in enumerate(STATE_NAMES):
        unit = "deg" if IS_ANGLE[i] else "m"
        k = deg if IS_ANGLE[i] else 1.0
        est[f"{name}_{unit}"] = np.degrees(x[:, i]) if IS_ANGLE[i] else x[:, i]
        est[f"{name}_sigma_{unit}"] = sig[:, i] * k
    est["nis"] = nis
    return pd.DataFrame(est, columns=ESTIMATE_COLUMNS)


def position_frame(rows: np.ndarray, times: np.ndarray, corrected_a, corrected_b, raw_diff, corrected_diff):
    """DataFrame of :data:`POSITION_COLUMNS` from (K, 3) ECEF arrays in metres."""
    import pandas as pd

    frame = pd.DataFrame(
        np.concatenate([corrected_a, corrected_b, raw_diff, corrected_diff], axis=1),
        columns=POSITION_COLUMNS[2:],
    )
    frame.insert(0, "time_s", times)
    frame.insert(0, "row", rows.astype(np.int64))
    return frame


def rejected_rows(path, rejections) -> list[list]:
    """rejected.csv rows (:data:`REJECTED_COLUMNS`) for the rejections of file ``path``."""
    return [[str(path), r.row, r.column, r.code, r.reason, r.values] for r in rejections]


class DifferenceStats:
    """Streaming max |.|, mean and sample std per axis (Chan et al. pairwise merge), exact to save."""

    def __init__(self, state: dict | None = None):
        if state is None:
            self.n, self.mean, self.m2, self.maxabs = 0, np.zeros(3), np.zeros(3), np.zeros(3)
        else:
            self.n = int(state["n"])
            self.mean, self.m2, self.maxabs = (
                np.asarray(state[k], dtype=float).reshape(3) for k in ("mean", "m2", "maxabs")
            )

    def add(self, z: np.ndarray) -> None:
        """Take in a block of differences (K, 3), m."""
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
        """max |.|, mean and std per axis (m), as lists."""
        std = np.sqrt(self.m2 / (self.n - 1)) if self.n > 1 else np.zeros(3)
        return {"max": self.maxabs.tolist(), "mean": self.mean.tolist(), "std": std.tolist()}
