"""TTM -> plots: distance units, true and relative bearings, status, time field, talkers."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from registration.core.angles import wrap_angle
from registration.io.nmea import import_nmea
from tests.io.nmea import encode
from tests.io.nmea.bridgelog import PLATFORM, BridgeLogConfig, simulate_bridge_log
from tests.io.nmea.logs import LAT, LON, import_lines, navigation_lines, radar_sensors, rejected_lines

T0 = 43200.0


@pytest.mark.parametrize("unit, per_unit", [("N", 1852.0), ("K", 1000.0), ("S", 1609.344)])
def test_distance_units(tmp_path, unit, per_unit):
    lines = navigation_lines() + [encode.ttm(3, f"{5000.0 / per_unit:.7f}", 45.0, "R", unit, t=T0 + 2.5)]
    plots = import_lines(tmp_path, lines).plots
    assert plots.range_m.tolist() == pytest.approx([5000.0], abs=1e-3)
    assert plots.track.tolist() == ["3"] and plots.time_s.tolist() == [T0 + 2.5]


def test_true_bearings_become_deck_bearings_with_the_heading_then(tmp_path):
    lines = navigation_lines(heading=30.0)
    cases = [
        ("T", 100.0, 70.0),
        ("R", 100.0, 100.0),
        ("T", 10.0, -20.0),
        ("T", 200.0, 170.0),
        ("R", 270.0, -90.0),
        ("T", 210.0, 180.0),
    ]
    lines += [encode.ttm(k + 1, "2.00000", b, ref, t=T0 + 1.05 + k) for k, (ref, b, _) in enumerate(cases)]
    plots = import_lines(tmp_path, lines).plots
    assert plots.bearing_deg.to_numpy() == pytest.approx([q for *_, q in cases], abs=1e-6)


def test_true_bearing_across_north_interpolates_the_heading_the_short_way(tmp_path):
    lines = []
    for k in range(6):
        t = T0 + k
        lines += [
            encode.gga(t, LAT, LON),
            encode.pashr(t, 359.0, 0.0, 0.0),
            encode.pashr(t + 0.5, 1.0, 0.0, 0.0),
        ]
    lines += [
        encode.ttm(1, "2.00000", 90.0, "T", t=T0 + 2.25),
        encode.ttm(2, "2.00000", 90.0, "T", t=T0 + 2.75),
    ]
    plots = import_lines(tmp_path, lines, date="2024-05-01").plots
    # heading 0 deg halfway between 359 and 1 (not 180); 0 between 1 and the next 359
    assert plots.bearing_deg.to_numpy() == pytest.approx([90.0, 90.0], abs=1e-6)


def test_generated_mixed_references_and_units_give_the_measured_deck_bearings(tmp_path):
    log = simulate_bridge_log(
        BridgeLogConfig(
            seed=2,
            duration_s=90.0,
            n_vessels=5,
            n_ais=2,
            bearing_reference="mixed",
            distance_unit="mixed",
            heading_error_rad=np.radians(0.7),
        )
    )
    result = import_nmea(log.write(tmp_path / "mixed.nmea"), PLATFORM, log.sensors)
    p = result.plots.sort_values(["track", "time_s"]).reset_index(drop=True)
    t = log.plots.sort_values(["track", "time_reported"]).reset_index(drop=True)
    assert set(t.reference) == {"T", "R"} and set(t.unit) == {"N", "K", "S"}
    assert result.summary["plots"]["bearing_reference"] == t.reference.value_counts().to_dict()
    assert np.abs(p.range_m - t.range_measured).max() < 0.02
    # true bearings: less the heading, which $PASHR gives to 0.001 deg at 10 Hz (interpolated: 2e-4 deg)
    err = np.abs(wrap_angle(np.radians(p.bearing_deg) - t.bearing_measured))
    assert err[(t.reference == "R").to_numpy()].max() < np.radians(1e-4) and err.max() < np.radians(1e-3)


def test_status_lost_and_acquiring(tmp_path):
    lines = navigation_lines() + [
        encode.ttm(1, "2.0", 10.0, status=s, t=T0 + 2 + k) for k, s in enumerate("TLQX")
    ]
    result = import_lines(tmp_path, lines)
    n = len(navigation_lines())
    assert result.plots.track.tolist() == ["1"]
    assert rejected_lines(result, "ttm_lost") == [n + 2]
    assert rejected_lines(result, "ttm_acquiring") == [n + 3]
    assert rejected_lines(result, "ttm_status") == [n + 4]
    kept = import_lines(tmp_path, lines, keep_acquiring=True)
    assert kept.plots.time_s.tolist() == [T0 + 2, T0 + 4] and rejected_lines(kept, "ttm_acquiring") == []


def test_ttm_without_time_field_is_set_aside_never_timed(tmp_path):
    lines = navigation_lines() + [encode.ttm(1, "2.0", 10.0)]
    result = import_lines(tmp_path, lines)
    assert len(result.plots) == 0 and rejected_lines(result, "no_time") == [len(lines)]


def test_true_bearing_outside_the_heading_is_set_aside(tmp_path):
    lines = navigation_lines(n=5) + [
        encode.ttm(1, "2.0", 10.0, "T", t=T0 + 100.0),
        encode.ttm(2, "2.0", 10.0, "R", t=T0 + 100.0),
    ]
    result = import_lines(tmp_path, lines)
    assert rejected_lines(result, "ttm_no_heading") == [len(lines) - 1]
    assert result.plots.track.tolist() == ["2"]  # relative: kept; the engine checks it against the navigation


def test_talkers_name_the_sensors(tmp_path):
    sensors = pd.concat([radar_sensors(talker="RA"), radar_sensors(talker="rb").assign(sensor="NAV2")])
    lines = navigation_lines() + [
        encode.ttm(j + 1, "2.0", 10.0, t=T0 + 2, talker=k) for j, k in enumerate(("RA", "RB", "RC"))
    ]
    result = import_lines(tmp_path, lines, sensors=sensors)
    assert result.plots.sensor.tolist() == ["RADAR", "NAV2"]
    assert rejected_lines(result, "ttm_no_sensor") == [len(lines)]
    assert "'RC'" in result.rejected.reason.iloc[-1] and "talker" not in result.sensors.columns
    single = import_lines(tmp_path, lines)  # one sensor, no talker column: it is meant
    assert single.plots.sensor.tolist() == ["RADAR"] * 3


def test_a_second_ttm_of_a_track_at_one_time_is_set_aside(tmp_path):
    lines = (
        navigation_lines()
        + [encode.ttm(1, "2.0", 10.0, t=T0 + 2)] * 2
        + [encode.ttm(2, "2.0", 10.0, t=T0 + 2)]
    )
    result = import_lines(tmp_path, lines, keep_duplicates=True)  # the same TTM line twice
    assert result.plots.track.tolist() == ["1", "2"] and rejected_lines(result, "duplicate_time") == [
        len(lines) - 1
    ]
