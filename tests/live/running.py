"""A ``registration serve`` subprocess for the tests: started on 127.0.0.1 with free ports (port 0,
read back from the line it prints), fed datagrams, asked over HTTP, stopped by PID."""

from __future__ import annotations

import json
import re
import signal
import socket
import subprocess
import sys
import time
import urllib.request
from contextlib import contextmanager
from pathlib import Path

from registration.io.asterix.capture.capture import read_capture
from registration.io.asterix.errors import LEDGER_COLUMNS
from registration.io.files.ledger import RejectedLedger

SAMPLES = Path(__file__).resolve().parents[2] / "examples" / "recordings"


def datagrams(path: Path) -> list[bytes]:
    """The UDP payloads of a capture, in order."""
    cap = read_capture(path, RejectedLedger(LEDGER_COLUMNS))
    seg = cap.segments
    return [cap.buf[a:b].tobytes() for a, b in zip(seg.start.tolist(), seg.end.tolist())]


class Running:
    def __init__(self, proc: subprocess.Popen, line: str) -> None:
        self.proc = proc
        m = re.search(
            r"inputs (?:nmea )?(?:udp|tcp|tcp-listen)://127\.0\.0\.1:(\d+).*page http://127\.0\.0\.1:(\d+)/",
            line,
        )
        assert m, line
        self.input_port, self.http_port = int(m.group(1)), int(m.group(2))
        self.line = line

    def send(self, payloads: list[bytes], per_ms: int = 200) -> None:
        s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        for k, p in enumerate(payloads):
            s.sendto(p, ("127.0.0.1", self.input_port))
            if k % per_ms == per_ms - 1:
                time.sleep(0.001)
        s.close()

    def get(self, path: str):
        with urllib.request.urlopen(f"http://127.0.0.1:{self.http_port}{path}", timeout=10) as r:
            body = r.read()
        return json.loads(body) if r.headers.get_content_type() == "application/json" else body.decode()

    def wait_for_plots(self, n: int, timeout_s: float = 60.0) -> dict:
        """The status once ``n`` plots are imported and every one of them estimated (nothing waits:
        no datagram, no plot in the backlog; on a loaded machine the estimator may trail the
        import by seconds), or at ``timeout_s``."""
        deadline = time.monotonic() + timeout_s
        while True:
            status = self.get("/api/status")
            ingest = status["ingest"]
            done = ingest["plots"] >= n and ingest["backlog_plots"] == 0 and ingest["waiting_datagrams"] == 0
            if done or time.monotonic() > deadline:
                return status
            time.sleep(0.2)

    def stop(self, timeout_s: float = 10.0) -> tuple[int, float, str]:
        t = time.monotonic()
        self.proc.send_signal(signal.SIGTERM)
        rc = self.proc.wait(timeout_s)
        return rc, time.monotonic() - t, self.proc.stderr.read() if self.proc.stderr else ""


@contextmanager
def serving(*options: str, sites: Path = SAMPLES / "SITES.csv", inputs: tuple[str, ...] | None = None):
    """The service with ``options``; ``inputs`` instead of the sample's SITES and one ASTERIX input."""
    inputs = ("--sites", str(sites), "--asterix", "udp://127.0.0.1:0") if inputs is None else inputs
    cmd = [sys.executable, "-m", "registration", "serve", *inputs]
    cmd += ["--http", "127.0.0.1:0", *options]
    proc = subprocess.Popen(cmd, stderr=subprocess.PIPE, text=True)
    try:
        line = proc.stderr.readline() if proc.stderr else ""
        yield Running(proc, line)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
