"""Fleet tables as CSV/Parquet files: round trip, unit conversion and the cell checks."""

import numpy as np
import pandas as pd
import pytest

from registration.core.frames import ecef2geodetic, geodetic2ecef
from registration.fleet import fleet_scenario
from registration.fleet.files import read_fleet_tables
from registration.fleet.files_write import write_fleet_tables

NAMES = ("plots", "navigation", "sensors", "platforms", "reference")


@pytest.fixture(scope="module")
def scenario():
    return fleet_scenario(0, duration_s=60.0)


def _write(scenario, folder, fmt="csv"):
    s = scenario
    write_fleet_tables(folder, s.plots, s.navigation, s.sensors, s.platforms, s.references, fmt)
    return {n: folder / f"{n}.{fmt}" for n in NAMES}


def _read(paths):
    return read_fleet_tables(paths["plots"], paths["navigation"], paths["sensors"], paths["platforms"], paths["reference"])


@pytest.mark.parametrize("fmt", ["csv", "parquet"])
def test_round_trip_gives_the_tables_back(scenario, tmp_path, fmt):
    paths = _write(scenario, tmp_path, fmt)
    assert list(pd.read_csv(paths["plots"]).columns if fmt == "csv" else pd.read_parquet(paths["plots"]).columns) == [
        "time_s", "sensor", "target", "range_m", "bearing_deg", "elevation_deg"]
    tables = _read(paths)
    for name in ("plots", "navigation", "sensors"):
        want, got = getattr(scenario, name), getattr(tables, name)
        for key, v in want.items():
            if v.dtype.kind in "US":
                assert (got[key] == v).all(), key
            else:
                np.testing.assert_allclose(got[key], v, rtol=1e-15, atol=1e-15, err_msg=key)
    assert np.isinf(tables.platforms["prior_heading"][:3]).all() and (tables.platforms["prior_heading"][3] == 0)
    p = np.stack([tables.references[c] for c in ("lat", "lon", "alt")])
    np.testing.assert_allclose(geodetic2ecef(*p), np.stack([scenario.references[c] for c in "xyz"], axis=1), atol=1e-6)
    problem = tables.problem()
    assert problem.n_plots == scenario.plots["time"].size


def test_ecef2geodetic_inverts_geodetic2ecef():
    lat = np.radians([-89.0, -30.0, 0.0, 36.0, 89.9])
    lon = np.radians([-179.0, -10.0, 0.0, 14.5, 170.0])
    alt = np.array([-100.0, 0.0, 5e3, 12e3, 4e5])
    got = ecef2geodetic(geodetic2ecef(lat, lon, alt))
    np.testing.assert_allclose(got[0], lat, atol=1e-12)
    np.testing.assert_allclose(got[1], lon, atol=1e-12)
    np.testing.assert_allclose(got[2], alt, atol=1e-6)


def test_zero_prior_fixes_the_state(scenario, tmp_path):
    paths = _write(scenario, tmp_path)
    sensors = pd.read_csv(paths["sensors"])
    sensors["prior_range_bias_m"] = [0.0] + [np.nan] * (len(sensors) - 1)
    sensors.to_csv(paths["sensors"], index=False)
    layout = _read(paths).problem().layout
    assert layout.prior_sigma[layout.index("A-3D:range_bias")] == 0
    assert np.isinf(layout.prior_sigma[layout.index("B-3D:range_bias")])


def _edit(paths, name, edit):
    frame = pd.read_csv(paths[name], dtype={"sensor": str, "platform": str, "target": str})
    edit(frame)
    frame.to_csv(paths[name], index=False)


def _set(column, row, value):
    def edit(frame):
        frame[column] = frame[column].astype(object)
        frame.loc[row, column] = value
    return edit


