"""``registration replay``: what arrives at a UDP (or TCP) receiver on 127.0.0.1 is the recording's
datagrams byte for byte and in order, at the recorded pace times the speed factor.

The expected datagrams are read by this file's own pcap reader (struct) from the sample capture,
encoded by libasterix for the raw recording and by pynmea2 for the NMEA log, never by the code
under test. The receivers ask for an 8 MiB receive buffer so that a burst at full speed is held
by the kernel until read (no datagram lost on loopback).
"""

from __future__ import annotations

import datetime as dt
import gzip
import os
import signal
import socket
import struct
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from registration.cli import main
from registration.live.replay import Timeline, parse_target, replay
from registration.live.replay.recordings import ReplayError, datagrams, recognise

pytest.importorskip("asterix")  # libasterix encodes the raw recording
pynmea2 = pytest.importorskip("pynmea2")

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = ROOT / "examples" / "recordings"
RCVBUF = 8 << 20


def _receiver(kind: int = socket.SOCK_DGRAM) -> socket.socket:
    s = socket.socket(socket.AF_INET, kind)
    s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, RCVBUF)
    s.bind(("127.0.0.1", 0))
    return s


def _drain(s: socket.socket) -> list[bytes]:
    """The datagrams waiting in ``s``."""
    s.setblocking(False)
    out = []
    try:
        while True:
            out.append(s.recv(1 << 16))
    except BlockingIOError:
        return out


def _pcap_payloads(data: bytes) -> tuple[list[bytes], list[float]]:
    """UDP payloads and capture times of an Ethernet/IPv4 pcap (microseconds, little-endian), read
    here with struct: the test's own reader."""
    assert data[:4] == b"\xd4\xc3\xb2\xa1"
    p, payloads, times = 24, [], []
    while p + 16 <= len(data):
        sec, usec, incl, _ = struct.unpack_from("<IIII", data, p)
        frame = data[p + 16 : p + 16 + incl]
        p += 16 + incl
        off, ethertype = 14, struct.unpack_from("!H", frame, 12)[0]
        while ethertype == 0x8100:
            ethertype, off = struct.unpack_from("!H", frame, off + 2)[0], off + 4
        if ethertype != 0x0800 or frame[off + 9] != 17:
            continue
        ihl = (frame[off] & 0x0F) * 4
        length = struct.unpack_from("!H", frame, off + ihl + 4)[0]
        payloads.append(frame[off + ihl + 8 : off + ihl + length])
        times.append(sec + usec * 1e-6)
    return payloads, times


def _raw_recording(n_blocks: int, step_s: float, t0_s: float = 43200.0) -> tuple[list[bytes], list[float]]:
    """Data blocks encoded by libasterix (CAT048 plots, every fifth block a CAT034 north marker)
    and the time of day of each block's first record."""
    from tests.io.asterix.encode import SPECS, cat034_record, cat048_record, spec

    blocks, times = [], []
    for k in range(n_blocks):
        t = t0_s + k * step_s
        if k % 5 == 4:
            records, cat = [cat034_record(SPECS[34], 1, 2, 1, t)], 34
        else:
            records = [cat048_record(SPECS[48], 1, 2, t + 0.01 * j, 1000 + j, 2000 * k + j) for j in range(3)]
            cat = 48
        blocks.append(spec(cat, SPECS[cat]).create(records).unparse().to_bytes())
        times.append(t)
    return blocks, times


def _nmea_lines(n_seconds: int) -> list[str]:
    """A bridge log written with pynmea2: per second a GGA, an HDT and a TTM; a ZDA first."""
    zda = pynmea2.ZDA("GP", "ZDA", ("120000.00", "01", "05", "2024", "00", "00"))
    lines = [str(pynmea2.HDT("HE", "HDT", ("10.0", "T"))), str(zda)]  # an HDT before any time
    for k in range(n_seconds):
        hhmmss = f"12{k // 60:02d}{k % 60:02d}.00"
        gga = ("4300.0000", "N", "00730.0000", "E", "1", "08", "0.9", "30.0", "M", "42.0", "M", "", "")
        lines.append(str(pynmea2.GGA("GP", "GGA", (hhmmss, *gga))))
        lines.append(str(pynmea2.HDT("HE", "HDT", (f"{k:.1f}", "T"))))
        ttm = ("01", "1.5", "45.0", "T", "10.0", "90.0", "T", "", "", "N", "", "T", "", hhmmss, "A")
        lines.append(str(pynmea2.TTM("RA", "TTM", ttm)))
    return lines


