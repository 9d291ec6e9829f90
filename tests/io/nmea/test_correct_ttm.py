"""TTM lines corrected by a registration's estimates (registration.io.nmea.correct), written by
pynmea2 (the independent encoder) and read back by pynmea2 with its checksum check: the distance
and bearing are the model's corrected values to the field's resolution, every other field is as
it was, and what is not a TTM passes unchanged."""

from __future__ import annotations

import math

import numpy as np
import pynmea2
import pytest

from registration.io.asterix.encode import PlotCorrection
from registration.io.nmea.correct import correct_ttm
from tests.io.nmea import encode

UNITS_M = {"N": 1852.0, "K": 1000.0, "S": 1609.344}
CORRECTIONS = [
    PlotCorrection(range_bias_m=85.0, range_gain=1.5e-3, azimuth_bias_rad=math.radians(0.8)),
    PlotCorrection(range_bias_m=-240.0, range_gain=-2e-3, azimuth_bias_rad=math.radians(-2.5)),
    PlotCorrection(range_bias_m=12.0, azimuth_bias_rad=math.radians(359.0)),
]


def _parse(line: str) -> pynmea2.TTM:
    msg = pynmea2.parse(line.strip(), check=True)  # checks the new checksum
    assert isinstance(msg, pynmea2.TTM)
    return msg


def _resolution(field: str) -> float:
    return 10.0 ** -len(field.partition(".")[2])


@pytest.mark.parametrize("k", range(len(CORRECTIONS)))
@pytest.mark.parametrize("unit", sorted(UNITS_M))
@pytest.mark.parametrize("reference", ["T", "R"])
def test_distance_and_bearing_follow_the_model_and_nothing_else_changes(k, unit, reference):
    c = CORRECTIONS[k]
    rng = np.random.default_rng(k)
    for _ in range(40):
        distance = f"{rng.uniform(0.2, 20.0):.{int(rng.integers(1, 5))}f}"
        line = encode.ttm(
            int(rng.integers(0, 100)), distance, float(rng.uniform(0, 360)), reference, unit, t=5.0
        )
        out = correct_ttm(line, c)
        before, after = _parse(line), _parse(out)
        assert after.talker == before.talker and after.sentence_type == "TTM"
        assert len(after.data) == len(before.data)
        for j, (a, b) in enumerate(zip(before.data, after.data)):
            if j not in (1, 2):  # pynmea2's data: field 2 distance, field 3 bearing at 1, 2
                assert a == b, j
        # the field's resolution is kept
        assert _resolution(after.data[1]) == _resolution(before.data[1])
        assert _resolution(after.data[2]) == _resolution(before.data[2])
        per_unit = UNITS_M[unit]
        expected = (float(before.data[1]) * per_unit - c.range_bias_m) / (1 + c.range_gain) / per_unit
        assert abs(float(after.data[1]) - expected) <= _resolution(before.data[1]) / 2 + 1e-9
        bearing = float(before.data[2]) - math.degrees(c.azimuth_bias_rad)
        got = float(after.data[2])
        assert 0.0 <= got < 360.0
        assert abs((got - bearing + 180.0) % 360.0 - 180.0) <= _resolution(before.data[2]) / 2 + 1e-9


def test_no_correction_gives_the_same_line_and_leading_zeros_are_kept():
    for distance, bearing in [("002.50", 45.0), ("10", 300.25), ("0.125", 0.0)]:
        line = encode.ttm(7, distance, bearing, "R", "K", t=100.0)
        assert correct_ttm(line, PlotCorrection()) == line
    line = encode.ttm(7, "002.50", 45.0, "R", "N", t=100.0)
    out = _parse(correct_ttm(line, PlotCorrection(range_bias_m=-1852.0)))
    assert out.data[1] == "003.50"


def test_the_bearing_wraps_to_0_360_and_a_negative_distance_becomes_zero():
    line = encode.ttm(1, "0.500", 0.5, "T", "N", t=100.0)
    out = _parse(correct_ttm(line, PlotCorrection(range_bias_m=2000.0, azimuth_bias_rad=math.radians(1.0))))
    assert float(out.data[2]) == pytest.approx(359.5) and float(out.data[1]) == 0.0
    line = encode.ttm(1, "0.500", 359.96, "T", "N", t=100.0)
    out = _parse(correct_ttm(line, PlotCorrection(azimuth_bias_rad=math.radians(-0.04))))
    assert float(out.data[2]) == 0.0


def test_prefix_tag_block_and_end_of_line_are_kept():
    line = encode.ttm(4, "3.25", 120.0, "R", "N", t=100.0)
    c = CORRECTIONS[0]
    sentence = correct_ttm(line, c)
    for head in ["2024-05-01T12:00:00.25Z ", "1714564800.25,", encode.tag(1714564800)]:
        for eol in ["", "\n", "\r\n"]:
            assert correct_ttm(head + line + eol, c) == head + sentence + eol


def test_lines_without_a_ttm_come_back_unchanged():
    lines = [
        encode.hdt(12.5),
        encode.pashr(10.0, 12.0, 1.0, 0.5),
        *encode.ais({"msg_type": 1, "mmsi": 244000001, "lat": 52.0, "lon": 4.0}),
        "",
        "garbage without a sentence",
        encode.checksummed("PXTTM,1,2,3"),
        "$GPGGA,120000.00,5200.0000,N,00400.0000,E,1,08,1.0,10.0,M,0.0,M,,*4A\r\n",
    ]
    for line in lines:
        assert correct_ttm(line, CORRECTIONS[0]) == line


@pytest.mark.parametrize(
    ("change", "match"),
    [
        (lambda f: f.__setitem__(2, ""), "TTM distance"),
        (lambda f: f.__setitem__(2, "abc"), "TTM distance"),
        (lambda f: f.__setitem__(3, "400.0"), "TTM bearing empty"),
        (lambda f: f.__setitem__(4, "X"), "TTM bearing reference"),
        (lambda f: f.__setitem__(10, "M"), "TTM distance unit"),
        (lambda f: f.__setitem__(1, ""), "TTM target number"),
        (lambda f: f.__delitem__(slice(11, None)), "TTM has 10 fields, at least 12"),
    ],
)
def test_a_malformed_ttm_raises_naming_the_field(change, match):
    line = encode.ttm(4, "3.25", 120.0, "R", "N", t=100.0)
    fields = line[1:-3].split(",")
    change(fields)
    with pytest.raises(ValueError, match=match):
        correct_ttm(encode.checksummed(",".join(fields)), CORRECTIONS[0])


def test_a_bad_or_missing_checksum_raises():
    line = encode.ttm(4, "3.25", 120.0, "R", "N", t=100.0)
    bad = line[:-2] + ("00" if line[-2:] != "00" else "01")
    with pytest.raises(ValueError, match="checksum"):
        correct_ttm(bad, CORRECTIONS[0])
    with pytest.raises(ValueError, match="without a checksum"):
        correct_ttm(line[:-3], CORRECTIONS[0])
    with pytest.raises(ValueError, match="range_gain"):
        correct_ttm(line, _Bad())


class _Bad:
    range_bias_m = 0.0
    range_gain = -1.0
    azimuth_bias_rad = 0.0
