"""`registration register` on two asynchronous plot files (+ navigation): pairing and accounting."""

from __future__ import annotations

import json
from functools import lru_cache

import pandas as pd
import pytest

from registration.cli import main
from registration.online.contract import STATE_NAMES
from registration.online.scenario import ShipMotion, paper_scenario
from registration.recorded import to_file_frame

FAST = ["--no-plots", "--no-progress"]
NAV = ("lat_deg", "lon_deg", "alt_m", "heading_deg", "pitch_deg", "roll_deg")
DT = 0.05  # simulation grid: 1 Hz, 0.8 Hz and 10 Hz all fall on it


@lru_cache(maxsize=2)
def fine(seed: int = 4, seconds: float = 300.0):
    """The paper scenario simulated at 20 Hz with rolling ships, in file units."""
    sc = paper_scenario(n_steps=int(seconds / DT), dt=DT, seed=seed, ship_motion=ShipMotion())
    return sc, to_file_frame(sc.data)


def write_async(tmp_path, *, offset_b=0.3, nav_in_plots=False, drop_b=None, seed=4):
    """Radar A at 1 Hz, radar B at 0.8 Hz on a clock 0.3 s ahead, navigation at 10 Hz."""
    sc, f = fine(seed)
    a = f.iloc[::20]
    b = f.iloc[::25]
    cols_a = ["time_s", "a_range_m", "a_bearing_deg", "a_elevation_deg"] + (
        [f"a_{c}" for c in NAV] if nav_in_plots else []
    )
    cols_b = ["time_s", "b_range_m", "b_bearing_deg", "b_elevation_deg"] + (
        [f"b_{c}" for c in NAV] if nav_in_plots else []
    )
    a = a[cols_a].rename(columns=lambda c: c[2:] if c.startswith("a_") else c)  # unprefixed: A by position
    b = b[cols_b].copy()  # prefixed: says it is radar B's
    b["time_s"] = b["time_s"] + offset_b
    if drop_b is not None:
        b = b[(b["time_s"] < drop_b[0]) | (b["time_s"] > drop_b[1])]
    paths = [tmp_path / "radar_a.csv", tmp_path / "radar_b.parquet"]
    a.to_csv(paths[0], index=False)
    b.to_parquet(paths[1], index=False)
    extra = []
    if not nav_in_plots:
        nav = f[["time_s"] + [f"{p}_{c}" for p in "ab" for c in NAV]].iloc[::2]
        paths.append(tmp_path / "nav.csv")
        nav.to_csv(paths[2], index=False)
        extra = ["--nav", str(paths[2])]
    return sc, paths, extra, (len(a), len(b))


def _summary(out):
    return json.loads((out / "summary.json").read_text())


def _check_against_truth(summary, truth, k=3.5):
    """Every state and identifiable combination within k sigma of the simulation's truth."""
    est = {e["name"]: e for e in summary["estimates"]}
    for i, name in enumerate(STATE_NAMES):
        e = est[name]
        assert abs(e["estimate"] - truth[i]) <= k * e["sigma"], (
            name,
            (e["estimate"] - truth[i]) / e["sigma"],
        )


def test_async_plots_with_clock_offset_and_10hz_navigation_are_consistent_with_the_truth(tmp_path):
    sc, paths, nav, (n_a, n_b) = write_async(tmp_path)
    out = tmp_path / "reg"
    assert (
        main(
            [
                "register",
                str(paths[0]),
                str(paths[1]),
                *nav,
                "--clock-offset-b",
                "0.3",
                "--out",
                str(out),
                *FAST,
            ]
        )
        == 0
    )
    s = _summary(out)
    p = s["pairing"]
    # A's instants are whole seconds; B's plots (0, 1.25, 2.5, ... s on the reference clock) coincide every 5
    # s
    assert p["instants"] == n_a and p["exact"] == 60 and p["paired"] == p["exact"] + p["interpolated"]
    assert p["paired"] + p["unpaired"] == p["instants"]
    assert p["unpaired"] == 1 and p["unpaired_reasons"] == {
        "plots of radar B: extrapolation beyond limit": 1
    }  # t = 299 s
    unpaired = pd.read_csv(out / "unpaired.csv")
    assert unpaired["time_s"].tolist() == [299.0] and "extrapolation" in unpaired["reason"][0]
    files = p["files"]
    assert files[str(paths[1])]["rows"] == n_b and files[str(paths[2])]["rows"] == 3000
    assert all(f["accepted"] + f["rejected"] == f["rows"] for f in files.values())
    assert s["rows"]["accepted"] == p["paired"]
    _check_against_truth(s, sc.truth_state)
    # the synchronous run on the same scenario at 1 Hz: the two agree within the asynchronous sigmas
    sync = tmp_path / "sync.csv"
    fine()[1].iloc[::20].to_csv(sync, index=False)
    assert main(["register", str(sync), "--out", str(tmp_path / "sync"), *FAST]) == 0
    ref = {e["name"]: e for e in _summary(tmp_path / "sync")["estimates"]}
    for e in s["estimates"][:12]:
        assert abs(e["estimate"] - ref[e["name"]]["estimate"]) <= 3 * e["sigma"], e["name"]


