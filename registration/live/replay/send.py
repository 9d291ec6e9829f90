"""Replay recordings to the network at their recorded pace (``registration replay``,
docs/howto/replay.md).

The recordings (:mod:`registration.live.replay.recordings`: pcap/pcapng captures, raw ASTERIX, NMEA 0183
logs) are sent in the order given as one stream: each datagram at ``t0_wall + (t - t0) / speed`` on
a monotonic clock, ``t`` its recorded time and ``t0`` the first one's, every deadline counted from
the start (no drift). Times of day are placed on the day nearest to the time before them, across
files (a capture's UTC times and a raw recording's times of day then share one axis). A datagram
whose time goes back (a replayed tail, a late block) is sent at once and counted. ``speed`` inf
sends as fast as the socket takes them. ``loop`` starts again at the end, the next pass's first
datagram due when the last one of the pass before was.
"""

from __future__ import annotations

import errno
import ipaddress
import math
import re
import socket
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Iterable, Sequence

import numpy as np

from registration.core.progress import progress_bar
from registration.io.nmea.clock import unwrap_days
from registration.live.replay.recordings import Recording, ReplayError, datagrams, recognise
from registration.live.replay.stream import Datagrams

__all__ = ["Target", "parse_target", "ReplayStats", "Timeline", "Replayer", "replay", "RATE_BATCH"]

#: Datagrams sent between two checks of the rate limit (``max_rate_mbps``).
RATE_BATCH = 16
#: The socket send buffer asked for (octets): a burst at full speed does not block on it.
SEND_BUFFER = 4 << 20


@dataclass(frozen=True)
class Target:
    """Where to send: ``scheme`` ('udp' or 'tcp'), ``host`` (an IP address), ``port``; ``text`` as given."""

    scheme: str
    host: str
    port: int
    text: str

    @property
    def family(self) -> int:
        return socket.AF_INET6 if ":" in self.host else socket.AF_INET


def parse_target(text: str) -> Target:
    """``udp://HOST:PORT`` or ``tcp://HOST:PORT``; HOST an IPv4 address, an IPv6 address in
    brackets or ``localhost`` (no name is looked up). :class:`ReplayError` otherwise."""
    what = f"--to {text!r}"
    m = re.fullmatch(r"([A-Za-z][A-Za-z0-9+.-]*)://(.*)", text)
    if m is None:
        raise ReplayError(f"{what}: expected udp://HOST:PORT or tcp://HOST:PORT")
    scheme, rest = m.group(1).lower(), m.group(2)
    if scheme not in ("udp", "tcp"):
        raise ReplayError(f"{what}: unknown scheme {scheme!r}; expected udp:// or tcp:// (NMEA logs only)")
    v6 = re.fullmatch(r"\[([^\]]*)\](?::(.*))?", rest)
    host, sep, port = (
        (v6.group(1), ":" if v6.group(2) is not None else "", v6.group(2) or "")
        if v6
        else (rest.rpartition(":") if ":" in rest else (rest, "", ""))
    )
    if not sep or not port:
        raise ReplayError(f"{what}: no port; expected {scheme}://HOST:PORT")
    if not port.isdigit() or not 0 < int(port) < 65536:
        raise ReplayError(f"{what}: port {port!r} is not a number 1-65535")
    if host.lower() == "localhost":
        host = "127.0.0.1"
    try:
        address = ipaddress.ip_address(host)
    except ValueError:
        raise ReplayError(
            f"{what}: host {host!r} is not an IP address or localhost (names are not looked up)"
        ) from None
    return Target(scheme, str(address), int(port), text)


