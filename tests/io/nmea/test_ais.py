"""AIS -> reference positions: the time of a report, its sigma, own ship, names, reception stamps."""

from __future__ import annotations

import datetime as dt
import math

import numpy as np
import pytest

from registration.io.nmea import AisSigmas, import_nmea
from tests.io.nmea import encode
from tests.io.nmea.bridgelog import PLATFORM, BridgeLogConfig, simulate_bridge_log
from tests.io.nmea.logs import DAY, import_lines, navigation_lines, rejected_lines

MIDNIGHT = dt.datetime.combine(DAY, dt.time(0), tzinfo=dt.timezone.utc).timestamp()
T0 = 43200.0
KNOT = 1852.0 / 3600.0


def _report(received_s: float, mmsi: int = 244000001, own: bool = False, **fields) -> list[str]:
    data = {"msg_type": 1, "mmsi": mmsi, "lat": 43.1, "lon": 7.6, "speed": 10.0, "accuracy": True, **fields}
    return [encode.tag(MIDNIGHT + received_s) + s for s in encode.ais(data, own=own)]


def test_report_time_is_its_second_within_the_minute_of_reception(tmp_path):
    lines = navigation_lines(t0=T0 - 5, n=70)
    lines += _report(T0 + 60.4, second=59) + _report(T0 + 3.2, second=2) + _report(T0 + 59.9, second=58)
    lines += _report(T0 + 61.0, second=60)  # not available: the reception time
    result = import_lines(tmp_path, lines)
    assert result.reference.time_s.tolist() == [T0 + 59, T0 + 2, T0 + 58, T0 + 61]
    s = result.reference.sigma_m.to_numpy()
    assert s[:3] == pytest.approx([math.hypot(5.0, 10 * KNOT / math.sqrt(12))] * 3)
    assert s[3] == pytest.approx(math.hypot(5.0, 10 * KNOT * 2.0))


def test_message_27_class_b_and_accuracy_sigmas(tmp_path):
    lines = navigation_lines(n=8)
    lines += _report(T0 + 2.5, msg_type=27, lat=43.2, lon=7.7, speed=12, accuracy=False)
    lines += _report(T0 + 3.5, mmsi=244000002, msg_type=18, second=3, speed=102.3, accuracy=False)
    lines += _report(
        T0 + 4.5, mmsi=244000003, msg_type=19, second=4, shipname="NINETEEN", speed=0.0, accuracy=True
    )
    result = import_lines(tmp_path, lines)
    ref = result.reference
    assert ref.target.tolist() == ["244000001", "244000002", "244000003"]
    assert ref.time_s.tolist() == [T0 + 2, T0 + 3, T0 + 4]  # msg 27: the (whole-second) reception time
    assert ref.lat_deg.iloc[0] == pytest.approx(43.2, abs=1e-9)  # 1/10 minute
    expected = [
        math.hypot(math.hypot(10.0, 185.2 / math.sqrt(12)), 12 * KNOT * 2.0),
        math.hypot(10.0, 15.0 / math.sqrt(12)),
        5.0,
    ]  # speed not available: 15 m/s assumed
    assert ref.sigma_m.tolist() == pytest.approx(expected)
    assert ref.sigma_up_m.tolist() == [math.inf] * 3  # AIS gives no height
    targets = result.targets.set_index("target")  # the vessels move on the sea: surface targets
    assert (
        targets.sigma_surface_m.tolist() == [10.0] * 3 and (targets.surface_alt_m == ref.alt_m.iloc[0]).all()
    )
    assert targets.loc["244000003", "name"] == "NINETEEN"
    vessels = {v["mmsi"]: v for v in result.summary["ais"]["vessels"]}
    assert vessels["244000003"]["name"] == "NINETEEN" and vessels["244000001"]["class"] == "long range"
    custom = import_lines(
        tmp_path, lines, ais_sigmas=AisSigmas(high_accuracy_m=1.0, latency_s=0.0, height_m=4.0)
    )
    assert custom.reference.sigma_m.iloc[2] == pytest.approx(1.0)
    assert custom.targets.sigma_surface_m.tolist() == [4.0] * 3
    for bad in (float("nan"), 0.0):
        with pytest.raises(ValueError, match="AisSigmas.height_m"):
            AisSigmas(height_m=bad)
    with pytest.raises(ValueError, match="AisSigmas.latency_s"):
        AisSigmas(latency_s=-1.0)


def test_own_ship_names_and_duplicates(tmp_path):
    lines = navigation_lines(n=8)
    lines += _report(T0 + 1.2, mmsi=244999999, own=True, second=1)  # !AIVDO: counted, not a reference
    lines += _report(T0 + 2.2, mmsi=244999999, second=2)  # the own ship heard as !AIVDM: set aside
    lines += _report(T0 + 3.2, second=3) + _report(T0 + 3.6, second=3)  # the same report twice
    lines += [
        encode.tag(MIDNIGHT + T0 + 4) + x
        for x in encode.ais({"msg_type": 24, "mmsi": 244000001, "partno": 0, "shipname": "BRAVO"})
    ]
    result = import_lines(tmp_path, lines, keep_duplicates=True)  # the same line twice: an AIS duplicate
    n = len(navigation_lines(n=8))
    assert result.reference.target.tolist() == ["244000001"]
    assert rejected_lines(result, "ais_own_ship") == [n + 2]
    assert rejected_lines(result, "ais_duplicate") == [n + 4]
    ais = result.summary["ais"]
    assert ais["own_ship"] == {"mmsi": ["244999999"], "messages": {"1": 1}}
    assert [v["name"] for v in ais["vessels"]] == ["BRAVO"]


def test_position_not_available_and_no_reception_time(tmp_path):
    lines = navigation_lines(n=5) + _report(T0 + 1.5, lat=91.0, lon=181.0, second=1)
    lines += encode.ais({"msg_type": 1, "mmsi": 244000001, "lat": 43.1, "lon": 7.6, "second": 2})
    result = import_lines(tmp_path, lines)
    assert rejected_lines(result, "ais_no_position") == [len(lines) - 1]
    assert rejected_lines(result, "ais_no_time") == [len(lines)]


def test_tag_block_milliseconds(tmp_path):
    lines = navigation_lines(n=5)
    body = encode.ais({"msg_type": 1, "mmsi": 244000001, "lat": 43.1, "lon": 7.6, "second": 60})[0]
    block = encode.checksummed(
        "c:" + str(int(round((MIDNIGHT + T0 + 2.345) * 1000))), ""
    )  # NMEA 4.10 allows ms
    lines.append("\\" + block + "\\" + body)
    result = import_lines(tmp_path, lines)
    assert result.reference.time_s.tolist() == pytest.approx([T0 + 2.345])


@pytest.mark.parametrize("stamp", ["prefix-iso", "prefix-unix"])
def test_logger_prefixes_give_the_reception_time(tmp_path, stamp):
    log = simulate_bridge_log(
        BridgeLogConfig(seed=5, duration_s=60.0, n_vessels=3, n_ais=3, reception_stamp=stamp)
    )
    assert not log.lines[0].startswith("$")
    result = import_nmea(log.write(tmp_path / "prefixed.nmea"), PLATFORM, log.sensors)
    rep = log.reports
    expected = np.where(rep.second < 60, rep.time_true, np.round(rep.time_received, 3))
    assert np.allclose(np.sort(result.reference.time_s), np.sort(expected), atol=1e-6)
    assert len(result.plots) == len(log.plots) and len(result.rejected) == 9
