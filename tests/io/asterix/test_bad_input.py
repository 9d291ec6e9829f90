"""Bad input never gives a traceback: files that are not ASTERIX raise AsterixImportError naming
the file; inside a file, what cannot be read is set aside with its offset and reason, the rest
imported."""

from __future__ import annotations

import gzip

import numpy as np
import pytest

from registration.io.asterix import AsterixImportError, import_asterix
from tests.io.asterix.encode import cat021_record, cat034_record, cat048_record, encode_recording
from tests.io.asterix.scenario import DATE

SAC, SIC = 10, 1


@pytest.fixture(scope="module")
def blocks() -> list:
    """Five CAT048 blocks of three plots each, each plot with an address."""
    messages = []
    for k in range(15):
        t = 1000.0 + k
        messages.append(
            (t, 48, SAC, SIC, cat048_record("1.32", SAC, SIC, t, 2560 + k, 1000 * k, address=0x100000 + k))
        )
    rec = encode_recording(messages, DATE, max_records=3)
    assert len(rec.blocks) == 5
    return rec.blocks


def _run(tmp_path, sites, data: bytes, name: str = "bad.ast", **kwargs):
    path = tmp_path / name
    path.write_bytes(data)
    return import_asterix(path, sites.assign(sac=[SAC, SAC], sic=[SIC, 2]), **kwargs)


def _reasons(result) -> dict:
    return result.rejected.groupby("reason_code").size().to_dict()


@pytest.mark.parametrize(
    "content, words",
    [
        (b"", "empty file"),
        (b"time_s,sensor,target\n1.0,R1,T1\n", "a text file"),
        (bytes([0xFF, 0x00, 0x10]) + bytes(13), "no ASTERIX category"),
        (bytes([48, 0x40, 0x00]) + bytes(20), "declares 16384 bytes; the file has 23"),
        (b"\x89PNG\r\n\x1a\n" + bytes(40), "neither a pcap/pcapng capture nor an ASTERIX recording"),
        (gzip.compress(b"hello world, not asterix at all\n", mtime=0), "a text file"),
    ],
)
def test_not_asterix_raises_one_line_naming_the_file(tmp_path, sites, content, words):
    path = tmp_path / "strange.bin"
    path.write_bytes(content)
    with pytest.raises(AsterixImportError, match=words) as info:
        import_asterix(path, sites)
    assert str(info.value).startswith(str(path)) and "\n" not in str(info.value)
    assert isinstance(info.value, ValueError)


def test_missing_file(tmp_path, sites):
    with pytest.raises(AsterixImportError, match="cannot read the file"):
        import_asterix(tmp_path / "nowhere.pcap", sites)


def test_truncated_last_block(tmp_path, sites, blocks):
    data = b"".join(blocks)
    result = _run(tmp_path, sites, data[:-7])
    assert len(result.plots) == 12 and _reasons(result) == {"truncated_block": 1}
    row = result.rejected.iloc[0]
    assert row["offset"] == len(data) - len(blocks[-1]) and "left in the file" in row["reason"]


@pytest.mark.parametrize(
    "length, code", [(0xFFFF, "truncated_block"), (1, "bad_block_length"), (0, "bad_block_length")]
)
def test_bad_length_field_mid_file_resynchronises(tmp_path, sites, blocks, length, code):
    broken = bytearray(blocks[1])
    broken[1:3] = length.to_bytes(2, "big")
    result = _run(tmp_path, sites, b"".join([blocks[0], bytes(broken), *blocks[2:]]))
    assert len(result.plots) == 12 and _reasons(result) == {code: 1}
    row = result.rejected.iloc[0]
    next_block = len(blocks[0]) + len(blocks[1])
    assert row["offset"] == len(blocks[0])
    assert f"skipped to the next valid data block at offset {next_block}" in row["reason"]


def _with_record(block: bytes, record: bytes) -> bytes:
    """``block`` with ``record`` appended (length field updated)."""
    body = block[3:] + record
    return block[:1] + (len(body) + 3).to_bytes(2, "big") + body


