"""The live estimator on recordings written by libasterix from simulations it was not tuned on:
a 0.1 deg azimuth step of one radar raises an alarm on that state alone within 2 min of data
time, and the estimate settles on the new value within 5 min; recordings without a step raise
none; the stream import counts what the file import counts; a saved state restores the same
estimates."""

from __future__ import annotations

import numpy as np
import pytest

from registration.io.asterix import import_asterix
from registration.live.estimator import LiveEstimator
from registration.live.inputs.asterix import AsterixStream
from registration.live.state import STATE_FILE, StateError, load_state, save_state
from tests.live.running import SAMPLES, datagrams

pytest.importorskip("asterix")  # libasterix writes the recordings

STEP_DEG = 0.1


def _recording(tmp_path, seed: int, duration_s: float, step_radar: str | None):
    from tests.io.asterix.atc import atc_truth, encode_atc

    atc = atc_truth(seed, duration_s=duration_s)
    t_step = float(np.min(atc.plots["time_s"])) + duration_s / 2
    if step_radar is not None:
        bearing = np.asarray(atc.plots["bearing_deg"], dtype=float).copy()
        bearing[
            (np.asarray(atc.plots["radar"]) == step_radar) & (np.asarray(atc.plots["time_s"]) > t_step)
        ] += STEP_DEG
        atc.plots["bearing_deg"] = bearing
    path = tmp_path / f"atc{seed}.pcap"
    path.write_bytes(encode_atc(atc.plots, atc.adsb, atc.sites, atc.date, atc.scans).pcap())
    return atc, path, t_step


def _run(atc, path, batch: int = 300) -> LiveEstimator:
    payloads = datagrams(path)
    stream = AsterixStream(atc.sites, date=atc.date)
    est = LiveEstimator(atc.sites)
    for i in range(0, len(payloads), batch):
        est.feed(stream.decode(payloads[i : i + batch], [8600] * len(payloads[i : i + batch])))
    est.flush()
    return est


def test_a_step_raises_one_alarm_within_2_min_and_the_estimate_settles_within_5_min(tmp_path):
    atc, path, t_step = _recording(tmp_path, 21, 900.0, "R3")
    est = _run(atc, path)
    alarms = list(est.alarms)
    assert [(a.object, a.state) for a in alarms] == [("R3", "bearing_bias")], alarms
    assert t_step < alarms[0].time_s <= t_step + 120.0
    assert alarms[0].z > 0  # the bearing grew
    i = est.layout.index("R3:bearing_bias")
    new = np.degrees(atc.truth["R3:bearing_bias"]) + STEP_DEG
    settled = [(t, np.degrees(x[i]), np.degrees(s[i])) for t, x, s in est.history if t >= t_step + 300.0]
    assert settled
    for t, x, s in settled:
        assert abs(x - new) < 3.5 * s, (t, x, s, new)


def test_no_alarm_without_a_change(tmp_path):
    atc, path, _ = _recording(tmp_path, 22, 600.0, None)
    est = _run(atc, path, batch=97)
    assert list(est.alarms) == []
    assert est.consistency()["verdict"] == "consistent"
    for name, value in atc.truth.items():
        i = est.layout.index(name)
        assert abs(est.filter.x[i] - value) < 3.5 * np.sqrt(est.filter.P[i, i]), name


def test_the_stream_counts_what_the_file_import_counts():
    sites = SAMPLES / "SITES.csv"
    from registration.io.asterix.tables.sites import read_sites

    stream = AsterixStream(read_sites(sites))
    payloads = datagrams(SAMPLES / "atc.pcap.gz")
    kept = 0
    for i in range(0, len(payloads), 211):
        kept += (
            stream.decode(payloads[i : i + 211], [8600] * len(payloads[i : i + 211]))
            .file_plots["time_s"]
            .size
        )
    result = import_asterix(SAMPLES / "atc.pcap.gz", sites)
    assert kept == stream.counters.plots == len(result.plots)
    assert stream.counters.references == len(result.reference)
    assert stream.counters.plots_without_id == int((result.plots["target"] == "").sum())


