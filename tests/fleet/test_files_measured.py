"""The fleet reader on measured columns (issue 31, 7): NaN in range_m, bearing_deg or elevation_deg
is a bad row (an empty cell is "not measured"); a measured column a sensor's sigma asks for but
the plots file lacks gets a note naming it; sigmas and priors beyond float64 are refused (issue 32,
3)."""

import re

import pandas as pd
import pytest

from registration.fleet import fleet_scenario
from registration.io.fleet.reading.read import read_fleet_tables
from registration.io.fleet.schema import HELD
from registration.io.fleet.write import write_fleet_tables

NAMES = ("plots", "navigation", "sensors", "platforms", "reference")


@pytest.fixture(scope="module")
def scenario():
    return fleet_scenario(0, duration_s=60.0)


@pytest.fixture
def paths(scenario, tmp_path):
    s = scenario
    write_fleet_tables(tmp_path, s.plots, s.navigation, s.sensors, s.platforms, s.references, "csv")
    return {n: tmp_path / f"{n}.csv" for n in NAMES}


def _read(paths, **kw):
    return read_fleet_tables(*(paths[n] for n in NAMES), **kw)


def _cells(path, edits):
    frame = pd.read_csv(path, dtype=str, keep_default_na=False)
    for row, column, value in edits:
        frame.loc[row, column] = value
    frame.to_csv(path, index=False)


@pytest.mark.parametrize("column", ["range_m", "bearing_deg", "elevation_deg"])
@pytest.mark.parametrize("text", ["nan", "NaN", "NA", "null"])
def test_nan_in_a_measured_column_is_a_bad_row(paths, column, text):
    """Before: taken as "not measured"."""
    _cells(paths["plots"], [(4, column, text)])
    with pytest.raises(
        ValueError, match=rf"plots.csv: row 4, column '{column}': '{text}' is not a measurement"
    ):
        _read(paths)
    tables = _read(paths, on_bad_row="skip")
    assert [(r.row, r.column, r.code) for r in tables.rejected] == [(4, column, "non_finite")]


def test_an_empty_measured_cell_is_still_not_measured(paths):
    plots = pd.read_csv(paths["plots"], dtype=str, keep_default_na=False)
    assert (plots["range_m"] == "").any()  # the ESM and 2D sensors' plots
    assert not _read(paths).rejected


def test_a_missing_measured_column_gets_a_note(paths):
    """Before: exit 0 with the bearing biases undetermined and no note."""
    plots = pd.read_csv(paths["plots"], dtype=str, keep_default_na=False)
    plots.drop(columns=["bearing_deg"]).to_csv(paths["plots"], index=False)
    notes = [n for n in _read(paths).notes if "no column 'bearing_deg'" in n]
    assert len(notes) == 1 and "sigma_bearing_deg" in notes[0] and "A-3D" in notes[0]
    assert "bearing biases stay undetermined" in notes[0]


def test_no_note_when_the_columns_are_there(paths):
    assert not [n for n in _read(paths).notes if "no column" in n]


@pytest.mark.parametrize(
    "name, column, value",
    [
        ("sensors", "sigma_range_m", "1e-300"),
        ("sensors", "prior_range_bias_m", "1e308"),
        ("sensors", "prior_bearing_bias_deg", "1e-16"),
        ("platforms", "prior_heading_deg", "1e300"),
        ("reference", "sigma_m", "1e-300"),
        ("reference", "sigma_up_m", "1e300"),
    ],
)
def test_values_beyond_float64_are_refused_naming_file_row_column_unit(paths, name, column, value):
    frame = pd.read_csv(paths[name], dtype=str, keep_default_na=False)
    if column not in frame:
        frame[column] = ""
    frame.to_csv(paths[name], index=False)
    _cells(paths[name], [(0, column, value)])
    unit = column.rsplit("_", 1)[1]
    with pytest.raises(ValueError) as err:
        _read(paths)
    text = str(err.value)
    assert text.startswith(f"{paths[name]}: row 0, column {column!r}: ")
    assert re.search("cannot be held: .*" + re.escape(f"[{HELD[0]:g}, {HELD[1]:g}] {unit}"), text), text


@pytest.mark.parametrize("value", ["0", "inf", "1e-15", "1e15", ""])
def test_a_prior_of_0_inf_or_within_the_limits_is_taken(paths, value):
    frame = pd.read_csv(paths["sensors"], dtype=str, keep_default_na=False)
    frame["prior_time_bias_s"] = value
    frame.to_csv(paths["sensors"], index=False)
    assert _read(paths).sensors["prior_time_bias"].size == len(frame)