def test_the_sample_capture_arrives_byte_for_byte_in_order():
    expected, _ = _pcap_payloads(gzip.decompress((SAMPLES / "atc.pcap.gz").read_bytes()))
    with _receiver() as rx:
        stats = replay([SAMPLES / "atc.pcap.gz"], f"udp://127.0.0.1:{rx.getsockname()[1]}", np.inf)
        got = _drain(rx)
    assert len(expected) == 5064 and stats.datagrams == len(expected)
    assert got == expected
    assert stats.bytes == sum(map(len, expected))
    assert stats.data_s == pytest.approx(300.0, abs=0.5)


def test_ports_keep_only_those_destination_ports(tmp_path):
    from tests.io.asterix.containers import pcap_bytes, udp_frame

    frames = [udp_frame(bytes([48, 0, 4, k]), dport=8600 + k % 2) for k in range(6)]
    path = tmp_path / "two-ports.pcap"
    path.write_bytes(pcap_bytes(frames, [1714557600.0 + k for k in range(6)]))
    with _receiver() as rx:
        replay([path], f"udp://127.0.0.1:{rx.getsockname()[1]}", np.inf, ports=[8601])
        got = _drain(rx)
    assert got == [bytes([48, 0, 4, k]) for k in (1, 3, 5)]


def test_a_raw_recording_sends_one_datagram_per_data_block(tmp_path):
    blocks, times = _raw_recording(40, 0.5)
    plain, zipped = tmp_path / "rec.ast", tmp_path / "rec.ast.gz"
    plain.write_bytes(b"".join(blocks))
    zipped.write_bytes(gzip.compress(b"".join(blocks)))
    pieces = list(datagrams(recognise(plain)))
    assert recognise(zipped).kind == "raw"
    np.testing.assert_allclose(np.concatenate([p.time for p in pieces]), times, atol=1 / 128)
    with _receiver() as rx:  # two files as one stream: the second's times follow the first's
        stats = replay([plain, zipped], f"udp://127.0.0.1:{rx.getsockname()[1]}", np.inf)
        got = _drain(rx)
    assert got == blocks + blocks
    assert stats.went_back == len(blocks) - 1  # the second file starts again 19.5 s earlier


def test_the_nmea_log_goes_line_by_line_with_crlf(tmp_path):
    lines = _nmea_lines(20)
    path = tmp_path / "bridge.log"
    path.write_text("\n".join(lines[:5]) + "\n\n" + "\n".join(lines[5:]) + "\n")  # a blank line, LF ends
    zipped = tmp_path / "bridge.log.gz"
    zipped.write_bytes(gzip.compress(path.read_bytes()))
    assert recognise(zipped).kind == "nmea"
    piece = next(datagrams(recognise(path)))
    # the HDT before any time has none; then each line at the time of the last GGA/ZDA before it
    assert np.isnan(piece.time[0])
    np.testing.assert_allclose(
        piece.time[1:], [43200.0] * 4 + [43200.0 + k for k in range(1, 20) for _ in range(3)]
    )
    with _receiver() as rx:
        stats = replay([path], f"udp://127.0.0.1:{rx.getsockname()[1]}", np.inf)
        got = _drain(rx)
    assert got == [line.encode() + b"\r\n" for line in lines]
    assert stats.data_s == pytest.approx(19.0)


def test_the_nmea_log_goes_over_tcp(tmp_path):
    lines = _nmea_lines(10)
    path = tmp_path / "bridge.log"
    path.write_text("\r\n".join(lines) + "\r\n")
    server = socket.create_server(("127.0.0.1", 0))
    got = bytearray()

    def serve() -> None:
        conn, _ = server.accept()
        with conn:
            while chunk := conn.recv(1 << 16):
                got.extend(chunk)

    thread = threading.Thread(target=serve)
    thread.start()
    replay([path], f"tcp://127.0.0.1:{server.getsockname()[1]}", np.inf)
    thread.join(10)
    server.close()
    assert bytes(got) == path.read_bytes()


def _command(*args: str) -> list[str]:
    return [sys.executable, "-m", "registration", "replay", *args]


def _env() -> dict:
    return dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))


