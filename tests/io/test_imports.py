"""The one import contract: ImportResult's tables and write (the one folder writer, exact floats)."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd

from registration.io.imports import IMPORT_FILES, ImportResult


def _result(targets=None) -> ImportResult:
    plots = pd.DataFrame({"time_s": [0.1, 1 / 3], "sensor": ["R", "R"], "range_m": [np.pi * 1e4, 2.0]})
    empty = pd.DataFrame({"time_s": pd.Series([], dtype=float)})
    rejected = pd.DataFrame({"file": ["a"], "line": [3], "code": ["x"], "reason": ["why"]})
    one = pd.DataFrame({"platform": ["P"]})
    return ImportResult(plots, empty, one, one, empty, rejected, {"n": 2}, targets)


def test_tables_in_order_and_targets_only_when_given():
    assert list(_result().tables) == ["plots", "navigation", "sensors", "platforms", "reference"]
    assert list(_result(pd.DataFrame({"target": ["1"]})).tables)[-1] == "targets"


def test_write_skips_empty_tables_and_floats_read_back_exactly(tmp_path):
    result = _result()
    written = result.write(tmp_path / "out")
    assert list(written) == ["plots", "sensors", "platforms", "rejected", "summary"]
    assert {p.name for p in written.values()} <= IMPORT_FILES
    back = pd.read_csv(written["plots"])
    np.testing.assert_array_equal(back.range_m.to_numpy(), result.plots.range_m.to_numpy())
    np.testing.assert_array_equal(back.time_s.to_numpy(), result.plots.time_s.to_numpy())
    assert json.loads(written["summary"].read_text()) == {"n": 2}
    assert pd.read_csv(written["rejected"]).line.tolist() == [3]
    parquet = result.write(tmp_path / "pq", "parquet")
    assert parquet["plots"].suffix == ".parquet" and parquet["rejected"].suffix == ".csv"