@dataclass
class ReplayStats:
    """What a replay sent: ``datagrams`` and ``bytes`` (payloads), ``data_s`` the recorded time
    span replayed (s, summed over the passes), ``wall_s`` the wall time from the first send (s),
    ``passes`` begun,
    ``went_back`` datagrams sent at once because their time went back, ``too_big`` datagrams over
    the UDP limit (not sent), ``refused`` sends refused by the receiver's host (ICMP port
    unreachable; not sent), ``notes`` about the recordings."""

    datagrams: int = 0
    bytes: int = 0
    data_s: float = 0.0
    wall_s: float = 0.0
    passes: int = 0
    went_back: int = 0
    too_big: int = 0
    refused: int = 0
    notes: list[str] = field(default_factory=list)

    @property
    def speed(self) -> float:
        """The speed factor achieved: recorded time replayed over wall time."""
        return self.data_s / self.wall_s if self.wall_s > 0 else math.nan

    def line(self, target: str) -> str:
        """One line: datagrams and bytes sent, data span, wall time, speed factor, what went astray."""
        text = (
            f"sent {self.datagrams} datagrams ({self.bytes} bytes) to {target}: {self.data_s:.3f} s of "
            f"recording in {self.wall_s:.3f} s wall time, speed x{self.speed:.3g}"
        )
        if self.passes > 1:
            text += f", {self.passes} passes"
        extra = [
            f"{n} {what}"
            for n, what in (
                (self.went_back, "sent at once (their time went back)"),
                (self.too_big, "too big for UDP (not sent)"),
                (self.refused, "refused by the receiver's host (not sent)"),
            )
            if n
        ]
        return text + ("; " + ", ".join(extra) if extra else "")


class Timeline:
    """Recorded times placed on one axis (s) across the files of a pass: times of day on the day
    nearest to the time before them, a missing time (NaN) taking the one before; ``last`` and
    ``latest`` (the maximum) so far."""

    def __init__(self) -> None:
        self.last = math.nan
        self.latest = -math.inf

    def place(self, piece: Datagrams) -> tuple[np.ndarray, np.ndarray]:
        """The times (K,) of ``piece`` on the axis (NaN before the first time of the pass), and
        whether each went back (K,) bool: earlier than a time before it."""
        t = np.array(piece.time, dtype=np.float64)
        ok = np.isfinite(t)
        if piece.time_of_day and ok.any():
            before = [] if math.isnan(self.last) else [self.last]
            t[ok] = unwrap_days(np.concatenate([before, t[ok]]))[len(before) :]
        if not ok.all():  # forward fill: a datagram without a time is at the one before
            idx = np.maximum.accumulate(np.where(ok, np.arange(t.size), -1))
            t = np.where(idx >= 0, t[np.maximum(idx, 0)], self.last)
        if not t.size or np.isnan(t).all():
            return t, np.zeros(t.size, dtype=bool)
        running = np.maximum.accumulate(np.concatenate([[self.latest], np.nan_to_num(t, nan=-math.inf)]))
        self.latest, self.last = float(running[-1]), float(t[-1])
        return t, t < running[:-1]


class _Sender:
    """A UDP socket (one datagram per send) or a TCP connection (the bytes of the lines due)."""

    def __init__(self, target: Target) -> None:
        self.target, self.addr = target, (target.host, target.port)
        if target.scheme == "tcp":
            try:
                self.sock = socket.create_connection(self.addr, timeout=10.0)
            except OSError as exc:
                raise ReplayError(f"--to {target.text}: cannot connect: {exc.strerror or exc}") from exc
            self.sock.settimeout(None)
        else:
            self.sock = socket.socket(target.family, socket.SOCK_DGRAM)
            self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, SEND_BUFFER)
            self.sock.connect(self.addr)  # send() without an address to parse: ~20 % faster

    def send(self, mv: memoryview, starts: list, ends: list, stats: ReplayStats) -> int:
        """Send datagrams [starts[k], ends[k]) of ``mv``; returns the bytes not sent."""
        if self.target.scheme == "tcp":  # the lines of a piece lie end to end
            try:
                self.sock.sendall(mv[starts[0] : ends[-1]])
            except OSError as exc:  # not standard output's broken pipe: the receiver hung up
                raise ReplayError(
                    f"--to {self.target.text}: the receiver closed the connection ({exc.strerror or exc})"
                ) from None
            return 0
        send, lost = self.sock.send, 0
        for a, b in zip(starts, ends):
            try:
                send(mv[a:b])
            except OSError as exc:
                if exc.errno == errno.EMSGSIZE:
                    stats.too_big += 1
                elif exc.errno == errno.ECONNREFUSED:
                    stats.refused += 1
                else:
                    raise
                lost += b - a
        return lost

    def close(self) -> None:
        self.sock.close()