def test_speed_20_paces_by_the_recorded_times(tmp_path):
    """40 blocks 1 s apart (39 s of data) at x20: each arrives (t - t0) / 20 after the first, in
    1.95 s. Tolerance: never early by more than the first datagram's own lateness (a deadline is
    absolute and sleep does not return early; 30 ms covers the first one's delay on a loaded
    machine); late by at most 0.25 s (one slow wakeup on a busy 2-core machine: lateness does not
    add up, as every deadline counts from the start, so this bounds each datagram, not a sum)."""
    blocks, times = _raw_recording(40, 1.0)
    path = tmp_path / "rec.ast"
    path.write_bytes(b"".join(blocks))
    arrivals: list[float] = []
    with _receiver() as rx:
        rx.settimeout(20.0)

        def receive() -> None:
            while len(arrivals) < len(blocks):
                rx.recv(1 << 16)
                arrivals.append(time.monotonic())

        thread = threading.Thread(target=receive)
        thread.start()
        stats = replay([path], f"udp://127.0.0.1:{rx.getsockname()[1]}", 20.0)
        thread.join(20)
    offset = np.array(arrivals) - arrivals[0]
    expected = (np.array(times) - times[0]) / 20.0
    assert (offset - expected).min() > -0.03
    assert (offset - expected).max() < 0.25
    assert stats.datagrams == 40 and stats.data_s == pytest.approx(39.0)
    assert stats.speed == pytest.approx(20.0, rel=0.1)


def test_loop_runs_until_sigterm_and_exits_0(tmp_path):
    blocks, _ = _raw_recording(10, 0.1)
    path = tmp_path / "rec.ast"
    path.write_bytes(b"".join(blocks))
    with _receiver() as rx:
        proc = subprocess.Popen(
            _command(str(path), "--to", f"udp://127.0.0.1:{rx.getsockname()[1]}", "--speed", "10", "--loop"),
            env=_env(),
            stderr=subprocess.PIPE,
            text=True,
        )
        rx.settimeout(20.0)
        got = [rx.recv(1 << 16) for _ in range(25)]  # 0.9 s of data at x10: a pass in 0.09 s
        proc.send_signal(signal.SIGTERM)
        _, err = proc.communicate(timeout=20)
    assert proc.returncode == 0, err
    assert got[:20] == blocks + blocks
    line = err.strip().splitlines()[-1]  # datagrams, bytes, span, wall time, speed factor
    assert line.startswith("registration replay: sent ") and "s of recording in" in line
    assert "speed x" in line and "passes" in line and line.endswith("(stopped)")
    # the passes follow each other at the recorded pace; the wall time ends at the signal, at most
    # one interval (0.01 s) after the last send: a few % of a run of 0.25 s or more
    assert float(line.split("speed x")[1].split(",")[0]) == pytest.approx(10.0, rel=0.3)


def test_speed_max_runs_fast(tmp_path):
    blocks, _ = _raw_recording(500, 0.2)  # 100 s of data
    path = tmp_path / "rec.ast"
    path.write_bytes(b"".join(blocks))
    with _receiver() as rx:
        t = time.perf_counter()
        stats = replay([path], f"udp://127.0.0.1:{rx.getsockname()[1]}", np.inf)
        wall = time.perf_counter() - t
        got = _drain(rx)
    assert got == blocks
    assert wall < 5.0 and stats.speed > 20.0


def _arrivals(path: Path, n: int, speed: float, start_at: float) -> tuple[list[float], object]:
    """The time of day (Unix s) each of the ``n`` datagrams of a replay of ``path`` started with
    ``start_at`` arrived, and the replay's stats."""
    arrivals: list[float] = []
    with _receiver() as rx:
        rx.settimeout(20.0)

        def receive() -> None:
            while len(arrivals) < n:
                rx.recv(1 << 16)
                arrivals.append(time.time())

        thread = threading.Thread(target=receive)
        thread.start()
        stats = replay([path], f"udp://127.0.0.1:{rx.getsockname()[1]}", speed, start_at=start_at)
        thread.join(20)
    return arrivals, stats


def test_start_at_sends_the_first_datagram_then_and_paces_from_it(tmp_path):
    """--start-at 0.6 s ahead: nothing before it, then the recorded pace counted from it (the
    tolerances of the pacing test above); the wall time and speed reported run from the start."""
    blocks, times = _raw_recording(20, 1.0)
    path = tmp_path / "rec.ast"
    path.write_bytes(b"".join(blocks))
    start = time.time() + 0.6
    arrivals, stats = _arrivals(path, len(blocks), 20.0, start)
    late = np.array(arrivals) - (start + (np.array(times) - times[0]) / 20.0)
    assert late.min() > -0.03 and late.max() < 0.25
    assert stats.speed == pytest.approx(20.0, rel=0.1)


