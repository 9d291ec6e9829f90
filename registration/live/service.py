"""``registration serve``: the live service (docs/howto/serve.md).

Threads: one receives the UDP datagrams of every ``--asterix`` input (and of a ``--nmea udp://``
input) into a list (nothing else, so that the sockets are drained while the rest works; large
receive buffers take the bursts); one reads a ``--nmea tcp://`` or ``tcp-listen://`` input
(:mod:`registration.live.inputs.tcp`); the HTTP server answers from the latest snapshot; the main
thread runs rounds every ``tick_s`` (back to back while work waits): it takes the
datagrams received, imports them (:class:`~registration.live.inputs.asterix.AsterixStream`), sends the
corrected plots on, imports the ship's NMEA lines (:class:`~registration.live.inputs.bridge.Bridge`),
feeds the estimator (:class:`~registration.live.estimator.LiveEstimator`),
sends CAT063 every ``cat063_period_s``, writes the state every ``checkpoint_s`` and builds the next
snapshot. SIGTERM and SIGINT end the service after its current round, with a last checkpoint.
"""

from __future__ import annotations

import selectors
import signal
import socket
import struct
import sys
import threading
import time
from collections import Counter, deque
from typing import Callable

from registration.io.asterix.tables.sites import read_sites
from registration.live.config import Endpoint, ServeConfig
from registration.live.estimator import LiveEstimator
from registration.live.http.api import SensorActivity, Snapshot, build_snapshot
from registration.live.http.server import start_http
from registration.live.inputs.asterix import AsterixStream, IngestCounters, StreamBatch, split_batch
from registration.live.inputs.bridge import Bridge
from registration.live.inputs.merge import TimeMerge
from registration.live.inputs.tcp import TcpClient, TcpServer
from registration.live.outputs import cat063_message, corrected_lines, plot_corrections, ttm_corrections
from registration.live.state import load_state, save_state

__all__ = ["Service", "SILENT_S", "RECEIVE_BUFFER"]

#: A sensor without a plot for this long (s of data time) while data flows is reported silent.
SILENT_S = 60.0
#: A round feeds the estimator for at most this long (s), so that the inputs are drained and
#: imported on time when the estimator lags (a replay at full speed); the rest waits its turn.
ESTIMATE_BUDGET_S = 0.5
#: The answers are built again at most this often (s of wall time).
SNAPSHOT_S = 0.25
#: A round imports at most this many datagrams (the rest wait for the next rounds).
ROUND_DATAGRAMS = 20000
#: With at least this many datagrams waiting (a burst: a live feed brings tens a second), a round
#: imports and does not estimate; the estimator catches up once the inputs are drained.
HURRY_DATAGRAMS = 1000
#: The estimator takes a round's plots in pieces of about this many.
CHUNK_PLOTS = 500
#: Receive buffer asked for each input socket (octets).
RECEIVE_BUFFER = 32 << 20
_RATE_S = 60.0
#: The interpreter's thread switch interval while serving (s; Python's default is 0.005): the
#: receiving thread drains the sockets at least this often while the main thread computes.
SWITCH_INTERVAL_S = 0.0005


def _listen(endpoint: Endpoint, interface: str, option: str = "--asterix") -> socket.socket:
    """A UDP socket bound to the endpoint (joined to its group when multicast); OSError with the
    address when the port is taken."""
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:  # beyond the system's cap (net.core.rmem_max) where allowed (CAP_NET_ADMIN)
        s.setsockopt(socket.SOL_SOCKET, getattr(socket, "SO_RCVBUFFORCE", 33), RECEIVE_BUFFER)
    except OSError:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, RECEIVE_BUFFER)
    try:
        if endpoint.multicast:
            s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            s.bind(("", endpoint.port))
            mreq = struct.pack("4s4s", socket.inet_aton(endpoint.host), socket.inet_aton(interface))
            s.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, mreq)
        else:
            s.bind((endpoint.host, endpoint.port))
    except OSError as exc:
        s.close()
        raise OSError(exc.errno, f"{option} {endpoint}: cannot listen ({exc.strerror})") from None
    s.setblocking(False)
    return s


