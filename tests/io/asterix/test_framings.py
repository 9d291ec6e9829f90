"""Recorder framings told by content: the standard recording's data blocks (encoded with libasterix)
wrapped here, from the layouts in docs/reference/asterix-framings.md, in each framing; the import
gives the plots of the same blocks read raw, and uses the recorder's time stamps. Files that walk
as no framing and not as plausible raw ASTERIX exit 2 "not an ASTERIX recording"."""

from __future__ import annotations

import datetime as dt
import gzip
import struct

import numpy as np
import pandas as pd
import pytest

from registration.cli import main
from registration.io.asterix import import_asterix
from registration.io.asterix.errors import AsterixImportError
from tests.io.asterix.encode import cat048_record, encode_recording
from tests.io.asterix.scenario import DATE

#: Seconds the recorder stamps each block after its emission time.
DELAY_S = 3.0


def _tod(t_s: float) -> float:
    return t_s % 86400.0


def gps(blocks: list, times: list, header: bytes = b" ") -> bytes:
    """2200-byte header, then each block and a 10-byte trailer (time of day in 1/128 s at 6-8)."""
    out = [header * (2200 // len(header))]
    for b, t in zip(blocks, times):
        out += [b, bytes([0xAA] * 6) + int(round(_tod(t) * 128)).to_bytes(3, "big") + b"\x00"]
    return b"".join(out)


def ioss(blocks: list, times: list, seq: bool = False) -> bytes:
    """Per record: length of the whole record, [sequence number], line, board, day, time (10 ms),
    the block, A5 A5 A5 A5."""
    out = []
    for k, (b, t) in enumerate(zip(blocks, times)):
        head = bytes([0, 3, 1]) + int(round(_tod(t) * 100)).to_bytes(3, "big")
        head = (struct.pack(">I", k) if seq else b"") + head
        out.append(struct.pack(">H", 2 + len(head) + len(b) + 4) + head + b + b"\xa5" * 4)
    return b"".join(out)


def oradis(blocks: list, times: list) -> bytes:
    """Per record: length of the whole record, 32-bit time (not read), the block."""
    return b"".join(struct.pack(">HI", 6 + len(b), k) + b for k, b in enumerate(blocks))


def rff(blocks: list, times: list) -> bytes:
    """128-byte header (start and end date-time as text), then per record ms since the start
    (big-endian), the block's length (little-endian), the block."""
    start = DATE.strftime("%Y-%m-%d") + " 00:00:00"
    head = start.encode().ljust(20, b"\0") + start.encode().ljust(20, b"\0") + bytes(88)
    return head + b"".join(
        struct.pack(">I", int(round(t * 1000))) + struct.pack("<H", len(b)) + b for b, t in zip(blocks, times)
    )


def _fcs(data: bytes) -> int:
    """FCS-16 of ISO/IEC 13239, bit by bit (reflected polynomial 0x8408, init and final XOR 0xFFFF)."""
    crc = 0xFFFF
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = (crc >> 1) ^ 0x8408 if crc & 1 else crc >> 1
    return crc ^ 0xFFFF


def hdlc(blocks: list, times: list) -> bytes:
    """Per frame: flag 7E, address 01, control 03, the block, FCS least significant octet first."""
    return b"".join(b"\x7e" + (f := b"\x01\x03" + b) + struct.pack("<H", _fcs(f)) for b in blocks)


WRAPPERS = {"gps": gps, "ioss": ioss, "ioss_seq": lambda b, t: ioss(b, t, True), "oradis": oradis}
WRAPPERS.update({"rff": rff, "hdlc": hdlc})
STAMPED = {"gps", "ioss", "ioss_seq", "rff"}


def test_fcs_of_the_check_string():
    assert _fcs(b"123456789") == 0x906E


@pytest.fixture(scope="module")
def raw_import(recording, sites, tmp_path_factory):
    path = tmp_path_factory.mktemp("raw") / "rec.ast"
    path.write_bytes(recording.raw())
    return import_asterix(path, sites)


def _import(tmp_path, sites, data: bytes, name: str, **kw):
    path = tmp_path / name
    path.write_bytes(data)
    return import_asterix(path, sites, **kw)


def _lag(result) -> float:
    return result.summary["sensors"]["R1"]["capture_minus_plot_time_s"]


@pytest.mark.parametrize("name", sorted(WRAPPERS))
def test_each_framing_gives_the_plots_of_the_raw_blocks(recording, sites, raw_import, tmp_path, name):
    stamps = [t + DELAY_S for t in recording.times]
    data = WRAPPERS[name](recording.blocks, stamps)
    result = _import(tmp_path, sites, gzip.compress(data) if name == "ioss" else data, f"rec.{name}")
    pd.testing.assert_frame_equal(result.plots, raw_import.plots)
    pd.testing.assert_frame_equal(result.reference, raw_import.reference)
    file = result.summary["files"][0]
    assert file["framing"] == name and file["data_blocks"] == raw_import.summary["files"][0]["data_blocks"]
    assert file["records"] == raw_import.summary["files"][0]["records"]
    if name in STAMPED:  # the recorder's stamps are the capture times: DELAY_S later gives DELAY_S more
        later = _import(tmp_path, sites, WRAPPERS[name](recording.blocks, [t + 2 for t in stamps]), "b")
        assert _lag(later) - _lag(result) == pytest.approx(2.0, abs=0.02)
        assert 0 < _lag(result) < 2 * DELAY_S
    else:
        assert _lag(result) is None
    if name == "rff":  # a date in the header: the reference day and the file placed by it
        assert result.summary["time"]["reference_date"] == DATE.isoformat()
        assert result.summary["time"]["files_placed_by_packet_times"] == 1
    else:
        assert result.summary["time"]["reference_date"] is None


@pytest.mark.parametrize("name", sorted(WRAPPERS))
def test_the_framing_named_reads_the_same(recording, sites, raw_import, tmp_path, name):
    data = WRAPPERS[name](recording.blocks, recording.times)
    result = _import(tmp_path, sites, data, "rec.bin", framing=name)
    pd.testing.assert_frame_equal(result.plots, raw_import.plots)


def test_gps_header_of_zeros_and_a_cut_last_record(recording, sites, raw_import, tmp_path):
    data = gps(recording.blocks, recording.times, header=b"\0")
    result = _import(tmp_path, sites, data[:-4], "cut.gps")
    assert result.summary["files"][0]["framing"] == "gps"
    file = result.summary["files"][0]
    assert file["framing_records"] == len(recording.blocks) - 1
    assert sum(file["records"].values()) < sum(raw_import.summary["files"][0]["records"].values())
    cut = result.rejected[result.rejected["reason_code"] == "truncated_packet"]
    assert len(cut) == 1 and cut["offset"].iloc[0] == len(data) - 10 - len(recording.blocks[-1])
    assert "GPS record" in cut["reason"].iloc[0]


def test_gps_recording_of_five_radars(sites, tmp_path):
    """Several SAC/SIC in one GPS file (the file that was read as random categories)."""
    radars = [(20, k) for k in range(1, 6)]
    messages = [
        (t, 48, sac, sic, cat048_record("1.32", sac, sic, t, 256 * (10 + sic), 4096 * sic, address=sic))
        for t in np.arange(100.0, 160.0, 4.0)
        for sac, sic in radars
    ]
    rec = encode_recording(messages, DATE, max_records=1)
    frame = pd.DataFrame(
        [(f"S{sic}", sac, sic, 45.0, 5.0, 100.0) for sac, sic in radars],
        columns=["sensor", "sac", "sic", "lat_deg", "lon_deg", "alt_m"],
    ).assign(sigma_range_m=30.0, sigma_bearing_deg=0.1)
    result = _import(tmp_path, frame, gps(rec.blocks, rec.times), "five.gps", keep_duplicates=True)
    assert result.summary["files"][0]["framing"] == "gps"
    assert result.summary["files"][0]["data_blocks"] == {"048": len(messages)}
    assert result.plots["sensor"].value_counts().to_dict() == {f"S{k}": 15 for k in range(1, 6)}


def _cli(tmp_path, data: bytes, sites_csv, capsys) -> tuple[int, str]:
    path = tmp_path / "strange.bin"
    path.write_bytes(data)
    out = tmp_path / "out"
    out.mkdir(exist_ok=True)
    (out / "keep.txt").write_text("as it was")
    code = main(["import", "asterix", str(path), "--sites", str(sites_csv), "--out", str(out)])
    assert sorted(p.name for p in out.iterdir()) == ["keep.txt"]
    return code, capsys.readouterr().err


@pytest.fixture
def sites_csv(sites, tmp_path):
    path = tmp_path / "sites.csv"
    sites.to_csv(path, index=False)
    return path


def _random_categories(rng) -> bytes:
    """Blocks whose lengths chain but whose categories are random (mostly unassigned)."""
    out = []
    for _ in range(400):
        body = rng.bytes(int(rng.integers(1, 40)))
        out.append(bytes([int(rng.choice([5, 6, 12, 13, 14, 27, 28, 99, 111, 200]))]))
        out.append(struct.pack(">H", 3 + len(body)) + body)
    return b"".join(out)


@pytest.mark.parametrize("kind", ["random", "first_block", "categories", "spaces_and_random"])
def test_what_walks_as_nothing_exits_2(tmp_path, sites_csv, capsys, kind):
    rng = np.random.default_rng(11)
    data = {
        "random": rng.bytes(30000),
        "first_block": bytes([48, 0, 12]) + bytes([0x80, 10, 1]) * 3 + rng.bytes(30000),
        "categories": _random_categories(rng),
        "spaces_and_random": b" " * 2200 + rng.bytes(30000),
    }[kind]
    code, err = _cli(tmp_path, data, sites_csv, capsys)
    assert code == 2 and "strange.bin: " in err and "not an ASTERIX recording (" in err
    with pytest.raises(AsterixImportError, match="not an ASTERIX recording \\(") as info:
        import_asterix(tmp_path / "strange.bin", sites_csv)
    assert all(f"{name}: " in str(info.value) for name in WRAPPERS) and "\n" not in str(info.value)


def test_raw_times_of_day_that_do_not_advance_are_refused(tmp_path, sites):
    """Known categories whose lengths chain, but times of day at random: no recording."""
    rng = np.random.default_rng(4)
    messages = [
        (float(t), 48, 10, 1, cat048_record("1.32", 10, 1, float(t), 2560, 100, address=5))
        for t in rng.uniform(0, 86000, 40)
    ]
    rec = encode_recording(messages, DATE, max_records=1)
    order = rng.permutation(len(rec.blocks))
    with pytest.raises(AsterixImportError, match="not an ASTERIX recording \\(the times of day"):
        _import(tmp_path, sites, b"".join(rec.blocks[k] for k in order), "shuffled.ast")


def test_midnight_and_a_replayed_tail_are_still_a_recording(tmp_path, sites):
    messages = [
        (float(t), 48, 10, 1, cat048_record("1.32", 10, 1, float(t) % 86400, 2560, 100, address=5))
        for t in np.arange(86300.0, 86500.0, 4.0)
    ]
    rec = encode_recording(messages, DATE, max_records=1)
    data = rec.raw() + b"".join(rec.blocks[:10])
    result = _import(tmp_path, sites, data, "midnight.ast", keep_duplicates=True)
    assert result.summary["files"][0]["framing"] == "netto" and len(result.plots) == len(messages) + 10


def test_unknown_framing_is_a_value_error(tmp_path, sites, recording):
    with pytest.raises(ValueError, match="framing: 'pcapx'"):
        _import(tmp_path, sites, recording.raw(), "x.ast", framing="pcapx")


def test_the_date_of_the_rff_header_forms(sites, tmp_path, recording):
    from registration.io.asterix.capture.framings import parse_header_time

    want = dt.datetime(2024, 5, 1, 12, 30, 5, tzinfo=dt.timezone.utc).timestamp()
    for text in ("2024-05-01 12:30:05", "01.05.2024 12:30:05", "2024/05/01T12:30:05.000\0"):
        assert parse_header_time(text) == pytest.approx(want)
    assert parse_header_time("recording of radar 3") is None


def _pcap_of(recording, wrap) -> bytes:
    """A pcap whose datagrams hold the recording's blocks, each wrapped by ``wrap``."""
    from tests.io.asterix.containers import pcap_bytes, udp_frame

    midnight = dt.datetime.combine(DATE, dt.time(), dt.timezone.utc).timestamp()
    frames, times = [], []
    for k, group in enumerate(recording.datagrams):
        frames.append(udp_frame(b"".join(wrap(recording.blocks[i], i) for i in group), ident=k))
        times.append(midnight + max(recording.times[i] for i in group) + 0.01)
    return pcap_bytes(frames, times)


@pytest.mark.parametrize("framing", ["auto", "oradis"])
def test_oradis_records_inside_pcap_datagrams(recording, sites, tmp_path, framing):
    """The asterix tool's -R: ORADIS records (length, 32-bit time, blocks) as UDP payloads."""
    plain = _import(tmp_path, sites, _pcap_of(recording, lambda b, i: b), "plain.pcap")
    wrapped = _pcap_of(recording, lambda b, i: struct.pack(">HI", 6 + len(b), i) + b)
    result = _import(tmp_path, sites, wrapped, "oradis.pcap", framing=framing)
    pd.testing.assert_frame_equal(result.plots, plain.plots)
    file = result.summary["files"][0]
    assert file["format"] == "pcap" and file["framing"] == "oradis"
    assert plain.summary["files"][0]["framing"] == "pcap"
    assert _lag(result) == pytest.approx(_lag(plain))