def test_a_replay_started_after_its_start_at_catches_up_and_keeps_in_step(tmp_path):
    """A replay whose process starts 0.5 s after the start agreed with another (a loaded machine):
    what was due meanwhile goes at once, the rest at the agreed deadlines, so the two stay in step."""
    blocks, times = _raw_recording(30, 1.0)
    path = tmp_path / "rec.ast"
    path.write_bytes(b"".join(blocks))
    start = time.time() - 0.5
    arrivals, _ = _arrivals(path, len(blocks), 20.0, start)
    due = start + (np.array(times) - times[0]) / 20.0
    late = np.array(arrivals) - due
    caught_up = due < arrivals[0]  # due before the replay began: sent in one burst
    assert 8 <= caught_up.sum() <= 12 and np.ptp(np.array(arrivals)[caught_up]) < 0.1
    assert late[~caught_up].min() > -0.03 and late[~caught_up].max() < 0.25


def test_start_at_with_speed_max_waits_then_sends_at_once(tmp_path):
    blocks, _ = _raw_recording(50, 1.0)
    path = tmp_path / "rec.ast"
    path.write_bytes(b"".join(blocks))
    start = time.time() + 0.4
    arrivals, _ = _arrivals(path, len(blocks), np.inf, start)
    assert arrivals[0] > start - 0.03 and arrivals[-1] - start < 0.5


@pytest.mark.parametrize("text", ["2024-05-01T10:00:00", "tomorrow", "nan"])
def test_a_start_at_without_a_utc_offset_or_not_a_time_exits_2(text, capsys):
    code = main(["replay", str(SAMPLES / "bridge.log"), "--to", "udp://127.0.0.1:4000", "--start-at", text])
    last = capsys.readouterr().err.strip().splitlines()[-1]
    assert code == 2 and "--start-at" in last and ("UTC offset" in last or "expected a time" in last)


