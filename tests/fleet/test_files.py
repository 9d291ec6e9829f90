"""Fleet tables as CSV/Parquet files: round trip, unit conversion and the cell checks."""

import re

import numpy as np
import pandas as pd
import pytest

from registration.core.frames import ecef2geodetic, geodetic2ecef
from registration.fleet import build_problem, fleet_scenario
from registration.io.fleet.reading.read import read_fleet_tables
from registration.io.fleet.write import write_fleet_tables

NAMES = ("plots", "navigation", "sensors", "platforms", "reference")


@pytest.fixture(scope="module")
def scenario():
    return fleet_scenario(0, duration_s=60.0)


def _write(scenario, folder, fmt="csv"):
    s = scenario
    write_fleet_tables(folder, s.plots, s.navigation, s.sensors, s.platforms, s.references, fmt)
    return {n: folder / f"{n}.{fmt}" for n in NAMES}


def _read(paths):
    return read_fleet_tables(
        paths["plots"], paths["navigation"], paths["sensors"], paths["platforms"], paths["reference"]
    )


@pytest.mark.parametrize("fmt", ["csv", "parquet"])
def test_round_trip_gives_the_tables_back(scenario, tmp_path, fmt):
    paths = _write(scenario, tmp_path, fmt)
    assert list(
        pd.read_csv(paths["plots"]).columns if fmt == "csv" else pd.read_parquet(paths["plots"]).columns
    ) == ["time_s", "sensor", "target", "range_m", "bearing_deg", "elevation_deg"]
    tables = _read(paths)
    for name in ("plots", "navigation", "sensors"):
        want, got = getattr(scenario, name), getattr(tables, name)
        for key, v in want.items():
            if v.dtype.kind in "US":
                assert (got[key] == v).all(), key
            else:
                np.testing.assert_allclose(got[key], v, rtol=1e-15, atol=1e-15, err_msg=key)
    assert np.isinf(tables.platforms["prior_heading"][:3]).all() and (
        tables.platforms["prior_heading"][3] == 0
    )
    p = np.stack([tables.references[c] for c in ("lat", "lon", "alt")])
    np.testing.assert_allclose(
        geodetic2ecef(*p), np.stack([scenario.references[c] for c in "xyz"], axis=1), atol=1e-6
    )
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


