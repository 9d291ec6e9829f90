"""The rejected ledger: what a reader set aside, with where and why, in one type for every source.

Every reader that sets input aside (the ASTERIX and NMEA importers, the fleet table files) keeps
a :class:`RejectedLedger`. Its table has the common columns ``file``, a reason code and
``reason`` (words), and between them the *location* columns that the source declares in its
:class:`LedgerColumns`: a byte offset, packet and category for ASTERIX, a line for NMEA, a row
and column for a table file. Items are added in vectorised batches (:meth:`RejectedLedger.add`);
:meth:`RejectedLedger.frame` gives the table (the source's ``rejected.csv``),
:meth:`RejectedLedger.by_code` the counts per reason code. A reader that checks a table row by
row records each row set aside as a :class:`RejectedRow`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Collection, Sequence

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["LOCATION_KINDS", "LedgerColumns", "Location", "RejectedLedger", "RejectedRow"]

#: How a location column is written: ``int`` (int64), ``nullable`` (Int64), ``positive`` (Int64,
#: empty where the value is 0 or below: "does not apply"), ``text``.
LOCATION_KINDS = ("int", "nullable", "positive", "text")


@dataclass(frozen=True)
class Location:
    """One location column of a source's ledger: its ``name`` and ``kind`` (:data:`LOCATION_KINDS`)."""

    name: str
    kind: str = "int"

    def __post_init__(self) -> None:
        if self.kind not in LOCATION_KINDS:
            raise ValueError(f"kind: expected one of {LOCATION_KINDS}, got {self.kind!r}")


@dataclass(frozen=True)
class LedgerColumns:
    """A source's ledger columns: ``file``, the ``location`` columns, the reason code column
    (named ``code``), ``reason``. ``reasons``: the reason codes the source may use (None: any).
    ``sort``: the table is ordered by file (in the order the files were given or first added)
    then by the first location column; False: in the order added."""

    location: tuple[Location, ...]
    code: str = "reason_code"
    reasons: Collection[str] | None = None
    sort: bool = True

    @property
    def names(self) -> tuple[str, ...]:
        """The table's columns, in order."""
        return ("file", *(c.name for c in self.location), self.code, "reason")


@dataclass(frozen=True)
class RejectedRow:
    """One row of a table file set aside (the fleet's files, ``registration register``'s files):
    its ``file`` (path as given), ``row`` (from 0, the first data row), the ``column`` of its first
    problem, the reason ``code``, the ``reason`` in words and, where the reader keeps them, the
    row's cells as JSON text (``values``)."""

    file: str
    row: int
    column: str
    code: str
    reason: str
    values: str = ""

    def text(self) -> str:
        return f"{self.file}: row {self.row}, column {self.column!r}: {self.reason} [{self.code}]"


