"""``registration serve`` as a user runs it: a subprocess on 127.0.0.1 fed the sample recording's
datagrams (written by libasterix, not by this package). It counts every plot the import counts,
its biases end within 3.5 sigma of the truth, its CAT063 messages (read by libasterix) carry the
served estimates to their LSB, SIGTERM ends it with exit 0, and a restart on the same state serves
the same estimates before any data; a port in use and a bad sites file exit 2 with one line."""

from __future__ import annotations

import json
import math
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request

import pytest

from registration.io.asterix import import_asterix
from tests.live.running import SAMPLES, datagrams, serving

pytest.importorskip("asterix")  # libasterix reads the CAT063 messages

AZ_LSB_DEG = 360.0 / 65536.0
NM_M = 1852.0


@pytest.fixture(scope="module")
def expected():
    result = import_asterix(SAMPLES / "atc.pcap.gz", SAMPLES / "SITES.csv")
    return {"plots": len(result.plots), "references": len(result.reference)}


@pytest.fixture(scope="module")
def run(tmp_path_factory, expected):
    """The service fed the whole sample at full speed, with CAT063 every 0.5 s and a state folder."""
    state = tmp_path_factory.mktemp("state")
    listener = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    listener.bind(("127.0.0.1", 0))
    listener.settimeout(5.0)
    options = ("--cat063", f"udp://127.0.0.1:{listener.getsockname()[1]}", "--cat063-period-s", "0.5")
    with serving(*options, "--state", str(state), "--date", "2024-05-01") as svc:
        svc.send(datagrams(SAMPLES / "atc.pcap.gz"))
        status = svc.wait_for_plots(expected["plots"])
        time.sleep(1.0)  # every plot estimated, the last snapshot built: nothing changes from here on
        estimates = svc.get("/api/estimates")
        messages = []
        deadline = time.monotonic() + 3.0
        while time.monotonic() < deadline:
            messages.append(listener.recv(65535))
        page = svc.get("/")
        history = svc.get("/api/history?sensor=R2")
        metrics = svc.get("/metrics")
        csv_text = svc.get("/api/estimates.csv")
        stopped = svc.stop()
    listener.close()
    return dict(
        status=status,
        estimates=estimates,
        cat063=messages[-1],
        page=page,
        history=history,
        metrics=metrics,
        csv=csv_text,
        stopped=stopped,
        state=state,
    )


def _rows(estimates: dict) -> dict:
    return {f"{r['object']}:{r['state']}": r for r in estimates["estimates"]}


def test_every_plot_and_reference_the_import_finds_is_counted(run, expected):
    ingest = run["status"]["ingest"]
    assert ingest["plots"] == expected["plots"]
    assert ingest["references"] == expected["references"]
    assert ingest["rejected"] == {}
    assert [s["sensor"] for s in run["status"]["sensors"]] == ["R1", "R2", "R3"]
    assert sum(s["plots"] for s in run["status"]["sensors"]) == expected["plots"]


def test_every_bias_ends_within_3_5_sigma_of_the_truth(run):
    truth = json.loads((SAMPLES / "truth.json").read_text())["asterix"]
    rows = _rows(run["estimates"])
    factor = {"bearing_bias": math.degrees(1.0)}
    for name, value in truth.items():
        row = rows[name]
        assert row["status"] == "identifiable", row
        z = (row["estimate"] - value * factor.get(name.split(":")[1], 1.0)) / row["sigma"]
        assert abs(z) < 3.5, (name, row, value)


