"""The plot id rules (Mode S address, Mode 3/A), the ADS-B quality rules (NACp, NUCp, GVA) and
SITES.csv checks, on hand-made fields and files."""

from __future__ import annotations

import math

import numpy as np
import pytest

from registration.io.asterix import read_sites
from registration.io.asterix.tables.adsb21 import CIRCULAR_95, adsb_sigma_m, reference_verdicts
from registration.io.asterix.tables.plots48 import target_ids


def _fields048(**columns) -> dict:
    n = len(next(iter(columns.values())))
    base = {k: np.zeros(n, dtype=np.int64) for k in ("m3a_v", "m3a_g", "m3a_l", "m3a", "address")}
    base.update(has_070=np.ones(n, dtype=bool), has_220=np.zeros(n, dtype=bool))
    base.update({k: np.asarray(v) for k, v in columns.items()})
    return base


def test_mode_3a_rules():
    codes = [0o4521, 0o4521, 0o4521, 0o4521, 0o7700, 0o1200, 0o0001, 0o1234, 0o7500]
    f = _fields048(
        m3a=codes,
        m3a_v=[0, 1, 0, 0, 0, 0, 0, 0, 0],
        m3a_g=[0, 0, 1, 0, 0, 0, 0, 0, 0],
        m3a_l=[0, 0, 0, 1, 0, 0, 0, 0, 0],
        has_070=[True] * 7 + [False, True],
    )
    ids, kind = target_ids(f)
    assert list(ids) == ["A4521", "", "", "A4521", "", "", "A0001", "", ""]
    assert list(kind) == ["mode_a", "none", "none", "mode_a", "none", "none", "mode_a", "none", "none"]


def test_mode_s_address_wins_and_is_six_uppercase_hex_digits():
    f = _fields048(
        m3a=[0o1234, 0o1234, 0],
        address=[0x4CA1F3, 0x00000A, 0],
        has_220=[True, True, False],
        has_070=[True, False, False],
    )
    ids, kind = target_ids(f)
    assert list(ids) == ["4CA1F3", "00000A", ""] and list(kind) == ["mode_s", "mode_s", "none"]


def _fields021(nacp, gva=None, old=False) -> dict:
    n = len(nacp)
    f = {k: np.zeros(n, dtype=np.int64) for k in ("sac", "tod", "tst", "sim", "rab", "nucp", "nacp", "gva")}
    f.update(
        has_080=np.ones(n, bool),
        time_item=np.full(n, "071", dtype=object),
        has_position=np.ones(n, bool),
        lat_deg=np.zeros(n),
        lon_deg=np.zeros(n),
        has_140=np.ones(n, bool),
    )
    key = "nucp" if old else "nacp"
    f[key] = np.array([0 if v is None else v for v in nacp])
    f[f"has_{key}"] = np.array([v is not None for v in nacp])
    f["has_nacp" if old else "has_nucp"] = np.zeros(n, bool)
    f["gva"] = np.array(gva if gva is not None else [0] * n)
    f["has_gva"] = np.ones(n, bool)
    return f


def test_nacp_rules_and_sigma():
    f = _fields021([None, 6, 7, 8, 9, 10, 11, 12])
    v, epu = reference_verdicts(f, old_edition=False)
    assert list(v.code) == ["no_quality", "low_nacp", "", "", "", "", "", "no_quality"]
    np.testing.assert_allclose(epu[2:7], [185.2, 92.6, 30.0, 10.0, 3.0])
    assert "NACp 12 is reserved" in v.reason[7]
    horizontal, vertical = adsb_sigma_m(epu[2:7], np.zeros(5))
    np.testing.assert_allclose(horizontal, np.array([185.2, 92.6, 30.0, 10.0, 3.0]) / CIRCULAR_95)
    np.testing.assert_allclose(vertical, 2 * horizontal)  # no GVA: twice the horizontal sigma
    assert CIRCULAR_95 == pytest.approx(2.4477, abs=1e-4)
    horizontal, vertical = adsb_sigma_m([3.0, 3.0, 185.2], [2, 1, 2])
    np.testing.assert_allclose(horizontal, np.array([3.0, 3.0, 185.2]) / CIRCULAR_95)
    np.testing.assert_allclose(
        vertical, [45 / 1.959964, 150 / 1.959964, 45 / 1.959964]
    )  # GVA 2: 45 m, 1: 150 m


