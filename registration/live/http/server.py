"""The live service's HTTP server: the page and the API of :mod:`registration.live.http.api`, read-only
(``GET`` and ``HEAD``; every other method is refused with 405, so that no request changes state).
It serves what the latest :class:`~registration.live.http.api.Snapshot` holds, handed over by
``snapshot()``; it binds 127.0.0.1 unless told otherwise."""

from __future__ import annotations

import threading
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Callable
from urllib.parse import parse_qs, urlsplit

from registration.live.http.api import Snapshot

__all__ = ["ApiServer", "start_http"]

_JSON = "application/json"
_PAGES = {"/": "index.html", "/index.html": "index.html", "/app.js": "app.js", "/style.css": "style.css"}


class ApiServer(ThreadingHTTPServer):
    daemon_threads = True
    snapshot: Callable[[], Snapshot]


class _Handler(BaseHTTPRequestHandler):
    server: ApiServer
    server_version = "registration-serve"

    def log_message(self, format: str, *args) -> None:  # noqa: A002 - the base class's name
        pass  # no line per request on standard error

    def _send(self, code: int, body: bytes, content_type: str, head: bool = False) -> None:
        self.send_response(code)
        self.send_header("Content-Type", content_type)
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Cache-Control", "no-store")
        self.send_header("X-Content-Type-Options", "nosniff")
        self.end_headers()
        if not head:
            self.wfile.write(body)

    def _answer(self, head: bool) -> None:
        url = urlsplit(self.path)
        snap = self.server.snapshot()
        path = url.path
        if path in _PAGES:
            from registration.live.http.assets import asset

            body, kind = asset(_PAGES[path])
            return self._send(200, body, kind, head)
        fixed = {
            "/api/estimates": (snap.estimates, _JSON),
            "/api/estimates.csv": (snap.estimates_csv, "text/csv; charset=utf-8"),
            "/api/status": (snap.status, _JSON),
            "/api/residuals": (snap.residuals, _JSON),
            "/metrics": (snap.metrics, "text/plain; version=0.0.4; charset=utf-8"),
        }
        if path in fixed:
            return self._send(200, *fixed[path], head=head)
        if path == "/api/history":
            sensor = parse_qs(url.query).get("sensor", [""])[0]
            if sensor not in snap.history:
                body = f'{{"error": "unknown sensor {sensor!r}; sensors: {sorted(snap.history)}"}}'.encode()
                return self._send(404, body, _JSON, head)
            return self._send(200, snap.history[sensor], _JSON, head)
        self._send(404, b'{"error": "not found"}', _JSON, head)

    def do_GET(self) -> None:
        self._answer(head=False)

    def do_HEAD(self) -> None:
        self._answer(head=True)

    def _refuse(self) -> None:
        self.send_response(405)
        self.send_header("Allow", "GET, HEAD")
        self.send_header("Content-Length", "0")
        self.end_headers()

    do_POST = do_PUT = do_DELETE = do_PATCH = _refuse


def start_http(host: str, port: int, snapshot: Callable[[], Snapshot]) -> ApiServer:
    """Bind ``host:port`` (OSError when taken) and serve in a daemon thread; ``shutdown()`` stops it."""
    server = ApiServer((host, port), _Handler)
    server.snapshot = snapshot
    threading.Thread(target=server.serve_forever, name="http", daemon=True).start()
    return server
