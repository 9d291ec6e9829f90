"""The bounds on one import, so that a small hostile or broken input (a gzip of millions of empty
records, a decompression bomb) cannot take the machine's memory, time or disk:

* ``max_bytes``: the decompressed size read of each input (gzip or not); beyond it the rest of the
  file is not read (reason ``over_limit``, one row, and a note in the summary);
* ``max_records``: the records walked per input, all categories together, in file order; beyond it
  the rest of the file, of every category, is set aside (``over_limit``, one row per category), so
  an import cut by it covers one span of the recording;
* ``max_rejected_rows``: the rows the rejected table lists; every item set aside beyond it is
  still counted in the summary (per reason), and one last row (reason ``not_listed``) says how
  many more were set aside.

The defaults hold a few hours of a few radars with ADS-B (a day of three radars with ADS-B is
about 4 million records: raise ``max_records`` for it); :func:`~registration.io.asterix.import_asterix`
takes each as a keyword argument, ``registration import asterix`` as an option
(``--max-bytes``, ``--max-records``, ``--max-rejected-rows``).
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from typing import TYPE_CHECKING, Sequence

import numpy as np

from registration.io.files.ledger import LedgerColumns, RejectedLedger

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["Limits", "BoundedLedger", "DEFAULT_MAX_BYTES", "DEFAULT_MAX_RECORDS", "DEFAULT_MAX_REJECTED_ROWS"]

#: Decompressed octets read per input (8 GiB).
DEFAULT_MAX_BYTES = 8 << 30
#: Records decoded per input (all categories); the import holds about 400 bytes per record.
DEFAULT_MAX_RECORDS = 2_000_000
#: Rows listed in the rejected table (the rest counted only).
DEFAULT_MAX_REJECTED_ROWS = 100_000


@dataclass(frozen=True)
class Limits:
    """The bounds of one import (see the module); each a positive integer."""

    max_bytes: int = DEFAULT_MAX_BYTES
    max_records: int = DEFAULT_MAX_RECORDS
    max_rejected_rows: int = DEFAULT_MAX_REJECTED_ROWS

    def __post_init__(self) -> None:
        for name in ("max_bytes", "max_records", "max_rejected_rows"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
                raise ValueError(f"{name}: expected a positive integer, got {value!r}")


class BoundedLedger(RejectedLedger):
    """A :class:`~registration.io.files.ledger.RejectedLedger` that lists at most ``max_rows``
    items; the items beyond are counted per reason code (:meth:`count`, :meth:`by_code` include
    them) and :meth:`frame` ends with one row of code ``not_listed`` saying how many."""

    def __init__(self, columns: LedgerColumns, max_rows: int, files: Sequence[str] = ()) -> None:
        super().__init__(columns, files)
        self.max_rows = int(max_rows)
        self.listed = 0
        self.unlisted: Counter = Counter()
        self.first_unlisted_file = ""

    def add(self, file, code, reason, **location) -> None:
        sizes = [np.size(v) for v in (file, code, reason, *location.values()) if np.ndim(v)]
        n = sizes[0] if sizes else 1
        room = max(self.max_rows - self.listed, 0)
        if n <= room:
            super().add(file, code, reason, **location)
            self.listed += n if n else 0
            return
        cut = {k: (v[:room] if np.ndim(v) else v) for k, v in location.items()}
        part = [v[:room] if np.ndim(v) else v for v in (file, code, reason)]
        if room:
            super().add(*part, **cut)
            self.listed += room
        rest = (
            [code] * (n - room) if isinstance(code, str) else np.asarray(code, dtype=object)[room:].tolist()
        )
        if not self.unlisted:
            self.first_unlisted_file = (
                file if isinstance(file, str) else str(self.files[int(np.ravel(file)[room])])
            )
        self.unlisted.update(rest)

    def count(self) -> int:
        return super().count() + sum(self.unlisted.values())

    def by_code(self, order: Sequence[str] | None = None) -> dict[str, int]:
        counts = Counter(super().by_code()) + self.unlisted
        if order is not None:
            return {code: counts[code] for code in order if code in counts}
        return dict(sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])))

    def frame(self) -> pd.DataFrame:
        import pandas as pd

        listed = super().frame()
        if not self.unlisted:
            return listed
        total = sum(self.unlisted.values())
        codes = ", ".join(f"{c}: {n}" for c, n in self.unlisted.most_common())
        row: dict = {
            name: [
                0
                if pd.api.types.is_integer_dtype(t) and not isinstance(t, pd.api.extensions.ExtensionDtype)
                else pd.NA
            ]
            for name, t in listed.dtypes.items()
        }
        row["file"] = [self.first_unlisted_file]
        row[self.columns.code] = ["not_listed"]
        row["reason"] = [
            f"{total} more items set aside are not listed ({codes}); the table lists the first "
            f"{self.max_rows} (max_rejected_rows, --max-rejected-rows)"
        ]
        extra = pd.DataFrame(row).astype(listed.dtypes.to_dict())
        return pd.concat([listed, extra], ignore_index=True)