def test_ignoring_the_clock_offset_changes_the_pairing(tmp_path):
    """Without --clock-offset-b no plot of B coincides with an instant of A: the offset is honoured."""
    _, paths, nav, _ = write_async(tmp_path)
    assert (
        main(
            [
                "register",
                *map(str, paths[:2]),
                *nav,
                "--out",
                str(tmp_path / "reg"),
                "--observability",
                "filter",
                *FAST,
            ]
        )
        == 0
    )
    assert _summary(tmp_path / "reg")["pairing"]["exact"] == 0


def test_navigation_inside_the_plot_files_and_a_gap(tmp_path):
    sc, paths, nav, (n_a, _) = write_async(tmp_path, nav_in_plots=True, drop_b=(100.0, 130.0))
    assert nav == []
    out = tmp_path / "reg"
    assert (
        main(
            [
                "register",
                *map(str, paths),
                "--clock-offset-b",
                "0.3",
                "--pair-at",
                "a",
                "--out",
                str(out),
                *FAST,
            ]
        )
        == 0
    )
    p = _summary(out)["pairing"]
    gap = p["unpaired_reasons"].get("plots of radar B with navigation: gap", 0)
    assert 25 <= gap <= 32  # the instants inside the 30 s hole in B's plots
    rows = pd.read_csv(out / "unpaired.csv")
    assert rows["reason"].str.contains("gap of").sum() == gap
    assert p["paired"] + p["unpaired"] == n_a
    _check_against_truth(_summary(out), sc.truth_state)


def _damage(paths, *, plots: bool = True, nav: bool = True) -> None:
    """Radar B's plot row 7: range -5 m, row 9: B's time repeated; navigation row 11: latitude 91 deg."""
    if plots:
        b = pd.read_parquet(paths[1])
        b.loc[7, "b_range_m"] = -5.0
        b.loc[9, "time_s"] = b.loc[8, "time_s"]
        b.to_parquet(paths[1], index=False)
    if nav:
        nav_frame = pd.read_csv(paths[2])
        nav_frame.loc[11, "a_lat_deg"] = 91.0
        nav_frame.to_csv(paths[2], index=False)


B_ROW_7 = (
    "radar_b.parquet: row 7, column 'b_range_m': value -5.0 must be > 0 m (slant range) [non_positive_range]"
)
NAV_ROW_11 = (
    "nav.csv: row 11, column 'a_lat_deg': value 91.0 is outside [-90, 90] deg (latitude) [out_of_range]"
)


@pytest.mark.parametrize(
    "plots,nav_file,expected",
    [
        (True, False, B_ROW_7),
        (False, True, NAV_ROW_11),
        # both: the files are read in the order plot files (A, B), then navigation files, so B's row comes
        # first
        (True, True, B_ROW_7),
    ],
)
def test_stop_mode_names_the_first_bad_row_in_reading_order(tmp_path, capsys, plots, nav_file, expected):
    _, paths, nav, _ = write_async(tmp_path)
    _damage(paths, plots=plots, nav=nav_file)
    rc = main(
        [
            "register",
            *map(str, paths[:2]),
            *nav,
            "--clock-offset-b",
            "0.3",
            "--out",
            str(tmp_path / "reg"),
            *FAST,
        ]
    )
    assert rc == 2
    err = capsys.readouterr().err
    assert err.count(": row ") == 1 and f"{tmp_path}/{expected}" in err
    assert not (tmp_path / "reg" / "paired.csv").exists()  # nothing published


