"""The reader splits fields itself (vectorised per sentence type); pynmea2, parsing each line on its
own, must read the same values from the same sentences."""

from __future__ import annotations

import datetime as dt

import numpy as np
import pynmea2
import pytest

from registration.io.files.ledger import RejectedLedger
from registration.io.nmea.attitude import read_headings, read_pashr
from registration.io.nmea.errors import LEDGER_COLUMNS
from registration.io.nmea.fixes import EPOCH_ORDINAL, read_fixes
from registration.io.nmea.lines import read_log
from tests.io.nmea import encode


def _seconds(t: dt.time) -> float:
    return t.hour * 3600 + t.minute * 60 + t.second + t.microsecond * 1e-6


@pytest.fixture(scope="module")
def random_log(tmp_path_factory):
    """Sentences of random values in every hemisphere and at any time of day, encoded by pynmea2."""
    rng = np.random.default_rng(7)
    n = 400
    lat = np.radians(rng.uniform(-89.9, 89.9, n))
    lon = np.radians(rng.uniform(-179.9, 179.9, n))
    t = rng.uniform(0, 86399.99, n)
    days = [dt.date(2000, 1, 1) + dt.timedelta(days=int(d)) for d in rng.integers(0, 20000, n)]
    lines = []
    for k in range(n):
        lines += [
            encode.gga(
                t[k],
                lat[k],
                lon[k],
                alt_msl=float(rng.uniform(-50, 500)),
                geoid=f"{rng.uniform(-100, 80):.2f}",
            ),
            encode.rmc(t[k], lat[k], lon[k], days[k]),
            encode.gns(t[k], lat[k], lon[k]),
            encode.zda(t[k], days[k]),
            encode.hdt(float(rng.uniform(0, 360))),
            encode.pashr(
                t[k], float(rng.uniform(0, 360)), float(rng.uniform(-30, 30)), float(rng.uniform(-20, 20))
            ),
        ]
    path = tmp_path_factory.mktemp("fast") / "random.nmea"
    path.write_text("\n".join(lines) + "\n")
    rejections = RejectedLedger(LEDGER_COLUMNS, [str(path)])
    return lines, read_log([path], rejections), rejections


def _parsed(lines: list[str], kind: str) -> list:
    return [pynmea2.parse(x) for x in lines if x[3:6] == kind or (kind == "PASHR" and x.startswith("$PASHR"))]


def test_positions_and_dates_as_pynmea2_reads_them(random_log):
    lines, log, rejections = random_log
    fixes, dates = read_fixes(log, rejections)
    assert rejections.count() == 0
    for kind in ("GGA", "RMC", "GNS"):
        ref = _parsed(lines, kind)
        f = fixes[kind]
        assert len(ref) == f.index.size == 400
        assert np.allclose(np.degrees(f.lat), [m.latitude for m in ref], rtol=0, atol=1e-12)
        assert np.allclose(np.degrees(f.lon), [m.longitude for m in ref], rtol=0, atol=1e-12)
        assert np.allclose(f.tod, [_seconds(m.timestamp) for m in ref], rtol=0, atol=1e-9)
    gga = _parsed(lines, "GGA")
    assert np.allclose(fixes["GGA"].alt_msl, [m.altitude for m in gga])
    assert np.allclose(fixes["GGA"].geoid, [float(m.geo_sep) for m in gga])
    zda, rmc = _parsed(lines, "ZDA"), _parsed(lines, "RMC")
    by_index = dict(zip(dates.index.tolist(), dates.day.tolist()))
    zda_days = [by_index[i] for i in log.where("ZDA")]
    assert zda_days == [m.datestamp.toordinal() - EPOCH_ORDINAL for m in zda]
    assert [by_index[i] for i in log.where("RMC")] == [m.datestamp.toordinal() - EPOCH_ORDINAL for m in rmc]


def test_attitude_as_pynmea2_reads_it(random_log):
    lines, log, rejections = random_log
    pashr = read_pashr(log, rejections)
    ref = _parsed(lines, "PASHR")
    assert len(ref) == len(pashr) == 400
    assert np.allclose(np.degrees(pashr.heading), [m.true_heading for m in ref])
    assert np.allclose(np.degrees(pashr.roll), [m.roll for m in ref])
    assert np.allclose(np.degrees(pashr.pitch), [m.pitch for m in ref])
    assert np.allclose(pashr.tod, [_seconds(m.timestamp) for m in ref], atol=1e-9)
    hdt = read_headings(log, "HDT", rejections)
    assert np.allclose(np.degrees(hdt.heading), [float(m.heading) for m in _parsed(lines, "HDT")])


def test_plots_as_pynmea2_reads_the_ttm(bridge):
    log, path, result = bridge
    ttm = [pynmea2.parse(x) for x in log.lines if x.startswith("$RATTM")]
    unit = {"N": 1852.0, "K": 1000.0, "S": 1609.344}
    plots = result.plots
    assert len(plots) == len(ttm)
    assert plots.track.tolist() == [str(m.target_number) for m in ttm]
    assert np.allclose(plots.range_m, [float(m.distance) * unit[m.dist_unit] for m in ttm], rtol=0, atol=1e-9)
    relative = np.array([float(m.bearing) for m in ttm])
    assert np.allclose(plots.bearing_deg, np.where(relative > 180, relative - 360, relative))
    day = 0  # the log does not cross midnight
    assert np.allclose(plots.time_s, [day + _seconds(m.timestamp) for m in ttm], atol=1e-9)