def test_nucp_rules_of_editions_0_2x():
    f = _fields021([None, 5, 6, 7, 8, 9], old=True)
    v, epu = reference_verdicts(f, old_edition=True)
    assert list(v.code) == ["no_quality", "low_nacp", "", "", "", ""]
    np.testing.assert_allclose(epu[2:], [185.2, 92.6, 10.0, 3.0])


def test_other_adsb_rules_in_order():
    f = _fields021([9, 9, 9, 9, 9])
    f["has_080"][0] = False
    f["sim"][1] = 1
    f["lat_deg"][2] = 91.0
    f["has_140"][3] = False
    f["tst"][4] = 1
    f["has_140"][4] = False  # test target comes first
    v, _ = reference_verdicts(f, old_edition=False)
    assert list(v.code) == ["no_address", "simulated", "bad_position", "no_geometric_height", "test_target"]


HEADER = "sensor,sac,sic,lat_deg,lon_deg,alt_m,sigma_range_m,sigma_bearing_deg"


@pytest.mark.parametrize(
    "text, words",
    [
        (
            HEADER + "\nR1,1,2,45,5,10,30,0.1\nR2,1,2,45,5,10,30,0.1\n",
            "row 1, column 'sic': SAC/SIC 1/2 is also in row 0",
        ),
        (HEADER + "\nR1,1,2,95,5,10,30,0.1\n", "row 0, column 'lat_deg': 95 deg is outside [-90, 90] deg"),
        (HEADER + "\nR1,1,256,45,5,10,30,0.1\n", "row 0, column 'sic': '256' is not an integer in [0, 255]"),
        (HEADER + "\nR1,1,2,45,5,10,0,0.1\n", "row 0, column 'sigma_range_m': 0 m is outside (0, 1e+06] m"),
        (HEADER + "\nR1,1,2,45,5,10,30,25\n", "column 'sigma_bearing_deg': 25 deg is outside (0, 20] deg"),
        (HEADER + "\nR1,1,2,45,five,10,30,0.1\n", "row 0, column 'lon_deg': 'five' is not a number (deg)"),
        (HEADER + "\nR1,1,2,45,5,,30,0.1\n", "row 0, column 'alt_m': empty; a number (m) is required"),
        (HEADER + "\nR1,1,2,45,5,10,30\n", "row 0: 7 fields, the header 8 (cut short?)"),
        (
            HEADER + ",prior_range_gain\nR1,1,2,45,5,10,30,0.1,0.5\n",
            "'prior_range_gain': 0.5 dimensionless is outside [0, 0.1]",
        ),
        (HEADER + ",colour\nR1,1,2,45,5,10,30,0.1,red\n", "unknown column(s) ['colour']"),
        ("sensor,sac,lat_deg\nR1,1,45\n", "missing column(s) ['sic', 'lon_deg'"),
        (HEADER + "\n", "no data rows"),
        (HEADER + "\n,1,2,45,5,10,30,0.1\n", "row 0, column 'sensor': empty"),
    ],
)
def test_sites_errors_name_file_row_column_unit(tmp_path, text, words):
    path = tmp_path / "SITES.csv"
    path.write_text(text)
    with pytest.raises(ValueError) as info:
        read_sites(path)
    assert str(info.value).startswith(str(path)) and words in str(info.value)


def test_sites_read(tmp_path):
    path = tmp_path / "SITES.csv"
    path.write_text(HEADER + ",prior_time_bias_s,prior_heading_deg\nR1, 1,2,45,5,10,30,0.1,,inf\n")
    sites = read_sites(path)
    assert sites["sac"].dtype == np.int64 and sites["sensor"].iloc[0] == "R1"
    assert math.isnan(sites["prior_time_bias_s"].iloc[0]) and math.isinf(sites["prior_heading_deg"].iloc[0])
