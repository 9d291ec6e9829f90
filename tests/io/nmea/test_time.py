"""One time axis: seconds since midnight UTC of the log's first day (or of ``date``), across midnight."""

from __future__ import annotations

import datetime as dt

import numpy as np

from registration.io.nmea import import_nmea
from tests.io.nmea import encode
from tests.io.nmea.bridgelog import PLATFORM, BridgeLogConfig, simulate_bridge_log
from tests.io.nmea.logs import DAY, LAT, LON, import_lines, navigation_lines, rejected_lines

MIDNIGHT = dt.datetime.combine(DAY, dt.time(0), tzinfo=dt.timezone.utc).timestamp()


def test_midnight_rollover_keeps_one_time_axis(tmp_path):
    start = dt.datetime(2024, 5, 1, 23, 58, 0, tzinfo=dt.timezone.utc)
    log = simulate_bridge_log(
        BridgeLogConfig(seed=4, start_utc=start, duration_s=240.0, n_vessels=4, n_ais=3)
    )
    result = import_nmea(log.write(tmp_path / "midnight.nmea"), PLATFORM, log.sensors)
    nav = result.navigation.time_s.to_numpy()
    assert np.all(np.diff(nav) > 0) and nav[0] == 86280.0 and nav[-1] > 86400.0 + 110
    plots = np.sort(result.plots.time_s.to_numpy())
    assert np.allclose(plots, np.sort(log.plots.time_reported), atol=1e-6)  # the truth counts past 86400 s
    assert (plots > 86400.0).sum() > 0.4 * plots.size
    ref = result.reference.time_s.to_numpy()
    rep = log.reports
    expected = np.where(rep.second < 60, rep.time_true, np.floor(rep.time_received))
    assert ref.max() > 86400.0 + 100 and np.array_equal(np.sort(ref), np.sort(expected))
    s = result.summary
    assert s["date"]["origin"] == "2024-05-01"
    assert s["time_span"]["navigation"]["end_utc"].startswith("2024-05-02T00:01:")
    assert result.rejected["code"].isin(["outside_positions"]).all()


def test_rollover_without_dates_from_the_times_of_day(tmp_path):
    lines = navigation_lines(t0=86400.0 - 5, n=10)
    lines = [x for x in lines if "ZDA" not in x]
    result = import_lines(tmp_path, lines, date="2024-05-01")
    t = result.navigation.time_s.to_numpy()
    assert t[0] == 86395.0 and np.all(np.diff(t) > 0) and t[-1] > 86400.0
    assert result.summary["date"] == {"origin": "2024-05-01", "source": "date argument"}


def test_date_argument_sets_the_origin(tmp_path):
    lines = navigation_lines(t0=43200.0, n=5)
    result = import_lines(tmp_path, lines, date=dt.date(2024, 4, 30))
    assert result.navigation.time_s.iloc[0] == 86400.0 + 43200.0  # the log (ZDA) says the next day
    assert any("date argument" in n for n in result.summary["notes"])


def test_date_from_reception_times_without_zda_rmc_or_argument(tmp_path):
    lines = [x for x in navigation_lines(t0=43200.0, n=5) if "ZDA" not in x]
    report = encode.ais(
        {"msg_type": 1, "mmsi": 244000001, "lat": 43.1, "lon": 7.6, "second": 2, "speed": 10.0}
    )
    lines.append(encode.tag(MIDNIGHT + 43202.7) + report[0])
    result = import_lines(tmp_path, lines)
    assert result.summary["date"] == {"origin": "2024-05-01", "source": "reception times"}
    assert result.reference.time_s.tolist() == [43202.0]


def test_without_any_date_times_count_from_the_first_midnight_and_ais_is_set_aside(tmp_path):
    lines = [x for x in navigation_lines(t0=43200.0, n=5) if "ZDA" not in x]
    report = encode.ais({"msg_type": 1, "mmsi": 244000001, "lat": 43.1, "lon": 7.6, "second": 2})
    lines.append(report[0])
    result = import_lines(tmp_path, lines)
    assert result.navigation.time_s.iloc[0] == 43200.0
    assert result.summary["date"] == {"origin": None, "source": "none"}
    assert rejected_lines(result, "ais_no_time") == [len(lines)]
    assert len(result.reference) == 0


def test_heading_without_time_field_takes_the_previous_navigation_time(tmp_path):
    lines = []
    for k in range(6):
        t = 43200.0 + k
        lines += [encode.gga(t, LAT, LON), encode.zda(t, DAY), encode.hdt(10.0 * k)]
    result = import_lines(tmp_path, lines)
    nav = result.navigation
    assert nav.time_s.tolist() == [43200.0 + k for k in range(6)]
    assert np.allclose(nav.heading_deg, [10.0 * k for k in range(6)])
    assert (nav.roll_deg == 0).all() and (nav.pitch_deg == 0).all()
    assert any("no $PASHR" in n for n in result.summary["notes"])
    assert result.summary["navigation"]["attitude"] == "HDT (HE)"
