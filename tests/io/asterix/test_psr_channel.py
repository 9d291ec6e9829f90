"""SITES' ``psr_channel`` and ``prior_eccentricity_deg``: the import of the acceptance scenario
(tests/io/asterix/atc.py, encoded by libasterix) with ``psr_channel own`` on one radar gives that
radar's primary-only plots (CAT048 I048/020 TYP 1) to the sensor ``<radar>.psr``, a channel of the
radar in the sensors file; a bad value stops the import with exit 2 naming the row and column and
writes nothing."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from registration.cli import main
from registration.io.asterix import import_asterix
from registration.io.fleet.reading.read import read_fleet_tables
from tests.io.asterix.atc import atc_truth, encode_atc


@pytest.fixture(scope="module")
def atc(tmp_path_factory):
    folder = tmp_path_factory.mktemp("psr")
    truth = atc_truth(seed=7, duration_s=40.0)
    rec = encode_atc(truth.plots, truth.adsb, truth.sites, truth.date, truth.scans)
    (folder / "atc.ast").write_bytes(rec.raw())
    sites = truth.sites.copy()
    sites["psr_channel"] = ["own", "", ""]
    sites["prior_eccentricity_deg"] = [np.inf, 0.0, 0.0]
    return truth, folder, sites


def test_primary_only_plots_form_the_channel(atc):
    truth, folder, sites = atc
    result = import_asterix(folder / "atc.ast", sites, date=truth.date)
    sensors = result.sensors
    assert sensors["sensor"].tolist() == ["R1", "R2", "R3", "R1.psr"]
    assert sensors["channel_of"].tolist() == ["", "", "", "R1"]
    assert sensors["platform"].tolist() == ["R1", "R2", "R3", "R1"]
    ecc = sensors["prior_eccentricity_deg"].tolist()  # the channel's copy of its radar's (not used)
    assert np.isinf(ecc[0]) and ecc[1:3] == [0.0, 0.0] and np.isinf(ecc[3])
    counts = result.plots["sensor"].value_counts().to_dict()
    p = pd.DataFrame(truth.plots)
    primary = (p["radar"] == "R1") & (p["kind"] == "primary")
    assert primary.sum() > 0
    assert counts["R1.psr"] == primary.sum()
    assert counts["R1"] == ((p["radar"] == "R1") & ~primary).sum()
    assert counts["R2"] == (p["radar"] == "R2").sum()  # no channel: primary-only plots stay with the radar
    assert (result.plots.loc[result.plots["sensor"] == "R1.psr", "target"] == "").all()
    plain = import_asterix(folder / "atc.ast", truth.sites, date=truth.date)
    assert "channel_of" not in plain.sensors and set(plain.plots["sensor"]) == {"R1", "R2", "R3"}
    pd.testing.assert_frame_equal(
        plain.plots.drop(columns="sensor"), result.plots.drop(columns="sensor")
    )  # only the sensor of the primary-only plots changed


def test_the_written_tables_read_back_with_the_shared_states(atc, tmp_path):
    truth, folder, sites = atc
    sites_csv = tmp_path / "sites.csv"
    sites.to_csv(sites_csv, index=False)
    out = tmp_path / "tables"
    argv = ["import", "asterix", str(folder / "atc.ast"), "--sites", str(sites_csv), "--out", str(out)]
    assert main([*argv, "--date", truth.date.isoformat()]) == 0
    tables = read_fleet_tables(
        out / "plots.csv", out / "navigation.csv", out / "sensors.csv", out / "platforms.csv"
    )
    assert list(tables.sensors["channel_of"]) == ["", "", "", "R1"]
    assert np.isinf(tables.sensors["prior_eccentricity"][0])


@pytest.mark.parametrize("value", ["shared", "R2", "1"])
def test_a_bad_psr_channel_names_row_and_column(atc, tmp_path, capsys, value):
    truth, folder, sites = atc
    bad = sites.copy()
    bad["psr_channel"] = ["own", value, ""]
    sites_csv = tmp_path / "sites.csv"
    bad.to_csv(sites_csv, index=False)
    out = tmp_path / "out"
    code = main(["import", "asterix", str(folder / "atc.ast"), "--sites", str(sites_csv), "--out", str(out)])
    err = capsys.readouterr().err
    assert code == 2
    assert f"{sites_csv}: row 1, column 'psr_channel': {value!r} is not a PSR channel" in err
    assert not out.exists() or not any(out.iterdir())
