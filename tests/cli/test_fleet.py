"""`registration fleet simulate` and `registration fleet register`: outputs, reproduction, errors, gate."""

import json
import shutil

import numpy as np
import pandas as pd
import pytest

from registration.cli import main

TABLES = ("plots", "navigation", "sensors", "platforms", "reference")
ESTIMATE_COLUMNS = ["object", "state", "unit", "estimate", "sigma", "status"]


@pytest.fixture(scope="module")
def simulated(tmp_path_factory):
    out = tmp_path_factory.mktemp("fleet") / "sim"
    assert main(["fleet", "simulate", "--out", str(out)]) == 0
    return out


def _register_args(folder, out, fmt="csv", extra=()):
    args = ["fleet", "register", "--out", str(out), "--no-plots", *extra]
    for name in TABLES:
        args += [f"--{name}", str(folder / f"{name}.{fmt}")]
    return args


def test_simulate_writes_tables_and_outputs(simulated):
    for name in (*TABLES, "estimates", "summary"):
        assert any(simulated.glob(f"{name}.*")), name
    for png in ("estimates.png", "map.png", "residuals.png"):
        assert (simulated / png).stat().st_size > 10_000
    est = pd.read_csv(simulated / "estimates.csv")
    assert list(est.columns) == [*ESTIMATE_COLUMNS, "truth"]
    assert set(est["state"]) == {
        "range_bias",
        "bearing_bias",
        "elevation_bias",
        "heading_error",
        "pitch_error",
        "roll_error",
    }
    assert set(est["unit"]) == {"m", "deg"}
    free = est[est["status"] != "fixed"]
    assert (np.abs(free["estimate"] - free["truth"]) < 4 * free["sigma"]).all()
    summary = json.loads((simulated / "summary.json").read_text())
    assert {"estimates", "observability", "chi_square", "consistency", "excluded", "inputs"} <= set(summary)
    assert summary["chi_square"]["consistent"] and summary["inputs"]["plots_used"] == 4725


def test_a_zero_prior_is_listed_fixed_with_sigma_0(simulated):
    est = pd.read_csv(simulated / "estimates.csv")
    site = est[est["object"] == "S"]
    assert (
        len(site) == 3
        and (site["status"] == "fixed").all()
        and (site["sigma"] == 0).all()
        and (site["estimate"] == 0).all()
    )


def test_register_reproduces_simulate_bit_for_bit(simulated, tmp_path, capsys):
    assert main(_register_args(simulated, tmp_path / "reg")) == 0
    assert "every state is observable" in capsys.readouterr().out
    got = pd.read_csv(tmp_path / "reg" / "estimates.csv")
    want = pd.read_csv(simulated / "estimates.csv").drop(columns="truth")
    pd.testing.assert_frame_equal(got, want, check_exact=True)
    assert not list((tmp_path / "reg").glob("*.png"))


def test_parquet_tables_register_to_the_same_estimates(simulated, tmp_path):
    assert (
        main(["fleet", "simulate", "--format", "parquet", "--no-plots", "--out", str(tmp_path / "sim")]) == 0
    )
    assert (tmp_path / "sim" / "plots.parquet").exists() and not (tmp_path / "sim" / "plots.csv").exists()
    assert main(_register_args(tmp_path / "sim", tmp_path / "reg", "parquet")) == 0
    got = pd.read_csv(tmp_path / "reg" / "estimates.csv")
    pd.testing.assert_frame_equal(
        got, pd.read_csv(simulated / "estimates.csv").drop(columns="truth"), check_exact=True
    )


def test_a_zero_bias_prior_in_the_sensors_file_fixes_that_bias(simulated, tmp_path):
    folder = tmp_path / "in"
    shutil.copytree(simulated, folder)
    sensors = pd.read_csv(folder / "sensors.csv")
    sensors["prior_range_bias_m"] = np.where(sensors["sensor"] == "S-2D", 0.0, np.nan)
    sensors.to_csv(folder / "sensors.csv", index=False)
    assert main(_register_args(folder, tmp_path / "reg", extra=["--allow-inconsistent"])) == 0
    est = pd.read_csv(tmp_path / "reg" / "estimates.csv").set_index(["object", "state"])
    row = est.loc[("S-2D", "range_bias")]
    assert row["status"] == "fixed" and row["sigma"] == 0 and row["estimate"] == 0


def _broken(simulated, tmp_path, name, edit):
    folder = tmp_path / "in"
    shutil.copytree(simulated, folder)
    frame = pd.read_csv(folder / f"{name}.csv", dtype={"sensor": str, "platform": str, "target": str})
    edited = edit(frame)
    (edited if isinstance(edited, pd.DataFrame) else frame).to_csv(folder / f"{name}.csv", index=False)
    return folder