@pytest.mark.parametrize(
    "name, edit, words",
    [
        ("plots", lambda f: f.pop("time_s"), ["plots.csv", "missing column", "time_s"]),
        (
            "plots",
            lambda f: f.insert(0, "bearing", f.pop("bearing_deg")),
            ["plots.csv", "unknown column", "bearing"],
        ),
        (
            "plots",
            lambda f: f.__setitem__("bearing_deg", np.radians(f["bearing_deg"])),
            ["plots.csv", "row", "'bearing_deg'", "radians?"],
        ),
        (
            "navigation",
            lambda f: (
                f.__setitem__("lat_deg", np.radians(f["lat_deg"])),
                f.__setitem__("lon_deg", np.radians(f["lon_deg"])),
            ),
            ["navigation.csv", "row", "'lat_deg'", "radians?"],
        ),
        (
            "plots",
            _set("sensor", 7, "Z-9"),
            ["plots.csv", "row 7", "'sensor'", "unknown sensor 'Z-9'", "sensors.csv"],
        ),
        ("sensors", _set("platform", 2, "Q"), ["sensors.csv", "row 2", "'platform'", "unknown platform 'Q'"]),
        (
            "plots",
            _set("range_m", 4, "far"),
            ["plots.csv", "row 4", "'range_m'", "'far' is not a number (m)"],
        ),
        ("plots", _set("elevation_deg", 5, 120.0), ["plots.csv", "row 5", "'elevation_deg'", "deg"]),
        ("navigation", _set("alt_m", 3, np.nan), ["navigation.csv", "row 3", "'alt_m'", "empty", "(m)"]),
        (
            "sensors",
            _set("sigma_bearing_deg", 1, 0.0),
            ["sensors.csv", "row 1", "'sigma_bearing_deg'", "outside (0"],
        ),
        (
            "plots",
            lambda f: f.loc.__setitem__((0, ["range_m", "bearing_deg", "elevation_deg"]), np.nan),
            ["plots.csv", "row 0", "no measured channel"],
        ),
    ],
)
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
        47: (
            "sensor",
            np.nan,
            "empty_id",
        ),  # an empty target cell is no id now (associated), a sensor's is bad
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
    from registration.io.files.tablefile import REASON_CODES
    from registration.io.fleet.reading.rejects import FLEET_REASON_CODES

    paths, _, want = spoiled
    first = min(want)
    with pytest.raises(ValueError, match=rf"plots.csv: row {first}, column '{want[first][0]}': "):
        _read(paths)  # stop: the earliest bad row, whichever column is wrong
    tables = read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row="skip")
    got = {r.row: (r.column, r.code) for r in tables.rejected if r.file == str(paths["plots"])}
    assert got == want
    refs = [r for r in tables.rejected if r.file == str(paths["reference"])]
    assert [(r.row, r.column, r.code) for r in refs] == [(5, "lat_deg", "non_numeric")]
    assert set(REASON_CODES) <= set(FLEET_REASON_CODES) and {r.code for r in tables.rejected} <= set(
        FLEET_REASON_CODES
    )
    n_plots = len(_frame(paths["plots"]))
    assert tables.rows()["plots"] == n_plots - len(want) and tables.rows_read()["plots"] == n_plots
    frame = tables.rejected_frame()
    assert (
        list(frame.columns) == ["file", "row", "column", "reason_code", "reason"]
        and len(frame) == len(want) + 1
    )
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
    from registration.io.fleet.reading.rejects import NoValidPlotsError

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


@pytest.mark.parametrize(
    "name, column, row", [("navigation", "alt_m", 3), ("sensors", "sigma_bearing_deg", 1)]
)
def test_a_bad_row_of_the_defining_files_still_stops_in_skip_mode(scenario, tmp_path, name, column, row):
    paths = _write(scenario, tmp_path)
    _edit(paths, name, _set(column, row, "high"))
    with pytest.raises(
        ValueError, match=rf"{name}.csv: row {row}, column '{column}': 'high' is not a number"
    ):
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


# --- a CSV line with fewer or more fields than the header is a bad row, not a row of empty cells ---


def _lines(path):
    return path.read_text().splitlines()


def _put_lines(path, lines):
    path.write_text("\n".join(lines) + "\n")


def _cut(line: str, keep: int) -> str:
    """The first ``keep`` fields of a CSV line (the files' ids are quoted but hold no comma)."""
    return ",".join(line.split(",")[:keep])


@pytest.mark.parametrize(
    "where, edit, column, code, fields",
    [
        ("last", lambda line: _cut(line, 5), "elevation_deg", "short_row", 5),  # a half-written last line
        ("middle", lambda line: _cut(line, 4), "bearing_deg", "short_row", 4),
        ("first", lambda line: line + ",7.5", "*", "long_row", 7),  # pandas would truncate it with a warning
        ("middle", lambda line: line + ",7.5,8", "*", "long_row", 8),  # pandas would refuse the whole file
    ],
)
def test_a_line_with_another_number_of_fields_is_a_bad_row(
    scenario, tmp_path, where, edit, column, code, fields
):
    """Before: a line cut to 5 of 6 fields read as a plot without elevation ("not measured"), exit 0."""
    paths = _write(scenario, tmp_path)
    lines = _lines(paths["plots"])
    row = {"first": 0, "middle": 60, "last": len(lines) - 2}[where]
    lines[row + 1] = edit(lines[row + 1])
    _put_lines(paths["plots"], lines)
    with pytest.raises(
        ValueError,
        match=rf"plots.csv: row {row}, column '{re.escape(column)}': line {row + 2} has "
        rf"{fields} fields, the header 6",
    ):
        _read(paths)
    tables = read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row="skip")
    assert [(r.row, r.column, r.code) for r in tables.rejected] == [(row, column, code)]
    assert tables.rows()["plots"] == len(lines) - 2 and tables.rows_read()["plots"] == len(lines) - 1
    del lines[row + 1]
    _put_lines(paths["plots"], lines)
    clean = _read(paths)
    for key, v in clean.plots.items():  # nothing shifted, nothing read as empty: the file without the line
        np.testing.assert_array_equal(tables.plots[key], v, err_msg=key)


