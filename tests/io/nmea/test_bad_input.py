"""Bad input never raises: every bad line is set aside and counted with its line number and reason."""

from __future__ import annotations

import numpy as np

from registration.io.nmea import REASONS, import_nmea
from tests.io.nmea import encode
from tests.io.nmea.logs import import_lines, navigation_lines, radar_sensors

T0 = 43200.0


def _corrupt(sentence: str) -> str:
    """One character of the sentence changed, its checksum kept."""
    k = sentence.index(",") + 3
    return sentence[:k] + ("7" if sentence[k] != "7" else "8") + sentence[k + 1 :]


def _edited(sentence: str, old: str, new: str) -> str:
    """The sentence with ``old`` replaced by ``new`` and its checksum recomputed (by pynmea2)."""
    return encode.checksummed(sentence[1:-3].replace(old, new, 1), sentence[0])


def _bad_lines() -> list[tuple[str | None, str]]:
    """(expected code or None: accepted, line)."""
    static = encode.ais(
        {"msg_type": 5, "mmsi": 244000001, "shipname": "LONE PART", "callsign": "X1"}, seq_id=4
    )
    position = encode.ais({"msg_type": 1, "mmsi": 244000002, "lat": 43.1, "lon": 7.6, "second": 3})[0]
    return [
        ("bad_checksum", _corrupt(encode.gga(T0 + 3.5, 0.75, 0.13))),
        ("no_checksum", encode.gga(T0 + 3.5, 0.75, 0.13)[:40]),  # a truncated line
        ("too_few_fields", encode.checksummed("GPGGA,120003.50,4300.0,N")),  # truncated, then checksummed
        ("unknown_type", encode.checksummed("GPXYZ,1,2,3")),
        ("unknown_type", encode.checksummed("PQQQA,1,2")),
        (None, encode.checksummed("GPVTG,40.0,T,,M,15.6,N,28.9,K,D")),  # known to pynmea2, not used
        (None, encode.checksummed("PGRME,15.0,M,45.0,M,25.0,M")),
        (
            None,
            encode.checksummed(
                "PASHR,POS,0,10,120003.00,4300.0,N,00730.0,E,30.0,,0.0,0.0,0.0,0.0,1.0,1.0,1.0,1.0,,"
            ),
        ),
        ("ais_fragment", static[0]),  # a first part whose second never comes
        (
            "ais_fragment",
            encode.ais({"msg_type": 5, "mmsi": 244000003, "shipname": "SECOND ONLY"}, seq_id=6)[1],
        ),
        ("ais_decode", encode.checksummed("AIVDM,1,1,,A,w,0", "!")),
        ("ais_decode", encode.checksummed("AIVDM,1,1,,A,1,0", "!")),
        ("bad_field", encode.checksummed("AIVDM,0,1,,A,1,0", "!")),
        ("bad_tag_block", "\\c:1714564800*00\\" + position),
        ("bad_tag_block", "\\c:1714564800" + position),
        ("bad_prefix", "yesterday " + position),
        ("not_a_sentence", "garbage without a start"),
        ("not_a_sentence", "\\c:1714564800*55\\garbage"),
        ("bad_time", encode.checksummed("GPGGA,256103.00,4300.0,N,00730.0,E,1,08,0.9,10.0,M,42.0,M,,")),
        ("bad_field", encode.checksummed("GPGGA,120003.00,43x0.0,N,00730.0,E,1,08,0.9,10.0,M,42.0,M,,")),
        ("bad_field", encode.ttm(1, "abc", 10.0, t=T0 + 3)),
        ("bad_field", encode.ttm(1, "2.0", 10.0, unit="X", t=T0 + 3)),
        ("bad_field", _edited(encode.ttm(1, "2.0", 10.0, t=T0 + 3), ",10.0000,", ",400.0,")),
        ("bad_field", encode.ttm(1, "2.0", 10.0, reference="M", t=T0 + 3)),
        ("bad_field", _edited(encode.ttm(1, "2.0", 10.0, t=T0 + 3), "RATTM,01,", "RATTM,,")),
        ("bad_time", _edited(encode.ttm(1, "2.0", 10.0, t=T0 + 3), ",120003.00,", ",1203.00,")),
        (None, ""),
        (None, "   "),
    ]