def test_skip_mode_sets_bad_rows_of_every_file_aside(tmp_path):
    _, paths, nav, (_, n_b) = write_async(tmp_path)
    _damage(paths)
    out = tmp_path / "reg"
    assert (
        main(
            [
                "register",
                *map(str, paths[:2]),
                *nav,
                "--clock-offset-b",
                "0.3",
                "--on-bad-row",
                "skip",
                "--out",
                str(out),
                *FAST,
            ]
        )
        == 0
    )
    rej = pd.read_csv(out / "rejected.csv")
    got = {(r.file.rsplit("/", 1)[-1], r.row, r.reason_code) for r in rej.itertuples()}
    assert got == {
        ("radar_b.parquet", 7, "non_positive_range"),
        ("radar_b.parquet", 9, "time_duplicate"),
        ("nav.csv", 11, "out_of_range"),
    }
    files = _summary(out)["pairing"]["files"]
    assert files[str(paths[1])] == {
        "role": "plots of radar B",
        "rows": n_b,
        "accepted": n_b - 2,
        "rejected": 2,
    }
    assert files[str(paths[2])]["rejected"] == 1


def test_a_cut_line_of_a_plot_or_navigation_file_is_a_bad_row(tmp_path, capsys):
    """Before: the cut lines' missing cells read as empty, so the reason did not say what happened."""
    _, paths, nav, (n_a, _) = write_async(tmp_path)
    lines = paths[0].read_text().splitlines()
    lines[-1] = ",".join(lines[-1].split(",")[:2])  # radar A's last plot, half written
    paths[0].write_text("\n".join(lines) + "\n")
    args = ["register", *map(str, paths[:2]), *nav, "--clock-offset-b", "0.3", *FAST]
    assert main([*args, "--out", str(tmp_path / "stop")]) == 2
    assert (
        f"radar_a.csv: row {n_a - 1}, column 'bearing_deg': line {n_a + 1} has 2 fields, the header 4"
        in capsys.readouterr().err
    )
    out = tmp_path / "reg"
    assert main([*args, "--on-bad-row", "skip", "--out", str(out)]) == 0
    rej = pd.read_csv(out / "rejected.csv")
    assert [(r.file.rsplit("/", 1)[-1], r.row, r.reason_code) for r in rej.itertuples()] == [
        ("radar_a.csv", n_a - 1, "short_row")
    ]
    assert _summary(out)["pairing"]["files"][str(paths[0])]["rejected"] == 1


def test_ambiguous_or_missing_navigation_is_refused(tmp_path, capsys):
    _, paths, nav, _ = write_async(tmp_path)
    assert main(["register", *map(str, paths[:2]), "--out", str(tmp_path / "reg"), *FAST]) == 2
    assert "no navigation for ship A" in capsys.readouterr().err
    assert main(["register", *map(str, paths[:2]), *nav, *nav, "--out", str(tmp_path / "reg"), *FAST]) == 2
    assert "given twice" in capsys.readouterr().err


def test_async_run_with_checkpoint_reuses_its_pairing_and_knows_it_is_done(tmp_path, capsys):
    _, paths, nav, _ = write_async(tmp_path, seed=5)
    out, ckpt = tmp_path / "reg", tmp_path / "run.ckpt"
    args = [
        "register",
        *map(str, paths[:2]),
        *nav,
        "--clock-offset-b",
        "0.3",
        "--out",
        str(out),
        "--checkpoint",
        str(ckpt),
        "--checkpoint-every",
        "50",
        "--observability",
        "filter",
        *FAST,
    ]
    assert main(args) == 0
    first = (out / "estimates.csv").read_bytes()
    assert main(args) == 0
    assert "already complete" in capsys.readouterr().err
    ckpt.unlink()  # start over: the published pairing is reused, the results are the same
    assert main(args) == 0
    assert "reusing the pairing" in capsys.readouterr().err
    assert (out / "estimates.csv").read_bytes() == first
