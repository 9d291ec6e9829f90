"""What the NMEA reader refuses: :class:`NmeaImportError` for a log that cannot give a navigation
table at all, and :class:`Rejections`, the lines set aside with a reason (bad input never raises).

Every line set aside is listed once, with its file, its line number (from 1, as an editor shows
it), a reason code and a reason in words. The codes are listed in :data:`REASONS`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["NmeaImportError", "REASONS", "Rejections"]

#: Reason code -> what it means (docs/nmea.md lists the same).
REASONS = {
    "not_a_sentence": "no '$' or '!' starts a sentence on the line",
    "bad_prefix": "the text before the sentence is not a timestamp the reader knows",
    "bad_tag_block": "an NMEA 4.10 tag block that is not closed or whose checksum is wrong",
    "no_checksum": "the sentence does not end in '*' and two hex digits (a truncated line?)",
    "bad_checksum": "the checksum does not match the sentence",
    "unknown_type": "a sentence type neither this reader nor pynmea2 knows",
    "too_few_fields": "fewer fields than the sentence type has (a truncated sentence?)",
    "bad_field": "a field the reader needs is empty, not a number or out of range",
    "bad_time": "the UTC time field is empty or not a time of day",
    "no_time": "the sentence has no UTC time field and the line no reception time",
    "invalid_fix": "the receiver marks the fix invalid (GGA quality 0, RMC status V, GNS mode N, THS mode V)",
    "outside_positions": "attitude at a time without position fixes around it to interpolate from",
    "duplicate_time": "a second sample of the same source at the same time",
    "ttm_lost": "TTM status L: the target is lost",
    "ttm_acquiring": "TTM status Q: the target is being acquired (kept with keep_acquiring=True)",
    "ttm_status": "TTM status is not T, Q or L",
    "ttm_no_sensor": "the TTM talker names no sensor of the platform",
    "ttm_no_heading": "a true TTM bearing at a time without heading to convert it to a deck bearing",
    "ais_fragment": "a part of a multi-sentence AIS message whose other parts are missing",
    "ais_decode": "an AIS payload pyais cannot decode",
    "ais_no_time": "an AIS position without a reception time (tag block c: or timestamp prefix)",
    "ais_no_position": "an AIS position report whose position is not available",
    "ais_own_ship": "an AIS position of the own ship (its MMSI is in !AIVDO)",
    "ais_duplicate": "the same AIS report (MMSI, time and position) received again",
    "no_date": "the log gives no date, so AIS reception times cannot be placed",
}


class NmeaImportError(ValueError):
    """The log cannot be imported: no valid position or no valid heading in it. The message is one
    line naming what is missing (the command line maps it to exit code 2)."""


@dataclass
class Rejections:
    """Lines set aside: parallel lists of file index, line number (from 1), code, reason."""

    files: list[str]
    file: list[np.ndarray] = field(default_factory=list)
    line: list[np.ndarray] = field(default_factory=list)
    code: list[np.ndarray] = field(default_factory=list)
    reason: list[np.ndarray] = field(default_factory=list)

    def add(self, file, line, code: str, reason) -> None:
        """Set aside lines: ``file`` (K,) file indices, ``line`` (K,) line numbers, one ``code`` of
        :data:`REASONS`, ``reason`` a text or (K,) texts."""
        if code not in REASONS:
            raise KeyError(f"unknown rejection code {code!r}")
        file = np.atleast_1d(np.asarray(file, dtype=np.int64))
        if file.size == 0:
            return
        line = np.atleast_1d(np.asarray(line, dtype=np.int64))
        texts = np.broadcast_to(np.asarray(reason, dtype=object), file.shape)
        self.file.append(file)
        self.line.append(line)
        self.code.append(np.full(file.shape, code, dtype=object))
        self.reason.append(np.array(texts, dtype=object))

    def count(self) -> int:
        return int(sum(a.size for a in self.file))

    def counts(self) -> dict[str, int]:
        """Lines set aside per reason code, most frequent first."""
        if not self.code:
            return {}
        codes, n = np.unique(np.concatenate(self.code).astype(str), return_counts=True)
        order = np.argsort(-n, kind="stable")
        return {str(codes[k]): int(n[k]) for k in order}

    def frame(self) -> pd.DataFrame:
        """The lines set aside as a DataFrame with columns ``file``, ``line``, ``code``, ``reason``,
        in file order then line order."""
        import pandas as pd

        if not self.file:
            return pd.DataFrame(
                {
                    "file": pd.Series([], dtype=object),
                    "line": pd.Series([], dtype=np.int64),
                    "code": pd.Series([], dtype=object),
                    "reason": pd.Series([], dtype=object),
                }
            )
        f = np.concatenate(self.file)
        ln = np.concatenate(self.line)
        order = np.lexsort((ln, f))
        names = np.array(self.files, dtype=object)
        return pd.DataFrame(
            {
                "file": names[f[order]],
                "line": ln[order],
                "code": np.concatenate(self.code)[order],
                "reason": np.concatenate(self.reason)[order],
            }
        )