@pytest.mark.parametrize(
    "name, edit, words",
    [
        (
            "plots",
            lambda f: f.__setitem__("bearing_deg", np.radians(f["bearing_deg"])),
            ["plots.csv", "row", "'bearing_deg'", "radians?"],
        ),
        ("sensors", lambda f: f.pop("platform"), ["sensors.csv", "missing column", "platform"]),
        (
            "plots",
            lambda f: f.__setitem__("sensor", np.where(f.index == 11, "X1", f["sensor"])),
            ["plots.csv", "row 11", "'sensor'", "unknown sensor 'X1'"],
        ),
    ],
)
def test_bad_tables_exit_2_naming_file_row_column(simulated, tmp_path, capsys, name, edit, words):
    folder = _broken(simulated, tmp_path, name, edit)
    assert main(_register_args(folder, tmp_path / "reg")) == 2
    err = capsys.readouterr().err
    assert err.startswith("registration fleet register: error:")
    for word in words:
        assert word in err, (word, err)


def test_gross_misfit_exits_3_after_writing_unless_allowed(simulated, tmp_path, capsys):
    folder = _broken(
        simulated,
        tmp_path,
        "sensors",
        lambda f: f.__setitem__("sigma_bearing_deg", f["sigma_bearing_deg"] / 10),
    )
    assert main(_register_args(folder, tmp_path / "reg")) == 3
    err = capsys.readouterr().err
    assert "grossly inconsistent" in err and "Likely causes" in err and "--allow-inconsistent" in err
    assert (tmp_path / "reg" / "estimates.csv").exists() and (tmp_path / "reg" / "summary.json").exists()
    assert main(_register_args(folder, tmp_path / "reg2", extra=["--allow-inconsistent"])) == 0


def test_fleet_needs_an_action_and_the_register_files(capsys):
    assert main(["fleet"]) == 2
    assert main(["fleet", "register", "--plots", "p.csv"]) == 2
    assert "--navigation" in capsys.readouterr().err


def test_online_method_writes_the_history_and_ends_near_the_batch(simulated, tmp_path, capsys):
    out = tmp_path / "online"
    assert main([*_register_args(simulated, out), "--method", "online"]) == 0
    text = capsys.readouterr().out
    assert "online filter: 15 epochs" in text and text.count(" epochs, ") == 1  # said once
    assert "consistency: mean squared normalised residual per degree of freedom at the final estimate" in text
    assert "normalised innovations (information on the filter's covariance, not the verdict)" in text
    online = pd.read_csv(out / "estimates.csv")
    batch = pd.read_csv(simulated / "estimates.csv")
    assert list(online.columns) == ESTIMATE_COLUMNS
    free = batch["status"] != "fixed"
    assert (np.abs(online["estimate"] - batch["estimate"])[free] < 0.5 * batch["sigma"][free]).all()
    assert (online["sigma"][~free] == 0).all() and (online["status"][~free] == "fixed").all()
    history = pd.read_csv(out / "history.csv")
    assert list(history.columns) == ["time_s", "object", "state", "unit", "estimate", "sigma"]
    last = history[history["time_s"] == history["time_s"].max()].reset_index(drop=True)
    np.testing.assert_allclose(last["estimate"], online["estimate"][free].to_numpy(), rtol=1e-12)
    summary = json.loads((out / "summary.json").read_text())
    assert summary["method"] == "online" and summary["consistency"]["status"] == "consistent"
    assert (
        summary["residuals_at_final_estimate"]["consistent"]
        and summary["innovations"]["status"] == "consistent"
    )
    assert summary["consistency"]["mean"] == pytest.approx(summary["residuals_at_final_estimate"]["mean"])


def test_online_method_plots(simulated, tmp_path):
    out = tmp_path / "online"
    args = [a for a in _register_args(simulated, out) if a != "--no-plots"]
    assert main([*args, "--method", "online"]) == 0
    for png in ("estimates.png", "map.png", "residuals.png"):
        assert (out / png).stat().st_size > 10_000


def _spoil_plots(frame):
    frame["range_m"] = frame["range_m"].astype(object)
    frame.loc[3, "range_m"] = "abc"
    frame.loc[7, "sensor"] = "X1"
    frame.loc[20, "bearing_deg"] = 400.0