@pytest.mark.parametrize("name, edit, words", [
    ("plots", lambda f: f.pop("time_s"), ["plots.csv", "missing column", "time_s"]),
    ("plots", lambda f: f.insert(0, "bearing", f.pop("bearing_deg")), ["plots.csv", "unknown column", "bearing"]),
    ("plots", lambda f: f.__setitem__("bearing_deg", np.radians(f["bearing_deg"])),
     ["plots.csv", "row", "'bearing_deg'", "radians?"]),
    ("navigation", lambda f: (f.__setitem__("lat_deg", np.radians(f["lat_deg"])), f.__setitem__("lon_deg", np.radians(f["lon_deg"]))),
     ["navigation.csv", "row", "'lat_deg'", "radians?"]),
    ("plots", _set("sensor", 7, "Z-9"), ["plots.csv", "row 7", "'sensor'", "unknown sensor 'Z-9'", "sensors.csv"]),
    ("sensors", _set("platform", 2, "Q"), ["sensors.csv", "row 2", "'platform'", "unknown platform 'Q'"]),
    ("plots", _set("range_m", 4, "far"), ["plots.csv", "row 4", "'range_m'", "'far' is not a number (m)"]),
    ("plots", _set("elevation_deg", 5, 120.0), ["plots.csv", "row 5", "'elevation_deg'", "deg"]),
    ("navigation", _set("alt_m", 3, np.nan), ["navigation.csv", "row 3", "'alt_m'", "empty", "(m)"]),
    ("sensors", _set("sigma_bearing_deg", 1, 0.0), ["sensors.csv", "row 1", "'sigma_bearing_deg'", "outside (0"]),
    ("plots", lambda f: f.loc.__setitem__((0, ["range_m", "bearing_deg", "elevation_deg"]), np.nan),
     ["plots.csv", "row 0", "no measured channel"]),
])
def test_bad_cells_name_file_row_column_and_unit(scenario, tmp_path, name, edit, words):
    paths = _write(scenario, tmp_path)
    _edit(paths, name, edit)
    with pytest.raises(ValueError) as err:
        _read(paths).problem()
    for word in words:
        assert word in str(err.value), (word, str(err.value))


def test_a_missing_file_is_named(tmp_path, scenario):
    paths = _write(scenario, tmp_path)
    paths["sensors"].unlink()
    with pytest.raises(ValueError, match="sensors.csv: no such file"):
        _read(paths)


# --- on_bad_row="skip": bad rows of the plots and reference files set aside with a reason code ---

def _frame(path):
    return pd.read_csv(path, dtype={"sensor": str, "platform": str, "target": str})


def _first_row(plots, sensor):
    """A row of ``sensor`` away from the start and end of the file, after row 50."""
    return int(plots.index[(plots["sensor"] == sensor) & (plots.index > 50)][0])


def _spoil_plots(plots):
    """Several kinds of bad rows; returns {row: (column, code)} as the reader should report them."""
    plots = plots.astype({c: object for c in ("time_s", "range_m", "bearing_deg", "elevation_deg")})
    c2d, a3d, esm = _first_row(plots, "C-2D"), _first_row(plots, "A-3D") + 7, _first_row(plots, "A-ESM")
    edits = {
        3: ("range_m", "far", "non_numeric"),
        10: ("elevation_deg", 120.0, "out_of_range"),
        20: ("sensor", "Z-9", "unknown_sensor"),
        30: ("range_m", -5.0, "non_positive_range"),
        44: ("time_s", np.nan, "non_finite"),
        47: ("target", np.nan, "empty_id"),
        c2d: ("elevation_deg", 1.0, "unmeasured_channel"),
        a3d: ("time_s", 75.0, "outside_navigation"),
    }
    for row, (column, value, _) in edits.items():
        plots.loc[row, column] = value
    plots.loc[esm, ["bearing_deg", "elevation_deg"]] = np.nan
    want = {row: (column, code) for row, (column, _, code) in edits.items()}
    want[esm] = ("range_m", "no_channel")
    return plots, want


@pytest.fixture
def spoiled(scenario, tmp_path):
    """Files with bad plots rows and one bad reference row, and the same files without those rows."""
    bad_dir, clean_dir = tmp_path / "bad", tmp_path / "clean"
    bad_dir.mkdir(), clean_dir.mkdir()
    paths, clean = _write(scenario, bad_dir), _write(scenario, clean_dir)
    plots, want = _spoil_plots(_frame(paths["plots"]))
    plots.to_csv(paths["plots"], index=False)
    _frame(clean["plots"]).drop(index=list(want)).to_csv(clean["plots"], index=False)
    ref = _frame(paths["reference"]).astype({"lat_deg": object})
    ref.loc[5, "lat_deg"] = "north"
    ref.to_csv(paths["reference"], index=False)
    _frame(clean["reference"]).drop(index=[5]).to_csv(clean["reference"], index=False)
    return paths, clean, want


