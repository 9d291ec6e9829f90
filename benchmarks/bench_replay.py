#!/usr/bin/env python3
"""Speed of ``registration replay --speed max`` (``registration.live.replay.replay``) on loopback.

Run from a checkout::

    python3 benchmarks/bench_replay.py               # 200 000 datagrams per recording
    python3 benchmarks/bench_replay.py --datagrams 50000 --repeat 5

Three recordings are written once into a temporary folder from the sample recordings of
``examples/recordings/``, repeated to ``--datagrams``: a pcap capture (the sample's UDP datagrams,
ASTERIX of three radars and ADS-B, in Ethernet/IPv4 frames written with struct by the tests'
``containers`` module), the same data blocks as a raw ASTERIX recording, and the NMEA bridge log
(one datagram per line). Each is sent as fast as possible to a UDP socket on 127.0.0.1 that a
receiver process drains and counts. Interleaved ``--repeat`` times (common.interleave) with a
baseline: ``socket.sendto`` of the same payloads from a list of bytes in a bare loop (the floor of
one system call per datagram from Python).

Printed: datagrams per second of each (sent; the receiver's count too), the replay over the
baseline. The aim: well above 50 000 datagrams/s. Figures: benchmarks/results/replay.json.
"""

from __future__ import annotations

import argparse
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from common import ROOT, Timed, add_arguments, interleave, median, paired_ratio, summary, write

from registration.live.replay import replay
from registration.live.replay.recordings import datagrams, recognise
from tests.io.asterix.containers import pcap_bytes, udp_frame  # the tests' struct writer

SAMPLES = ROOT / "examples" / "recordings"
#: The receiver: drains a UDP socket (8 MiB buffer) and prints its count once idle for 0.5 s.
RECEIVER = """
import socket, sys
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 8 << 20)
s.bind(("127.0.0.1", 0))
print(s.getsockname()[1], flush=True)
n, rounds = 0, 0
s.settimeout(0.5)
while True:
    try:
        s.recv(65536)
        n += 1
    except socket.timeout:
        if n:
            print(n, flush=True)
            n = 0
"""


def _payloads(path: Path) -> list[bytes]:
    out = []
    for piece in datagrams(recognise(path)):
        buf = bytes(piece.buf)
        out += [buf[a:b] for a, b in zip(piece.start.tolist(), piece.end.tolist())]
    return out


def _recordings(folder: Path, n: int) -> dict[str, tuple[Path, list[bytes]]]:
    """name -> (file, its datagrams), each of ``n`` datagrams."""
    blocks = _payloads(SAMPLES / "atc.pcap.gz")
    lines = _payloads(SAMPLES / "bridge.log")
    reps = lambda items: (items * (n // len(items) + 1))[:n]  # noqa: E731
    pcap, raw, log = reps(blocks), reps(blocks), reps(lines)
    out = {
        "pcap": (folder / "atc.pcap", pcap),
        "raw ASTERIX": (folder / "atc.ast", raw),
        "NMEA log": (folder / "bridge.log", log),
    }
    t0 = 1714557600.0
    out["pcap"][0].write_bytes(pcap_bytes([udp_frame(p) for p in pcap], [t0 + k * 1e-3 for k in range(n)]))
    out["raw ASTERIX"][0].write_bytes(b"".join(raw))
    out["NMEA log"][0].write_bytes(b"".join(log))
    return out


def _bare(payloads: list[bytes], port: int) -> Timed:
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    addr = ("127.0.0.1", port)
    t = time.perf_counter()
    for p in payloads:
        s.sendto(p, addr)
    seconds = time.perf_counter() - t
    s.close()
    return Timed(seconds, len(payloads))


def _replay(path: Path, port: int) -> Timed:
    stats = replay([path], f"udp://127.0.0.1:{port}", float("inf"))
    return Timed(stats.wall_s, stats.datagrams)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--datagrams", type=int, default=200_000, help="datagrams per recording (default 200000)")
    ap.add_argument("--repeat", type=int, default=3, help="runs of each case, alternated (default 3)")
    add_arguments(ap)
    args = ap.parse_args(argv)
    if args.tiny:
        args.datagrams, args.repeat = 5000, 1
    receiver = subprocess.Popen(
        [sys.executable, "-c", RECEIVER], stdout=subprocess.PIPE, text=True, bufsize=1
    )
    assert receiver.stdout is not None
    port = int(receiver.stdout.readline())
    try:
        with tempfile.TemporaryDirectory() as folder:
            recs = _recordings(Path(folder), args.datagrams)
            print(f"{args.datagrams} datagrams per recording, sent to 127.0.0.1:{port}")
            contenders = {
                f"replay {name}": (lambda p=path: _replay(p, port)) for name, (path, _) in recs.items()
            }
            contenders["bare sendto loop"] = lambda: _bare(recs["pcap"][1], port)
            times, values = interleave(contenders, args.repeat, warmup=0)
    finally:
        time.sleep(0.7)
        receiver.terminate()
        out, _ = receiver.communicate(timeout=10)
    received = sum(int(x) for x in out.split()) if out.strip() else 0
    rates = {name: values[name] / median(ts) for name, ts in times.items()}  # a datagram may hold 2 blocks
    for name, ts in times.items():
        print(
            f"  {name:22s} best {min(ts):6.3f} s  median {median(ts):6.3f} s  {rates[name]:9.0f} datagrams/s"
        )
    sent = sum(int(v) for v in values.values()) * args.repeat  # type: ignore[call-overload]
    print(f"received {received} of {sent} sent (loopback; a lost datagram is the receiver's buffer)")
    ratios = {
        name: paired_ratio(times, name, "bare sendto loop") for name in times if name.startswith("replay")
    }
    for name, r in ratios.items():
        print(f"  {name} / bare sendto loop: {r:.2f}")
    slowest = min(v for k, v in rates.items() if k.startswith("replay"))
    verdict = "met" if slowest > 50_000 else "NOT met"
    print(f"slowest replay: {slowest:.0f} datagrams/s (aim: well above 50 000: {verdict})")
    figures = {
        "seconds": summary(times),
        "datagrams_per_s": rates,
        "over_bare_sendto": ratios,
        "received": received,
        "sent": sent,
    }
    write("replay", args, {"datagrams": args.datagrams, "repeat": args.repeat}, figures)


if __name__ == "__main__":
    main()
