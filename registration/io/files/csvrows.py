"""CSV rows checked against the header: the fields of every line counted from the raw bytes.

pandas reads a line with fewer fields than the header as a row whose missing cells are empty
(NaN), so a line cut short by a recorder that stopped mid-write reads as "not measured"; a line
with more fields is truncated with a warning, taken as an index, or refused, depending on where
it stands. :func:`read_csv_blocks` therefore reads a CSV file in blocks of whole lines, counts
each line's fields itself, and parses each block with pandas against the header's names (padded
with spare names for over-long lines, so that every line is one row and no cell moves). A frame
with such a line carries the column :data:`SHAPE_COLUMN`: None for a row with as many fields as
the header, else its :class:`RowShape` (reason code ``short_row`` or ``long_row``).

Counting is vectorised (numpy over the bytes; no Python loop per row): separators and line ends
are those outside quotes, quotes being paired by parity. That is exact when every quote opens a
field (after optional spaces) or follows its closing quote (``""``), and every closing quote
ends its field; a block where some quote does not (a quote inside an unquoted value, ``ab"c``)
is counted by the :mod:`csv` module instead, row by row. The rules are pandas' own: a line end is
``\\n``, ``\\r\\n`` or a lone ``\\r`` outside quotes; blank lines (only spaces, tabs) are not rows.
Measured cost (``benchmarks/bench_csv_fields.py``, CPU time, 10^6 rows): a 68 MiB plots file with
quoted ids reads in 0.53 s against 0.24 s with pandas' chunks (the read and count alone 0.20 s);
a 334 MiB numeric table in 1.58 s against 0.99 s (the read and count alone 0.35 s; the rest is
pandas parsing 4 MiB blocks rather than its own chunks).
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from typing import Iterator

import numpy as np

__all__ = ["NA_TEXTS", "SHAPE_COLUMN", "RowShape", "read_csv_blocks", "count_fields", "BLOCK_BYTES"]

#: The texts pandas reads as a missing cell by default (``pandas.read_csv``'s ``na_values``).
NA_TEXTS = (
    "",
    "#N/A",
    "#N/A N/A",
    "#NA",
    "-1.#IND",
    "-1.#QNAN",
    "-NaN",
    "-nan",
    "1.#IND",
    "1.#QNAN",
    "<NA>",
    "N/A",
    "NA",
    "NULL",
    "NaN",
    "None",
    "n/a",
    "nan",
    "null",
)
#: The column of a frame of :func:`read_csv_blocks` with a bad line: None or the row's :class:`RowShape`.
SHAPE_COLUMN = "<row shape>"
#: Bytes read per block (the last line of a block is completed from the next read).
BLOCK_BYTES = 4 << 20
_COMMA, _LF, _CR, _QUOTE, _SPACE, _TAB = 44, 10, 13, 34, 32, 9
_BOM = b"\xef\xbb\xbf"


@dataclass(frozen=True)
class RowShape:
    """A row whose line has another number of fields than the header: its physical ``line``
    (1 = the file's first line), its ``fields``, the ``header``'s, and the ``column`` to name:
    the first column the line does not reach (short), or ``"*"`` (long)."""

    line: int
    fields: int
    header: int
    column: str

    @property
    def code(self) -> str:
        return "short_row" if self.fields < self.header else "long_row"

    def reason(self) -> str:
        if self.fields < self.header:
            return (
                f"line {self.line} has {self.fields} fields, the header {self.header}: "
                "cut short (a truncated or half-written line?); leave a field empty, not out"
            )
        return (
            f"line {self.line} has {self.fields} fields, the header {self.header}: "
            "fields no column is named for (a missing line break, or a separator in an unquoted value?)"
        )


@dataclass(frozen=True)
class _Lines:
    """The lines of a buffer: start byte (L,), fields (L,), blank (L,) bool; ``cut``: the byte after
    the last complete line (the rest waits for the next read); ``newlines``: the LF bytes."""

    starts: np.ndarray
    fields: np.ndarray
    blank: np.ndarray
    cut: int
    newlines: np.ndarray  # the position of every LF byte (inside quotes too), for line numbers


def count_fields(data: bytes) -> tuple[np.ndarray, np.ndarray]:
    """(fields (L,), blank (L,) bool) of every line of a whole CSV text ``data`` (bytes, UTF-8)."""
    lines = _scan(data, final=True)
    return lines.fields, lines.blank


def _scan(data: bytes, final: bool) -> _Lines:
    """The lines of ``data`` (starting outside quotes); the vectorised count, else the csv module's."""
    b = np.frombuffer(data, dtype=np.uint8)
    ev = np.flatnonzero(
        b <= _COMMA
    )  # one pass: ',', '"', CR, LF are all <= ','; digits, '.' and letters are not
    c = b[ev]
    lf = c == _LF
    all_lf = ev[lf]  # every LF, for the line numbers
    q = np.flatnonzero(c == _QUOTE)  # indices into ev
    if q.size:
        if not _quotes_regular(b, ev[q]):
            return _scan_exact(data, final)
        if q.size % 2:  # a quote opened at the end of the buffer: its line continues in the next read
            ev, c, lf, q = ev[: q[-1]], c[: q[-1]], lf[: q[-1]], q[:-1]
        seps = np.cumsum((c == _COMMA) | lf | (c == _CR))
        if not np.array_equal(
            seps[q[0::2]], seps[q[1::2]]
        ):  # some quoted value holds a separator or line end
            outside = (np.cumsum(c == _QUOTE) & 1) == 0
            ev, c, lf = ev[outside], c[outside], lf[outside]
    is_end = lf
    cr = c == _CR
    if cr.any():  # a lone carriage return ends a line too (at the buffer's end: known at the next read)
        after = np.where(ev + 1 < b.size, b[np.minimum(ev + 1, b.size - 1)], _LF if final else -1)
        is_end = lf | (cr & (after != _LF) & (after != -1))
    ends = ev[is_end]
    cut = int(ends[-1]) + 1 if ends.size else 0
    if final and cut < b.size:
        ends, cut = np.append(ends, b.size), b.size
    starts = np.r_[0, ends[:-1] + 1].astype(np.int64) if ends.size else np.zeros(0, dtype=np.int64)
    commas = ev[c == _COMMA]
    fields = np.diff(np.searchsorted(commas, ends), prepend=0) + 1
    return _Lines(starts, fields, _blank(b, starts, ends, fields == 1), cut, all_lf)


def _blank(b: np.ndarray, starts: np.ndarray, ends: np.ndarray, candidate: np.ndarray) -> np.ndarray:
    """(L,) bool: the candidate lines [start, end) holding only spaces, tabs and carriage returns."""
    blank = np.zeros(starts.size, dtype=bool)
    lines = np.flatnonzero(candidate)
    if lines.size <= 64:  # usually: blank lines and lines cut to one field are rare
        for i in lines:
            blank[i] = not bytes(b[starts[i] : ends[i]]).strip(b" \t\r\n")
    else:  # a one-column file
        solid = np.r_[0, np.cumsum(~((b == _SPACE) | (b == _TAB) | (b == _CR) | (b == _LF)))]
        blank[lines] = solid[ends[lines]] == solid[starts[lines]]
    return blank


def _quotes_regular(b: np.ndarray, quotes: np.ndarray) -> bool:
    """Whether pairing the quotes at ``quotes`` by parity is how pandas reads them: every opening
    quote starts a field (after optional spaces) or follows its closing quote (an escaped ``""``),
    and every closing quote is followed by a separator, a line end, a quote or the end."""
    opening, closing = quotes[0::2], quotes[1::2]
    nxt = b[np.minimum(closing + 1, b.size - 1)]
    end = closing + 1 >= b.size
    if not (end | (nxt == _COMMA) | (nxt == _LF) | (nxt == _CR) | (nxt == _QUOTE)).all():
        return False
    prev = b[np.maximum(opening - 1, 0)]
    escaped = np.r_[False, closing[: opening.size - 1] == opening[1:] - 1]
    ok = (opening == 0) | (prev == _COMMA) | (prev == _LF) | (prev == _CR) | escaped
    if ok.all():
        return True
    todo = np.flatnonzero(~ok)  # spaces between the separator and the quote (skipinitialspace; not tabs)
    pos = opening[todo] - 1
    for _ in range(16):
        blank = (pos >= 0) & (b[np.maximum(pos, 0)] == _SPACE)
        if not blank.any():
            break
        pos = pos - blank
    before = b[np.maximum(pos, 0)]
    bom = (pos == 2) & (bytes(b[:3]) == _BOM)  # a quoted first header name after the byte-order mark
    ok[todo] = (pos < 0) | bom | (before == _COMMA) | (before == _LF) | (before == _CR)
    return bool(ok.all())


def _scan_exact(data: bytes, final: bool) -> _Lines:
    """:func:`_scan` by the csv module, one row at a time (for irregular quoting only)."""
    text = io.StringIO(data.decode("utf-8", "surrogateescape"), newline="")
    pos = 0

    def lines():
        nonlocal pos
        for line in text:
            pos += len(line.encode("utf-8", "surrogateescape"))
            yield line

    starts, fields, blank, start = [], [], [], 0
    for row in csv.reader(lines(), skipinitialspace=True):
        starts.append(start)
        fields.append(len(row))
        blank.append(not data[start:pos].strip(b" \t\r\n"))
        start = pos
    if not final and starts:  # the last row may continue in the next read
        start = starts.pop()
        fields.pop(), blank.pop()
    b = np.frombuffer(data, dtype=np.uint8)
    return _Lines(
        np.array(starts, dtype=np.int64),
        np.array(fields, dtype=np.int64),
        np.array(blank, dtype=bool),
        start if not final else len(data),
        np.flatnonzero(b == _LF),
    )


def _header(data: bytes, lines: _Lines, path) -> tuple[list[str], int]:
    """(names, index of the header line): the first line that is not blank, named as pandas names it."""
    import pandas as pd

    first = np.flatnonzero(~lines.blank)
    if first.size == 0:
        raise ValueError(f"{path}: the file is empty: no header line and no data rows")
    i = int(first[0])
    end = int(lines.starts[i + 1]) if i + 1 < lines.starts.size else lines.cut
    names = [
        str(n)
        for n in pd.read_csv(io.BytesIO(data[lines.starts[i] : end]), nrows=0, skipinitialspace=True).columns
    ]
    return names, i


def read_csv_blocks(
    path, dtype: dict | None = None, block_bytes: int = BLOCK_BYTES, nan_text: tuple[str, ...] = ()
) -> Iterator["object"]:
    """The data rows of a CSV file as DataFrames of whole lines, in file order, with the header's
    columns (``dtype``: pandas dtypes by column name) and, in a block with a line of another
    number of fields than the header, :data:`SHAPE_COLUMN`. In the columns ``nan_text`` only an
    empty cell is missing: a text such as ``nan`` is kept as text (pandas reads the texts of
    :data:`NA_TEXTS` as missing elsewhere). Rows are the
    non-blank lines after the header, one per line (a quoted value may span lines). ValueError
    for a file with no header line; pandas' errors for a file it cannot parse."""
    with open(path, "rb") as f:
        names, carry, line, empty = None, b"", 1, True
        while True:
            chunk = f.read(block_bytes)
            data = carry + chunk
            lines = _scan(data, final=not chunk)
            if names is None and chunk and not (~lines.blank).any():
                carry = data  # no complete header line yet
                continue
            if names is None:
                names, h = _header(data, lines, path)
                skip = lines.starts[h + 1] if h + 1 < lines.starts.size else lines.cut
                line += int(np.searchsorted(lines.newlines, skip))
                data, lines = data[skip:], _scan(data[skip:], final=not chunk)
            if lines.cut and (~lines.blank).any():
                yield _parse(data, lines, names, line, dtype, nan_text)
                empty = False
            line += int(np.searchsorted(lines.newlines, lines.cut))
            carry = data[lines.cut :]
            if not chunk:
                break
    if empty:  # a header and no rows
        yield _parse(b"", _scan(b"", final=True), names, line, dtype, nan_text)


def _missing(names: list[str], nan_text: tuple[str, ...]) -> dict:
    """pandas.read_csv's arguments for the missing cells: its defaults, but in the columns
    ``nan_text`` only an empty cell."""
    if not any(n in nan_text for n in names):
        return {}
    return {
        "keep_default_na": False,
        "na_values": {n: [""] if n in nan_text else list(NA_TEXTS) for n in names},
    }


def _parse(
    data: bytes,
    lines: _Lines,
    names: list[str],
    line: int,
    dtype: dict | None,
    nan_text: tuple[str, ...] = (),
):
    """One block of whole lines (``line``: the physical line of its first byte) as a DataFrame."""
    import pandas as pd

    rows = ~lines.blank
    fields, starts = lines.fields[rows], lines.starts[rows]
    n = len(names)
    shape = np.full(fields.size, None, dtype=object)
    if fields.size == 0:
        return pd.DataFrame({c: pd.Series(dtype=object) for c in names})
    spare = [f"<field {k}>" for k in range(n + 1, int(fields.max()) + 1)]
    frame = pd.read_csv(
        io.BytesIO(data[: lines.cut]),
        header=None,
        names=names + spare,
        index_col=False,
        skipinitialspace=True,
        dtype={k: v for k, v in (dtype or {}).items() if k in names},
        **_missing(names + spare, nan_text),
    )
    if len(frame) != fields.size:
        raise ValueError(
            f"pandas reads {len(frame)} rows from the {fields.size} lines from line {line} on; "
            "the file's quoting is not understood"
        )
    frame = frame[names] if spare else frame
    bad = np.flatnonzero(fields != n)
    if bad.size:  # the column only where it is needed: a file's good rows read as pandas reads them
        at = line + np.searchsorted(lines.newlines, starts[bad])
        for i, ln in zip(bad, at):
            shape[i] = RowShape(int(ln), int(fields[i]), n, names[fields[i]] if fields[i] < n else "*")
        frame[SHAPE_COLUMN] = shape
    return frame
