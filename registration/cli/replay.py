"""``registration replay``: send recordings to UDP (or an NMEA log to TCP) at their recorded pace,
to feed a live service (``registration serve``) or a test with real traffic.

What is sent (:mod:`registration.live.replay`): each UDP datagram of a pcap/pcapng capture (its
payload as captured), each data block of a raw ASTERIX recording, each line of an NMEA 0183 log;
paced by the recorded times times ``--speed``. At the end (or at Ctrl-C or SIGTERM, which end a
replay normally, exit code 0) one line on standard error: datagrams and bytes sent, the recorded
time span, the wall time and the speed factor achieved.
"""

from __future__ import annotations

import argparse
import datetime as dt
import math
import signal
import sys
from pathlib import Path

from registration.cli.errors import CommandError

__all__ = ["HELP", "add_arguments", "run"]

HELP = (
    "send recordings (pcap/pcapng captures, raw ASTERIX, NMEA 0183 logs) to UDP (NMEA also TCP) at their "
    "recorded pace, for a live service or a test"
)


def _speed(text: str) -> float:
    """A speed factor > 0; 0 or 'max': as fast as possible (inf)."""
    if text.strip().lower() in ("max", "0", "0.0", "inf"):
        return math.inf
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not value > 0:
        raise argparse.ArgumentTypeError(
            f"expected a factor > 0, or 0 or max (as fast as possible), got {text!r}"
        )
    return value


def _ports(text: str) -> list[int]:
    try:
        ports = [int(p) for p in text.split(",") if p.strip()]
    except ValueError:
        ports = []
    if not ports or not all(0 < p < 65536 for p in ports):
        raise argparse.ArgumentTypeError(
            f"expected UDP port numbers 1-65535 separated by commas, got {text!r}"
        )
    return ports


def _rate(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (value > 0 and math.isfinite(value)):
        raise argparse.ArgumentTypeError(f"expected a rate in Mbit/s > 0, got {text!r}")
    return value


def _start_at(text: str) -> float:
    """A time of day: Unix seconds, or ISO 8601 with its UTC offset (2024-05-01T10:00:00Z)."""
    try:
        return float(text)
    except ValueError:
        pass
    try:
        when = dt.datetime.fromisoformat(text.strip())
    except ValueError:
        when = None
    if when is None or when.tzinfo is None:
        raise argparse.ArgumentTypeError(
            f"expected Unix seconds or an ISO 8601 time with its UTC offset (2024-05-01T10:00:00Z), "
            f"got {text!r}"
        )
    return when.timestamp()


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "recordings",
        nargs="+",
        type=Path,
        metavar="RECORDING",
        help="pcap/pcapng captures, raw ASTERIX recordings or NMEA 0183 logs (gzip or not), sent in "
        "the order given as one stream",
    )
    p.add_argument(
        "--to",
        required=True,
        metavar="URL",
        help="udp://HOST:PORT (tcp://HOST:PORT for NMEA logs); HOST an IP address ([...] for IPv6) "
        "or localhost",
    )
    p.add_argument(
        "--speed",
        type=_speed,
        default=1.0,
        metavar="X",
        help="times the recorded pace; 0 or max: as fast as possible",
    )
    p.add_argument("--loop", action="store_true", help="start again at the end, until Ctrl-C or SIGTERM")
    p.add_argument(
        "--ports",
        type=_ports,
        default=None,
        metavar="PORT[,PORT...]",
        help="UDP destination ports sent from captures (default: all)",
    )
    p.add_argument(
        "--max-rate-mbps",
        type=_rate,
        default=None,
        metavar="MBPS",
        help="cap on the payload rate, Mbit/s (default: none)",
    )
    p.add_argument(
        "--start-at",
        type=_start_at,
        default=None,
        metavar="TIME",
        help="send the first datagram at this time (Unix seconds, or ISO 8601 with its UTC offset) and "
        "count every deadline from it: replays to several inputs started with the same TIME stay in "
        "step (default: at once)",
    )
    p.add_argument("--progress", action="store_true", help="show a progress bar over the files' sizes")


def _terminate(signum: int, frame: object) -> None:
    raise KeyboardInterrupt


def run(args: argparse.Namespace) -> int:
    """Send the recordings; Ctrl-C and SIGTERM end the replay with exit code 0 and the summary line."""
    for path in args.recordings:
        if path.is_dir():
            raise CommandError(f"{path}: a directory; give the recording's files")
        if not path.is_file():
            raise CommandError(
                f"{path}: no such file" if not path.exists() else f"{path}: not a regular file"
            )
    from registration.live.replay import Replayer

    replayer = Replayer(
        args.recordings,
        args.to,
        args.speed,
        loop=args.loop,
        ports=args.ports,
        max_rate_mbps=args.max_rate_mbps,
        progress=args.progress,
        start_at=args.start_at,
    )
    previous = signal.signal(signal.SIGTERM, _terminate)
    stopped = ""
    try:
        replayer.run()
    except KeyboardInterrupt:
        stopped = " (stopped)"
    finally:
        signal.signal(signal.SIGTERM, previous)
    for note in replayer.stats.notes:
        print(f"{args._prog}: note: {note}", file=sys.stderr)
    print(f"{args._prog}: {replayer.stats.line(replayer.target.text)}{stopped}", file=sys.stderr)
    return 0