class Replayer:
    """A replay of ``recordings`` (paths, or :class:`Recording`) to ``target``; :meth:`run` sends
    them and can be interrupted (KeyboardInterrupt) with ``stats`` holding what was sent.
    Arguments as :func:`replay`'s; ``clock``, ``sleep`` and ``now`` (the time of day, Unix s, that
    ``start_at`` is read on) can be replaced in tests."""

    def __init__(
        self,
        recordings: Sequence[str | Path | Recording],
        target: str | Target,
        speed: float = 1.0,
        *,
        loop: bool = False,
        ports: Iterable[int] | None = None,
        max_rate_mbps: float | None = None,
        progress: bool = False,
        start_at: float | None = None,
        clock: Callable[[], float] = time.monotonic,
        sleep: Callable[[float], None] = time.sleep,
        now: Callable[[], float] = time.time,
    ) -> None:
        if not recordings:
            raise ReplayError("no recording given")
        if not speed > 0:
            raise ReplayError(f"--speed {speed!r}: expected a factor > 0 (inf: as fast as possible)")
        if max_rate_mbps is not None and not max_rate_mbps > 0:
            raise ReplayError(f"--max-rate-mbps {max_rate_mbps!r}: expected a rate > 0 (Mbit/s)")
        self.target = parse_target(target) if isinstance(target, str) else target
        self.recordings = [r if isinstance(r, Recording) else recognise(r) for r in recordings]
        if self.target.scheme == "tcp":
            other = [r for r in self.recordings if r.kind != "nmea"]
            if other:
                raise ReplayError(
                    f"--to {self.target.text}: tcp:// sends NMEA logs only; {other[0].path} is a "
                    f"{other[0].kind} recording (use udp://)"
                )
        self.speed, self.loop, self.progress = float(speed), loop, progress
        self.ports = list(ports) if ports else None
        self.rate = None if max_rate_mbps is None else max_rate_mbps * 1e6 / 8.0  # bytes/s
        self.clock, self.sleep = clock, sleep
        self.stats = ReplayStats()
        self._t0_wall = self._t0_data = math.nan
        if start_at is not None:  # the first datagram is due then, on the monotonic clock
            if not math.isfinite(start_at):
                raise ReplayError(f"--start-at {start_at!r}: expected a time (Unix seconds)")
            self._t0_wall = self.clock() + (float(start_at) - now())
        self._rate_next = -math.inf
        self._started = math.nan  # the clock at the first send
        self._first, self._latest = math.nan, -math.inf  # the times sent in this pass

    def run(self) -> ReplayStats:
        """Send the recordings (every pass when looping); returns :attr:`stats`."""
        sender = _Sender(self.target)
        total = sum(Path(r.path).stat().st_size for r in self.recordings)
        bar = progress_bar(self.progress, "replay", total=total, unit="B", unit_scale=True)
        try:
            while True:
                timeline = Timeline()
                self.stats.passes += 1
                sent_before = self.stats.datagrams
                for rec in self.recordings:
                    done = 0
                    for piece in datagrams(rec, self.ports):
                        self._send_piece(sender, piece, *timeline.place(piece))
                        bar.update(piece.position - done)
                        done = piece.position
                latest = self._end_pass()
                if not self.loop or self.stats.datagrams == sent_before:
                    break
                self._next_pass(latest)
                bar.reset(total)
        finally:
            self._end_pass()  # a pass cut short
            self.stats.wall_s = self.clock() - self._started if not math.isnan(self._started) else 0.0
            bar.close()
            sender.close()
        return self.stats

    def _end_pass(self) -> float:
        """Count the recorded time span sent in this pass; returns the latest time sent."""
        latest = self._latest
        if not math.isnan(self._first):
            self.stats.data_s += self._latest - self._first
        self._first, self._latest = math.nan, -math.inf
        return latest

    def _sent(self, t: np.ndarray, running: np.ndarray, k: int, j: int) -> None:
        """Datagrams ``k .. j - 1`` of times ``t`` (running maximum ``running``) were sent."""
        top = float(running[j - 1])
        if math.isnan(top):
            return
        if math.isnan(self._first):
            sent = t[k:j]
            self._first = float(sent[np.isfinite(sent)][0])
        self._latest = max(self._latest, top)

    def _next_pass(self, latest: float) -> None:
        """The next pass starts when the last datagram of this one (recorded at ``latest``) was due."""
        if not math.isnan(self._t0_data):
            self._t0_wall += (latest - self._t0_data) / self.speed
        self._t0_data = math.nan

    def _deadlines(self, t: np.ndarray) -> np.ndarray | None:
        """Wall deadlines (K,) of times ``t`` (-inf: at once); None when sending as fast as possible."""
        if math.isinf(self.speed):  # as fast as possible, from ``start_at`` if given
            return None if math.isnan(self._t0_wall) else np.full(t.size, self._t0_wall)
        ok = np.isfinite(t)
        if math.isnan(self._t0_data):
            if not ok.any():
                return np.full(t.size, -math.inf)
            self._t0_data = float(t[ok][0])
            if math.isnan(self._t0_wall):
                self._t0_wall = self.clock()
        return np.where(ok, self._t0_wall + (t - self._t0_data) / self.speed, -math.inf)

    def _send_piece(self, sender: _Sender, piece: Datagrams, t: np.ndarray, back: np.ndarray) -> None:
        """Send the datagrams of ``piece`` (times ``t``; ``back``: the time went back), each when
        due: those due at once in one batch, then a sleep until the next deadline (the rate limit
        holds batches of :data:`RATE_BATCH`)."""
        n = piece.size
        if n == 0:
            return
        mv = memoryview(piece.buf).cast("B")  # type: ignore[arg-type]  # a uint8 array is a buffer
        starts, ends = piece.start.tolist(), piece.end.tolist()
        cum = np.concatenate([[0], np.cumsum(piece.end - piece.start)])
        back_cum = np.concatenate([[0], np.cumsum(back)])
        running = np.fmax.accumulate(t)
        if math.isnan(self._started):  # the first send: now, or the start asked for
            self._started = self.clock() if math.isnan(self._t0_wall) else max(self.clock(), self._t0_wall)
        deadlines = self._deadlines(t)
        due = None if deadlines is None else np.maximum.accumulate(deadlines)
        batch = RATE_BATCH if self.rate else n
        k = 0
        while k < n:
            wait = max(-math.inf if due is None else float(due[k]), self._rate_next)
            now = self.clock()
            if wait > now:
                self.sleep(wait - now)
                now = self.clock()
            j = n if due is None else max(int(np.searchsorted(due, now, side="right")), k + 1)
            j = min(j, k + batch)
            failed = self.stats.too_big + self.stats.refused
            lost = sender.send(mv, starts[k:j], ends[k:j], self.stats)
            size = int(cum[j] - cum[k])
            if self.rate:
                self._rate_next = max(self._rate_next, now) + size / self.rate
            self.stats.bytes += size - lost
            self.stats.datagrams += j - k - (self.stats.too_big + self.stats.refused - failed)
            self.stats.went_back += int(back_cum[j] - back_cum[k])
            self._sent(t, running, k, j)
            k = j


