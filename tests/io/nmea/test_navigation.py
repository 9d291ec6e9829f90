"""Navigation: position sources, invalid fixes, heights, attitude sources and conventions, what is missing."""

from __future__ import annotations

import numpy as np
import pytest

from registration.io.nmea import NmeaImportError
from tests.io.nmea import encode
from tests.io.nmea.logs import DAY, LAT, LON, import_lines, navigation_lines, rejected_lines

T0 = 43200.0


def test_invalid_fixes_are_set_aside_with_their_lines(tmp_path):
    lines = navigation_lines(n=6)
    lines.insert(1, encode.gga(T0 + 0.5, LAT + 0.01, LON, quality="0"))
    lines.insert(2, encode.rmc(T0 + 0.5, LAT + 0.01, LON, DAY, status="V"))
    lines.insert(3, encode.gns(T0 + 0.5, LAT + 0.01, LON, mode="NN"))
    result = import_lines(tmp_path, lines)
    assert rejected_lines(result, "invalid_fix") == [2, 3, 4]
    reasons = result.rejected.loc[result.rejected.code == "invalid_fix", "reason"].tolist()
    assert "quality '0'" in reasons[0] and "status 'V'" in reasons[1] and "mode 'NN'" in reasons[2]
    assert np.allclose(result.navigation.lat_deg, 43.0)  # the invalid fix's position is not used
    assert result.summary["rejected"]["by_reason"]["invalid_fix"] == 3


def test_without_heading_or_position_one_error_names_what_is_missing(tmp_path):
    no_heading = [x for x in navigation_lines(n=3) if "PASHR" not in x]
    with pytest.raises(NmeaImportError, match=r"\.nmea: no valid heading in the log: no \$PASHR, HDT") as e:
        import_lines(tmp_path, no_heading)
    assert isinstance(e.value, ValueError) and "\n" not in str(e.value)
    no_position = [x for x in navigation_lines(n=3) if "GGA" not in x]
    with pytest.raises(NmeaImportError, match=r"\.nmea: no valid position in the log: no GGA, GNS or RMC"):
        import_lines(tmp_path, no_position)
    only_invalid = [encode.gga(T0 + k, LAT, LON, quality="0") for k in range(3)] + [encode.hdt(10.0)]
    with pytest.raises(NmeaImportError, match="no valid position"):
        import_lines(tmp_path, only_invalid)
    with pytest.raises(NmeaImportError, match="no valid position"):
        import_lines(tmp_path, ["this is no log", ""])


def test_heights_from_gns_and_rmc(tmp_path):
    gns = [encode.gns(T0 + k, LAT, LON, alt_msl=12.0, geoid="47.50") for k in range(3)]
    result = import_lines(tmp_path, gns + [encode.pashr(T0 + 1, 0, 0, 0)], date="2024-05-01")
    assert (
        result.navigation.alt_m.tolist() == [59.5] and result.summary["navigation"]["position"] == "GNS (GN)"
    )
    rmc = [encode.rmc(T0 + k, LAT, LON, DAY) for k in range(3)]
    result = import_lines(tmp_path, rmc + [encode.pashr(T0 + 1, 0, 0, 0)])
    assert result.navigation.alt_m.tolist() == [0.0]
    assert any("RMC" in n and "no height" in n for n in result.summary["notes"])
    no_geoid = [encode.gga(T0 + k, LAT, LON, alt_msl=20.0, geoid="") for k in range(3)]
    result = import_lines(tmp_path, no_geoid + [encode.pashr(T0 + 1, 0, 0, 0)], date="2024-05-01")
    assert result.navigation.alt_m.tolist() == [20.0]
    assert any("without geoid separation" in n for n in result.summary["notes"])


def test_the_most_frequent_talker_is_the_position_source(tmp_path):
    lines = navigation_lines(n=5) + [encode.gga(T0 + k + 0.5, LAT + 0.1, LON, talker="GN") for k in range(2)]
    result = import_lines(tmp_path, lines)
    assert (
        np.allclose(result.navigation.lat_deg, 43.0)
        and result.summary["navigation"]["position"] == "GGA (GP)"
    )
    assert result.summary["sentences"]["GGA"] == {"GN": 2, "GP": 5}


def test_pashr_tss_roll_is_converted(tmp_path):
    lines = [encode.gga(T0 + k, LAT, LON) for k in range(3)] + [encode.pashr(T0 + 1, 0.0, 10.0, 20.0)]
    tb = import_lines(tmp_path, lines, date="2024-05-01").navigation
    tss = import_lines(tmp_path, lines, date="2024-05-01", pashr_angles="tss").navigation
    assert tb.roll_deg.tolist() == [10.0] and tb.pitch_deg.tolist() == [20.0]
    expected = np.degrees(np.arcsin(np.sin(np.radians(10.0)) / np.cos(np.radians(20.0))))
    assert tss.roll_deg.tolist() == pytest.approx([expected]) and expected > 10.5
    with pytest.raises(ValueError, match="pashr_angles"):
        import_lines(tmp_path, lines, pashr_angles="nautical")


def test_attitude_samples_set_aside(tmp_path):
    lines = [encode.gga(T0 + k, LAT, LON) for k in (0, 1, 2, 20, 21)]
    lines += [
        encode.pashr(T0 + 1.5, 0, 0, 0),
        encode.pashr(T0 + 1.5, 5, 0, 0),
        encode.pashr(T0 + 1.7, 0, 0, 0, flag="M"),
        encode.pashr(T0 + 10.0, 0, 0, 0),
        encode.pashr(T0 + 20.5, 0, 0, 0),
        encode.ths(10.0, "V"),
    ]
    result = import_lines(tmp_path, lines, date="2024-05-01")
    assert result.navigation.time_s.tolist() == [T0 + 1.5, T0 + 20.5]
    assert rejected_lines(result, "duplicate_time") == [7]
    assert rejected_lines(result, "bad_field") == [8]
    assert rejected_lines(result, "outside_positions") == [9]  # 18 s between the fixes around it
    assert rejected_lines(result, "invalid_fix") == [11]
