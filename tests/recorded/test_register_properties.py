"""Property tests: arbitrary tables into the reader, the validator and the runner.

Only the documented errors may escape (FileFormatError, BadRowError, ValueError for "no valid
rows"), every input row is either accepted or rejected with a reason, and the filter state never
becomes non-finite.
"""

from __future__ import annotations

import json
import math
import re
import tempfile
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from registration.recorded import (
    SYNC_COLUMNS,
    BadRowError,
    FileFormatError,
    RunOptions,
    check_frame,
    iter_frames,
    run_register,
    sync_layout,
)

from ._register_data import frame

SETTINGS = settings(
    max_examples=int(__import__("os").environ.get("HYPOTHESIS_EXAMPLES", "40")),
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)

cells = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.floats(min_value=-400, max_value=400),
    st.integers(min_value=-(10**20), max_value=10**20),
    st.text(max_size=6),
    st.booleans(),
    st.none(),
)


@st.composite
def arbitrary_tables(draw):
    columns = draw(
        st.lists(st.sampled_from(list(SYNC_COLUMNS) + ["extra", "time"]), unique=True, max_size=22)
    )
    n = draw(st.integers(min_value=0, max_value=12))
    data = {c: draw(st.lists(cells, min_size=n, max_size=n)) for c in columns}
    return pd.DataFrame(data, columns=columns)


def _write(df: pd.DataFrame, path: Path) -> None:
    if path.suffix == ".csv":
        df.to_csv(path, index=False)
    else:
        df.astype(str).to_parquet(path, index=False)  # Parquet needs one type per column


@SETTINGS
@given(df=arbitrary_tables(), suffix=st.sampled_from([".csv", ".parquet"]), chunk=st.integers(1, 5))
def test_reader_and_validator_accept_or_reject_every_row_and_raise_only_documented_errors(df, suffix, chunk):
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / f"t{suffix}"
        _write(df, path)
        if suffix == ".csv" and not len(df.columns):
            # the only table that cannot be read: a CSV without a header line; the error names the file
            with pytest.raises(
                FileFormatError, match=f"^{re.escape(str(path))}: the file is empty: no header line"
            ):
                list(iter_frames(path, SYNC_COLUMNS, chunk))
            return
        blocks = list(iter_frames(path, SYNC_COLUMNS, chunk))  # every other table is read
        last, seen, accepted, rejected = None, 0, 0, []
        for first, f in blocks:
            assert first == seen
            blk = check_frame(f, sync_layout(), str(path), first_row=first, mode="skip", last_time=last)
            last = blk.last_time
            seen += blk.n_rows
            accepted += int(blk.accepted.sum())
            rejected += [r.row for r in blk.rejections]
            assert np.isfinite(blk.values[blk.accepted]).all()
            for r in blk.rejections:
                assert r.reason and r.code and json.loads(r.values) is not None
        # the rows a CSV parser sees (a bare carriage return inside a text cell ends a record)
        expected = (
            len(pd.read_csv(path, index_col=False, skipinitialspace=True)) if suffix == ".csv" else len(df)
        )
        assert accepted + len(rejected) == seen == expected
        assert len(set(rejected)) == len(rejected)
        # stop mode: the first bad row, or nothing
        try:
            last = None
            for first, f in blocks:
                last = check_frame(
                    f, sync_layout(), str(path), first_row=first, mode="stop", last_time=last
                ).last_time
            assert not rejected
        except BadRowError as exc:
            assert exc.row == min(rejected) and str(path) in str(exc)


extreme = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from(
        [0.0, -0.0, 90.0, -90.0, 89.999999, 180.0, -180.0, 360.0, 1e-300, 5e-324, 1e300, 1e6, -12000.0, 1e-9]
    ),
    st.text(max_size=3),
)


@st.composite
def near_valid_tables(draw):
    """A valid table with some cells replaced by extreme, invalid or odd values."""
    df = frame(24).astype(object)
    for _ in range(draw(st.integers(0, 12))):
        row = draw(st.integers(0, len(df) - 1))
        col = draw(st.sampled_from(list(SYNC_COLUMNS)))
        df.loc[row, col] = draw(extreme)
    return df


@SETTINGS
@given(
    df=near_valid_tables(),
    q_mode=st.sampled_from(["fixed", "adaptive"]),
    lin=st.sampled_from(["paper", "relinearized"]),
)
def test_runner_never_lets_the_filter_state_become_non_finite(df, q_mode, lin):
    from registration.online import RegistrationConfig

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "t.csv"
        df.to_csv(path, index=False)
        options = RunOptions(
            out=Path(tmp) / "out",
            config=RegistrationConfig(q_mode=q_mode, linearization=lin),
            on_bad_row="skip",
            chunk_rows=5,
            plots=False,
            progress=False,
            log=lambda m: None,
        )
        n = len(pd.read_csv(path, index_col=False, skipinitialspace=True))  # as a CSV parser sees it
        try:
            summary = run_register([path], options)
        except ValueError as exc:  # documented: every row rejected, each in rejected.csv
            assert "no valid rows to register" in str(exc) and str(path) in str(exc)
            assert pd.read_csv(Path(tmp) / "out" / "rejected.csv")["row"].tolist() == list(range(n))
            return
        rows = summary["rows"]
        assert rows["read"] == n == rows["accepted"] + rows["rejected"]
        est = pd.read_csv(Path(tmp) / "out" / "estimates.csv")
        rej = pd.read_csv(Path(tmp) / "out" / "rejected.csv")
        assert sorted(est["row"].tolist() + rej["row"].tolist()) == list(range(n))
        assert np.isfinite(est.to_numpy(dtype=float)).all()
        assert all(math.isfinite(e["estimate"]) and math.isfinite(e["sigma"]) for e in summary["estimates"])