def test_cat063_carries_the_served_estimates_to_their_lsb(run):
    from asterix.base import Bits, RawDatablock
    from asterix.generated import Cat_063_1_7

    rows = _rows(run["estimates"])
    blocks = RawDatablock.parse(Bits.from_bytes(run["cat063"]))
    assert not isinstance(blocks, ValueError)
    records = Cat_063_1_7.cv_uap.parse(blocks[0].get_raw_records())
    assert not isinstance(records, ValueError) and len(records) == 3
    sources = {(30, 1): "R1", (30, 2): "R2", (30, 3): "R3"}
    for rec in records:
        items = rec.items_regular
        sac, sic = items["050"].unparse().to_bytes()
        name = sources[(sac, sic)]
        raw = lambda item, a=0, b=2: int.from_bytes(items[item].unparse().to_bytes()[a:b], "big", signed=True)  # noqa: E731
        assert abs(raw("081") * AZ_LSB_DEG - rows[f"{name}:bearing_bias"]["estimate"]) <= AZ_LSB_DEG / 2
        assert abs(raw("070") * 1e-3 - rows[f"{name}:time_bias"]["estimate"]) <= 0.5e-3
        assert abs(raw("080", 0, 2) * 1e-5 - rows[f"{name}:range_gain"]["estimate"]) <= 0.5e-5
        assert abs(raw("080", 2, 4) * NM_M / 128 - rows[f"{name}:range_bias"]["estimate"]) <= NM_M / 256
        assert items["010"].unparse().to_bytes() == bytes([25, 200])


def test_the_api_page_history_metrics_and_csv_agree(run):
    assert "<html" in run["page"].lower()
    states = {s["state"] for s in run["history"]["states"]}
    assert states == {"range_bias", "bearing_bias", "range_gain", "time_bias"}
    h = run["history"]["states"][0]
    assert len(h["time_s"]) == len(h["estimate"]) == len(h["sigma"]) > 5
    assert 'registration_plots_total{sensor="R1"}' in run["metrics"]
    lines = run["csv"].splitlines()
    assert lines[0] == "object,state,unit,estimate,sigma,status"
    assert len(lines) - 1 == len(run["estimates"]["estimates"])


def test_sigterm_ends_the_service_with_exit_0_within_10_s(run):
    rc, seconds, stderr = run["stopped"]
    assert rc == 0, stderr
    assert seconds < 10.0
    assert (run["state"] / "state.npz").is_file()


def test_a_restart_on_the_same_state_serves_the_same_estimates_before_any_data(run):
    with serving("--state", str(run["state"]), "--date", "2024-05-01") as svc:
        assert "resumed" in svc.line
        again = svc.get("/api/estimates")
        svc.stop()
    assert again == run["estimates"]


def test_no_request_changes_state():
    with serving() as svc:
        for method in ("POST", "PUT", "DELETE"):
            req = urllib.request.Request(f"http://127.0.0.1:{svc.http_port}/api/estimates", method=method)
            with pytest.raises(urllib.error.HTTPError) as err:
                urllib.request.urlopen(req, timeout=5)
            assert err.value.code == 405
        with pytest.raises(urllib.error.HTTPError) as err:
            svc.get("/api/history?sensor=R9")
        assert err.value.code == 404
        svc.stop()


def _exit_of(*options: str) -> subprocess.CompletedProcess:
    cmd = [sys.executable, "-m", "registration", "serve", *options]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=60)


def test_a_port_in_use_exits_2_with_one_line():
    taken = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    taken.bind(("127.0.0.1", 0))
    port = taken.getsockname()[1]
    try:
        r = _exit_of(
            "--sites",
            str(SAMPLES / "SITES.csv"),
            "--asterix",
            f"udp://127.0.0.1:{port}",
            "--http",
            "127.0.0.1:0",
        )
    finally:
        taken.close()
    assert r.returncode == 2, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1 and f"127.0.0.1:{port}" in r.stderr


def test_an_unreadable_sites_file_exits_2_with_one_line(tmp_path):
    bad = tmp_path / "SITES.csv"
    bad.write_text("sensor,sac\nR1,x\n")
    r = _exit_of("--sites", str(bad), "--asterix", "udp://127.0.0.1:0", "--http", "127.0.0.1:0")
    assert r.returncode == 2
    assert len(r.stderr.strip().splitlines()) == 1 and "SITES.csv" in r.stderr