def test_every_bad_line_is_set_aside_with_its_line_number(tmp_path):
    nav = navigation_lines(n=6)
    cases = _bad_lines()
    lines = nav[:30] + [x for _, x in cases] + nav[30:]
    result = import_lines(tmp_path, lines)
    expected = {}
    for k, (code, _) in enumerate(cases):
        if code:
            expected.setdefault(code, []).append(31 + k)
    got = {code: sorted(g.line.tolist()) for code, g in result.rejected.groupby("code")}
    got.pop("outside_positions", None)  # the last 0.9 s of $PASHR after the last fix
    assert got == expected
    assert set(result.rejected.columns) == {"file", "line", "code", "reason"}
    assert set(result.rejected.code) <= set(REASONS)
    s = result.summary
    assert s["blank_lines"] == 2 and s["lines"] == len(lines)
    assert s["not_used"] == {"PASHR (not attitude)": 1, "PGRME": 1, "VTG": 1}
    assert s["rejected"]["by_reason"]["unknown_type"] == 2
    assert len(result.navigation) == 60 - 9 and len(result.plots) == 0  # the good lines still count


def test_binary_garbage_and_crlf_do_not_break_the_reader(tmp_path):
    path = tmp_path / "dirty.nmea"
    lines = navigation_lines(n=3)
    blob = (
        b"\r\n".join(x.encode() for x in lines[:12])
        + b"\r\n\x00\xff\xfe\x85junk\x1c\r\n"
        + b"\r\n".join(x.encode() for x in lines[12:])
        + b"\r\n"
    )
    path.write_bytes(blob)
    result = import_nmea(path, "OWN", radar_sensors())
    assert result.rejected.loc[result.rejected.code == "not_a_sentence", "line"].tolist() == [13]
    assert len(result.navigation) == 21
    assert np.all(result.rejected.line.to_numpy() >= 1)


def test_fragments_out_of_order_and_interleaved(tmp_path):
    a = encode.ais({"msg_type": 5, "mmsi": 244000001, "shipname": "ALPHA", "callsign": "A1"}, seq_id=1)
    b = encode.ais({"msg_type": 5, "mmsi": 244000002, "shipname": "BRAVO", "callsign": "B2"}, seq_id=2)
    c = encode.ais({"msg_type": 5, "mmsi": 244000003, "shipname": "CHARLIE", "callsign": "C3"}, seq_id=3)
    lines = navigation_lines(n=3) + [a[0], b[0], a[1], b[1], c[1], c[0], a[0], a[0], a[1]]
    result = import_lines(tmp_path, lines)
    n = len(navigation_lines(n=3))
    assert result.rejected.loc[result.rejected.code == "ais_fragment", "line"].tolist() == [
        n + 5,
        n + 6,
        n + 7,
    ]
    names = {v["mmsi"]: v["name"] for v in result.summary["ais"]["vessels"]}
    assert names == {"244000001": "ALPHA", "244000002": "BRAVO"}
    assert result.summary["ais"]["vessels"][0]["messages"] == {"5": 2}


def test_bounds_on_bytes_and_rejected_rows(tmp_path):
    """Issue 32: the bytes read per file and the rows listed are bounded (max_bytes,
    max_rejected_rows); beyond them the lines are set aside as over_limit, the rows counted."""
    from registration.cli import main

    lines = navigation_lines(n=6) + ["not a sentence"] * 500
    result = import_lines(tmp_path, lines, max_rejected_rows=50)
    total = result.summary["rejected"]["lines"]
    assert result.summary["rejected"]["by_reason"]["not_a_sentence"] == 500 and len(result.rejected) == 51
    last = result.rejected.iloc[-1]
    assert last["code"] == "not_listed" and f"{total - 50} more items" in last["reason"]
    size = len("\n".join(navigation_lines(n=6)).encode()) + 1
    result = import_lines(tmp_path, lines, max_bytes=size + 20)
    by_reason = result.summary["rejected"]["by_reason"]
    assert by_reason["not_a_sentence"] == 1 and by_reason["over_limit"] == 1
    path = tmp_path / "log.nmea"
    sensors = tmp_path / "sensors.csv"
    radar_sensors().to_csv(sensors, index=False)
    argv = ["import", "nmea", str(path), "--platform", "OWN", "--sensors", str(sensors)]
    assert main([*argv, "--out", str(tmp_path / "o"), "--max-rejected-rows", "10"]) == 0
    assert sum(1 for _ in open(tmp_path / "o" / "rejected.csv")) == 1 + 11