def replay(
    recordings: Sequence[str | Path],
    target: str,
    speed: float = 1.0,
    *,
    loop: bool = False,
    ports: Iterable[int] | None = None,
    max_rate_mbps: float | None = None,
    progress: bool = False,
    start_at: float | None = None,
) -> ReplayStats:
    """Send ``recordings`` (paths, in order, as one stream) to ``target`` (``udp://HOST:PORT``, or
    ``tcp://HOST:PORT`` for NMEA logs) at ``speed`` times their recorded pace (inf: as fast as
    possible); ``loop``: again and again until interrupted; ``ports``: UDP destination ports kept
    from captures (None: all); ``max_rate_mbps``: a cap on the payload rate (Mbit/s);
    ``progress``: a bar over the files' sizes (:func:`registration.core.progress.progress_bar`);
    ``start_at``: the time (Unix s) the first datagram is due (default: at once), every deadline
    counted from it: replays started apart with the same ``start_at`` stay in step (one that starts
    after it sends what is already due at once). With ``speed`` inf: nothing is sent before it.
    :class:`~registration.live.replay.recordings.ReplayError` (a ValueError) naming the file or option for
    a recording that is none of the kinds read or a bad target."""
    return Replayer(
        recordings,
        target,
        speed,
        loop=loop,
        ports=ports,
        max_rate_mbps=max_rate_mbps,
        progress=progress,
        start_at=start_at,
    ).run()
