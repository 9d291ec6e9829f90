"""The sensors file with its talker column: read, checked, errors naming file, row, column and unit."""

from __future__ import annotations

import pandas as pd
import pytest

from registration.io.nmea import check_sensors, import_nmea, read_sensors
from tests.io.nmea.logs import import_lines, navigation_lines

HEADER = "sensor,platform,talker,sigma_range_m,sigma_bearing_deg,prior_range_bias_m,lever_y_m\n"


def _file(tmp_path, rows: str, header: str = HEADER, name: str = "SENSORS.csv"):
    path = tmp_path / name
    path.write_text(header + rows)
    return path


def test_a_good_file(tmp_path):
    path = _file(tmp_path, "RADAR,OWN,ra,15,0.1,,20\nNAV2,OWN,RB,20,0.2,50,\nSITE,SHORE,RA,30,0.1,,\n")
    table = read_sensors(path)
    assert table.talker.tolist() == ["RA", "RB", "RA"]  # one talker per platform: RA twice on two platforms
    assert table.sigma_range_m.tolist() == [15.0, 20.0, 30.0] and pd.isna(table.prior_range_bias_m[0])
    assert table.attrs["source"] == str(path)


@pytest.mark.parametrize(
    "rows, header, message",
    [
        (
            "RADAR,OWN,RA,abc,0.1,,\n",
            HEADER,
            r"SENSORS.csv: row 0 \(line 2\), column 'sigma_range_m': 'abc' is not a number \(m\)",
        ),
        (
            "RADAR,OWN,RA,15,0.1,,\nB,OWN,RB,15,25,,\n",
            HEADER,
            r"row 1 \(line 3\), column 'sigma_bearing_deg': 25 deg is outside \(0, 20\] deg",
        ),
        ("RADAR,OWN,RA,0,0.1,,\n", HEADER, r"column 'sigma_range_m': 0 m is outside \(0, 1e\+06\] m"),
        ("RADAR,OWN,RA,15,0.1,-1,\n", HEADER, r"column 'prior_range_bias_m': -1 m is outside \[0, inf\] m"),
        ("RADAR,OWN,R,15,0.1,,\n", HEADER, r"column 'talker': 'R' is not an NMEA talker"),
        (
            "RADAR,OWN,RA,15,0.1,,\nB,OWN,ra,15,0.1,,\n",
            HEADER,
            r"row 1 \(line 3\), column 'talker': talker 'RA' is given twice",
        ),
        (
            "RADAR,OWN,RA,15,0.1,,\nRADAR,OWN,RB,15,0.1,,\n",
            HEADER,
            r"row 1 \(line 3\), column 'sensor': sensor 'RADAR' is given twice",
        ),
        (",OWN,RA,15,0.1,,\n", HEADER, r"row 0 \(line 2\), column 'sensor': empty"),
        ("RADAR,OWN,15\n", "sensor,platform,range_sigma\n", r"unknown column\(s\) \['range_sigma'\]"),
        ("RADAR,15\n", "sensor,sigma_range_m\n", r"missing column\(s\) \['platform'\]"),
        ("", HEADER, r"SENSORS.csv: no rows"),
    ],
)
def test_errors_name_the_file_row_column_and_unit(tmp_path, rows, header, message):
    with pytest.raises(ValueError, match=message):
        read_sensors(_file(tmp_path, rows, header))


def test_import_checks_the_platform_and_the_ttm_sensors(tmp_path):
    lines = navigation_lines(n=3)
    path = _file(tmp_path, "RADAR,OWN,RA,15,0.1,,\n")
    assert import_lines(tmp_path, lines, sensors=read_sensors(path)).sensors.sensor.tolist() == ["RADAR"]
    log = tmp_path / "log.nmea"
    assert len(import_nmea(log, "OWN", path).navigation) == 21  # a path works too
    with pytest.raises(
        ValueError, match=r"SENSORS.csv: no sensor on platform 'SHIP' \(platforms in the table: \['OWN'\]\)"
    ):
        import_nmea(log, "SHIP", read_sensors(path))
    no_sigma = _file(tmp_path, "RADAR,OWN,RA,,0.1,,\n", name="NO_SIGMA.csv")
    with pytest.raises(ValueError, match="sensor 'RADAR' receives TTM plots .* no sigma_range_m"):
        import_nmea(log, "OWN", no_sigma)
    with pytest.raises(ValueError, match="no such file"):
        import_nmea(tmp_path / "missing.nmea", "OWN", path)
    with pytest.raises(ValueError, match="no such file"):
        read_sensors(tmp_path / "missing.csv")


def test_platform_priors(tmp_path):
    lines = navigation_lines(n=3)
    frame = check_sensors(
        pd.DataFrame(
            {"sensor": ["RADAR"], "platform": ["OWN"], "sigma_range_m": [15.0], "sigma_bearing_deg": [0.1]}
        )
    )
    result = import_lines(
        tmp_path, lines, sensors=frame, platform_priors={"prior_heading_deg": 0.5, "prior_roll_deg": 0}
    )
    row = result.platforms.iloc[0]
    assert row.platform == "OWN" and row.prior_heading_deg == 0.5 and row.prior_roll_deg == 0.0
    assert pd.isna(row.prior_pitch_deg)
    with pytest.raises(ValueError, match=r"unknown key\(s\) \['prior_heading'\]"):
        import_lines(tmp_path, lines, sensors=frame, platform_priors={"prior_heading": 0.5})
    with pytest.raises(ValueError, match="prior_pitch_deg"):
        import_lines(tmp_path, lines, sensors=frame, platform_priors={"prior_pitch_deg": -1.0})
