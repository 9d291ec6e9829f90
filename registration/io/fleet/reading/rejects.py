"""Bad rows of the fleet's input files: the reason codes, the fleet's rejected-ledger columns, and
the collection of one file's bad rows in either mode of ``on_bad_row``.

``"stop"`` raises a ValueError for the first problem (``FILE: row R, column 'C': reason``);
``"skip"`` records the first problem of each row as a
:class:`~registration.io.files.ledger.RejectedRow` and the caller drops the row. Rows are
numbered from 0, the first data row (a CSV header line is not a row).

Reason codes (:data:`FLEET_REASON_CODES`): those of the recorded files
(:data:`registration.recorded.reading.rowcheck.REASON_CODES`: ``non_numeric``, ``non_finite`` for an
empty, NaN or infinite number, ``out_of_range``, ``non_positive_range``, ...) and the fleet's own:

* ``empty_id``: an empty sensor, target or platform id;
* ``unknown_sensor``: a plot of a sensor the sensors file does not list;
* ``unknown_target``: a reference position of a target that has no (accepted) plots;
* ``no_channel``: a plot with no measured value (reported in column ``range_m``);
* ``unmeasured_channel``: a value in a channel the sensor does not measure (no sigma for it);
* ``outside_navigation``: a plot outside its platform's navigation time span;
* ``duplicate``: a plot row equal in every column to an earlier one (reported in column ``*``);
* ``short_row`` / ``long_row`` (from the recorded files' codes): a CSV line with fewer / more
  fields than the header (a line cut short, a missing line break), reported in the first column
  the line does not reach / in column ``*``.
"""

from __future__ import annotations

from collections import Counter
from typing import TYPE_CHECKING, Callable

import numpy as np

from registration.io.files.ledger import LedgerColumns, Location, RejectedLedger, RejectedRow
from registration.io.files.tablefile import REASON_CODES, NoValidRowsError

if TYPE_CHECKING:
    import pandas

__all__ = [
    "BAD_ROW_MODES",
    "FLEET_REASON_CODES",
    "LEDGER_COLUMNS",
    "REJECTED_COLUMNS",
    "SET_ASIDE_CODES",
    "RejectedRow",
    "BadRows",
    "NoValidPlotsError",
    "rejected_frame",
    "check_mode",
]

BAD_ROW_MODES = ("stop", "skip")
FLEET_REASON_CODES = REASON_CODES + (
    "empty_id",
    "unknown_sensor",
    "unknown_target",
    "no_channel",
    "unmeasured_channel",
    "outside_navigation",
    "duplicate",
)
#: Reason codes of plots set aside in either mode (``on_bad_row="stop"`` too), with a note: no cell
#: of theirs is wrong, they only cannot be used.
SET_ASIDE_CODES = ("outside_navigation", "duplicate")
#: The fleet's rejected ledger: ``file``, ``row`` (from 0), ``column``, ``reason_code``, ``reason``
#: (named as in the rejected.csv of ``registration register``, whose rows also carry the raw values),
#: in the order the rows were set aside.
LEDGER_COLUMNS = LedgerColumns((Location("row", "int"), Location("column", "text")), sort=False)
#: Columns of :func:`rejected_frame` (and of the fleet's rejected.csv).
REJECTED_COLUMNS = LEDGER_COLUMNS.names


def check_mode(on_bad_row: str) -> str:
    """``on_bad_row`` itself, if it is one of :data:`BAD_ROW_MODES`; else a ValueError."""
    if on_bad_row not in BAD_ROW_MODES:
        raise ValueError(f"on_bad_row: expected 'stop' or 'skip', got {on_bad_row!r}")
    return on_bad_row


def rejected_frame(rows) -> "pandas.DataFrame":
    """The rejected rows, in the order given, as the frame of a rejected ledger with columns
    :data:`REJECTED_COLUMNS` (an empty frame with those columns when there are none)."""
    rows = list(rows)
    files = list(dict.fromkeys(r.file for r in rows))
    rank = {f: i for i, f in enumerate(files)}
    ledger = RejectedLedger(LEDGER_COLUMNS, files)
    ledger.add(
        np.array([rank[r.file] for r in rows], dtype=np.int64),
        np.array([r.code for r in rows], dtype=object),
        np.array([r.reason for r in rows], dtype=object),
        row=np.array([r.row for r in rows], dtype=np.int64),
        column=np.array([r.column for r in rows], dtype=object),
    )
    return ledger.frame()


class NoValidPlotsError(NoValidRowsError):
    """Every row of the plots file was set aside in skip mode; ``rejected`` lists all rows set aside
    (of every file), so they can still be written out."""

    def __init__(self, file: str, n_rows: int, rejected: list[RejectedRow]):
        self.rejected = list(rejected)
        mine = [r for r in self.rejected if r.file == file]
        codes = ", ".join(f"{n} {code}" for code, n in sorted(Counter(r.code for r in mine).items()))
        first = (
            f", the first at row {mine[0].row}, column {mine[0].column!r}: {mine[0].reason}" if mine else ""
        )
        super().__init__(f"{file}: no valid rows to register: all {n_rows} rows rejected ({codes}){first}")

    def rejected_frame(self):
        return rejected_frame(self.rejected)


class BadRows:
    """The bad rows of one file: ``skip`` True records the first problem of each row (the order of
    the :meth:`add` calls decides which is first); False raises at the first problem added.
    ``file_rows`` (n_rows,): the file row of each row checked, when some of the file's rows are
    not checked (default: row i is file row i)."""

    def __init__(self, file, n_rows: int, skip: bool, file_rows: np.ndarray | None = None):
        self.file, self.n_rows, self.skip = str(file), int(n_rows), skip
        self.file_rows = file_rows
        self.first: dict[int, tuple[str, str, str]] = {}  # row -> (column, code, reason)

    def add(
        self,
        column: str | Callable[[int], str],
        code: str | Callable[[int], str],
        bad: np.ndarray,
        reason: Callable[[int], str],
        rows: np.ndarray | None = None,
    ) -> None:
        """Rows flagged in ``bad`` (K,) have the problem ``reason(i)``; ``rows`` (K,) maps them to
        the rows checked (default: the identity), which ``file_rows`` maps to file rows. ``column``,
        ``code``: one for all, or per flagged row i."""
        hit = np.flatnonzero(bad)
        if hit.size == 0:
            return

        def at(v: str | Callable[[int], str], i: int) -> str:
            return v if isinstance(v, str) else v(i)

        row = (lambda i: int(i)) if rows is None else (lambda i: int(rows[i]))
        if not self.skip:
            first = int(hit[0])
            raise ValueError(
                f"{self.file}: row {self.file_row(row(first))}, column {at(column, first)!r}: {reason(first)}"
            )
        for i in hit.tolist():
            r = row(i)
            if r not in self.first:
                self.first[r] = (at(column, i), at(code, i), reason(i))

    def file_row(self, r: int) -> int:
        """The file row (from 0) of row ``r`` checked."""
        return r if self.file_rows is None else int(self.file_rows[r])

    def ok(self) -> np.ndarray:
        """(n_rows,) bool: the rows with no problem recorded."""
        out = np.ones(self.n_rows, dtype=bool)
        out[list(self.first)] = False
        return out

    def rejected(self) -> list[RejectedRow]:
        return [RejectedRow(self.file, self.file_row(r), *self.first[r]) for r in sorted(self.first)]