@pytest.mark.parametrize("mode", ["stop", "skip"])
def test_a_cut_line_of_the_navigation_stops_in_both_modes(scenario, tmp_path, mode):
    paths = _write(scenario, tmp_path)
    lines = _lines(paths["navigation"])
    lines[-1] = _cut(lines[-1], 6)
    _put_lines(paths["navigation"], lines)
    with pytest.raises(
        ValueError,
        match=rf"navigation.csv: row {len(lines) - 2}, column 'pitch_deg': line "
        rf"{len(lines)} has 6 fields, the header 8",
    ):
        read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row=mode)


def test_an_empty_plots_file_is_named(scenario, tmp_path):
    """Before: "no plots to register (every target was excluded: )"."""
    paths = _write(scenario, tmp_path)
    paths["plots"].write_text(_lines(paths["plots"])[0] + "\n")
    for mode in ("stop", "skip"):
        with pytest.raises(ValueError, match=r"plots.csv: no data rows \(the file holds only a header\)"):
            read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row=mode)
    with pytest.raises(ValueError, match="plots: the table has no rows"):
        build_problem({k: v[:0] for k, v in scenario.plots.items()}, scenario.sensors, scenario.navigation)


# --- navigation of platforms that carry no sensor: ignored, with a note ---


def _with_extra_ship(scenario):
    """The scenario's navigation with a ship 'X' (a copy of A's rows) that carries no sensor."""
    nav = scenario.navigation
    extra = {k: np.asarray(v)[nav["platform"] == "A"] for k, v in nav.items()}
    extra["platform"] = np.full(extra["platform"].size, "X")
    return {k: np.concatenate([np.asarray(v), extra[k]]) for k, v in nav.items()}, int(extra["platform"].size)


def test_navigation_of_a_platform_without_sensors_is_ignored_with_a_note(scenario, tmp_path):
    """Before: navigation.csv: row R: platform 'X' is not in the platforms/sensors tables."""
    s = scenario
    nav, n_extra = _with_extra_ship(s)
    paths = _write(scenario, tmp_path)
    write_fleet_tables(tmp_path, s.plots, nav, s.sensors, s.platforms, s.references)
    frame = _frame(paths["navigation"]).astype({"alt_m": object})
    frame.loc[frame.index[frame["platform"] == "X"][3], "alt_m"] = "high"  # a bad cell in an ignored row
    frame.to_csv(paths["navigation"], index=False)
    tables = _read(paths)
    assert len(tables.notes) == 1 and "navigation.csv: platform(s) ['X'] carry no sensor" in tables.notes[0]
    assert f"their {n_extra} navigation rows are ignored" in tables.notes[0]
    problem = tables.problem()
    assert problem.notes == tuple(tables.notes)
    (tmp_path / "without").mkdir()
    without = _read(_write(scenario, tmp_path / "without")).problem()
    np.testing.assert_array_equal(problem.nav, without.nav)
    # the library tables too: a note, no error
    direct = build_problem(s.plots, s.sensors, nav, s.platforms, s.references)
    assert len(direct.notes) == 1 and "platform(s) ['X'] carry no sensor" in direct.notes[0]
    assert "note: navigation: platform(s) ['X']" in "\n".join(direct.lines())


