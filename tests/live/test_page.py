"""The live page in headless Chromium against a stand-in of the service's JSON API: a tiny
``http.server`` on 127.0.0.1 serving the packaged page (through ``registration.live.http.assets``) and
fixtures with known numbers, then changed numbers, then no service at all. The expected texts are
worked out by hand from the fixtures, not by the page's code."""

from __future__ import annotations

import json
import re
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from urllib.parse import parse_qs, urlsplit

import pytest

from registration.live.http.assets import asset
from tests.live.browser import watch

PAGE_FILES = {"/": "index.html", "/app.js": "app.js", "/style.css": "style.css"}


def _states(t0: float, n: int, rows: list[tuple[str, str, float, float]], hole: int | None = None) -> list:
    """Histories of n points 50 s apart from t0, each state a slow ramp; ``hole``: one null estimate."""
    out = []
    for state, unit, value, sigma in rows:
        est: list[float | None] = [value * (0.5 + 0.5 * k / (n - 1)) for k in range(n)]
        if hole is not None:
            est[hole] = None
        times = [t0 + 50.0 * k for k in range(n)]
        sig = [sigma * (2.0 - k / (n - 1)) for k in range(n)]
        out.append({"state": state, "unit": unit, "time_s": times, "estimate": est, "sigma": sig})
    return out


HISTORY = {
    "R1": _states(0.0, 30, [("azimuth_bias", "deg", 0.05, 0.002), ("range_bias", "m", 12.3, 1.5)]),
    "R2": _states(500.0, 20, [("azimuth_bias", "deg", -0.12, 0.03), ("range_bias", "m", 0.0, 0.0)], hole=7),
}
# (sensor, state) -> (points drawn, separate runs of the line)
DRAWN = {
    ("R1", "azimuth_bias"): (30, 1),
    ("R1", "range_bias"): (30, 1),
    ("R2", "azimuth_bias"): (19, 2),
    ("R2", "range_bias"): (19, 2),
}


def _estimate(obj, state, unit, value, sigma, status):
    return {"object": obj, "state": state, "unit": unit, "estimate": value, "sigma": sigma, "status": status}


def _api(version: int) -> dict:
    """The four answers of the API; version 2 has moved on: new numbers, a second alarm, a bad verdict."""
    az1, saz1 = (0.05, 0.002) if version == 1 else (0.0612, 0.0015)
    estimates = [  # deliberately not in order: the page sorts by object
        _estimate("ShipA", "heading_bias", "deg", 0.3, 0.05, "undetermined"),
        _estimate("R2", "azimuth_bias", "deg", -0.12, 0.03, "weak"),
        _estimate("R2", "range_bias", "m", 0.0, 0.0, "fixed"),
        _estimate("R1", "azimuth_bias", "deg", az1, saz1, "determined"),
        _estimate("R1", "range_bias", "m", 12.3, 1.5, "determined"),
    ]
    alarms = [
        {"time_s": 1400.0, "object": "R2", "state": "azimuth_bias", "unit": "deg", "before": -0.02,
         "after": -0.12, "sigma": 0.03, "z": 3.3}
    ]  # fmt: skip
    if version == 2:
        alarms.append(dict(alarms[0], time_s=1460.0, object="R1", before=0.05, after=0.0612, sigma=0.0015))
    sensors = [
        {"sensor": "R2", "plots": 800, "rate_per_s": 0.0, "last_time_s": 900.0, "silent": True},
        {"sensor": "R1", "plots": 1500, "rate_per_s": 10.0, "last_time_s": 1450.0, "silent": False},
    ]
    if version == 2:  # a sensor just seen: no plot time yet, no history yet
        sensors.append({"sensor": "R3", "plots": 0, "rate_per_s": 0.0, "last_time_s": None, "silent": True})
    status = {
        "uptime_s": 3725.0,
        "memory_rss_bytes": 150 * 2**20,
        "data_time_s": 1450.0 if version == 1 else 1460.0,
        "ingest": {
            "datagrams": 1234 if version == 1 else 1300,
            "bytes": 567890,
            "records_by_category": {"048": 2300, "021": 150},
            "plots": 2300,
            "references": 150,
            "rejected": {"range_out_of_bounds": 7, "stale_time": 0},
        },
        "sensors": sensors,
        "consistency": {"value": 1.02 if version == 1 else 1.31, "band": [0.9, 1.1],
                        "verdict": "consistent" if version == 1 else "outside band"},
        "alarms": alarms,
    }  # fmt: skip
    channels = [
        {"channel": "range", "unit": "m", "n": 1500, "mean": 1.25, "rms": 20.0},
        {"channel": "bearing", "unit": "deg", "n": 1500, "mean": -0.0031, "rms": 0.045},
    ]
    residuals = {"sensors": [{"sensor": "R1", "channels": channels}]}
    return {"estimates": {"time_s": 1450.0, "estimates": estimates}, "status": status, "residuals": residuals}


