"""import_asterix on the standard recording (tests/io/asterix/scenario.py): every container form
gives the same tables, the plot and reference rules, the summary, and the fleet reader accepts
the tables."""

from __future__ import annotations

import io
import math

import numpy as np
import pandas as pd
import pytest

import registration.core.progress as progress
from registration.io.asterix import import_asterix
from tests.io.asterix.scenario import ADSB_TARGETS, DURATION, PLOT_TARGETS, RADARS, STAMP_DELAY_S, T0

FORMS = ("raw", "pcap", "pcapng", "raw.gz", "pcap.gz", "pcapng.gz")


def _scans(sensor: str) -> int:
    return int(DURATION // RADARS[sensor][5])


@pytest.mark.parametrize("form", FORMS[1:])
def test_every_form_gives_the_same_tables(imported, form):
    """Raw, pcap, pcapng, each gzip too: the same data blocks, so the same tables, row for row."""
    base, other = imported["raw"], imported[form]
    for name in ("plots", "navigation", "sensors", "platforms", "reference"):
        pd.testing.assert_frame_equal(getattr(base, name), getattr(other, name), check_exact=True, obj=name)
    assert base.summary["rejected"] == other.summary["rejected"]
    assert base.summary["sensors"]["R1"]["clock_check"] == other.summary["sensors"]["R1"]["clock_check"]


def test_the_captures_count_the_packets_that_are_not_udp(imported):
    pcap = imported["pcap"].summary["files"][0]
    assert pcap["format"] == "pcap" and pcap["non_udp_packets"] == 2  # an ARP and a TCP frame
    assert pcap["skipped_packets"]["not_ip"] == 1 and pcap["skipped_packets"]["not_udp"] == 1
    assert imported["pcapng"].summary["files"][0]["non_udp_packets"] == 3  # and a Simple Packet Block of ARP
    assert imported["pcapng.gz"].summary["files"][0]["gzip"] is True


def test_plot_ids_follow_the_mode_s_and_mode_3a_rules(imported):
    plots = imported["pcap"].plots
    for sensor in ("R1", "R2"):
        mine = plots[plots["sensor"] == sensor]
        got = mine.groupby("target").size().to_dict()
        want = {}
        for _, _, kwargs, expect in PLOT_TARGETS.values():
            if expect in ("test_target", "simulated", "field_monitor"):
                continue
            want[expect] = want.get(expect, 0) + _scans(sensor)
        assert got == want, sensor
    assert set(plots["target"]) == {"4CA1F3", "3C6DD2", "A1234", "A6543", ""}
    assert "elevation_deg" not in plots.columns


def test_plot_values_are_the_encoded_ones(imported):
    plots = imported["raw"].plots
    r1 = plots[(plots["sensor"] == "R1") & (plots["target"] == "A1234")].reset_index(drop=True)
    bearing0, rho, _, _ = PLOT_TARGETS["MA1"]
    period = RADARS["R1"][5]
    scans = np.arange(_scans("R1"))
    bearing = (bearing0 + 0.5 * scans) % 360
    np.testing.assert_array_equal(r1["range_m"], rho * 1852.0)  # 1/256 NM, 1852 m exactly
    np.testing.assert_allclose(
        r1["bearing_deg"], np.round(bearing / 360 * 65536) * 360 / 65536, rtol=0, atol=0
    )
    np.testing.assert_allclose(
        r1["time_s"], np.round((T0 + (scans + bearing / 360) * period) * 128) / 128, atol=0
    )


def test_set_aside_plots_and_reports_name_their_reason(imported):
    rejected = imported["pcapng"].rejected
    counts = rejected.groupby(["category", "reason_code"]).size().to_dict()
    radars = _scans("R1") + _scans("R2")
    assert counts[(48, "test_target")] == counts[(48, "simulated")] == counts[(48, "field_monitor")] == radars
    assert counts[(48, "unknown_sac_sic")] == len(PLOT_TARGETS) * _scans("RX")
    assert counts[(34, "unknown_sac_sic")] > 0
    for address, (_, expect) in ADSB_TARGETS.items():
        if expect in ("low_nacp", "no_quality", "no_geometric_height"):
            assert counts[(21, expect)] == DURATION, expect
    assert counts[(21, "simulated")] == DURATION
    assert (rejected["packet"].notna()).all() and rejected["offset"].min() > 0
    assert set(rejected.columns) == {"file", "offset", "packet", "category", "reason_code", "reason"}
    assert imported["raw"].rejected["packet"].isna().all()


def test_reference_sigma_comes_from_nacp_and_gva(imported):
    ref = imported["raw"].reference
    assert set(ref["target"]) == {"4CA1F3", "3C6DD2"}  # DDDDDD is never plotted
    sigma = ref.groupby("target")["sigma_m"].unique()
    sigma_up = ref.groupby("target")["sigma_up_m"].unique()
    circular_95 = math.sqrt(-2 * math.log(0.05))
    assert sigma["4CA1F3"] == pytest.approx(10.0 / circular_95)  # NACp 10: EPU 10 m
    assert sigma_up["4CA1F3"] == pytest.approx(45.0 / 1.959964)  # GVA 2: 45 m at 95 %
    assert sigma["3C6DD2"] == pytest.approx(92.6 / circular_95)  # NACp 8: EPU 0.05 NM
    assert sigma_up["3C6DD2"] == pytest.approx(2 * 92.6 / circular_95)  # no GVA: twice the horizontal
    first = ref[ref["target"] == "4CA1F3"].iloc[0]
    assert first["alt_m"] == pytest.approx(1600 * 6.25 * 0.3048)
    assert first["lat_deg"] == pytest.approx(45.1, abs=2e-7) and first["time_s"] == pytest.approx(
        T0, abs=1 / 128
    )


def test_all_reference_targets_on_request(files, sites):
    result = import_asterix(files["raw"], sites, reference_targets="all")
    assert "DDDDDD" in set(result.reference["target"])
    assert result.summary["reference"]["kept"] == "all"


def test_summary_scan_periods_clock_check_and_unknown_sources(imported):
    summary = imported["pcap"].summary
    r1, r2 = summary["sensors"]["R1"], summary["sensors"]["R2"]
    assert r1["scan_period_s"] == pytest.approx(4.0) and r2["scan_period_s"] == pytest.approx(5.0)
    assert r1["antenna_rotation_period_s"] == pytest.approx(4.0)
    assert (
        abs(r1["clock_check"]["median_offset_s"]) < 1 / 128
        and r1["clock_check"]["plots_outside_their_sector"] == 0
    )
    assert r2["clock_check"]["median_offset_s"] == pytest.approx(STAMP_DELAY_S["R2"], abs=1 / 128)
    assert r2["clock_check"]["plots_outside_their_sector"] > 0  # stamped 0.25 s late: past their sector
    unknown = {(s["category"], s["sac"], s["sic"]): s["records"] for s in summary["sac_sic_not_in_sites"]}
    assert set(unknown) == {("034", 10, 9), ("048", 10, 9)}
    assert unknown[("048", 10, 9)] == len(PLOT_TARGETS) * _scans("RX")
    assert summary["time"]["reference_date"] == "2024-05-01"
    assert imported["raw"].summary["time"]["reference_date"] is None
    assert "first day of the recording" in imported["raw"].summary["time"]["time_s"]
    assert 0.0 < r1["capture_minus_plot_time_s"] < 0.1
    import json

    json.dumps(summary)  # JSON-able


def test_site_tables(imported):
    result = imported["raw"]
    nav = result.navigation
    assert list(nav.columns) == [
        "time_s",
        "platform",
        "lat_deg",
        "lon_deg",
        "alt_m",
        "heading_deg",
        "pitch_deg",
        "roll_deg",
    ]
    assert (
        list(nav["platform"]) == ["R1", "R2"]
        and (nav[["heading_deg", "pitch_deg", "roll_deg"]] == 0).all().all()
    )
    assert nav["time_s"].iloc[0] >= T0
    assert list(result.sensors.columns) == ["sensor", "platform", "sigma_range_m", "sigma_bearing_deg"]
    assert (result.platforms[["prior_heading_deg", "prior_pitch_deg", "prior_roll_deg"]] == 0).all().all()


def test_sites_priors_pass_through(files, sites):
    sites = sites.assign(
        prior_range_gain=[0.01, np.nan], prior_time_bias_s=[1.0, 2.0], prior_heading_deg=[0.5, np.nan]
    )
    result = import_asterix(files["raw"], sites)
    assert list(result.sensors["prior_time_bias_s"]) == [1.0, 2.0]
    assert result.sensors["prior_range_gain"].iloc[0] == 0.01 and np.isnan(
        result.sensors["prior_range_gain"].iloc[1]
    )
    assert (
        result.platforms["prior_heading_deg"].iloc[0] == 0.5
        and result.platforms["prior_pitch_deg"].iloc[1] == 0
    )


def _read_fleet_tables():
    try:
        from registration.io.fleet.reading.read import read_fleet_tables
    except ImportError:  # before the fleet files moved to registration.io.fleet
        from registration.fleet import read_fleet_tables
    return read_fleet_tables


def test_the_fleet_reader_accepts_the_tables(imported, tmp_path):
    """Written with pandas, read back by the fleet reader (plots with ids only: rows without one
    are for the engine's mixed-id support)."""
    result = imported["pcap"]
    tables = result.tables
    tables["plots"] = tables["plots"][tables["plots"]["target"] != ""]
    paths = {}
    for name, frame in tables.items():
        paths[name] = tmp_path / f"{name}.csv"
        frame.to_csv(paths[name], index=False)
    fleet = _read_fleet_tables()(
        paths["plots"], paths["navigation"], paths["sensors"], paths["platforms"], paths["reference"]
    )
    np.testing.assert_allclose(fleet.plots["bearing"], np.radians(tables["plots"]["bearing_deg"]), rtol=1e-15)
    np.testing.assert_allclose(fleet.plots["range"], tables["plots"]["range_m"], rtol=1e-15)
    assert set(fleet.references["target"]) == {"4CA1F3", "3C6DD2"}
    np.testing.assert_allclose(
        fleet.references["lat"], np.radians(tables["reference"]["lat_deg"]), rtol=1e-15
    )
    np.testing.assert_array_equal(fleet.references["sigma_up"], tables["reference"]["sigma_up_m"])
    assert np.all(fleet.platforms["prior_heading"] == 0)
    problem = fleet.problem()
    assert problem.n_plots == len(tables["plots"])


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_progress_bar(files, sites, capsys, monkeypatch):
    """A bar over the bytes read on a terminal (the rule of registration.core.progress); captured,
    none; the import is the same either way."""
    quiet = import_asterix([files["raw"], files["pcap.gz"]], sites, progress=True, keep_duplicates=True)
    assert capsys.readouterr().err == ""
    terminal = _Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    monkeypatch.setattr(progress, "PROGRESS_DELAY_S", 0.0)
    result = import_asterix([files["raw"], files["pcap.gz"]], sites, progress=True, keep_duplicates=True)
    assert "ASTERIX" in terminal.getvalue()
    assert len(result.plots) == 2 * len(import_asterix(files["raw"], sites).plots)
    pd.testing.assert_frame_equal(result.plots, quiet.plots)
