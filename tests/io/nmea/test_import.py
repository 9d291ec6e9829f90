"""The simulated bridge log imported: every table against the truth the generator encoded."""

from __future__ import annotations

import numpy as np
import pytest

from registration.core.angles import wrap_angle
from registration.io.nmea import import_nmea
from tests.io.nmea.bridgelog import OWN_MMSI, PLATFORM


def test_navigation_rows_at_the_attitude_rate_with_interpolated_positions(bridge):
    log, _, result = bridge
    nav = result.navigation
    assert list(nav.columns) == [
        "time_s",
        "platform",
        "lat_deg",
        "lon_deg",
        "alt_m",
        "heading_deg",
        "pitch_deg",
        "roll_deg",
    ]
    assert np.allclose(np.diff(nav.time_s), 0.1)  # 10 Hz
    # the last 0.9 s of $PASHR lie after the last GGA: set aside, never extrapolated
    assert len(nav) == 6000 - 9 and (result.rejected["code"] == "outside_positions").sum() == 9
    truth = log.truth.own(nav.time_s.to_numpy())
    east = (np.radians(nav.lon_deg) - truth["lon"]) * 6.4e6 * np.cos(truth["lat"])
    north = (np.radians(nav.lat_deg) - truth["lat"]) * 6.4e6
    assert (
        np.abs(east).max() < 0.01 and np.abs(north).max() < 0.01
    )  # straight course: linear interpolation exact
    assert np.allclose(nav.alt_m, 30.0 + 42.0)  # MSL altitude + geoid separation
    assert np.abs(wrap_angle(np.radians(nav.heading_deg) - truth["heading"])).max() < np.radians(0.001)
    # $PASHR signs are the package's: roll starboard down, pitch bow up
    assert np.abs(np.radians(nav.roll_deg) - truth["roll"]).max() < np.radians(0.001)
    assert np.abs(np.radians(nav.pitch_deg) - truth["pitch"]).max() < np.radians(0.001)
    assert (nav.platform == "OWN").all()


def test_plots_are_the_measured_ranges_deck_bearings_and_radar_times(bridge):
    log, _, result = bridge
    plots, truth = result.plots, log.plots
    assert list(plots.columns) == ["time_s", "sensor", "track", "range_m", "bearing_deg"]
    assert len(plots) == len(truth)
    p = plots.sort_values(["track", "time_s"]).reset_index(drop=True)
    t = truth.sort_values(["track", "time_reported"]).reset_index(drop=True)
    assert (p.track == t.track).all() and (p.sensor == "RADAR").all()
    assert np.abs(p.time_s - t.time_reported).max() < 1e-6  # the radar's clock, offset included
    assert np.abs(p.range_m - t.range_measured).max() < 0.02  # 1e-5 NM in the sentence
    assert np.abs(wrap_angle(np.radians(p.bearing_deg) - t.bearing_measured)).max() < np.radians(1e-4)
    assert p.bearing_deg.between(-180, 180).all()
    # the measured bias shows: bearing - true bearing averages the simulated bias
    d = wrap_angle(np.radians(p.bearing_deg) - t.bearing_true).mean()
    assert d == pytest.approx(
        log.config.bearing_bias_rad, abs=3 * log.config.sigma_bearing_rad / np.sqrt(len(p))
    )