class StandIn(ThreadingHTTPServer):
    """The page and the API's fixtures on 127.0.0.1, port chosen by the system."""

    daemon_threads = True
    version = 1
    down = False  # True: every API call answers 503, as a service that went away behind a proxy would


class Handler(BaseHTTPRequestHandler):
    server: StandIn

    def log_message(self, *args) -> None:
        pass

    def _send(self, code: int, body: bytes, ctype: str) -> None:
        self.send_response(code)
        self.send_header("Content-Type", ctype)
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Cache-Control", "no-store")
        self.end_headers()
        self.wfile.write(body)

    def do_GET(self) -> None:
        url = urlsplit(self.path)
        if url.path in PAGE_FILES:
            self._send(200, *asset(PAGE_FILES[url.path]))
        elif url.path == "/foreign":  # a page that asks another host for an image: the watch must catch it
            self._send(200, b'<img src="http://foreign.invalid/x.png">', "text/html")
        elif not url.path.startswith("/api/"):
            self._send(404, b"not found", "text/plain")
        elif self.server.down:
            self._send(503, b"down", "text/plain")
        else:
            api = _api(self.server.version)
            name = url.path.removeprefix("/api/")
            if name == "history":
                sensor = parse_qs(url.query)["sensor"][0]
                body = {"sensor": sensor, "states": HISTORY.get(sensor, [])}  # R3: just seen, no history
            else:
                body = api[name]
            self._send(200, json.dumps(body).encode(), "application/json")


