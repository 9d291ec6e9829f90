"""The acceptance scenario's encoder (tests/io/asterix/atc.py) on a short run: raw and pcap give the
same tables, and the plots and references are the truth arrays to the ASTERIX resolution. The
registration itself (every error within 3.5 sigma) is ``python3 -m tests.io.asterix.acceptance``,
too slow for the unit tests (about 45 s)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from registration.io.asterix import import_asterix
from tests.io.asterix.atc import RADAR_LAYOUT, atc_truth, encode_atc


@pytest.fixture(scope="module")
def atc(tmp_path_factory):
    folder = tmp_path_factory.mktemp("atc")
    truth = atc_truth(seed=5, duration_s=60.0)
    rec = encode_atc(truth.plots, truth.adsb, truth.sites, truth.date, truth.scans)
    (folder / "atc.ast").write_bytes(rec.raw())
    (folder / "atc.pcap").write_bytes(rec.pcap())
    return (
        truth,
        import_asterix(folder / "atc.ast", truth.sites, date=truth.date),
        import_asterix(folder / "atc.pcap", truth.sites),
    )


def test_raw_and_pcap_agree(atc):
    _, raw, pcap = atc
    for name in ("plots", "reference", "navigation", "sensors", "platforms"):
        pd.testing.assert_frame_equal(getattr(raw, name), getattr(pcap, name), obj=name)


def test_plots_are_the_truth_to_the_asterix_resolution(atc):
    truth, _, pcap = atc
    p = (
        pd.DataFrame({k: v for k, v in truth.plots.items()})
        .sort_values("time_s", kind="stable")
        .reset_index(drop=True)
    )
    got = pcap.plots
    assert len(got) == len(p)
    order = np.lexsort((got["bearing_deg"], np.round(got["time_s"] * 128)))
    want = np.lexsort((p["bearing_deg"], np.round(p["time_s"] * 128)))
    got, p = got.iloc[order].reset_index(drop=True), p.iloc[want].reset_index(drop=True)
    np.testing.assert_allclose(got["time_s"], p["time_s"], atol=0.5 / 128)
    np.testing.assert_allclose(got["range_m"], p["range_m"], atol=0.5 * 1852 / 256)
    bearing = (got["bearing_deg"] - p["bearing_deg"] + 180) % 360 - 180
    assert np.abs(bearing).max() <= 0.5 * 360 / 65536 + 1e-9
    assert (got["sensor"].to_numpy() == p["radar"].to_numpy()).all()
    ids = np.where(
        p["kind"] == "mode_s",
        [f"{a:06X}" for a in p["address"]],
        np.where(p["kind"] == "mode_a", [f"A{m:04o}" if m >= 0 else "" for m in p["mode_a"]], ""),
    )
    assert (got["target"].to_numpy() == ids).all()
    assert (got["kind"].to_numpy() == p["kind"].to_numpy()).all()  # mode_s, mode_a, primary (TYP 1)


def test_references_and_summary(atc):
    truth, _, pcap = atc
    ref = pcap.reference
    assert len(ref) == len(truth.adsb["time_s"])
    np.testing.assert_allclose(
        np.sort(ref["alt_m"]), np.sort(truth.adsb["height_m"]), atol=0.5 * 6.25 * 0.3048
    )
    for name, layout in RADAR_LAYOUT.items():
        s = pcap.summary["sensors"][name]
        assert s["scan_period_s"] == pytest.approx(layout[5])
        assert abs(s["clock_check"]["median_offset_s"]) < 0.02  # azimuth bias / 360 x period, plus rounding
        assert s["plots_without_id"] > 0 and s["plots_mode_a"] > 0 and s["plots_mode_s"] > 0