class _Receiver(threading.Thread):
    """Drains the input sockets into ``take()``'s list of (payload, destination port)."""

    def __init__(self, sockets: list[socket.socket]) -> None:
        super().__init__(name="receive", daemon=True)
        self.selector = selectors.DefaultSelector()
        for s in sockets:
            self.selector.register(s, selectors.EVENT_READ, s.getsockname()[1])
        self.lock = threading.Lock()
        self.items: list[tuple[bytes, int]] = []
        self.stopping = threading.Event()

    def run(self) -> None:
        while not self.stopping.is_set():
            for key, _ in self.selector.select(timeout=0.1):
                s, port = key.fileobj, key.data
                got = []
                while True:
                    try:
                        got.append((s.recv(65535), port))  # type: ignore[union-attr]
                    except BlockingIOError:
                        break
                with self.lock:
                    self.items.extend(got)

    def take(self, most: int) -> list[tuple[bytes, int]]:
        """The first ``most`` datagrams received and not taken yet."""
        with self.lock:
            items, self.items = self.items[:most], self.items[most:]
        return items

    def waiting(self) -> int:
        with self.lock:
            return len(self.items)


class Service:
    """The service of ``config`` (module docstring). Raises ValueError or OSError naming the option
    or file for a bad sites file, a state that does not fit, or a port already in use."""

    def __init__(self, config: ServeConfig, log: Callable[[str], None] = print) -> None:
        self.config, self.log = config, log
        sites = read_sites(config.sites) if config.sites is not None else None
        self.sources = (
            {str(r.sensor): (int(r.sac), int(r.sic)) for r in sites.itertuples()} if sites is not None else {}
        )
        editions = {21: config.cat021_edition} if config.cat021_edition else None
        self.stream = (
            AsterixStream(sites, editions, date=config.date, name=",".join(map(str, config.asterix)))
            if sites is not None
            else None
        )
        self.counters = self.stream.counters if self.stream is not None else IngestCounters()
        self.bridge = (
            Bridge(config.platform, config.sensors, config.window_s, date=config.date, name=str(config.nmea))
            if config.nmea is not None and config.platform is not None and config.sensors is not None
            else None
        )
        ship = self.bridge.file_tables if self.bridge is not None else None
        self.estimator = LiveEstimator(
            sites, alarm_window_s=config.alarm_window_s, options=self._options(), ship=ship
        )
        self.resumed = load_state(config.state, self.estimator) if config.state is not None else False
        self.sockets = [_listen(e, config.interface) for e in config.asterix]
        nmea = config.nmea
        self.nmea_socket = (
            _listen(nmea, config.interface, "--nmea") if nmea is not None and nmea.scheme == "udp" else None
        )
        self.tcp = (
            TcpClient(nmea)
            if nmea is not None and nmea.scheme == "tcp"
            else TcpServer(nmea)
            if nmea is not None and nmea.scheme == "tcp-listen"
            else None
        )
        self.out = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.receiver = _Receiver(self.sockets + ([self.nmea_socket] if self.nmea_socket else []))
        self.started = time.monotonic()
        self.recent: deque[tuple[float, Counter]] = deque()
        self.backlog: deque[StreamBatch] = deque()
        self.merge = TimeMerge()  # with a ship: the radar plots wait for its plots of the same time
        self._next_snapshot = 0.0
        self.stop = threading.Event()
        self._snapshot = Snapshot()
        self._snapshot = self._build()
        try:
            self.http = start_http(*config.http, lambda: self._snapshot)
        except OSError as exc:
            self.close()
            raise OSError(
                exc.errno, f"--http {config.http[0]}:{config.http[1]}: cannot listen ({exc.strerror})"
            ) from None
        self.stop = threading.Event()

    def _options(self):
        from registration.fleet.online.options import OnlineOptions

        return OnlineOptions(window_s=self.config.window_s)

    @property
    def http_port(self) -> int:
        return int(self.http.server_address[1])

    @property
    def input_ports(self) -> list[int]:
        return [int(s.getsockname()[1]) for s in self.sockets]

    # -- rounds ----------------------------------------------------------------------------------
    def run(self) -> int:
        """Serve until SIGTERM/SIGINT (or ``stop`` set); returns 0."""
        sys.setswitchinterval(SWITCH_INTERVAL_S)  # the receiving thread gets its turn often
        previous = {s: signal.signal(s, lambda *_: self.stop.set()) for s in (signal.SIGTERM, signal.SIGINT)}
        self.receiver.start()
        if self.tcp is not None:
            self.tcp.start()
        inputs = ", ".join(f"udp://{e.host}:{p}" for e, p in zip(self.config.asterix, self.input_ports))
        if self.config.nmea is not None:
            n = self.config.nmea
            port = self.nmea_socket.getsockname()[1] if self.nmea_socket is not None else n.port
            port = self.tcp.port if isinstance(self.tcp, TcpServer) else port
            inputs = ", ".join(x for x in (inputs, f"nmea {n.scheme}://{n.host}:{port}") if x)
        resumed = " (resumed from the state)" if self.resumed else ""
        self.log(f"serving: inputs {inputs}; page http://{self.config.http[0]}:{self.http_port}/{resumed}")
        next_063 = next_checkpoint = time.monotonic()
        next_checkpoint += self.config.checkpoint_s
        try:
            while not self.stop.wait(0.0 if self.busy() else self.config.tick_s):
                self.round()
                now = time.monotonic()
                if self.config.cat063 is not None and now >= next_063:
                    self.send_cat063()
                    next_063 = now + self.config.cat063_period_s
                if self.config.state is not None and now >= next_checkpoint:
                    save_state(self.config.state, self.estimator)
                    next_checkpoint = now + self.config.checkpoint_s
            if self.config.state is not None:  # what is still waiting is not imported: exit on time
                save_state(self.config.state, self.estimator)
        finally:
            for s, handler in previous.items():
                signal.signal(s, handler)
            self.close()
        self.log("stopped")
        return 0

    def busy(self) -> bool:
        """Work is waiting (plots in the backlog, or a quarter of a round's datagrams): the next
        round starts at once instead of after ``tick_s``."""
        return bool(self.backlog) or self.receiver.waiting() >= ROUND_DATAGRAMS // 4

    def round(self) -> None:
        """Import what was received, send the corrected plots, estimate, and publish a snapshot."""
        items = self.receiver.take(ROUND_DATAGRAMS)
        ship = None
        if self.bridge is not None:
            items, ship = self._nmea_round(items)
        if items and self.stream is not None:
            payloads, ports = [p for p, _ in items], [q for _, q in items]
            if self.config.corrected is not None:
                self.send_corrected(payloads)
            batch = self.stream.decode(payloads, ports)
            if self.bridge is None:
                self.backlog.extend(split_batch(batch, CHUNK_PLOTS))
            else:  # held until the ship's plots of the same time are handed over
                self.merge.add(batch)
            fp = batch.file_plots
            if fp["time_s"].size:
                self.recent.append((float(fp["time_s"].max()), Counter(fp["sensor"].astype(str).tolist())))
        if self.bridge is not None:
            merged = self.merge.release(self.bridge.horizon, ship)
            if merged is not None:
                self.backlog.extend(split_batch(merged, CHUNK_PLOTS))
        # Datagrams pile up: import them first, and estimate once they are (one epoch of the
        # estimator can take longer than a budget, so even a small one would slow the import).
        hurry = self.receiver.waiting() >= HURRY_DATAGRAMS
        now = time.monotonic()
        deadline = now if hurry else now + ESTIMATE_BUDGET_S
        if items and self.backlog and deadline > now:  # the import's counters published before
            self._publish(force=True)  # the estimator takes its time (an epoch can take a second)
        while self.backlog and not self.stop.is_set() and time.monotonic() < deadline:
            self.estimator.feed(self.backlog.popleft())
        self._publish()

    def _publish(self, force: bool = False) -> None:
        """Build the answers again (every ``SNAPSHOT_S`` at most, unless ``force``)."""
        if force or time.monotonic() >= self._next_snapshot:
            self._snapshot = self._build()
            self._next_snapshot = time.monotonic() + SNAPSHOT_S

    def _nmea_round(
        self, items: list[tuple[bytes, int]]
    ) -> tuple[list[tuple[bytes, int]], StreamBatch | None]:
        """Import the NMEA lines received (passing them on corrected first); returns the other
        datagrams and the ship's associated plots now due (None: none)."""
        bridge = self.bridge
        assert bridge is not None
        if self.nmea_socket is not None:
            port = self.nmea_socket.getsockname()[1]
            mine = [p for p, q in items if q == port]
            items = [(p, q) for p, q in items if q != port]
            if mine:
                self.send_corrected_nmea(bridge.stream.add_datagrams(mine))
        if self.tcp is not None:
            data = self.tcp.take()
            if data:
                self.send_corrected_nmea(bridge.stream.add_bytes(data))
        batch = bridge.take(self.estimator)
        if batch is not None:
            t = batch.plots["time"]
            self.recent.append((float(t.max()), Counter(batch.plots["sensor"].astype(str).tolist())))
        return items, batch

    def send_corrected_nmea(self, lines: list[str]) -> None:
        """The lines on to ``--corrected``, each a datagram, TTMs corrected by the estimates."""
        target = self.config.corrected
        if target is None or not lines or self.bridge is None:
            return
        s = self.bridge.stream
        by_talker, other = ttm_corrections(self.estimator.values(), s.talkers, s.only)
        for line in corrected_lines(lines, by_talker, other):
            self.out.sendto((line + "\r\n").encode("latin-1"), (target.host, target.port))

    def send_corrected(self, payloads: list[bytes]) -> None:
        from registration.io.asterix.encode.cat048 import correct_cat048

        target = self.config.corrected
        assert target is not None
        corrections = plot_corrections(self.estimator.values(), self.sources)
        for p in payloads:
            self.out.sendto(correct_cat048(p, corrections).data, (target.host, target.port))

    def send_cat063(self) -> None:
        target = self.config.cat063
        assert target is not None
        t = self.estimator.data_time_s if self.estimator.data_time_s is not None else time.time() % 86400.0
        silent = frozenset(s for s, a in self.activity().items() if a.silent)
        message = cat063_message(self.estimator.values(), self.sources, t, self.config.sac_sic, silent)
        self.out.sendto(message, (target.host, target.port))

    # -- reports ---------------------------------------------------------------------------------
    def activity(self) -> dict[str, SensorActivity]:
        now = self.estimator.data_time_s
        while self.recent and now is not None and self.recent[0][0] < now - _RATE_S:
            self.recent.popleft()
        counts = sum((c for _, c in self.recent), Counter())
        c = self.counters
        out = {}
        ship = self.bridge.stream.sensors["sensor"].astype(str).tolist() if self.bridge is not None else []
        for name in [*self.sources, *ship]:
            if name in ship and self.bridge is not None:
                c = self.bridge.stream.counters  # type: ignore[assignment]
            last = c.sensor_last_s.get(name)
            silent = now is not None and (last is None or now - last > SILENT_S)
            out[name] = SensorActivity(
                int(c.sensor_plots.get(name, 0)), counts.get(name, 0) / _RATE_S, last, bool(silent)
            )
        return out

    def _build(self) -> Snapshot:
        backlog = sum(int(b.plots["time"].size) for b in self.backlog) + self.merge.held
        self.counters.waiting_datagrams = self.receiver.waiting()
        uptime = time.monotonic() - self.started
        nmea = None
        if self.bridge is not None:
            nmea = self.bridge.to_json()
            nmea["plots_outside_navigation"] = self.estimator.plots_outside_navigation
            if self.tcp is not None:
                nmea["tcp"] = self.tcp.to_json()
        return build_snapshot(self.estimator, self.counters, self.activity(), uptime, backlog, nmea)

    def close(self) -> None:
        self.receiver.stopping.set()
        if getattr(self, "tcp", None) is not None:
            self.tcp.stopping.set()  # type: ignore[union-attr]
        if getattr(self, "nmea_socket", None) is not None:
            self.nmea_socket.close()  # type: ignore[union-attr]
        if getattr(self, "http", None) is not None:
            self.http.shutdown()
            self.http.server_close()
        for s in self.sockets:
            s.close()
        self.out.close()