def test_skip_mode_sets_bad_rows_aside_with_their_reason(spoiled):
    from registration.fleet.rejects import FLEET_REASON_CODES
    from registration.recorded.rowcheck import REASON_CODES

    paths, _, want = spoiled
    first = min(want)
    with pytest.raises(ValueError, match=rf"plots.csv: row {first}, column '{want[first][0]}': "):
        _read(paths)  # stop: the earliest bad row, whichever column is wrong
    tables = read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row="skip")
    got = {r.row: (r.column, r.code) for r in tables.rejected if r.file == str(paths["plots"])}
    assert got == want
    refs = [r for r in tables.rejected if r.file == str(paths["reference"])]
    assert [(r.row, r.column, r.code) for r in refs] == [(5, "lat_deg", "non_numeric")]
    assert set(REASON_CODES) <= set(FLEET_REASON_CODES) and {r.code for r in tables.rejected} <= set(FLEET_REASON_CODES)
    n_plots = len(_frame(paths["plots"]))
    assert tables.rows()["plots"] == n_plots - len(want) and tables.rows_read()["plots"] == n_plots
    frame = tables.rejected_frame()
    assert list(frame.columns) == ["file", "row", "column", "reason_code", "reason"] and len(frame) == len(want) + 1
    assert "'Z-9'" in frame.set_index("row").loc[20, "reason"]


def test_skipped_tables_register_as_the_file_without_the_bad_rows(spoiled):
    from registration.fleet import BatchOptions, solve_batch

    paths, clean, want = spoiled
    skipped = read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row="skip").problem()
    reference = read_fleet_tables(*(clean[n] for n in NAMES), on_bad_row="skip").problem()
    kept = np.setdiff1d(np.arange(skipped.n_input_plots), list(want))
    np.testing.assert_array_equal(skipped.row, kept[reference.row])  # file rows of the plots used
    assert skipped.n_input_plots == reference.n_input_plots + len(want)
    options = BatchOptions(window_s=20.0)
    a, b = solve_batch(skipped, options), solve_batch(reference, options)
    for name in ("estimate", "covariance", "sigma"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)
    np.testing.assert_array_equal(a.residuals[skipped.row], b.residuals[reference.row])
    assert np.isnan(a.residuals[list(want)]).all()


def test_skip_mode_on_good_files_sets_nothing_aside(scenario, tmp_path):
    paths = _write(scenario, tmp_path)
    tables = read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row="skip")
    assert tables.rejected == [] and tables.rows() == _read(paths).rows()
    assert list(tables.rejected_frame().columns) == ["file", "row", "column", "reason_code", "reason"]
    assert tables.rejected_frame().empty
    with pytest.raises(ValueError, match="on_bad_row"):
        read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row="ignore")


def test_every_plot_row_bad_is_a_clear_error(scenario, tmp_path):
    from registration.fleet.rejects import NoValidPlotsError

    paths = _write(scenario, tmp_path)
    plots = _frame(paths["plots"])
    n = len(plots)
    plots["range_m"], plots["sensor"] = "far", ["Z-9"] + list(plots["sensor"][1:])
    plots.to_csv(paths["plots"], index=False)
    with pytest.raises(NoValidPlotsError) as err:
        read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row="skip")
    text = str(err.value)
    assert f"plots.csv: no valid rows to register: all {n} rows rejected ({n} non_numeric)" in text, text
    assert "row 0, column 'range_m'" in text
    assert len(err.value.rejected) == n and len(err.value.rejected_frame()) == n


@pytest.mark.parametrize("name, column, row", [("navigation", "alt_m", 3), ("sensors", "sigma_bearing_deg", 1)])
def test_a_bad_row_of_the_defining_files_still_stops_in_skip_mode(scenario, tmp_path, name, column, row):
    paths = _write(scenario, tmp_path)
    _edit(paths, name, _set(column, row, "high"))
    with pytest.raises(ValueError, match=rf"{name}.csv: row {row}, column '{column}': 'high' is not a number"):
        read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row="skip")


def test_skip_mode_sets_aside_the_reference_of_a_target_left_without_plots(scenario, tmp_path):
    paths = _write(scenario, tmp_path)
    plots = _frame(paths["plots"]).astype({"range_m": object})
    ref_target = str(_frame(paths["reference"])["target"][0])
    rows = plots.index[plots["target"] == ref_target]
    plots.loc[rows, "range_m"] = "far"
    plots.loc[rows, ["bearing_deg", "elevation_deg"]] = np.nan
    plots.to_csv(paths["plots"], index=False)
    tables = read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row="skip")
    codes = {r.code for r in tables.rejected if r.file == str(paths["reference"])}
    assert codes == {"unknown_target"} and tables.rows()["reference"] == 0
    assert tables.problem().references.time.size == 0