def test_a_navigation_error_names_the_file_row_with_ignored_rows_before_it(scenario, tmp_path):
    s = scenario
    nav, n_extra = _with_extra_ship(s)
    order = np.r_[
        np.arange(nav["time"].size - n_extra, nav["time"].size), np.arange(nav["time"].size - n_extra)
    ]
    nav = {k: v[order] for k, v in nav.items()}  # X's rows first
    write_fleet_tables(tmp_path, s.plots, nav, s.sensors, s.platforms, s.references)
    paths = {n: tmp_path / f"{n}.csv" for n in NAMES}
    frame = _frame(paths["navigation"])
    good = frame.copy()
    frame = frame.astype({"lat_deg": object})
    frame.loc[n_extra + 5, "lat_deg"] = "north"
    frame.to_csv(paths["navigation"], index=False)
    with pytest.raises(ValueError, match=rf"navigation.csv: row {n_extra + 5}, column 'lat_deg': 'north'"):
        _read(paths)
    good.loc[n_extra + 5, "time_s"] = good.loc[
        n_extra + 4, "time_s"
    ]  # a check of build_problem's, in both modes
    good.to_csv(paths["navigation"], index=False)
    for mode in ("stop", "skip"):
        with pytest.raises(
            ValueError,
            match=rf"navigation.csv: row {n_extra + 4}, column 'time_s': time .* does not increase",
        ):
            read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row=mode).problem()


# --- radians in the attitude columns, and angle sigmas that look like radians ---


def _track(heading_deg, speed=8.0, course_deg=None, n=600, dt=1.0, pitch=None, roll=None):
    """File columns of one platform sailing a course (deg; default: its heading) at ``speed`` m/s."""
    t = np.arange(n) * dt
    heading = np.broadcast_to(np.asarray(heading_deg, dtype=float), t.shape)
    course = np.radians(heading if course_deg is None else np.broadcast_to(course_deg, t.shape))
    step = speed * dt
    north, east = np.cumsum(step * np.cos(course)), np.cumsum(step * np.sin(course))
    lat = 36.0 + np.degrees(north / 6.371e6)
    lon = 14.0 + np.degrees(east / (6.371e6 * np.cos(np.radians(36.0))))
    zero = np.zeros(n)
    return {
        "time_s": t,
        "lat_deg": lat,
        "lon_deg": lon,
        "heading_deg": np.array(heading),
        "pitch_deg": zero if pitch is None else pitch,
        "roll_deg": zero if roll is None else roll,
    }


@pytest.mark.parametrize(
    "columns, refused",
    [
        (_track(60.0 + np.zeros(600)), False),  # degrees, a steady course
        (_track(np.radians(60.0) + np.zeros(600), course_deg=60.0), True),  # radians of the same ship
        (
            _track(np.radians(np.linspace(10, 300, 600)), course_deg=np.linspace(10, 300, 600)),
            True,
        ),  # radians, turning
        (
            _track(2.0 + np.zeros(600)),
            False,
        ),  # degrees, heading north within +-2 pi: matches its track as degrees
        (
            _track(np.radians(2.0) + np.zeros(600), course_deg=2.0),
            False,
        ),  # radians near north: undecidable, not refused
        (_track(3.0 + np.zeros(600), course_deg=20.0), False),  # degrees with 17 deg of drift
        (_track(np.zeros(600), speed=0.0), False),  # a site that does not move
    ],
)
def test_headings_in_radians_are_refused_only_when_the_track_says_so(columns, refused):
    from registration.io.fleet.reading.checks import attitude_check

    platform = np.full(columns["time_s"].size, "A")
    if refused:
        with pytest.raises(
            ValueError, match=r"nav.csv: row \d+, column 'heading_deg': .* platform 'A' .*radians\?"
        ):
            attitude_check("nav.csv", columns, platform)
    else:
        assert attitude_check("nav.csv", columns, platform) == []