def test_reference_positions_times_and_sigmas(bridge):
    log, _, result = bridge
    ref, rep = result.reference, log.reports
    assert list(ref.columns) == ["time_s", "target", "lat_deg", "lon_deg", "alt_m", "sigma_m", "sigma_up_m"]
    assert len(ref) == len(rep) and OWN_MMSI not in set(ref.target)
    r = ref.sort_values(["target", "time_s"], kind="stable").reset_index(drop=True)
    t = (
        rep.assign(target=rep.mmsi.astype(str))
        .sort_values(["target", "time_true"], kind="stable")
        .reset_index(drop=True)
    )
    assert (r.target == t.target).all()
    # AIS positions in 1/10000 minute (1.7e-6 deg)
    assert np.abs(r.lat_deg - np.degrees(t.lat_reported)).max() < 2e-6
    assert np.abs(r.lon_deg - np.degrees(t.lon_reported)).max() < 2e-6
    timed = (t.second < 60).to_numpy()
    assert 0 < (~timed).sum() < 0.2 * len(t)
    # the report's second within the minute of its reception: exactly the position's time
    assert np.array_equal(r.time_s[timed], t.time_true[timed])
    # without a second: the reception time (the tag block's whole second)
    assert np.array_equal(r.time_s[~timed], np.floor(t.time_received[~timed]))
    assert np.allclose(r.alt_m, 42.0)
    v = t.speed.to_numpy()
    pos = np.where(t.accuracy, 5.0, 10.0)
    expected = np.where(timed, np.hypot(pos, v / np.sqrt(12.0)), np.hypot(pos, v * 2.0))
    assert np.allclose(r.sigma_m, expected, rtol=0.02)  # speed over ground to 0.1 knot
    assert np.isinf(r.sigma_up_m).all()  # AIS gives no height: the vessels are surface targets instead
    surface = result.targets.set_index("target")
    assert set(surface.index) == set(r.target) and np.allclose(surface.surface_alt_m, 42.0)
    assert (surface.sigma_surface_m == 10.0).all()  # whatever height the radar sees: AisSigmas.height_m


def test_sensors_platforms_and_summary(bridge):
    log, path, result = bridge
    assert "talker" not in result.sensors.columns and list(result.sensors.sensor) == ["RADAR"]
    assert result.platforms.to_dict("records") == [
        {"platform": "OWN", "prior_heading_deg": np.nan, "prior_pitch_deg": np.nan, "prior_roll_deg": np.nan}
    ] or (result.platforms.platform.tolist() == ["OWN"] and result.platforms.iloc[0, 1:].isna().all())
    s = result.summary
    assert s["sentences"]["TTM"] == {"RA": len(log.plots)} and s["sentences"]["PASHR"] == {"-": 6000}
    assert s["navigation"]["position"] == "GGA (GP)" and s["navigation"]["attitude"] == "PASHR"
    assert s["date"] == {"origin": "2024-05-01", "source": "ZDA/RMC"}
    assert s["time_span"]["navigation"]["start_utc"] == "2024-05-01T12:00:00Z"
    names = {v["mmsi"]: v["name"] for v in s["ais"]["vessels"]}
    assert names == {v.mmsi: v.name for v in log.truth.vessels if v.mmsi}
    assert s["ais"]["own_ship"] == {
        "mmsi": [OWN_MMSI],
        "messages": {"1": sum("!AIVDO" in x for x in log.lines)},
    }
    assert s["plots"]["per_sensor"]["RADAR"]["tracks"] == 14
    assert s["rejected"] == {"lines": 9, "by_reason": {"outside_positions": 9}}
    import json

    json.dumps(s)  # JSON-able


def test_a_log_cut_into_two_files_imports_as_one(bridge, tmp_path):
    log, path, whole = bridge
    cut = 7001
    first, second = tmp_path / "part1.nmea", tmp_path / "part2.nmea"
    first.write_text("\n".join(log.lines[:cut]) + "\n")
    second.write_text("\n".join(log.lines[cut:]) + "\n")
    parts = import_nmea([first, second], PLATFORM, log.sensors, progress=True)
    for name in ("navigation", "plots", "reference"):
        assert parts.tables[name].equals(whole.tables[name]), name
    # the rejected lines name their file and count lines within it
    assert set(parts.rejected.file) == {str(second)}
    assert parts.rejected.line.tolist() == [k - cut for k in whole.rejected.line]
    assert parts.summary["files"] == [str(first), str(second)] and parts.summary["lines"] == len(log.lines)
