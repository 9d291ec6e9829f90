"""The first reason, if any, each record is set aside for: rules applied in order, a record keeps
the first that matches it."""

from __future__ import annotations

import numpy as np

from registration.io.files.ledger import RejectedLedger

__all__ = ["Verdicts"]


class Verdicts:
    """Per record (N,): ``code`` ('' while kept) and ``reason`` of the first rule that set it aside."""

    def __init__(self, n: int) -> None:
        self.code = np.full(n, "", dtype=object)
        self.reason = np.full(n, "", dtype=object)

    def rule(self, mask: np.ndarray, code: str, reason: str | np.ndarray) -> None:
        """Set aside the records of ``mask`` not yet set aside, with ``code`` and ``reason`` (one text,
        or (N,) texts)."""
        hit = np.asarray(mask, dtype=bool) & (self.code == "")
        if hit.any():
            self.code[hit] = code
            self.reason[hit] = reason if isinstance(reason, str) else np.asarray(reason, dtype=object)[hit]

    def kept(self) -> np.ndarray:
        return self.code == ""

    def counts(self) -> dict:
        codes, n = np.unique(self.code[self.code != ""].astype(str), return_counts=True)
        return {str(c): int(k) for c, k in zip(codes, n)}

    def report(
        self, rejections: RejectedLedger, file: str, offset: np.ndarray, packet: np.ndarray, category: int
    ) -> None:
        """Add the records set aside to ``rejections``, one call per reason code."""
        for code in np.unique(self.code[self.code != ""].astype(str)):
            m = self.code == code
            rejections.add(
                file, str(code), self.reason[m], offset=offset[m], packet=packet[m], category=category
            )