def test_pitch_and_roll_that_look_like_radians_are_noted_not_refused():
    from registration.io.fleet.reading.checks import attitude_check

    wave = np.sin(np.arange(600) / 8.0)
    platform = np.full(600, "A")
    assert (
        attitude_check("nav.csv", _track(60.0, pitch=1.5 * wave, roll=4.0 * wave), platform) == []
    )  # degrees
    notes = attitude_check(
        "nav.csv", _track(60.0, pitch=np.radians(1.5) * wave, roll=np.radians(4.0) * wave), platform
    )
    assert len(notes) == 1 and "pitch_deg and roll_deg of platform 'A'" in notes[0] and "radians?" in notes[0]
    assert attitude_check("nav.csv", _track(60.0), platform) == []  # level: zeros are not noted


def test_a_navigation_file_with_attitude_in_radians_is_refused_up_front(scenario, tmp_path):
    """Before: the run went on for seconds and ended in the consistency gate (exit 3)."""
    paths = _write(scenario, tmp_path)
    frame = _frame(paths["navigation"])
    for column in ("heading_deg", "pitch_deg", "roll_deg"):
        frame[column] = np.radians(frame[column])
    frame.to_csv(paths["navigation"], index=False)
    with pytest.raises(
        ValueError,
        match=r"navigation.csv: row \d+, column 'heading_deg': .*radians\? heading_deg, "
        r"pitch_deg and roll_deg are in degrees",
    ):
        read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row="skip")


def test_angle_sigmas_that_look_like_radians_are_noted(scenario, tmp_path):
    paths = _write(scenario, tmp_path)
    assert _read(paths).notes == []
    sensors = _frame(paths["sensors"])
    sensors["sigma_bearing_deg"] = np.radians(sensors["sigma_bearing_deg"])
    sensors.to_csv(paths["sensors"], index=False)
    notes = _read(paths).notes
    assert (
        len(notes) == 1 and "sensors.csv: sigma_bearing_deg below 0.02 deg for sensor(s) 'A-3D'" in notes[0]
    )
    assert "radians?" in notes[0]


# --- a channel with plot values but no sigma column in the sensors file is the sensors file's problem ---


@pytest.mark.parametrize("mode", ["stop", "skip"])
def test_a_missing_sigma_column_is_blamed_on_the_sensors_file(scenario, tmp_path, mode):
    """Before: plots.csv: row 0 ... has a elevation value but does not measure elevation."""
    paths = _write(scenario, tmp_path)
    _frame(paths["sensors"]).drop(columns="sigma_elevation_deg").to_csv(paths["sensors"], index=False)
    with pytest.raises(
        ValueError,
        match=r"sensors.csv: no column 'sigma_elevation_deg', but .*plots.csv has elevation "
        r"values .* for sensor\(s\) \['A-3D', 'A-ESM', 'B-3D', 'C-3D'\] .*give their "
        r"sigma_elevation_deg, or leave the plots' elevation_deg cells empty",
    ):
        read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row=mode)
    s = scenario
    sensors = {k: v for k, v in s.sensors.items() if k != "sigma_elevation"}
    with pytest.raises(
        ValueError, match=r"sensors: no sigma_elevation column, but the plots have elevation values"
    ):
        build_problem(s.plots, sensors, s.navigation, s.platforms, s.references)


def test_a_value_in_an_unmeasured_channel_reads_in_good_english(scenario, tmp_path):
    paths = _write(scenario, tmp_path)
    plots = _frame(paths["plots"])
    row = _first_row(plots, "C-2D")
    plots.loc[row, "elevation_deg"] = 1.0
    plots.to_csv(paths["plots"], index=False)
    with pytest.raises(
        ValueError,
        match=rf"plots.csv: row {row}, column 'elevation_deg': sensor 'C-2D' has an "
        r"elevation value but does not measure elevation \(its sigma_elevation",
    ):
        _read(paths)
