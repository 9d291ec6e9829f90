"""Flight levels in the live path: the Mode C / Mode S levels of the aircraft without ADS-B become
heights, with the relation learned on the stream's recent ADS-B reports; on a recording whose
atmosphere is ISA + 12 K at QNH 1025 hPa (heights some 250-580 m above the flight levels' ISA
heights) the heights agree with the aircraft's true heights and with the file import's, and the
estimator stays within 3.5 sigma of the truth without an alarm (a seed not used elsewhere)."""

from __future__ import annotations

import numpy as np
import pytest

from registration.io.asterix import import_asterix
from registration.live.estimator import LiveEstimator
from registration.live.inputs.asterix import AsterixStream
from tests.live.running import datagrams

pytest.importorskip("asterix")  # libasterix writes the recordings


def test_flight_levels_become_heights_and_the_estimates_stay_right(tmp_path):
    from tests.io.asterix.atc import atc_truth, encode_atc

    atc = atc_truth(61, duration_s=240.0, n_aircraft=15, flight_levels=(12.0, 102500.0))
    path = tmp_path / "levels.pcap"
    path.write_bytes(encode_atc(atc.plots, atc.adsb, atc.sites, atc.date, atc.scans).pcap())
    payloads = datagrams(path)
    stream, est = AsterixStream(atc.sites, date=atc.date), LiveEstimator(atc.sites)
    heights = []
    for i in range(0, len(payloads), 300):
        batch = stream.decode(payloads[i : i + 300], [8600] * len(payloads[i : i + 300]))
        if batch.references is not None:
            alone = ~np.isfinite(batch.references["sigma"])  # heights without a position
            heights.append({k: v[alone] for k, v in batch.references.items()})
        est.feed(batch)
    est.flush()
    rows = {k: np.concatenate([h[k] for h in heights]) for k in heights[0]}

    # every plot of the aircraft without ADS-B (12 and 13 Mode S, 14 Mode A/C) became a height
    without_adsb = np.asarray(atc.plots["aircraft"]) >= 12
    assert rows["time"].size == int(without_adsb.sum()) == stream.counters.flight_level_heights
    assert stream.counters.flight_levels_unused == 0
    kind = np.asarray(atc.plots["kind"])[without_adsb]
    ids = np.array(
        [
            f"{a:06X}" if k == "mode_s" else f"A{m:04o}"
            for k, a, m in zip(kind, atc.plots["address"][without_adsb], atc.plots["mode_a"][without_adsb])
        ]
    )
    t_plot = np.asarray(atc.plots["time_s"])[without_adsb]
    true_h = np.asarray(atc.plots["true_height_m"])[without_adsb]
    apart = np.abs(rows["time"][:, None] - t_plot[None, :]) + 1e9 * (rows["target"][:, None] != ids[None, :])
    nearest = apart.argmin(axis=1)  # the same aircraft's plot at that time (1/128 s apart)
    assert apart[np.arange(nearest.size), nearest].max() < 1.0 / 256.0
    error = (rows["alt"] - true_h[nearest]) / rows["sigma_up"]
    assert np.abs(error).max() < 4.0 and abs(error.mean()) < 0.5, (error.min(), error.max(), error.mean())
    # the file import's heights of the same plots: the relation learned on all its reports
    reference = import_asterix(path, atc.sites).reference
    alone = ~np.isfinite(reference["sigma_m"].to_numpy())
    assert int(alone.sum()) == rows["time"].size
    keys = zip(reference["time_s"].to_numpy()[alone], reference["target"].to_numpy()[alone].astype(str))
    file_alt = dict(zip(keys, reference["alt_m"].to_numpy()[alone]))
    diff = np.array([a - file_alt[(t, g)] for t, g, a in zip(rows["time"], rows["target"], rows["alt"])])
    assert np.abs(diff / rows["sigma_up"]).max() < 0.5

    assert list(est.alarms) == []
    for name, value in atc.truth.items():
        i = est.layout.index(name)
        assert abs(est.filter.x[i] - value) < 3.5 * np.sqrt(est.filter.P[i, i]), name
