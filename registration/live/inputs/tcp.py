"""The TCP inputs of the live service.

* ``--nmea tcp://HOST:PORT`` (:class:`TcpClient`) connects to HOST:PORT as a client, as a
  navigation display connects to a ship's NMEA multiplexer (which serves the bridge's sentences
  over TCP to whoever connects), and reads what it sends. A refused or dropped connection is tried
  again every :data:`RETRY_S` seconds; the service never stops for it.
* ``--nmea tcp-listen://HOST:PORT`` (:class:`TcpServer`) listens on HOST:PORT and reads what a
  client that connects writes (a multiplexer set to push to a TCP address, or ``registration
  replay --to tcp://``); one client at a time, the next one when it hangs up.
"""

from __future__ import annotations

import socket
import threading

from registration.live.config import Endpoint

__all__ = ["TcpClient", "TcpServer", "RETRY_S"]

#: Seconds between connection attempts.
RETRY_S = 1.0


class _Reader(threading.Thread):
    """Gathers octets for :meth:`take`, with the connection's counters."""

    def __init__(self, endpoint: Endpoint) -> None:
        super().__init__(name="tcp-input", daemon=True)
        self.endpoint = endpoint
        self.lock = threading.Lock()
        self.chunks: list[bytes] = []
        self.stopping = threading.Event()
        self.connected = False
        self.connects = self.drops = self.failures = 0

    def _read(self, s: socket.socket) -> None:
        """Read ``s`` until it closes or the service stops; then close it."""
        self.connected, self.connects = True, self.connects + 1
        s.settimeout(0.1)
        try:
            while not self.stopping.is_set():
                try:
                    data = s.recv(1 << 16)
                except socket.timeout:
                    continue
                if not data:
                    break
                with self.lock:
                    self.chunks.append(data)
        except OSError:
            pass
        finally:
            s.close()
            self.connected = False
        if not self.stopping.is_set():
            self.drops += 1

    def take(self) -> bytes:
        """The octets received since the last call."""
        with self.lock:
            chunks, self.chunks = self.chunks, []
        return b"".join(chunks)

    def to_json(self) -> dict:
        return {
            "address": str(self.endpoint),
            "connected": self.connected,
            "connects": self.connects,
            "drops": self.drops,
            "failed_attempts": self.failures,
        }


class TcpServer(_Reader):
    """Listens on ``endpoint`` (bound at once: OSError naming the option when the port is taken)
    and reads one client at a time; ``port`` is the port bound (port 0: any free one)."""

    def __init__(self, endpoint: Endpoint) -> None:
        super().__init__(endpoint)
        self.server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self.server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            self.server.bind((endpoint.host, endpoint.port))
            self.server.listen(4)
        except OSError as exc:
            self.server.close()
            raise OSError(exc.errno, f"--nmea {endpoint}: cannot listen ({exc.strerror})") from None
        self.server.settimeout(0.1)
        self.port = int(self.server.getsockname()[1])

    def run(self) -> None:
        try:
            while not self.stopping.is_set():
                try:
                    s, _ = self.server.accept()
                except socket.timeout:
                    continue
                except OSError:
                    return
                self._read(s)
        finally:
            self.server.close()


class TcpClient(_Reader):
    """Connects to ``endpoint`` and reads it, connecting again when it drops (module docstring)."""

    def run(self) -> None:
        while not self.stopping.is_set():
            try:
                s = socket.create_connection((self.endpoint.host, self.endpoint.port), timeout=RETRY_S)
            except OSError:
                self.failures += 1
                self.stopping.wait(RETRY_S)
                continue
            self._read(s)
            self.stopping.wait(RETRY_S)
