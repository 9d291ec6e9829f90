"""Time of day on the time axis: the midnight rollover, the date argument, the capture date,
files in sequence."""

from __future__ import annotations

import datetime as dt

import numpy as np
import pytest

from registration.io.asterix import import_asterix
from registration.io.asterix.tables.timeofday import Unwrapper, midnight_utc
from tests.io.asterix.encode import cat021_record, cat048_record, encode_recording
from tests.io.asterix.scenario import DATE, sites_frame

DAY = 86400.0


def _messages(t0: float, t1: float) -> list:
    out = []
    for t in np.arange(t0, t1, 0.5):
        out.append((t, 48, 10, 1, cat048_record("1.32", 10, 1, t, 2000, 100, address=0xABCDEF)))
        out.append(
            (
                t + 0.25,
                21,
                20,
                1,
                cat021_record(
                    "2.6",
                    20,
                    1,
                    t + 0.25,
                    address=0xABCDEF,
                    lat_deg=45.0,
                    lon_deg=5.0,
                    height_ft_raw=1000,
                    nacp=9,
                ),
            )
        )
    return out


@pytest.fixture(scope="module")
def midnight():
    """A recording from 23:59:50 to 00:00:10 on DATE -> DATE + 1."""
    return encode_recording(_messages(DAY - 10.0, DAY + 10.0), DATE, non_udp=False)


def _import(tmp_path, data: bytes, name: str, **kwargs):
    path = tmp_path / name
    path.write_bytes(data)
    return import_asterix(path, sites_frame(), **kwargs)


@pytest.mark.parametrize("form", ["raw", "pcap"])
def test_rollover_at_midnight_adds_a_day(tmp_path, midnight, form):
    data = midnight.raw() if form == "raw" else midnight.pcap()
    result = _import(tmp_path, data, f"m.{form}")
    t = result.plots["time_s"].to_numpy()
    np.testing.assert_allclose(t, np.arange(DAY - 10.0, DAY + 10.0, 0.5), atol=1 / 256)
    assert np.all(np.diff(result.reference["time_s"]) > 0) and result.reference["time_s"].max() > DAY
    assert result.summary["time"]["reference_date"] == (None if form == "raw" else "2024-05-01")


def test_a_capture_after_midnight_counts_from_the_date_given(tmp_path):
    rec = encode_recording(_messages(DAY + 5.0, DAY + 8.0), DATE, non_udp=False)
    own_day = _import(tmp_path, rec.pcap(), "a.pcap")
    assert own_day.summary["time"]["reference_date"] == "2024-05-02"
    assert own_day.plots["time_s"].min() == pytest.approx(5.0)
    given = _import(tmp_path, rec.pcap(), "a.pcap", date=DATE)
    assert given.plots["time_s"].min() == pytest.approx(DAY + 5.0)  # the packets say it is the next day
    assert given.summary["time"]["files_placed_by_packet_times"] == 1
    raw = _import(tmp_path, rec.raw(), "a.ast", date=DATE)
    assert raw.plots["time_s"].min() == pytest.approx(5.0)  # no packet times: the first record is on the date
    far = _import(tmp_path, rec.pcap(), "a.pcap", date=dt.date(2020, 1, 1))
    assert far.plots["time_s"].min() == pytest.approx(5.0)  # packets years away are not used
    assert far.summary["time"]["files_placed_by_packet_times"] == 0
    with pytest.raises(ValueError, match="date: 'yesterday' is not a date"):
        _import(tmp_path, rec.raw(), "a.ast", date="yesterday")


def test_files_in_sequence_carry_the_day(tmp_path):
    first = encode_recording(_messages(DAY - 4.0, DAY), DATE).raw()
    second = encode_recording(_messages(DAY, DAY + 4.0), DATE).raw()
    (tmp_path / "1.ast").write_bytes(first)
    (tmp_path / "2.ast").write_bytes(second)
    result = import_asterix([tmp_path / "1.ast", tmp_path / "2.ast"], sites_frame())
    np.testing.assert_allclose(result.plots["time_s"], np.arange(DAY - 4.0, DAY + 4.0, 0.5), atol=1 / 256)


def test_unwrapper_rules():
    u = Unwrapper(None)
    t = u.file_times(np.array([86399.9, 0.1, 86399.95, np.nan, 0.2, 43000.0]), np.full(6, np.nan))
    np.testing.assert_allclose(t[[0, 1, 2, 4, 5]], [86399.9, DAY + 0.1, 86399.95, DAY + 0.2, DAY + 43000.0])
    assert np.isnan(t[3])
    # a capture time of the day before the reference date places the file there
    u = Unwrapper(DATE)
    t = u.file_times(np.array([86000.0]), np.array([midnight_utc(DATE) - 400.0]))
    assert t[0] == 86000.0 - DAY
