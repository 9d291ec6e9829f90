"""Each CSV line's fields counted from the raw bytes (registration.io.files.csvrows): a short or long
line is flagged with its line number, every other row reads as pandas reads it, whatever the block
size, the quoting, the line ends and the blank lines."""

from __future__ import annotations

import csv
import io
import tempfile
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from registration.io.files.csvrows import SHAPE_COLUMN, RowShape, count_fields, read_csv_blocks

SETTINGS = settings(
    max_examples=int(__import__("os").environ.get("HYPOTHESIS_EXAMPLES", "60")),
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
#: cell text with the characters that matter to a CSV parser (quoted by csv.writer when needed)
cell = st.text(alphabet=list('ab1.-, "\n\r\t') + ["é"], max_size=6)


@st.composite
def tables(draw):
    """(header, rows, line terminator, blank-line positions): rows of 1..n+2 fields, most of n."""
    n = draw(st.integers(1, 5))
    header = [f"c{k}" for k in range(n)]
    rows = []
    for _ in range(draw(st.integers(0, 12))):
        width = draw(st.sampled_from([n] * 4 + [max(1, n - 1), n + 1, n + 2]))
        rows.append(["x" + draw(cell)] + [draw(cell) for _ in range(width - 1)])  # never a blank line
    blanks = draw(st.lists(st.integers(0, len(rows)), max_size=3))
    return header, rows, draw(st.sampled_from(["\n", "\r\n"])), blanks


def _field(value: str) -> str:
    """A cell as CSV text: quoted when it holds a separator, a quote or a line end."""
    return '"' + value.replace('"', '""') + '"' if any(ch in value for ch in ',"\r\n') else value


def _text(header, rows, terminator, blanks) -> tuple[str, list[int]]:
    """The CSV text and the physical line (from 1) of each row."""
    out, lines = [",".join(header) + terminator], []
    for i, row in enumerate(rows):
        out += [terminator] * blanks.count(i)
        lines.append(1 + "".join(out).count("\n"))
        out.append(",".join(_field(v) for v in row) + terminator)
    return "".join(out), lines


@SETTINGS
@given(table=tables(), block=st.integers(1, 80))
def test_short_and_long_lines_are_flagged_and_the_rest_reads_as_pandas_reads_it(table, block):
    header, rows, terminator, blanks = table
    text, lines = _text(header, rows, terminator, blanks)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "t.csv"
        path.write_bytes(text.encode())
        frames = list(read_csv_blocks(path, dtype={c: str for c in header}, block_bytes=block))
        got = pd.concat(frames, ignore_index=True)
        assert len(got) == len(rows)
        shapes = got[SHAPE_COLUMN].to_numpy() if SHAPE_COLUMN in got else np.full(len(rows), None)
        for i, row in enumerate(rows):
            s = shapes[i] if isinstance(shapes[i], RowShape) else None
            if len(row) == len(header):
                assert s is None, (i, s)
            else:
                assert (s.fields, s.header, s.line) == (len(row), len(header), lines[i]), (i, s, row)
                assert s.code == ("short_row" if len(row) < len(header) else "long_row")
                assert s.column == (header[len(row)] if len(row) < len(header) else "*")
        good = [r for r in rows if len(r) == len(header)]
        clean = Path(tmp) / "clean.csv"
        clean.write_bytes(_text(header, good, terminator, [])[0].encode())
        want = pd.read_csv(clean, dtype=str, index_col=False, skipinitialspace=True)
        ok = np.array([len(r) == len(header) for r in rows], dtype=bool)
        pd.testing.assert_frame_equal(got.loc[ok, header].reset_index(drop=True), want, check_dtype=False)


@pytest.mark.parametrize(
    "text, fields",
    [
        (b"a,b\n1,2\n3\n4,5,6\n", [2, 2, 1, 3]),
        (b'a,b\r\n"x,y",2\r\n  \r\n"line\nbreak",3\r\n', [2, 2, 2]),  # quoted separators, a blank line
        (b'a,b\n1, "q"\n2,"say ""hi"", ok"\n', [2, 2, 2]),  # a blank before a quote, escaped quotes
        (b'a,b\nab"c,2\n"x"y,3,4\n', [2, 2, 3]),  # quotes inside unquoted values: counted by the csv module
        (b"a,b\r1,2\r3\r", [2, 2, 1]),  # lone carriage returns end lines, as for pandas
        (b'\xef\xbb\xbf"a","b"\n1,2', [2, 2]),  # a byte-order mark, no final line end
    ],
)
def test_counts_match_the_csv_module(text, fields):
    got, blank = count_fields(text)
    assert got[~blank].tolist() == fields
    rows = [
        r
        for r in csv.reader(io.StringIO(text.decode("utf-8-sig"), newline=""), skipinitialspace=True)
        if r and "".join(r).strip()
    ]
    assert [len(r) for r in rows] == fields


def test_a_file_of_blank_lines_has_no_header(tmp_path):
    path = tmp_path / "e.csv"
    path.write_bytes(b"\n  \n\r\n")
    with pytest.raises(ValueError, match="e.csv: the file is empty: no header line"):
        list(read_csv_blocks(path))


@SETTINGS
@given(
    body=st.lists(st.sampled_from(list('a1, "\n\t') + ["\r\n"]), max_size=40).map("".join),
    block=st.integers(1, 20),
)
def test_any_text_pandas_reads_gives_its_rows(body, block):
    """Arbitrary text, stray quotes included: the rows are the rows pandas finds, or pandas' error."""
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "t.csv"
        path.write_bytes(("h0,h1\n" + body).encode())
        try:
            want = pd.read_csv(
                path,
                header=None,
                names=range(60),
                skiprows=1,
                index_col=False,
                skipinitialspace=True,
                dtype=str,
            )
        except pd.errors.ParserError:
            with pytest.raises(Exception):
                list(read_csv_blocks(path, block_bytes=block))
            return
        got = pd.concat(list(read_csv_blocks(path, block_bytes=block)), ignore_index=True)
        assert len(got) == len(want)
        fields = (want.notna().to_numpy() * np.arange(1, 61)).max(
            axis=1, initial=0
        )  # at least the last non-empty
        if SHAPE_COLUMN in got:
            flagged = got[SHAPE_COLUMN].to_numpy()
            counted = np.array([s.fields if isinstance(s, RowShape) else 2 for s in flagged])
            assert (counted >= fields).all()
