"""File formats, the block reader, checkpoints' exact encoding, `registration schema`."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest

from registration.cli import main
from registration.online.contract import DATA_COLUMNS
from registration.recorded import (
    SYNC_COLUMNS,
    CheckpointError,
    CsvAppender,
    FileFormatError,
    PartsWriter,
    from_file_frame,
    iter_frames,
    load_checkpoint,
    read_table,
    save_checkpoint,
    to_file_frame,
    write_table,
)

from ._register_data import frame, scenario


@pytest.mark.parametrize("suffix", [".csv", ".parquet"])
def test_write_then_read_table_converts_units_only_at_the_boundary(tmp_path, suffix):
    data = scenario(50).data
    path = write_table(data, tmp_path / f"t{suffix}")
    raw = pd.read_csv(path) if suffix == ".csv" else pd.read_parquet(path)
    assert tuple(raw.columns) == SYNC_COLUMNS
    assert np.allclose(
        raw["a_lat_deg"], np.degrees(data["a_lat"]), rtol=0, atol=0
    )  # degrees in the file, exactly
    assert np.array_equal(raw["a_range_m"], data["a_range"])
    back = read_table(path)
    assert tuple(back) == DATA_COLUMNS
    for c in DATA_COLUMNS:
        assert np.allclose(back[c], data[c], rtol=1e-15, atol=1e-300), c
    assert np.array_equal(from_file_frame(to_file_frame(back))["a_range"], back["a_range"])


def test_write_table_refuses_unknown_suffixes_and_incomplete_data(tmp_path):
    with pytest.raises(FileFormatError, match=r"\.csv or \.parquet"):
        write_table(scenario(5).data, tmp_path / "t.xlsx")
    data = dict(scenario(5).data)
    del data["b_roll"]
    with pytest.raises(ValueError, match="b_roll"):
        write_table(data, tmp_path / "t.csv")


@pytest.mark.parametrize("suffix", [".csv", ".parquet"])
@pytest.mark.parametrize("start", [0, 7, 21, 35])
def test_blocks_are_aligned_on_absolute_rows_whatever_the_start(tmp_path, suffix, start):
    f = frame(47)
    path = tmp_path / f"t{suffix}"
    if suffix == ".csv":
        f.to_csv(path, index=False)
    else:
        f.to_parquet(path, index=False, row_group_size=10)  # row groups that do not match the blocks
    blocks = list(iter_frames(path, SYNC_COLUMNS, 7, start_row=start))
    assert [b[0] for b in blocks] == list(range(start, 47, 7))
    got = pd.concat([b[1] for b in blocks], ignore_index=True)
    pd.testing.assert_frame_equal(got, f.iloc[start:].reset_index(drop=True), check_dtype=False)
    with pytest.raises(FileFormatError, match="fewer than"):
        list(iter_frames(path, SYNC_COLUMNS, 7, start_row=48))


def test_unreadable_files_raise_file_format_errors(tmp_path):
    bad = tmp_path / "t.parquet"
    bad.write_bytes(b"not parquet at all")
    with pytest.raises(FileFormatError):
        list(iter_frames(bad, SYNC_COLUMNS, 5))
    empty = tmp_path / "e.csv"
    empty.write_bytes(b"")
    with pytest.raises(FileFormatError):
        list(iter_frames(empty, SYNC_COLUMNS, 5))
    with pytest.raises(FileFormatError, match="no such file"):
        list(iter_frames(tmp_path / "missing.csv", SYNC_COLUMNS, 5))


def test_appenders_cut_back_to_a_recorded_length(tmp_path):
    cols = ["row", "v"]
    w = CsvAppender(tmp_path / "o.csv", cols)
    w.append_frame(pd.DataFrame({"row": [0, 1], "v": [0.1, 1 / 3]}))
    mark = (w.size, w.rows)
    w.append_frame(pd.DataFrame({"row": [2], "v": [2.0]}))
    w.close()
    w = CsvAppender(tmp_path / "o.csv", cols, resume=mark)
    w.append_frame(pd.DataFrame({"row": [2], "v": [2.5]}))
    w.close()
    back = pd.read_csv(tmp_path / "o.csv")
    assert back["row"].tolist() == [0, 1, 2] and back["v"].tolist() == [0.1, 1 / 3, 2.5]  # exact float text
    p = PartsWriter(tmp_path / "o.parquet", cols)
    p.append_frame(pd.DataFrame({"row": [0], "v": [1.0]}))
    mark = (p.size, p.rows)
    p.append_frame(pd.DataFrame({"row": [1], "v": [2.0]}))
    p = PartsWriter(tmp_path / "o.parquet", cols, resume=mark)
    p.append_frame(pd.DataFrame({"row": [1], "v": [3.0]}))
    assert pd.read_parquet(tmp_path / "o.parquet")["v"].tolist() == [1.0, 3.0]


def test_checkpoints_are_exact_and_damage_is_detected(tmp_path):
    path = tmp_path / "c.json"
    rng = np.random.default_rng(1)
    state = {
        "x": rng.normal(size=12) * 1e-7,
        "P": rng.normal(size=(12, 12)),
        "n": 12345678901234,
        "t": 0.1 + 0.2,
        "none": None,
        "tiny": 5e-324,
        "neg0": -0.0,
        "names": ["a", "b"],
        "nested": {"w": np.zeros((0, 12))},
    }
    save_checkpoint(path, state)
    back = load_checkpoint(path)
    assert np.array_equal(back["x"], state["x"]) and np.array_equal(back["P"], state["P"])
    assert back["t"] == state["t"] and back["tiny"] == 5e-324 and str(back["neg0"]) == "-0.0"
    assert back["n"] == state["n"] and back["none"] is None and back["nested"]["w"].shape == (0, 12)
    doc = json.loads(path.read_text())
    assert "pickle" not in path.read_text() and set(doc) == {"format", "version", "payload", "sha256"}
    text = path.read_text()
    path.write_text(text.replace('"n":12345678901234', '"n":12345678901235'))
    with pytest.raises(CheckpointError, match="modified or damaged"):
        load_checkpoint(path)
    path.write_text(text[:-40])
    with pytest.raises(CheckpointError, match="truncated or corrupt"):
        load_checkpoint(path)
    path.write_bytes(b"\xff\xfe\x00")
    with pytest.raises(CheckpointError, match="truncated or corrupt"):
        load_checkpoint(path)
    assert not (tmp_path / "c.json.tmp").exists()


def test_schema_prints_both_forms_with_units(capsys):
    assert main(["schema"]) == 0
    out = capsys.readouterr().out
    for col in SYNC_COLUMNS:
        assert col in out
    assert "range_m" in out and "--nav" in out and "rejected.csv" in out
    assert main(["schema", "--json"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert [c["column"] for c in s["synchronous"]["columns"]] == list(SYNC_COLUMNS)
    assert {c["unit"] for c in s["synchronous"]["columns"]} == {"s", "deg", "m"}


@pytest.mark.parametrize("line", [1, 40])
def test_a_csv_line_with_an_extra_field_is_a_bad_row_wherever_it_stands(tmp_path, line):
    """pandas truncates an over-long *first* data line with only a warning (data lost silently) and
    refuses one further down; the reader reports either as a bad row (``long_row``), with its line."""
    from registration.recorded import BadRowError, read_table

    path = tmp_path / "extra.csv"
    lines = frame(60).to_csv(index=False).splitlines()
    lines[line] += ",1.0"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(
        BadRowError,
        match=rf"row {line - 1}, column '\*': line {line + 1} has 20 fields, the header "
        r"19: .* \[long_row\]",
    ):
        read_table(path)