@pytest.fixture
def stand_in():
    server = StandIn(("127.0.0.1", 0), Handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield server
    server.shutdown()
    server.server_close()


def _origin(server: StandIn) -> str:
    host, port = server.server_address[:2]
    return f"http://{host}:{port}"


def _value(page, obj: str, state: str) -> str:
    return page.locator(f'#estimates tr[data-object="{obj}"][data-state="{state}"] .value').inner_text()


def _wait_text(page, selector: str, text: str, timeout_ms: float = 5000) -> float:
    """Seconds until the element's text is ``text``; fails after timeout_ms."""
    start = time.monotonic()
    page.wait_for_function(
        "([sel, want]) => document.querySelector(sel)?.textContent.trim() === want",
        arg=[selector, text],
        timeout=timeout_ms,
    )
    return time.monotonic() - start


def _check_first_numbers(page) -> None:
    rows = page.locator("#estimates tbody tr")
    assert [rows.nth(i).get_attribute("data-object") for i in range(rows.count())] == [
        "R1", "R1", "R2", "R2", "ShipA"
    ]  # fmt: skip
    assert _value(page, "R1", "azimuth_bias") == "0.0500 ± 0.0020 deg"
    assert _value(page, "R1", "range_bias") == "12.3 ± 1.5 m"
    assert _value(page, "R2", "azimuth_bias") == "-0.120 ± 0.030 deg"
    assert _value(page, "R2", "range_bias") == "0.0000 m"  # fixed: no ± 0
    assert _value(page, "ShipA", "heading_bias") == "0.300 ± 0.050 deg"
    assert page.locator('tr[data-object="R2"][data-state="azimuth_bias"] .status').inner_text() == "weak"

    for (sensor, state), (points, runs) in DRAWN.items():
        box = page.locator(f'figure[data-sensor="{sensor}"] .chart-box[data-state="{state}"]')
        line = box.locator("path.line")
        d = line.get_attribute("d")
        assert line.get_attribute("data-points") == str(points)
        assert len(re.findall(r"[ML]", d)) == points and d.count("M") == runs, (sensor, state, d)
        assert box.locator("path.band").get_attribute("d").count("Z") == runs
        assert box.locator("text.tick.x").count() >= 3 and box.locator("text.tick.y").count() >= 3
        assert box.locator("text.axis-label.x").text_content() == "data time (s)"
    assert (
        page.locator(
            'figure[data-sensor="R1"] .chart-box[data-state="range_bias"] text.axis-label.y'
        ).text_content()
        == "m"
    )

    alarms = page.locator("#alarms")
    assert alarms.is_visible() and alarms.locator("li").count() == 1
    assert alarms.evaluate("n => getComputedStyle(n).backgroundColor") == "rgb(180, 35, 24)"
    assert (
        alarms.locator("li").inner_text()
        == "t = 1400.0 s · R2 azimuth_bias: -0.020 → -0.120 deg (σ 0.030, z 3.3)"
    )
    assert page.locator("#consistency").inner_text() == "1.02 in band [0.9, 1.1]: consistent"

    assert page.locator('#ingest dd[data-key="datagrams"]').inner_text() == "1234"
    assert page.locator('#ingest dd[data-key="bytes"]').inner_text() == "567890"
    assert page.locator('#categories dd[data-key="CAT048"]').inner_text() == "2300"
    assert page.locator('#categories dd[data-key="CAT021"]').inner_text() == "150"
    assert page.locator('#rejected dd[data-key="range_out_of_bounds"]').inner_text() == "7"
    silent = page.locator('#sensors tr[data-sensor="R2"]')
    assert silent.get_attribute("data-silent") == "true" and silent.locator(".badge").inner_text() == "silent"
    assert page.locator('#sensors tr[data-sensor="R1"]').get_attribute("data-silent") == "false"
    assert page.locator('#sensors tr[data-sensor="R1"] .plots').inner_text() == "1500"
    assert page.locator('#sensors tr[data-sensor="R1"] .rate').inner_text() == "10.0"

    bearing = page.locator('#residuals tr[data-sensor="R1"][data-channel="bearing"]')
    assert (
        bearing.locator(".mean").inner_text() == "-0.0031 deg"
        and bearing.locator(".rms").inner_text() == "0.045 deg"
    )
    assert page.locator('#residuals tr[data-channel="range"] .rms').inner_text() == "20 m"
    assert (
        page.locator("#memory").inner_text() == "150.0 MiB"
        and page.locator("#uptime").inner_text() == "1 h 2 min"
    )


def test_the_page_shows_the_api_follows_it_and_survives_its_loss(browser_page, stand_in, tmp_path):
    page, origin = browser_page, _origin(stand_in)
    seen = watch(page, origin)
    page.clock.install()  # the page's timers run in real time, and the test may skip ahead to the next poll
    page.goto(origin + "/")
    _wait_text(
        page, '#estimates tr[data-object="R1"][data-state="azimuth_bias"] .value', "0.0500 ± 0.0020 deg"
    )
    _check_first_numbers(page)
    page.screenshot(path=str(tmp_path / "live-page.png"), full_page=True)

    stand_in.version = 2
    waited = _wait_text(
        page, '#estimates tr[data-object="R1"][data-state="azimuth_bias"] .value', "0.0612 ± 0.0015 deg"
    )
    assert waited < 4.0
    assert page.locator('#ingest dd[data-key="datagrams"]').inner_text() == "1300"
    assert page.locator("#alarms li").count() == 2
    assert page.locator("#alarms li").first.get_attribute("data-object") == "R1"  # newest first
    assert page.locator("#consistency").get_attribute("data-verdict") == "outside band"
    assert page.locator('figure[data-sensor="R3"] .empty').inner_text() == "no history yet"
    assert page.locator('#sensors tr[data-sensor="R3"] td').nth(3).inner_text() == "—"
    assert seen.foreign == [] and seen.errors == []

    stand_in.down = True  # the browser logs the 503s as console errors from here on: expected
    page.clock.fast_forward(2000)
    _wait_text(page, "#connection", "service unreachable: showing the last data received")
    assert _value(page, "R1", "azimuth_bias") == "0.0612 ± 0.0015 deg"  # the last data stays
    stand_in.down = False
    page.clock.fast_forward(2000)
    page.wait_for_function("() => document.getElementById('connection').textContent.startsWith('live')")
    assert "stale" not in (page.locator("body").get_attribute("class") or "")
    assert seen.foreign == []


def test_on_a_narrow_screen_nothing_spills_sideways(browser_page, stand_in, tmp_path):
    page, origin = browser_page, _origin(stand_in)
    seen = watch(page, origin)
    page.set_viewport_size({"width": 390, "height": 800})
    page.goto(origin + "/")
    page.wait_for_selector('figure[data-sensor="R2"] path.line')
    assert page.evaluate("() => document.documentElement.scrollWidth <= window.innerWidth")
    box = page.locator('figure[data-sensor="R1"] svg').first.bounding_box()
    assert box is not None and 300 <= box["width"] <= 390
    page.screenshot(path=str(tmp_path / "live-page-narrow.png"), full_page=True)
    assert seen.foreign == [] and seen.errors == []


def test_the_watch_catches_a_request_to_another_host(browser_page, stand_in):
    """The no-other-host check can fail: a page that asks another host is caught (and the request
    aborted in the browser, so nothing leaves the machine)."""
    page, origin = browser_page, _origin(stand_in)
    seen = watch(page, origin)
    page.goto(origin + "/foreign")
    page.wait_for_load_state("load")
    assert seen.foreign == ["http://foreign.invalid/x.png"]
