"""`registration register` on a synchronous table: round trip, bad rows in both modes, checkpoints."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest

from registration.cli import main
from registration.online import RegistrationConfig, register
from registration.recorded import REASON_CODES, from_file_frame, load_checkpoint, read_table, save_checkpoint

from ._register_data import file_estimates, file_sigmas, frame, in_file_units, scenario

FAST = ["--no-plots", "--no-progress"]


def _run(*args):
    return main(["register", *map(str, args)])


@pytest.mark.parametrize("suffix", [".csv", ".parquet"])
def test_simulate_export_then_register_recovers_the_python_api(tmp_path, suffix, capsys):
    exported = tmp_path / f"example{suffix}"
    assert (
        main(
            [
                "simulate",
                "--steps",
                "300",
                "--no-plots",
                "--out",
                str(tmp_path / "sim"),
                "--export",
                str(exported),
            ]
        )
        == 0
    )
    assert (
        _run(
            exported,
            "--out",
            tmp_path / "reg",
            "--chunk-rows",
            "64",
            *(["--no-progress"] if suffix == ".csv" else FAST),
        )
        == 0
    )
    text = capsys.readouterr().out
    assert "UNOBSERVABLE" in text and "not a converged estimate" in text
    est = pd.read_csv(tmp_path / "reg" / "estimates.csv")
    config = RegistrationConfig(sigma0=tuple(scenario().sigma0))
    # the same numbers as the API on the same (file) data, bit for bit
    api = register(read_table(exported), config)
    assert np.array_equal(file_estimates(est), in_file_units(api.estimates))
    assert np.array_equal(file_sigmas(est), in_file_units(np.sqrt(np.einsum("kii->ki", api.covariances))))
    assert np.array_equal(est["nis"], api.nis)
    # and the same estimates as the API on the simulated arrays (degrees <-> radians costs an ulp)
    direct = register(scenario().data, config)
    assert np.max(np.abs(api.estimates - direct.estimates) / direct.final_sigma) < 1e-9
    summary = json.loads((tmp_path / "reg" / "summary.json").read_text())
    stats = api.statistics()
    for key in ("before", "after"):
        for stat in ("max", "mean", "std"):
            assert np.allclose(summary[key][stat], stats[key][stat], rtol=1e-9), (key, stat)
    assert summary["observability"]["unobservable"] == api.observability.to_json()["unobservable"]
    assert np.allclose(
        summary["observability"]["singular_values"], api.observability.singular_values, rtol=1e-6, atol=1e-9
    )
    assert [e["status"] for e in summary["estimates"][:12]] == [
        api.observability.status[n] for n in summary["state_names"]
    ]
    pos = pd.read_csv(tmp_path / "reg" / "positions.csv")
    assert np.array_equal(pos[["a_ecef_x_m", "a_ecef_y_m", "a_ecef_z_m"]].to_numpy(), api.corrected_a_ecef)
    assert np.array_equal(
        pos[["diff_raw_x_m", "diff_raw_y_m", "diff_raw_z_m"]].to_numpy(), api.raw_difference_ecef
    )


def test_parquet_outputs_adaptive_q_and_plots(tmp_path):
    inp = tmp_path / "in.parquet"
    frame(120, motion=True).to_parquet(inp, index=False)
    assert (
        _run(
            inp,
            "--out",
            tmp_path / "reg",
            "--format",
            "parquet",
            "--q-mode",
            "adaptive",
            "--chunk-rows",
            "50",
            "--no-progress",
        )
        == 0
    )
    est = pd.read_parquet(tmp_path / "reg" / "estimates.parquet")
    assert len(est) == 120 and est["row"].tolist() == list(range(120))
    api = register(read_table(inp), RegistrationConfig(q_mode="adaptive"))
    assert np.array_equal(file_estimates(est), in_file_units(api.estimates))
    for png in ("estimates.png", "differences.png", "tracks.png"):
        assert (tmp_path / "reg" / png).stat().st_size > 10_000


def test_block_size_does_not_change_the_estimates(tmp_path):
    inp = tmp_path / "in.csv"
    frame(200).to_csv(inp, index=False)
    assert _run(inp, "--out", tmp_path / "a", "--chunk-rows", "7", *FAST) == 0
    assert _run(inp, "--out", tmp_path / "b", "--chunk-rows", "1000", *FAST) == 0
    assert (tmp_path / "a" / "estimates.csv").read_bytes() == (tmp_path / "b" / "estimates.csv").read_bytes()
    assert (tmp_path / "a" / "positions.csv").read_bytes() == (tmp_path / "b" / "positions.csv").read_bytes()


# ----------------------------------------------------------------------------- bad rows
BAD = [  # (row, column, value, reason code, text in the reason)
    (3, "a_lat_deg", 95.0, "out_of_range", "outside [-90, 90] deg"),
    (8, "b_elevation_deg", -120.0, "out_of_range", "outside [-90, 90] deg"),
    (11, "a_range_m", 0.0, "non_positive_range", "must be > 0 m"),
    (15, "b_range_m", -50.0, "non_positive_range", "must be > 0 m"),
    (20, "a_bearing_deg", "north", "non_numeric", "not a number"),
    (24, "b_heading_deg", np.nan, "non_finite", "empty or NaN"),
    (27, "a_pitch_deg", np.inf, "non_finite", "inf is not finite"),
    (31, "time_s", None, "time_duplicate", "duplicated"),
    (36, "time_s", 2.5, "time_backwards", "goes backwards"),
    (40, "a_alt_m", 5e6, "out_of_range", "altitude"),
]


def _bad_table(path):
    f = frame(60).astype(object)
    for row, col, value, _, _ in BAD:
        f.loc[row, col] = f.loc[row - 1, "time_s"] if value is None else value
    if path.suffix == ".csv":
        f.to_csv(path, index=False)
    else:
        f.astype(str).to_parquet(path, index=False)  # text cells: the reader converts them
    return len(f)


@pytest.mark.parametrize("suffix", [".csv", ".parquet"])
def test_every_bad_row_reason_in_skip_mode_accounts_for_every_row(tmp_path, suffix):
    inp = tmp_path / f"bad{suffix}"
    n = _bad_table(inp)
    assert _run(inp, "--out", tmp_path / "reg", "--on-bad-row", "skip", "--chunk-rows", "16", *FAST) == 0
    rej = pd.read_csv(tmp_path / "reg" / "rejected.csv")
    est = pd.read_csv(tmp_path / "reg" / "estimates.csv")
    assert sorted(rej["row"].tolist() + est["row"].tolist()) == list(range(n))
    assert rej["row"].tolist() == [b[0] for b in BAD]
    for (row, col, _, code, text), r in zip(BAD, rej.itertuples()):
        assert (r.column, r.reason_code) == (col, code) and text in r.reason, r
        assert r.file == str(inp) and json.loads(r.values)["time_s"] is not None
    assert {b[3] for b in BAD} == set(REASON_CODES) - {
        "missing_column",
        "filter_non_finite",
        "short_row",
        "long_row",
    }
    summary = json.loads((tmp_path / "reg" / "summary.json").read_text())
    assert summary["rows"]["read"] == n and summary["rows"]["accepted"] + summary["rows"]["rejected"] == n
    # the accepted rows give the same estimates as the API fed with exactly those rows
    clean = frame(60).drop(index=[b[0] for b in BAD]).reset_index(drop=True)
    api = register(from_file_frame(clean), RegistrationConfig())
    assert np.array_equal(file_estimates(est), in_file_units(api.estimates))


@pytest.mark.parametrize("row,column,value,code,text", BAD)
def test_every_bad_row_reason_in_stop_mode_names_file_row_and_column(
    tmp_path, capsys, row, column, value, code, text
):
    f = frame(60).astype(object)
    f.loc[row, column] = f.loc[row - 1, "time_s"] if value is None else value
    inp = tmp_path / "bad.csv"
    f.to_csv(inp, index=False)
    assert _run(inp, "--out", tmp_path / "reg", *FAST) == 2
    err = capsys.readouterr().err
    assert f"{inp}: row {row}, column '{column}'" in err and text in err and f"[{code}]" in err


@pytest.mark.parametrize("mode", ["stop", "skip"])
def test_missing_column_in_both_modes(tmp_path, capsys, mode):
    inp = tmp_path / "in.csv"
    frame(30).drop(columns=["b_roll_deg"]).to_csv(inp, index=False)
    assert _run(inp, "--out", tmp_path / "reg", "--on-bad-row", mode, *FAST) == 2
    err = capsys.readouterr().err
    assert "b_roll_deg" in err
    if mode == "stop":
        assert "row 0, column 'b_roll_deg'" in err and "missing_column" in err
    else:  # every row set aside with its reason, then: nothing left to register
        rej = pd.read_csv(tmp_path / "reg" / "rejected.csv")
        assert rej["row"].tolist() == list(range(30)) and set(rej["reason_code"]) == {"missing_column"}
        assert "no valid rows" in err


def _cut_lines(path, edits) -> None:
    """Apply ``edits`` {data row: function of the line's text} to a CSV file."""
    lines = path.read_text().splitlines()
    for row, edit in edits.items():
        lines[row + 1] = edit(lines[row + 1])
    path.write_text("\n".join(lines) + "\n")


SHAPES = {  # data row: (edit, column, reason code, fields)
    12: (lambda line: ",".join(line.split(",")[:5]), "a_pitch_deg", "short_row", 5),  # a half-written line
    20: (lambda line: line + ",1.5", "*", "long_row", 20),  # pandas refused the whole file
    59: (lambda line: ",".join(line.split(",")[:18]), "b_elevation_deg", "short_row", 18),  # the last, cut
}


def test_a_line_with_fewer_or_more_fields_than_the_header_is_a_bad_row(tmp_path, capsys):
    """Before: the cut lines' missing cells read as empty (non_finite, or nothing when only extra
    columns were cut) and a long line stopped the run in both modes as an unreadable file."""
    inp = tmp_path / "in.csv"
    frame(60).to_csv(inp, index=False)
    _cut_lines(inp, {row: edit for row, (edit, *_) in SHAPES.items()})
    assert _run(inp, "--out", tmp_path / "stop", *FAST) == 2
    err = capsys.readouterr().err
    assert (
        f"{inp}: row 12, column 'a_pitch_deg': line 14 has 5 fields, the header 19" in err
        and "[short_row]" in err
    )
    assert _run(inp, "--out", tmp_path / "reg", "--on-bad-row", "skip", *FAST) == 0
    rej = pd.read_csv(tmp_path / "reg" / "rejected.csv")
    assert [(r.row, r.column, r.reason_code) for r in rej.itertuples()] == [
        (row, c, code) for row, (_, c, code, _) in SHAPES.items()
    ]
    for row, (_, _, _, fields) in SHAPES.items():
        assert f"line {row + 2} has {fields} fields, the header 19" in rej.set_index("row").loc[row, "reason"]
    est = pd.read_csv(tmp_path / "reg" / "estimates.csv")
    api = register(
        from_file_frame(frame(60).drop(index=list(SHAPES)).reset_index(drop=True)), RegistrationConfig()
    )
    assert np.array_equal(file_estimates(est), in_file_units(api.estimates))


def test_a_line_cut_in_a_column_the_run_does_not_read_is_still_a_bad_row(tmp_path, capsys):
    """Before: a line missing only an extra column's field was registered as if whole."""
    inp = tmp_path / "in.csv"
    frame(30).assign(note="ok").to_csv(inp, index=False)
    _cut_lines(inp, {29: lambda line: line.rsplit(",", 1)[0]})
    assert _run(inp, "--out", tmp_path / "reg", *FAST) == 2
    assert f"{inp}: row 29, column 'note': line 31 has 19 fields, the header 20" in capsys.readouterr().err


def test_an_empty_file_is_named(tmp_path, capsys):
    inp = tmp_path / "in.csv"
    inp.write_bytes(b"")
    assert _run(inp, "--out", tmp_path / "reg", *FAST) == 2
    assert f"{inp}: the file is empty: no header line and no data rows" in capsys.readouterr().err


def test_malformed_csv_and_unknown_suffix_give_clear_errors(tmp_path, capsys):
    inp = tmp_path / "in.csv"
    frame(10).to_csv(inp, index=False)
    with open(inp, "a") as f:
        f.write('1,2,"3\n')  # a quote never closed: the rest of the file is one value
    assert _run(inp, "--out", tmp_path / "reg", *FAST) == 2
    assert "cannot be read as CSV" in capsys.readouterr().err
    other = tmp_path / "in.txt"
    other.write_text("x")
    assert _run(other, "--out", tmp_path / "reg", *FAST) == 2
    assert "expected a .csv or .parquet" in capsys.readouterr().err


def test_validate_only_reports_without_estimating(tmp_path, capsys):
    inp = tmp_path / "bad.csv"
    _bad_table(inp)
    assert _run(inp, "--out", tmp_path / "reg", "--validate-only") == 1
    out = capsys.readouterr().out
    assert f"{len(BAD)} bad" in out and "row 3, column 'a_lat_deg'" in out
    assert not (tmp_path / "reg" / "estimates.csv").exists()


# ----------------------------------------------------------------------------- checkpoints
def _checkpointed(tmp_path, inp, ckpt, *extra):
    return _run(
        inp, "--out", tmp_path / "reg", "--checkpoint", ckpt, "--checkpoint-every", "40", *FAST, *extra
    )


def test_damaged_checkpoints_give_a_clear_error_never_a_silent_restart(tmp_path, capsys):
    inp, ckpt = tmp_path / "in.csv", tmp_path / "run.ckpt"
    frame(100).to_csv(inp, index=False)
    assert _checkpointed(tmp_path, inp, ckpt) == 0
    good = ckpt.read_bytes()
    for damaged, message in [
        (good[: len(good) // 2], "truncated or corrupt"),
        (b"", "truncated or corrupt"),
        (good.replace(b'"phase":"done"', b'"phase":"filter"'), "modified or damaged"),
        (good.replace(b"0x1.", b"0x1.8", 1), "modified or damaged"),
        (b'{"format": "something else"}', "not a sensor-registration checkpoint"),
    ]:
        ckpt.write_bytes(damaged)
        before = (tmp_path / "reg" / "estimates.csv").read_bytes()
        assert _checkpointed(tmp_path, inp, ckpt) == 2
        err = capsys.readouterr().err
        assert message in err and str(ckpt) in err and "delete it" in err
        assert (tmp_path / "reg" / "estimates.csv").read_bytes() == before  # nothing was touched


def test_checkpoint_for_other_inputs_or_options_is_refused(tmp_path, capsys):
    inp, ckpt = tmp_path / "in.csv", tmp_path / "run.ckpt"
    frame(100).to_csv(inp, index=False)
    assert _checkpointed(tmp_path, inp, ckpt) == 0
    other = tmp_path / "other.csv"
    frame(100, seed=1).to_csv(other, index=False)
    assert _checkpointed(tmp_path, other, ckpt) == 2
    assert "other input files or options" in capsys.readouterr().err
    assert _checkpointed(tmp_path, inp, ckpt, "--linearization", "relinearized") == 2
    assert "other input files or options" in capsys.readouterr().err


def test_resume_refuses_outputs_shorter_than_the_checkpoint(tmp_path, capsys):
    inp, ckpt = tmp_path / "in.csv", tmp_path / "run.ckpt"
    frame(100).to_csv(inp, index=False)
    assert _checkpointed(tmp_path, inp, ckpt) == 0
    state = load_checkpoint(ckpt)
    state["phase"] = "filter"  # pretend the run stopped after its last checkpoint
    save_checkpoint(ckpt, state)
    (tmp_path / "reg" / "estimates.csv").write_text("row\n")
    assert _checkpointed(tmp_path, inp, ckpt) == 2
    assert "rows would be lost" in capsys.readouterr().err