class RejectedLedger:
    """Items set aside by one source, gathered as parallel arrays per :meth:`add`. ``files``: the
    source's files in their order, when known up front (then ``add`` may name a file by its index
    in it); files named by path are ranked in the order first added after them."""

    def __init__(self, columns: LedgerColumns, files: Sequence[str] = ()) -> None:
        self.columns = columns
        self.files = [str(f) for f in files]
        self._ranks: dict[str, int] = {}
        self._parts: list[tuple[np.ndarray, np.ndarray, np.ndarray, dict[str, np.ndarray]]] = []

    def add(self, file, code, reason, **location) -> None:
        """Set aside N items: ``file`` a path (str) or (N,) indices into ``files``; ``code`` one
        reason code or (N,) codes; ``reason`` one text or (N,) texts; ``location``: each of the
        source's location columns, (N,) values or one for all (N: from the first array given)."""
        reasons = self.columns.reasons
        for c in [code] if isinstance(code, str) else set(np.asarray(code, dtype=object).tolist()):
            if reasons is not None and c not in reasons:
                raise KeyError(f"unknown reason code {c!r}")
        if set(location) != {c.name for c in self.columns.location}:
            raise TypeError(
                f"location: expected {[c.name for c in self.columns.location]}, got {sorted(location)}"
            )
        sizes = [np.size(v) for v in (file, code, reason, *location.values()) if np.ndim(v)]
        n = sizes[0] if sizes else 1
        if n == 0:
            return
        if isinstance(file, str):
            if file not in self._ranks and file not in self.files:
                self._ranks[file] = len(self.files) + len(self._ranks)
            rank = self.files.index(file) if file in self.files else self._ranks[file]
            ranks = np.full(n, rank, dtype=np.int64)
        else:
            ranks = np.broadcast_to(np.asarray(file, dtype=np.int64), (n,))
        where = {}
        for c in self.columns.location:
            dtype = object if c.kind == "text" else np.int64
            where[c.name] = np.broadcast_to(np.asarray(location[c.name], dtype=dtype), (n,))
        codes = np.broadcast_to(np.asarray(code, dtype=object), (n,))
        self._parts.append((ranks, codes, np.broadcast_to(np.asarray(reason, dtype=object), (n,)), where))

    def count(self) -> int:
        """The number of items set aside."""
        return int(sum(p[0].size for p in self._parts))

    def by_code(self, order: Sequence[str] | None = None) -> dict[str, int]:
        """Reason code -> number of items set aside: codes in ``order`` (those present), or with
        None the most frequent first (ties by code)."""
        counts: dict[str, int] = {}
        for _, codes, _, _ in self._parts:
            if codes.size and (codes[0] == codes).all():  # one code for the part (the usual case)
                counts[codes[0]] = counts.get(codes[0], 0) + int(codes.size)
                continue
            for code, n in zip(*np.unique(codes.astype(str), return_counts=True)):
                counts[str(code)] = counts.get(str(code), 0) + int(n)
        if order is not None:
            return {code: counts[code] for code in order if code in counts}
        return dict(sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])))

    def frame(self) -> pd.DataFrame:
        """The items as a DataFrame with the columns of :attr:`LedgerColumns.names` (an empty
        frame with those columns and their types when there are none)."""
        import pandas as pd

        names = np.array(self.files + list(self._ranks), dtype=object)
        ranks = _join([p[0] for p in self._parts], np.int64)
        order = np.arange(ranks.size)
        if self.columns.sort and self.columns.location and ranks.size:
            first = self.columns.location[0].name
            order = np.lexsort((_join([p[3][first] for p in self._parts], np.int64), ranks))
        # text columns stay object arrays of str: a fixed-width copy (astype(str)) takes N times the
        # longest text times 4 bytes, 200 MB for half a million reasons
        out: dict[str, object] = {"file": _texts(names[ranks[order]]) if ranks.size else _empty("text")}
        for c in self.columns.location:
            dtype = object if c.kind == "text" else np.int64
            out[c.name] = _column(_join([p[3][c.name] for p in self._parts], dtype)[order], c.kind)
        codes = _join([p[1] for p in self._parts], object)
        out[self.columns.code] = _texts(codes[order]) if ranks.size else _empty("text")
        texts = _join([p[2] for p in self._parts], object)
        out["reason"] = _texts(texts[order]) if ranks.size else _empty("text")
        return pd.DataFrame(out)


def _join(parts: list, dtype) -> np.ndarray:
    return np.concatenate(parts).astype(dtype, copy=False) if parts else np.zeros(0, dtype=dtype)


def _texts(values: np.ndarray) -> np.ndarray:
    """(N,) object array of the texts (``str`` or numpy's ``str_``, a subclass), not copied to a
    fixed-width unicode array."""
    return np.asarray(values, dtype=object)


def _empty(kind: str):
    import pandas as pd

    return pd.Series([], dtype={"int": np.int64, "text": object}.get(kind, "Int64"))


def _column(values: np.ndarray, kind: str):
    """A location column's values as written: int64, text, or Int64 (empty where <= 0 for ``positive``)."""
    import pandas as pd

    if values.size == 0:
        return _empty(kind)
    if kind in ("int", "text"):
        return values
    column = pd.array(values.astype(np.int64), dtype="Int64")
    if kind == "positive":
        column[values <= 0] = pd.NA
    return column
