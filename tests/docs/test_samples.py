"""The sample recordings of examples/recordings/ (the first real-data run of docs/getting-started.md):
``make.py`` makes them again byte for byte, and the commands the page gives import and register
them, every error within 3.5 sigma of the truth they were simulated with."""

from __future__ import annotations

import importlib.util
import json
import math
from pathlib import Path

import pandas as pd
import pytest

from registration.cli import main

SAMPLES = Path(__file__).resolve().parents[2] / "examples" / "recordings"
FILES = ("atc.pcap.gz", "SITES.csv", "bridge.log", "sensors.csv", "truth.json")
Z_LIMIT = 3.5


def test_make_writes_the_committed_samples_again(tmp_path):
    pytest.importorskip("asterix")  # libasterix encodes the ASTERIX sample (the test extra)
    spec = importlib.util.spec_from_file_location("make_samples", SAMPLES / "make.py")
    assert spec is not None and spec.loader is not None
    make = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(make)
    make.main(tmp_path)
    for name in FILES:
        assert (tmp_path / name).read_bytes() == (SAMPLES / name).read_bytes(), name


def _estimates(folder: Path) -> pd.DataFrame:
    return pd.read_csv(folder / "estimates.csv").set_index(["object", "state"])


def test_the_asterix_sample_registers_to_its_truth(tmp_path):
    assert main(["import", "asterix", str(SAMPLES / "atc.pcap.gz"), "--sites", str(SAMPLES / "SITES.csv"),
                 "--out", str(tmp_path / "tables")]) == 0  # fmt: skip
    assert main(["fleet", "register", "--tables", str(tmp_path / "tables"), "--out", str(tmp_path / "r"),
                 "--no-plots"]) == 0  # fmt: skip
    est = _estimates(tmp_path / "r")
    truth = json.loads((SAMPLES / "truth.json").read_text())["asterix"]
    for key, value in truth.items():
        sensor, state = key.split(":")
        row = est.loc[(sensor, state)]
        scale = math.degrees(1.0) if state == "bearing_bias" else 1.0  # the truth in rad, estimates in deg
        assert abs(row["estimate"] - value * scale) < Z_LIMIT * row["sigma"], (key, row.to_dict(), value)


def test_the_nmea_sample_registers_to_its_truth(tmp_path):
    assert main(["import", "nmea", str(SAMPLES / "bridge.log"), "--platform", "OWN", "--sensors",
                 str(SAMPLES / "sensors.csv"), "--out", str(tmp_path / "bridge")]) == 0  # fmt: skip
    assert main(["fleet", "register", "--tables", str(tmp_path / "bridge"), "--out", str(tmp_path / "r"),
                 "--no-plots"]) == 0  # fmt: skip
    est = _estimates(tmp_path / "r")
    truth = json.loads((SAMPLES / "truth.json").read_text())["nmea"]
    for state, value in (("range_bias", truth["range_bias_m"]), ("bearing_bias", truth["bearing_bias_deg"]),
                         ("time_bias", truth["clock_offset_s"])):  # fmt: skip
        row = est.loc[("RADAR", state)]
        assert abs(row["estimate"] - value) < Z_LIMIT * row["sigma"], (state, row.to_dict(), value)
