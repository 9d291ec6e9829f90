"""The pieces of a ship's bridge input, without a service: the NMEA import run piece by piece gives
what ``import_nmea`` gives on the whole log (any cut of its lines), a filter takes navigation as it
arrives (across north without a jump), and a ship beside radar sites adds its states and leaves
theirs as they were."""

from __future__ import annotations

import numpy as np
import pytest

from registration.fleet.online.filter import FleetFilter
from registration.io.asterix.tables.sites import read_sites
from registration.io.nmea import import_nmea
from registration.live.estimator import LiveEstimator
from registration.live.inputs.bridge import Bridge
from registration.live.inputs.nmea import NmeaStream
from tests.io.nmea.bridgelog import PLATFORM, BridgeLogConfig, simulate_bridge_log
from tests.live.running import SAMPLES


@pytest.fixture(scope="module")
def bridge_log(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("piecewise")
    log = simulate_bridge_log(BridgeLogConfig(seed=21, duration_s=120.0, bearing_reference="mixed"))
    path = log.write(tmp / "bridge.nmea")
    sensors = log.write_sensors(tmp / "SENSORS.csv")
    return path, sensors, import_nmea(path, PLATFORM, sensors)


def _pieces(path, sensors, size: int) -> tuple[dict, NmeaStream]:
    stream = NmeaStream(PLATFORM, sensors, hold_s=1e9)
    lines = path.read_bytes().split(b"\n")
    out: dict[str, list] = {"plots": [], "navigation": [], "references": []}
    for a in range(0, len(lines), size):
        stream.add_datagrams([line + b"\n" for line in lines[a : a + size] if line.strip()])
        for batch in (stream.take(),):
            for k in out:
                if batch is not None and getattr(batch, k) is not None:
                    out[k].append(getattr(batch, k))
    batch = stream.take(force=True)
    for k in out:
        if batch is not None and getattr(batch, k) is not None:
            out[k].append(getattr(batch, k))
    return {k: {c: np.concatenate([p[c] for p in v]) for c in v[0]} for k, v in out.items()}, stream


@pytest.mark.parametrize("size", [37, 1500])
def test_the_import_piece_by_piece_gives_the_whole_logs(bridge_log, size):
    path, sensors, whole = bridge_log
    got, stream = _pieces(path, sensors, size)
    p = got["plots"]
    order = np.lexsort((p["track"], p["time"]))
    expected = whole.plots.sort_values(["time_s", "track"], kind="stable")
    assert np.array_equal(p["time"][order], expected["time_s"].to_numpy())
    assert np.array_equal(p["track"][order], expected["track"].to_numpy().astype(str))
    assert np.allclose(p["range"][order], expected["range_m"].to_numpy(), rtol=0, atol=1e-9)
    assert np.allclose(np.degrees(p["bearing"][order]), expected["bearing_deg"].to_numpy(), rtol=0, atol=1e-9)
    nav = got["navigation"]
    assert np.array_equal(nav["time"], whole.navigation["time_s"].to_numpy())
    assert np.allclose(np.degrees(nav["roll"]), whole.navigation["roll_deg"].to_numpy(), rtol=0, atol=1e-12)
    refs = got["references"]
    assert sorted(zip(refs["time"].tolist(), refs["target"].tolist())) == sorted(
        zip(whole.reference["time_s"].tolist(), whole.reference["target"].astype(str).tolist())
    )
    c = stream.counters
    assert dict(c.rejected) == whole.rejected["code"].value_counts().to_dict()
    assert dict(c.sentences) == {k: sum(v.values()) for k, v in whole.summary["sentences"].items()}


def test_navigation_added_as_it_arrives_continues_across_north(bridge_log):
    path, sensors, whole = bridge_log
    bridge = Bridge(PLATFORM, sensors, 20.0)
    ship = bridge.ship_tables()
    nav0 = {
        "time": np.array([0.0]),
        "platform": np.array([PLATFORM]),
        **{k: np.zeros(1) for k in ("lat", "lon", "alt", "heading", "pitch", "roll")},
    }
    f = FleetFilter(ship["sensors"], nav0, ship["platforms"])

    def rows(t, heading_deg):
        n = len(t)
        return {
            "time": np.asarray(t, dtype=float),
            "platform": np.full(n, PLATFORM),
            "lat": np.full(n, 0.75),
            "lon": np.full(n, 0.13),
            "alt": np.zeros(n),
            "heading": np.radians(heading_deg),
            "pitch": np.zeros(n),
            "roll": np.zeros(n),
        }

    assert f.add_navigation(rows([10.0, 11.0], [358.0, 359.5])) == 2  # replaces the placeholder
    assert f.add_navigation(rows([11.0, 12.0, 13.0], [359.5, 0.5, 1.5])) == 2  # 11 s is not new
    t, v = f.tracks[PLATFORM]
    assert np.array_equal(t, [10.0, 11.0, 12.0, 13.0])
    assert np.allclose(np.degrees(np.diff(v[:, 3])), [1.5, 1.0, 1.0])  # no 360 deg jump
    assert f.outside_navigation(np.array(["RADAR", "RADAR"]), np.array([12.5, 13.5])).tolist() == [
        False,
        True,
    ]
    f.forget_navigation(12.5)
    assert np.array_equal(f.tracks[PLATFORM][0], [12.0, 13.0])


def test_a_ship_beside_radar_sites_adds_its_states_and_leaves_theirs(bridge_log):
    _, sensors, _ = bridge_log
    sites = read_sites(SAMPLES / "SITES.csv")
    alone = LiveEstimator(sites)
    both = LiveEstimator(sites, ship=Bridge(PLATFORM, sensors, 20.0).file_tables)
    prior = dict(zip(both.layout.names, both.layout.prior_sigma))
    for name, sigma in zip(alone.layout.names, alone.layout.prior_sigma):
        assert prior.pop(name) == sigma, name
    # the radar's own states, estimated; the range gain its sensors file does not model, held at 0
    assert prior == {
        "OWN:heading_error": 0.0,
        "OWN:pitch_error": 0.0,
        "OWN:roll_error": 0.0,
        "RADAR:range_bias": np.inf,
        "RADAR:bearing_bias": np.inf,
        "RADAR:range_gain": 0.0,
        "RADAR:time_bias": np.inf,
    }


class _Ship:
    """An estimator's ship inputs, ignored: the labels alone are looked at."""

    def add_ship_data(self, navigation, references, targets) -> None:
        pass


def _labels(path, sensors, size: int) -> tuple[dict, int]:
    bridge = Bridge(PLATFORM, sensors, 20.0, hold_s=1e9)
    bridge.stream.hold_s = 1e9  # the feed never goes quiet by wall time: the test decides the end
    lines = path.read_bytes().split(b"\n")
    for a in range(0, len(lines), size):
        bridge.stream.add_datagrams([line + b"\n" for line in lines[a : a + size] if line.strip()])
        bridge.take(_Ship())
    bridge.take(_Ship(), force=True)
    return dict(bridge.labels.labels), bridge.labels.runs


def test_track_names_do_not_depend_on_how_the_stream_was_cut(bridge_log):
    """A loaded service imports bigger pieces: the association must run at the same data times
    (a grid) on the same data, so that every track gets the same vessel, and at the end once more."""
    path, sensors, _ = bridge_log
    small, runs_small = _labels(path, sensors, 40)
    big, runs_big = _labels(path, sensors, 2000)
    assert small and small == big
    assert runs_small == runs_big >= 4  # 120 s of data: the grid's runs (every 30 s) and the final one
