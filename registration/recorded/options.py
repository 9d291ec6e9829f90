"""Options of a recorded-data run (:class:`RunOptions`) and of the pairing of asynchronous plots
(:class:`PairingOptions`). Times in seconds."""

from __future__ import annotations

import sys
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from registration.online.config import RegistrationConfig

__all__ = ["PairingOptions", "RunOptions"]


@dataclass
class PairingOptions:
    """How two radars' plots are paired: clock offsets (s), the radar whose plot times are the
    common instants, the degree of the sliding-window fit and the limits (s) on extrapolation,
    gaps (None: ``gap_factor`` x the stream's median sample interval) and exact coincidence."""

    clock_offset_a: float = 0.0
    clock_offset_b: float = 0.0
    pair_at: str = "a"
    degree: int = 1
    max_extrapolation_s: float = 0.0
    max_gap_s: float | None = None
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

    def clock_offset(self, sensor: str) -> float:
        """Seconds that radar ``sensor``'s clock reads ahead of the reference clock."""
        return self.clock_offset_a if sensor == "a" else self.clock_offset_b

    def to_json(self) -> dict:
        return asdict(self)


@dataclass
class RunOptions:
    """A recorded-data run: output folder ``out``, filter ``config``, bad rows ``"stop"`` or
    ``"skip"``, an optional ``checkpoint`` file saved every ``checkpoint_every`` rows, rows per
    block ``chunk_rows``, outputs ``"csv"`` or ``"parquet"``, information matrix ``"final"``
    (second pass at the final estimate) or ``"filter"``, plots, progress bar, navigation files
    ``nav`` and ``pairing`` for the asynchronous form, ``log`` for messages."""

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
    pairing: PairingOptions | None = None  # for the asynchronous form; None: the defaults
    log: Callable[[str], None] | None = None  # for messages; default: print to stderr

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

    @property
    def output_suffix(self) -> str:
        """'.csv' or '.parquet': the suffix of the tabular outputs."""
        return ".csv" if self.out_format == "csv" else ".parquet"

    def message(self, text: str) -> None:
        """Pass a one-line message to ``log`` (default: print it to standard error)."""
        if self.log is None:
            print(text, file=sys.stderr)
        else:
            self.log(text)

    def progress_bar(self, total: int | None, initial: int, desc: str):
        """A bar on standard error counting rows, with ``progress`` (the rule of
        :mod:`registration.core.progress`)."""
        from registration.core.progress import progress_bar

        return progress_bar(self.progress, desc, total, "row", initial=initial, unit_scale=True)