def test_duplicated_datagrams_and_garbage_are_counted_and_change_nothing():
    from registration.io.asterix.tables.sites import read_sites

    sites = read_sites(SAMPLES / "SITES.csv")
    payloads = datagrams(SAMPLES / "atc.pcap.gz")[:1500]
    clean, rough = AsterixStream(sites), AsterixStream(sites)
    a = clean.decode(payloads, [1] * len(payloads))
    doubled = [p for q in payloads for p in (q, q)] + [b"GET / HTTP/1.1\r\n\r\n", b"\x30\x00", b"\xff" * 40]
    b = rough.decode(doubled, [1] * len(doubled))
    assert {k: v.tolist() for k, v in a.plots.items()} == {k: v.tolist() for k, v in b.plots.items()}
    assert rough.counters.rejected["duplicate"] >= len(payloads)  # every record of every repeated datagram
    assert sum(rough.counters.rejected.values()) > rough.counters.rejected["duplicate"]


def test_a_saved_state_restores_the_same_estimates(tmp_path):
    from registration.io.asterix.tables.sites import read_sites

    sites = read_sites(SAMPLES / "SITES.csv")
    stream, est = AsterixStream(sites), LiveEstimator(sites)
    payloads = datagrams(SAMPLES / "atc.pcap.gz")
    est.feed(stream.decode(payloads, [1] * len(payloads)))
    save_state(tmp_path, est)
    again = LiveEstimator(sites)
    assert load_state(tmp_path, again)
    assert again.rows() == est.rows()
    assert list(again.history)[-1][0] == list(est.history)[-1][0]
    other = sites.iloc[:2]
    with pytest.raises(StateError, match="states"):
        load_state(tmp_path, LiveEstimator(other))
    (tmp_path / "elsewhere").write_bytes((tmp_path / STATE_FILE).read_bytes())
    (tmp_path / STATE_FILE).unlink()
    (tmp_path / STATE_FILE).symlink_to(tmp_path / "elsewhere")
    with pytest.raises(StateError, match="symbolic link"):
        load_state(tmp_path, LiveEstimator(sites))


def test_a_radar_with_its_own_psr_channel_streams_two_sensors_and_cat063_carries_both():
    from asterix.base import Bits, RawDatablock
    from asterix.generated import Cat_063_1_7

    from registration.io.asterix.tables.sites import read_sites
    from registration.live.outputs import cat063_message

    sites = read_sites(SAMPLES / "SITES.csv")
    sites["psr_channel"] = ["own", "", ""]
    stream, est = AsterixStream(sites), LiveEstimator(sites)
    payloads = datagrams(SAMPLES / "atc.pcap.gz")
    batch = stream.decode(payloads, [1] * len(payloads))
    result = import_asterix(SAMPLES / "atc.pcap.gz", sites)
    assert sorted(batch.file_plots["sensor"].tolist()) == sorted(result.plots["sensor"].tolist())
    assert (batch.file_plots["sensor"] == "R1.psr").sum() > 0
    assert "R1.psr:bearing_bias" in est.layout.names
    est.feed(batch)
    values = est.values()
    values["R1.psr"] = {"range_bias": 100.0, "bearing_bias": 0.001, "range_gain": 2e-4}
    message = cat063_message(values, {"R1": (30, 1), "R2": (30, 2)}, 36000.0, (25, 200))
    records = Cat_063_1_7.cv_uap.parse(RawDatablock.parse(Bits.from_bytes(message))[0].get_raw_records())
    first = records[0].items_regular
    assert "090" in first and "091" in first and "090" not in records[1].items_regular
    raw = int.from_bytes(first["091"].unparse().to_bytes(), "big", signed=True)
    assert abs(raw * 360.0 / 65536.0 - np.degrees(0.001)) <= 360.0 / 65536.0 / 2
