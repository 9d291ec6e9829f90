"""Fleet tables as CSV/Parquet files: round trip, unit conversion and the cell checks."""

import numpy as np
import pandas as pd
import pytest

from registration.core.frames import ecef2geodetic, geodetic2ecef
from registration.fleet import fleet_scenario
from registration.fleet.files import read_fleet_tables, write_fleet_tables

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
