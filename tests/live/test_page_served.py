"""The page against the real service: ``registration serve`` fed the sample recording by
``registration replay`` (both subprocesses on 127.0.0.1), loaded in headless Chromium. The table
names every sensor and shows each bias with the numbers the API serves, the charts draw as many
points as the history holds, and the page asks nothing of any other host."""

from __future__ import annotations

import re
import subprocess
import sys

import pytest

from tests.live.browser import watch
from tests.live.running import SAMPLES, serving


@pytest.fixture(scope="module")
def served():
    """The service after the whole sample was replayed into it: its answers, then the page."""
    with serving("--date", "2024-05-01") as svc:
        replay = [sys.executable, "-m", "registration", "replay", str(SAMPLES / "atc.pcap.gz")]
        replay += ["--to", f"udp://127.0.0.1:{svc.input_port}", "--speed", "max"]
        subprocess.run(replay, check=True, capture_output=True, timeout=60)
        status = svc.wait_for_plots(3692)
        yield svc, status
        svc.stop()


def _number(text: str) -> tuple[float, int]:
    """A shown number and its decimals."""
    return float(text), len(text.split(".")[1]) if "." in text else 0


def test_the_page_shows_every_sensor_with_the_served_numbers(browser_page, served):
    svc, status = served
    origin = f"http://127.0.0.1:{svc.http_port}"
    page = browser_page
    seen = watch(page, origin)
    assert status["ingest"]["plots"] == 3692
    page.goto(origin + "/")
    page.wait_for_selector('#estimates tr[data-object="R3"][data-state="time_bias"]')
    estimates = svc.get("/api/estimates")["estimates"]
    shown = 0
    for row in estimates:
        if row["status"] == "fixed":
            continue
        cell = page.locator(
            f'#estimates tr[data-object="{row["object"]}"][data-state="{row["state"]}"] .value'
        )
        text = cell.inner_text()
        m = re.fullmatch(r"(-?[\d.]+) ± ([\d.]+) (\S+)", text)
        assert m, text
        (value, d), (sigma, _) = _number(m.group(1)), _number(m.group(2))
        assert m.group(3) == row["unit"]
        assert abs(value - row["estimate"]) <= 0.5 * 10.0**-d + 1e-12, (row, text)
        assert abs(sigma - row["sigma"]) <= 0.5 * 10.0**-d + 1e-12, (row, text)
        shown += 1
    assert shown == 12  # range bias, azimuth bias, range gain and time bias of R1, R2 and R3
    for sensor in ("R1", "R2", "R3"):
        history = svc.get(f"/api/history?sensor={sensor}")["states"]
        for h in history:
            line = page.locator(
                f'figure[data-sensor="{sensor}"] .chart-box[data-state="{h["state"]}"] path.line'
            )
            assert line.get_attribute("data-points") == str(len(h["time_s"])), (sensor, h["state"])
        row = page.locator(f'#sensors tr[data-sensor="{sensor}"]')
        assert row.locator(".plots").inner_text() == str(
            next(s["plots"] for s in status["sensors"] if s["sensor"] == sensor)
        )
    assert page.locator("#consistency").inner_text().endswith("consistent")
    assert seen.foreign == [] and seen.errors == []