@pytest.mark.parametrize(
    "record, last, code, words",
    [
        (b"\xff", True, "fspec_overrun", "FSPEC runs past the end"),
        (b"\xff\xff\xff\xff\xff\x00", False, "fspec_overrun", "FX bit set in its octet 4"),
        (b"\x00", False, "empty_record", "names no item"),
        (b"\x01\x20\xc8" + bytes(10), True, "item_overrun", "I048/250 (FRN 10) needs 1601 bytes, 11 left"),
        (
            b"\x20" + b"\x01" * 7,
            False,
            "bad_item",
            "I048/020 has the FX bit set in its last octet allowed (6 groups",
        ),
        (b"\x01\x01\x01\x04\x00", False, "bad_item", "explicit item I048/SP has length 0"),
        (b"\x02\x91", False, "bad_item", "compound item I048/130 has the FX bit set"),
    ],
)
def test_a_record_that_cannot_be_walked_ends_its_block(tmp_path, sites, blocks, record, last, code, words):
    """The block's earlier records are kept; the bad one and what follows it in the block (the
    three records of block 2 unless it is ``last``) are skipped."""
    data = b"".join(
        [
            blocks[0],
            _with_record(blocks[1], record + (b"" if last else blocks[2][3:])),
            *blocks[2 if last else 3 :],
        ]
    )
    result = _run(tmp_path, sites, data)
    assert len(result.plots) == (15 if last else 12) and _reasons(result) == {code: 1}
    row = result.rejected.iloc[0]
    assert row["offset"] == len(blocks[0]) + len(blocks[1]) and row["category"] == 48
    assert words in row["reason"] and "the rest of the data block" in row["reason"]


def test_spare_frn_and_unknown_categories(tmp_path, sites, blocks):
    cat021 = cat021_record("2.6", 1, 1, 1000.0, address=1, lat_deg=1, lon_deg=1, height_ft_raw=1, nacp=9)
    good21 = encode_recording([(1000.0, 21, 1, 1, cat021)], DATE).blocks[0]
    spare = _with_record(good21, bytes([1, 1, 1, 1, 1, 1, 0x80]))
    cat062 = bytes([62, 0, 6, 0x80, 1, 2])
    cat010 = bytes([10, 0, 5, 0x80, 9])  # CAT010: not decoded
    result = _run(tmp_path, sites, b"".join([blocks[0], spare, cat062, cat010, *blocks[1:]]))
    assert len(result.plots) == 15
    assert _reasons(result) == {"spare_frn": 1, "unknown_category": 2}
    rows = result.rejected.set_index("reason_code")
    assert "FRN 43, spare in CAT021 edition 2.7" in rows.loc["spare_frn", "reason"]
    assert result.summary["files"][0]["data_blocks"] == {"010": 1, "021": 1, "048": 5, "062": 1}


def test_records_without_what_the_reader_needs(tmp_path, sites):
    messages = [
        (1.0, 48, SAC, SIC, cat048_record("1.32", SAC, SIC, 1.0, 0, 10, address=1)),  # range 0
        (2.0, 48, SAC, SIC, cat048_record("1.32", SAC, SIC, 2.0, 10, 10, typ=0)),  # no detection
        (3.0, 48, SAC, SIC, cat048_record("1.32", SAC, SIC, 3.0, 10, 10).del_item("040")),
        (4.0, 48, SAC, SIC, cat048_record("1.32", SAC, SIC, 4.0, 10, 10).set_item("140", 86400 * 128 + 5)),
        (
            5.0,
            21,
            1,
            1,
            cat021_record("2.6", 1, 1, 5.0, address=None, lat_deg=1, lon_deg=1, height_ft_raw=1, nacp=9),
        ),
        (
            6.0,
            21,
            1,
            1,
            cat021_record(
                "2.6", 1, 1, 6.0, address=2, lat_deg=1, lon_deg=1, height_ft_raw=1, nacp=9
            ).del_item("071"),
        ),
        (7.0, 34, SAC, SIC, cat034_record("1.29", SAC, SIC, 1, 7.0).del_item("030")),
    ]
    result = _run(tmp_path, sites, encode_recording(messages, DATE).raw())
    assert len(result.plots) == 0
    assert _reasons(result) == {
        "zero_range": 1,
        "no_detection": 1,
        "missing_item": 3,
        "bad_time": 1,
        "no_address": 1,
    }
    reasons = set(result.rejected["reason"])
    assert {
        "no I048/040 (measured position)",
        "no I034/030 (time of day)",
        "no time item (I021/071, I021/073 or I021/077)",
    } <= reasons


def test_truncated_pcap_keeps_the_packets_before(tmp_path, sites, blocks):
    rec = encode_recording(
        [
            (1000.0 + k, 48, SAC, SIC, cat048_record("1.32", SAC, SIC, 1000.0 + k, 100, 0, address=k + 1))
            for k in range(6)
        ],
        DATE,
        max_records=1,
    )
    data = rec.pcap()
    result = _run(tmp_path, sites, data[:-10], "cut.pcap")
    assert 0 < len(result.plots) < 6 and _reasons(result) == {"truncated_packet": 1}
    assert "runs past the end of the file" in result.rejected["reason"].iloc[0]


