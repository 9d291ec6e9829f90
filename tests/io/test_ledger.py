"""The one rejected ledger: common columns plus the source's location columns, ordered by file
then location (or as added), counted per reason code; and the one file-error wrapper."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from registration.io.files.ledger import LedgerColumns, Location, RejectedLedger
from registration.io.files.unreadable import one_line, read_error

COLUMNS = LedgerColumns((Location("offset", "nullable"), Location("packet", "positive")), "code", ("a", "b"))


def test_a_ledger_orders_by_file_then_location_and_empties_what_does_not_apply():
    ledger = RejectedLedger(COLUMNS)
    ledger.add("y.pcap", "a", "first", offset=np.array([30, 10]), packet=np.array([2, 0]))
    ledger.add("x.pcap", "b", np.array(["r1", "r2"], dtype=object), offset=[5, 1], packet=3)
    ledger.add("y.pcap", "b", "third", offset=np.zeros(0, dtype=int), packet=0)  # nothing
    frame = ledger.frame()
    assert list(frame.columns) == ["file", "offset", "packet", "code", "reason"]
    assert frame.file.tolist() == ["y.pcap", "y.pcap", "x.pcap", "x.pcap"]  # files in the order added
    assert frame.offset.tolist() == [10, 30, 1, 5]
    assert frame.packet.isna().tolist() == [True, False, False, False]
    assert frame.reason.tolist() == ["first", "first", "r2", "r1"]
    assert ledger.count() == 4 and ledger.by_code() == {"a": 2, "b": 2}
    assert list(ledger.by_code(("b", "a"))) == ["b", "a"]


def test_files_given_up_front_are_named_by_index_and_codes_are_checked():
    ledger = RejectedLedger(LedgerColumns((Location("line"),), "code"), ["one.log", "two.log"])
    ledger.add(np.array([1, 0, 1]), np.array(["x", "y", "x"], dtype=object), "why", line=[4, 9, 2])
    frame = ledger.frame()
    assert frame.file.tolist() == ["one.log", "two.log", "two.log"] and frame.line.tolist() == [9, 2, 4]
    assert ledger.by_code() == {"x": 2, "y": 1}
    with pytest.raises(KeyError, match="unknown reason code 'c'"):
        RejectedLedger(COLUMNS).add("f", "c", "why", offset=1, packet=1)
    with pytest.raises(TypeError, match="location"):
        RejectedLedger(COLUMNS).add("f", "a", "why", offset=1)


def test_an_empty_ledger_has_the_columns_and_their_types():
    frame = RejectedLedger(COLUMNS).frame()
    assert list(frame.columns) == ["file", "offset", "packet", "code", "reason"] and len(frame) == 0
    assert frame.offset.dtype == pd.Int64Dtype() and frame.file.dtype == object
    unsorted = RejectedLedger(LedgerColumns((Location("row"), Location("column", "text")), sort=False))
    assert unsorted.frame().row.dtype == np.int64
    unsorted.add("b.csv", "c1", "r", row=5, column="x")
    unsorted.add("a.csv", "c2", "r", row=1, column="y")
    assert unsorted.frame().file.tolist() == ["b.csv", "a.csv"]  # in the order added


def test_the_file_error_is_one_line_naming_the_file():
    error = read_error("data.csv", ValueError("bad\n  quote\tat line 3"), "cannot read it as CSV")
    assert type(error) is ValueError and str(error) == "data.csv: cannot read it as CSV: bad quote at line 3"
    missing = FileNotFoundError(2, "No such file or directory", "data.csv")
    assert one_line(missing) == "No such file or directory"

    class MyError(ValueError):
        pass

    assert isinstance(read_error("f", missing, error=MyError), MyError)
    assert str(read_error("f", KeyError())) == "f: cannot be read: KeyError"