@pytest.mark.parametrize(
    ("to", "words"),
    [
        ("http://127.0.0.1:4000", "unknown scheme 'http'"),
        ("udp://127.0.0.1", "no port"),
        ("udp://127.0.0.1:0", "is not a number 1-65535"),
        ("udp://radar.example:4000", "not an IP address or localhost"),
        ("127.0.0.1:4000", "expected udp://HOST:PORT"),
    ],
)
def test_bad_targets_exit_2_with_one_line(to, words, capsys):
    assert main(["replay", str(SAMPLES / "bridge.log"), "--to", to]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and words in err and err.startswith("registration replay: error:")


def test_a_file_that_is_no_recording_exits_2_naming_it(tmp_path, capsys):
    for name, data in (
        ("sites.csv", (SAMPLES / "SITES.csv").read_bytes()),
        ("noise.bin", bytes(range(256)) * 8),
    ):
        path = tmp_path / name
        path.write_bytes(data)
        assert main(["replay", str(path), "--to", "udp://127.0.0.1:4000"]) == 2
        err = capsys.readouterr().err.strip()
        assert "\n" not in err and f"{path}: neither a pcap/pcapng capture" in err
    assert main(["replay", str(tmp_path / "missing.pcap"), "--to", "udp://127.0.0.1:4000"]) == 2
    assert "missing.pcap: no such file" in capsys.readouterr().err


def test_tcp_is_for_nmea_logs_only():
    with pytest.raises(ReplayError, match="tcp:// sends NMEA logs only"):
        replay([SAMPLES / "atc.pcap.gz"], "tcp://127.0.0.1:4000")


def test_targets_parse():
    assert parse_target("udp://localhost:4000").host == "127.0.0.1"
    assert parse_target("udp://[::1]:4000").host == "::1"
    assert parse_target("TCP://10.0.0.1:10110").scheme == "tcp"


def test_a_pcapng_capture_is_replayed(tmp_path):
    from tests.io.asterix.containers import pcapng_bytes, udp_frame

    payloads = [bytes([48, 0, 5, k, k]) for k in range(4)]
    path = tmp_path / "cap.pcapng"
    path.write_bytes(
        pcapng_bytes(
            [udp_frame(p) for p in payloads], [dt.datetime(2024, 5, 1).timestamp() + k for k in range(4)]
        )
    )
    with _receiver() as rx:
        replay([path], f"udp://127.0.0.1:{rx.getsockname()[1]}", np.inf)
        assert _drain(rx) == payloads


def _all(path) -> tuple[list[bytes], np.ndarray]:
    """The payloads and times (placed on the replay's time line) of a recording."""
    payloads, times, timeline = [], [], Timeline()
    for piece in datagrams(recognise(path)):
        buf = bytes(piece.buf)
        payloads += [buf[a:b] for a, b in zip(piece.start.tolist(), piece.end.tolist())]
        times.append(timeline.place(piece)[0])
    return payloads, np.concatenate(times)


def test_small_pieces_give_the_same_datagrams_and_times(tmp_path, monkeypatch):
    """A file read in pieces of 3000 bytes (packets, blocks and lines cut by a piece's end) gives
    what it gives read whole."""
    import registration.live.replay.recordings as recordings

    blocks, _ = _raw_recording(60, 0.5)
    raw = tmp_path / "rec.ast.gz"
    raw.write_bytes(gzip.compress(b"".join(blocks)))
    log = tmp_path / "bridge.log"
    log.write_text("\n".join(_nmea_lines(60)) + "\n")
    cap = SAMPLES / "atc.pcap.gz"
    from tests.io.asterix.containers import pcapng_bytes, udp_frame

    ng = tmp_path / "cap.pcapng"
    ng_payloads = [bytes([48, 0, 3 + k % 200]) + bytes(k % 200) for k in range(300)]
    ng.write_bytes(pcapng_bytes([udp_frame(p) for p in ng_payloads], [1714557600.0 + k for k in range(300)]))
    whole = {p: _all(p) for p in (raw, log, cap, ng)}
    monkeypatch.setattr(recordings, "PIECE_BYTES", 3000)
    monkeypatch.setattr(recordings, "NMEA_PIECE_BYTES", 3000)
    for path, (payloads, times) in whole.items():
        got, got_times = _all(path)
        assert got == payloads, path
        np.testing.assert_array_equal(got_times, times)
    assert whole[raw][0] == blocks
    assert whole[ng][0] == ng_payloads
    np.testing.assert_allclose(whole[ng][1], 1714557600.0 + np.arange(300))


def test_a_block_too_big_for_udp_is_counted_not_sent(tmp_path):
    blocks, _ = _raw_recording(2, 1.0)
    big = bytes([48]) + (65530).to_bytes(2, "big") + bytes(65527)  # over the 65507-byte UDP limit
    path = tmp_path / "rec.ast"
    path.write_bytes(blocks[0] + big + blocks[1])
    with _receiver() as rx:
        stats = replay([path], f"udp://127.0.0.1:{rx.getsockname()[1]}", np.inf)
        assert _drain(rx) == blocks
    assert stats.too_big == 1 and stats.datagrams == 2 and stats.bytes == sum(map(len, blocks))


def test_max_rate_caps_the_payload_rate(tmp_path):
    """100 datagrams of 1000 bytes at 4 Mbit/s: 0.8 Mbit take 0.2 s at least (the first batch of
    RATE_BATCH goes at once: 0.168 s is the floor)."""
    from tests.io.asterix.containers import pcap_bytes, udp_frame

    payloads = [bytes([48, 3, 232]) + bytes([k]) * 997 for k in range(100)]
    path = tmp_path / "cap.pcap"
    path.write_bytes(pcap_bytes([udp_frame(p) for p in payloads], [1714557600.0] * 100))
    with _receiver() as rx:
        stats = replay([path], f"udp://127.0.0.1:{rx.getsockname()[1]}", np.inf, max_rate_mbps=4.0)
        assert _drain(rx) == payloads
    assert stats.wall_s > 0.165


def test_a_tcp_receiver_that_hangs_up_ends_the_replay_with_exit_2(tmp_path, capsys):
    path = tmp_path / "bridge.log"
    path.write_text("\n".join(_nmea_lines(600)) + "\n")
    server = socket.create_server(("127.0.0.1", 0))

    def hang_up() -> None:
        conn, _ = server.accept()
        conn.recv(100)  # the replay has connected and is sending: now hang up mid-stream
        conn.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))  # reset
        conn.close()

    thread = threading.Thread(target=hang_up)
    thread.start()
    to = f"tcp://127.0.0.1:{server.getsockname()[1]}"
    assert main(["replay", str(path), "--to", to, "--speed", "100"]) == 2
    thread.join(10)
    server.close()
    assert "the receiver closed the connection" in capsys.readouterr().err
