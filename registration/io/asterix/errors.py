"""What the ASTERIX reader refuses and what it sets aside.

:class:`AsterixImportError` is raised, with a one-line message naming the file, only for a file
that is neither an ASTERIX recording nor a pcap/pcapng capture (nor a gzip of one), or that cannot
be read at all. Everything else bad in a file is set aside and listed in
:class:`Rejections`: its file, its byte offset (in the decompressed stream for a gzip file), its
packet number (from 1, captures only), its category, a reason code (:data:`REASONS`) and a reason
in words. The rest of the file is imported.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["AsterixImportError", "REASONS", "Rejections", "REJECTED_COLUMNS"]

#: Reason code -> what it means (docs/asterix.md lists the same).
REASONS = {
    "truncated_packet": "the capture ends inside a packet record (the rest of the file is lost)",
    "bad_block_length": "a data block whose length field is below 3 (the header itself)",
    "truncated_block": "a data block whose length runs past the end of the file or datagram",
    "unknown_category": "a data block of a category the reader does not decode",
    "fspec_overrun": "an FSPEC that runs past its data block or past the octets its UAP allows",
    "empty_record": "an FSPEC that names no item",
    "spare_frn": "an FSPEC that names a spare FRN of the edition",
    "item_overrun": "an item that runs past the end of its data block",
    "bad_item": "an item whose structure the edition does not allow (too many extension octets, "
    "an explicit length of 0, a spare compound subfield)",
    "missing_item": "a record without an item the reader needs (source, time, position, ...)",
    "bad_time": "a time of day of 24 h or more",
    "no_detection": "a CAT048 report of type 0 (no detection)",
    "zero_range": "a CAT048 plot at range 0",
    "test_target": "a test target report (I048/020 or I021/040 TST bit)",
    "simulated": "a simulated target report (I048/020 or I021/040 SIM bit)",
    "field_monitor": "a report from a field monitor, a fixed transponder (RAB bit)",
    "unknown_sac_sic": "a CAT048 or CAT034 record whose SAC/SIC is not in SITES",
    "no_address": "a CAT021 report without target address (I021/080)",
    "no_position": "a CAT021 report without WGS-84 position (I021/130, I021/131)",
    "bad_position": "a CAT021 position outside +-90 deg latitude or +-180 deg longitude",
    "no_quality": "a CAT021 report without NACp (I021/090; NUCp for editions 0.2x)",
    "low_nacp": "a CAT021 report with NACp below 7 (NUCp below 6 for editions 0.2x): EPU of 0.3 NM or more",
    "no_geometric_height": "a CAT021 report without geometric height (I021/140)",
}
#: The columns of the rejected table.
REJECTED_COLUMNS = ("file", "offset", "packet", "category", "reason_code", "reason")


class AsterixImportError(ValueError):
    """A file that is neither an ASTERIX recording nor a pcap/pcapng capture (nor a gzip of one), or
    that cannot be read. The message is one line naming the file (the command line maps it to exit
    code 2)."""


@dataclass
class Rejections:
    """Records and bytes set aside, gathered as parallel arrays per call of :meth:`add`."""

    parts: list = field(default_factory=list)

    def add(
        self,
        file: str,
        offset: np.ndarray | int,
        packet: np.ndarray | int,
        category: np.ndarray | int,
        code: str,
        reason: str | np.ndarray,
    ) -> None:
        """Set aside N items of one file with one reason code: ``offset`` (N,) byte offsets,
        ``packet`` (N,) packet numbers from 1 (0: not a capture), ``category`` (N,) or one value
        (0: unknown), ``reason`` one text or (N,) texts."""
        if code not in REASONS:
            raise KeyError(f"unknown reason code {code!r}")
        offset = np.atleast_1d(np.asarray(offset, dtype=np.int64))
        n = offset.size
        if n == 0:
            return
        packet = np.broadcast_to(np.asarray(packet, dtype=np.int64), (n,))
        category = np.broadcast_to(np.asarray(category, dtype=np.int64), (n,))
        reason = np.broadcast_to(np.asarray(reason, dtype=object), (n,))
        self.parts.append((file, offset, packet, category, code, reason))

    def count(self) -> int:
        return int(sum(p[1].size for p in self.parts))

    def by_code(self) -> dict:
        """Reason code -> number of items set aside, codes in the order of :data:`REASONS`."""
        counts = {}
        for part in self.parts:
            counts[part[4]] = counts.get(part[4], 0) + int(part[1].size)
        return {code: counts[code] for code in REASONS if code in counts}

    def frame(self) -> "pd.DataFrame":
        """A DataFrame with :data:`REJECTED_COLUMNS`, in file order then byte offset: ``packet`` and
        ``category`` empty where they do not apply."""
        import pandas as pd

        if not self.parts:
            return pd.DataFrame(
                {
                    c: pd.Series(dtype="Int64" if c in ("offset", "packet", "category") else object)
                    for c in REJECTED_COLUMNS
                }
            )
        cols = [
            np.concatenate(
                [
                    np.broadcast_to(np.asarray(p[k], dtype=object) if k in (0, 4) else p[k], (p[1].size,))
                    for p in self.parts
                ]
            )
            for k in range(6)
        ]
        order = np.lexsort((cols[1].astype(np.int64), _file_order(cols[0], self.parts)))
        frame = pd.DataFrame(
            {
                "file": cols[0][order].astype(str),
                "offset": pd.array(cols[1][order].astype(np.int64), dtype="Int64"),
                "packet": pd.array(
                    np.where(cols[2][order] > 0, cols[2][order], 0).astype(np.int64), dtype="Int64"
                ),
                "category": pd.array(cols[3][order].astype(np.int64), dtype="Int64"),
                "reason_code": cols[4][order].astype(str),
                "reason": cols[5][order].astype(str),
            }
        )
        frame.loc[frame["packet"] == 0, "packet"] = pd.NA
        frame.loc[frame["category"] == 0, "category"] = pd.NA
        return frame


def _file_order(files: np.ndarray, parts: list) -> np.ndarray:
    """Each row's file ranked in the order the files were first added."""
    import pandas as pd

    rank = {}
    for p in parts:
        rank.setdefault(p[0], len(rank))
    return pd.Series(files).map(rank).to_numpy(dtype=np.int64)