def test_on_bad_row_skip_sets_rows_aside_and_registers_the_rest(simulated, tmp_path, capsys):
    folder = _broken(simulated, tmp_path, "plots", _spoil_plots)
    assert main(_register_args(folder, tmp_path / "stop")) == 2
    assert "row 3" in capsys.readouterr().err
    out = tmp_path / "skip"
    assert main(_register_args(folder, out, extra=["--on-bad-row", "skip"])) == 0
    assert "set aside 3 bad rows" in capsys.readouterr().out
    rejected = pd.read_csv(out / "rejected.csv")
    assert list(rejected.columns) == ["file", "row", "column", "reason_code", "reason"]
    assert list(rejected["row"]) == [3, 7, 20]
    assert list(rejected["reason_code"]) == ["non_numeric", "unknown_sensor", "out_of_range"]
    # the same as registering a file without those rows
    clean = _broken(simulated, tmp_path / "clean", "plots", lambda f: None)
    plots = pd.read_csv(clean / "plots.csv", dtype={"sensor": str, "target": str})
    plots.drop(index=[3, 7, 20]).to_csv(clean / "plots.csv", index=False)
    assert main(_register_args(clean, tmp_path / "clean_out")) == 0
    got, want = pd.read_csv(out / "estimates.csv"), pd.read_csv(tmp_path / "clean_out" / "estimates.csv")
    pd.testing.assert_frame_equal(got, want, check_exact=True)
    summary = json.loads((out / "summary.json").read_text())
    assert summary["inputs"]["rows_rejected"] == 3 and summary["inputs"]["on_bad_row"] == "skip"


def test_plots_without_target_ids_are_associated(simulated, tmp_path, capsys):
    truth = pd.read_csv(simulated / "plots.csv", dtype={"sensor": str, "target": str})
    folder = _broken(simulated, tmp_path, "plots", lambda f: f.pop("target"))
    out = tmp_path / "assoc"
    assert main([a for a in _register_args(folder, out) if "reference" not in a]) == 0
    assert "association:" in capsys.readouterr().out
    found = pd.read_csv(out / "associations.csv", dtype={"target": str, "sensor": str}, keep_default_na=False)
    # behaviour changed with the robust association: the join's distance and the reason a plot was left out
    assert list(found.columns) == ["row", "time_s", "sensor", "target", "join", "reason"] and len(
        found
    ) == len(truth)
    assert ((found["join"] == "") | (found["target"] != "")).all()
    assert ((found["target"] != "") | (found["reason"] != "")).all()
    labelled = found["target"] != ""
    assert labelled.mean() > 0.98
    # each label found is (almost) one true target: majority share over the labelled plots
    pairs = pd.DataFrame({"found": found["target"][labelled], "true": truth["target"][labelled]})
    majority = pairs.groupby("found")["true"].agg(lambda s: s.value_counts().iloc[0]).sum()
    assert majority / labelled.sum() > 0.995
    est = pd.read_csv(out / "estimates.csv")
    want = pd.read_csv(simulated / "estimates.csv")
    free = want["status"] != "fixed"
    assert (np.abs(est["estimate"] - want["truth"])[free] < 4 * est["sigma"][free]).all()
    summary = json.loads((out / "summary.json").read_text())
    assert summary["inputs"]["association"]["converged"]


def test_plots_without_target_ids_run_online_on_the_associations_labels(simulated, tmp_path, capsys):
    """Behaviour changed with the robust association: --method online no longer refuses plots without
    target ids; the batch associates them first (it says so) and the filter runs on its labels."""
    folder = _broken(simulated, tmp_path, "plots", lambda f: f.pop("target"))
    args = [a for a in _register_args(folder, tmp_path / "o") if "reference" not in a]
    assert main([*args, "--method", "online"]) == 0
    out = capsys.readouterr().out
    assert "the association is a batch method" in out and "online filter:" in out
    assert (tmp_path / "o" / "history.csv").exists() and (tmp_path / "o" / "associations.csv").exists()


def test_a_run_replaces_the_earlier_runs_outputs_whole(simulated, tmp_path, capsys):
    """--out never holds a mixture of two runs: the online run's history.csv and PNGs go when a
    batch run with --no-plots follows; a failed run leaves the earlier outputs as they were."""
    out = tmp_path / "out"
    args = [a for a in _register_args(simulated, out) if a != "--no-plots"]
    assert main([*args, "--method", "online"]) == 0
    assert (out / "history.csv").exists() and (out / "map.png").exists()
    assert main(_register_args(simulated, out)) == 0
    assert sorted(p.name for p in out.iterdir()) == ["estimates.csv", "summary.json"]
    before = (out / "estimates.csv").read_bytes()
    broken = _broken(simulated, tmp_path, "plots", lambda f: f.__setitem__("sensor", "X1"))
    assert main(_register_args(broken, out)) == 2
    assert sorted(p.name for p in out.iterdir()) == ["estimates.csv", "summary.json"]
    assert (out / "estimates.csv").read_bytes() == before
    capsys.readouterr()


