"""A Mode A/C aircraft without ADS-B (no height measured anywhere) flying over a 2-D radar at
10 km: the radar sees it at elevations up to 80 deg, its slant range there measures the height
rather than the distance, and its plots start the window fit at elevation 0, kilometres from
the aircraft. The live estimator must raise no alarm and keep every estimate within 3.5 sigma of
the truth (a geometry and seed not used to find or tune the fix: the day recording's hour 17 was)."""

from __future__ import annotations

import numpy as np
import pytest

from tests.live.test_estimator import _run

pytest.importorskip("asterix")  # libasterix writes the recordings


def test_a_mode_ac_aircraft_over_a_radar_raises_no_alarm(tmp_path):
    from tests.io.asterix.atc import atc_truth, encode_atc

    atc = atc_truth(41, duration_s=240.0, n_aircraft=15, overfly=("R2", 2000.0, 10000.0))
    mine = (atc.plots["aircraft"] == 14) & (atc.plots["radar"] == "R2")
    assert atc.plots["range_m"][mine].min() < 10600.0  # overhead: 10 km up, 2 km aside
    assert set(atc.plots["kind"][atc.plots["aircraft"] == 14]) == {"mode_a"}  # no height, no ADS-B
    path = tmp_path / "overflight.pcap"
    path.write_bytes(encode_atc(atc.plots, atc.adsb, atc.sites, atc.date, atc.scans).pcap())
    est = _run(atc, path)
    assert list(est.alarms) == []
    assert est.filter.n_unconverged_plots == 0
    for name, value in atc.truth.items():
        i = est.layout.index(name)
        assert abs(est.filter.x[i] - value) < 3.5 * np.sqrt(est.filter.P[i, i]), name