def test_datagram_that_is_not_asterix(tmp_path, sites):
    from tests.io.asterix.containers import pcap_bytes, udp_frame

    good = encode_recording(
        [(5.0, 48, SAC, SIC, cat048_record("1.32", SAC, SIC, 5.0, 100, 0, address=7))], DATE
    ).raw()
    frames = [udp_frame(b"hello, this is not ASTERIX"), udp_frame(good), udp_frame(good + b"\x30\x00")]
    data = pcap_bytes(frames, [1.7e9, 1.7e9 + 1, 1.7e9 + 2])
    result = _run(tmp_path, sites, data, "mixed.pcap", keep_duplicates=True)  # the same record twice
    assert len(result.plots) == 2
    assert _reasons(result) == {"truncated_block": 2}
    assert list(result.rejected["packet"]) == [1, 3]


def test_truncated_gzip_imports_what_came_out(tmp_path, sites, blocks):
    data = gzip.compress(b"".join(blocks) * 20)
    result = _run(tmp_path, sites, data[: len(data) // 2], "half.ast.gz")
    assert 0 < len(result.plots) < 300
    assert "truncated" in " ".join(result.summary["files"][0]["notes"])


def test_random_damage_never_raises_anything_else(tmp_path, sites, recording):
    """Bytes overwritten at random in the standard recording, raw and pcap: an import, or the one
    exception class (when the damage hits the file's first header)."""
    rng = np.random.default_rng(3)
    for form, data in (("raw", recording.raw()), ("pcap", recording.pcap())):
        for trial in range(25):
            damaged = bytearray(data)
            for at in rng.integers(0, len(data), size=int(rng.integers(1, 40))):
                damaged[at] = int(rng.integers(0, 256))
            cut = bytes(damaged[: int(rng.integers(len(data) // 2, len(data) + 1))])
            try:
                result = _run(tmp_path, sites, cut, f"damaged.{form}")
            except AsterixImportError:
                continue
            assert result.summary["rejected"]["total"] == len(result.rejected)


@pytest.mark.parametrize("length", [12, 16, 20])
def test_pcapng_whose_last_packet_block_is_short(tmp_path, sites, length):
    """Issue 32: a last Enhanced Packet Block of 12-20 bytes (shorter than its fixed fields) is set
    aside with its offset; the packet before it is read."""
    from tests.io.asterix.repro import short_last_epb

    data = short_last_epb(length)
    result = _run(tmp_path, sites, data, "short.pcapng")
    assert _reasons(result) == {"truncated_packet": 1}
    assert result.rejected["offset"].iloc[0] == len(data) - length
    assert result.summary["files"][0]["packets"] == 1


def test_pcapng_packet_time_out_of_range(tmp_path, sites):
    """Issue 32: a packet time in the year 586524 is ignored with a note naming the file and the
    packet (the records are placed by their time of day), not a ValueError/OverflowError."""
    from tests.io.asterix.repro import out_of_range_time

    good = encode_recording(
        [(5.0, 48, SAC, SIC, cat048_record("1.32", SAC, SIC, 5.0, 100, 0, address=7))], DATE
    ).raw()
    result = _run(tmp_path, sites, out_of_range_time(good), "late.pcapng")
    assert len(result.plots) == 1
    notes = result.summary["files"][0]["notes"]
    assert any("late.pcapng" in n and "outside the years 1970-9999" in n and "packet 1" in n for n in notes)
    assert result.summary["time"]["reference_date"] is None


@pytest.mark.parametrize("seed", range(6))
def test_random_bytes_behind_a_good_first_header_are_refused(tmp_path, sites, seed):
    """Issue 31 item 2: random octets walk as data blocks of random categories; a raw file is
    judged by the share of its octets in blocks of known categories, and refused in one line."""
    rng = np.random.default_rng(seed)
    data = bytes([48, 0, 10]) + rng.integers(0, 256, 20000, dtype=np.uint8).tobytes()
    with pytest.raises(AsterixImportError, match="not an ASTERIX recording \\(only") as info:
        _run(tmp_path, sites, data, "random.ast")
    assert str(info.value).startswith(str(tmp_path / "random.ast")) and "\n" not in str(info.value)


def test_pcap_without_asterix_datagrams_is_refused(tmp_path, sites):
    """Issue 31 item 2: UDP traffic of something else (text, DNS-like bytes) is no ASTERIX recording."""
    from tests.io.asterix.containers import arp_frame, pcap_bytes, udp_frame

    rng = np.random.default_rng(5)
    frames = [udp_frame(b"GET / HTTP/1.1\r\nHost: x\r\n\r\n"), arp_frame()]
    frames += [udp_frame(bytes([0x12, 0x34, 0x01, 0x00]) + rng.bytes(40), dport=53) for _ in range(20)]
    with pytest.raises(AsterixImportError, match="not an ASTERIX recording \\(a pcap capture of 21 UDP"):
        _run(tmp_path, sites, pcap_bytes(frames, [1.7e9 + k for k in range(len(frames))]), "dns.pcap")