def test_registering_into_the_simulated_folder_keeps_its_tables(simulated, tmp_path):
    folder = tmp_path / "sim"
    shutil.copytree(simulated, folder)
    assert main(_register_args(folder, folder)) == 0
    for name in TABLES:
        assert (folder / f"{name}.csv").exists(), name
    assert not (folder / "estimates.png").exists()  # --no-plots: the simulate run's PNGs are replaced


# --- the findings of a first user of `fleet register` ---


def _cut_line(folder, name, row, keep):
    """Keep the first ``keep`` fields of data row ``row`` (from 0; -1: the last) of FOLDER/NAME.csv."""
    path = folder / f"{name}.csv"
    lines = path.read_text().splitlines()
    row = len(lines) - 2 if row < 0 else row
    lines[row + 1] = ",".join(lines[row + 1].split(",")[:keep])
    path.write_text("\n".join(lines) + "\n")
    return row


def test_a_truncated_plots_line_stops_or_is_set_aside(simulated, tmp_path, capsys):
    """Before: a last line cut to 5 fields and a middle line cut to 4 gave exit 0 and "N plots used of N"."""
    folder = _broken(simulated, tmp_path, "plots", lambda f: None)
    last, middle = _cut_line(folder, "plots", -1, 5), _cut_line(folder, "plots", 40, 4)
    assert main(_register_args(folder, tmp_path / "stop")) == 2
    err = capsys.readouterr().err
    assert (
        f"plots.csv: row {middle}, column 'bearing_deg': line {middle + 2} has 4 fields, the header 6" in err
    ), err
    assert main(_register_args(folder, tmp_path / "skip", extra=["--on-bad-row", "skip"])) == 0
    assert "set aside 2 bad rows (in rejected.csv)" in capsys.readouterr().out
    rejected = pd.read_csv(tmp_path / "skip" / "rejected.csv")
    assert list(zip(rejected["row"], rejected["column"], rejected["reason_code"])) == [
        (middle, "bearing_deg", "short_row"),
        (last, "elevation_deg", "short_row"),
    ]
    summary = json.loads((tmp_path / "skip" / "summary.json").read_text())
    assert summary["inputs"]["plots_used"] == summary["inputs"]["plots_read"] - 2


def test_navigation_of_every_ship_registers_with_a_note(simulated, tmp_path, capsys):
    """Before: navigation.csv: row R: platform 'X' is not in the platforms/sensors tables (exit 2)."""
    folder = tmp_path / "in"
    shutil.copytree(simulated, folder)
    nav = pd.read_csv(folder / "navigation.csv", dtype={"platform": str})
    pd.concat([nav, nav[nav["platform"] == "A"].assign(platform="X")]).to_csv(
        folder / "navigation.csv", index=False
    )
    assert main(_register_args(folder, tmp_path / "reg")) == 0
    out = capsys.readouterr().out
    assert "note: " in out and "navigation.csv: platform(s) ['X'] carry no sensor" in out
    got = pd.read_csv(tmp_path / "reg" / "estimates.csv")
    pd.testing.assert_frame_equal(
        got, pd.read_csv(simulated / "estimates.csv").drop(columns="truth"), check_exact=True
    )
    summary = json.loads((tmp_path / "reg" / "summary.json").read_text())
    assert any("['X'] carry no sensor" in n for n in summary["inputs"]["notes"])


@pytest.mark.parametrize(
    "name, edit, words",
    [
        (
            "navigation",
            lambda f: [f.__setitem__(c, np.radians(f[c])) for c in ("heading_deg", "pitch_deg", "roll_deg")],
            ["navigation.csv", "column 'heading_deg'", "radians?", "pitch_deg and roll_deg are in degrees"],
        ),
        (
            "sensors",
            lambda f: f.pop("sigma_elevation_deg"),
            [
                "sensors.csv: no column 'sigma_elevation_deg'",
                "plots.csv has elevation values",
                "give their sigma_elevation_deg",
            ],
        ),
        ("plots", lambda f: f.iloc[0:0], ["plots.csv: no data rows (the file holds only a header)"]),
    ],
)
def test_findings_exit_2_naming_the_file_at_fault(simulated, tmp_path, capsys, name, edit, words):
    """Before: attitude in radians ended in the consistency gate (exit 3); a missing sensors column was
    blamed on plots.csv row 0 ("a elevation"); an empty plots file said "every target was excluded: "."""
    folder = _broken(simulated, tmp_path, name, edit)
    assert main(_register_args(folder, tmp_path / "reg")) == 2
    err = capsys.readouterr().err
    for word in words:
        assert word in err, (word, err)
