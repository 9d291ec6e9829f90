"""Issue 31 item 4: the options that were API-only, on the command line: --cat021-edition (with a
hint in the summary when CAT021 records fail to walk in the edition chosen but walk in the other
family) and --ports."""

from __future__ import annotations

import json

import pandas as pd

from registration.cli import main
from registration.cli.importing import CAT021_EDITIONS
from registration.io.asterix import SUPPORTED_EDITIONS, import_asterix
from tests.io.asterix.encode import cat021_record, cat048_record, encode_recording
from tests.io.asterix.scenario import DATE, sites_frame


def test_the_edition_choices_are_the_supported_ones():
    assert CAT021_EDITIONS == SUPPORTED_EDITIONS[21]


def _old_feed(tmp_path):
    messages = [
        (
            10.0 + k,
            21,
            1,
            1,
            cat021_record(
                "0.26",
                1,
                1,
                10.0 + k,
                address=0x400000 + k,
                lat_deg=45.1,
                lon_deg=5.1,
                height_ft_raw=None,
                nacp=9,
            ),
        )
        for k in range(12)
    ]
    messages.append((30.0, 48, 10, 1, cat048_record("1.32", 10, 1, 30.0, 2560, 1000, address=0x400001)))
    path = tmp_path / "old.ast"
    path.write_bytes(encode_recording(messages, DATE, editions={21: "0.26"}).raw())
    return path


def test_cat021_edition_on_the_command_line_and_the_hint(tmp_path, capsys):
    path = _old_feed(tmp_path)
    default = import_asterix(path, sites_frame())
    notes = " ".join(default.summary["files"][0].get("notes", []))
    assert "failed to walk in edition 2.7" in notes and "--cat021-edition 0.26" in notes
    sites = tmp_path / "sites.csv"
    sites_frame().to_csv(sites, index=False)
    argv = ["import", "asterix", str(path), "--sites", str(sites), "--out", str(tmp_path / "o")]
    assert main([*argv, "--cat021-edition", "0.26"]) == 0
    summary = json.loads((tmp_path / "o" / "import_summary.json").read_text())
    assert summary["editions"]["021"] == "0.26" and summary["files"][0]["records"]["021"] == 12
    assert "notes" not in summary["files"][0]
    assert main([*argv, "--cat021-edition", "9.9"]) == 2
    assert "--cat021-edition" in capsys.readouterr().err


def test_ports_on_the_command_line(files, tmp_path, capsys):
    sites = tmp_path / "sites.csv"
    sites_frame().to_csv(sites, index=False)
    argv = ["import", "asterix", str(files["pcap"]), "--sites", str(sites)]
    assert main([*argv, "--out", str(tmp_path / "all")]) == 0
    assert main([*argv, "--out", str(tmp_path / "p"), "--ports", "8600"]) == 0
    pd.testing.assert_frame_equal(
        pd.read_csv(tmp_path / "all" / "plots.csv"), pd.read_csv(tmp_path / "p" / "plots.csv")
    )
    capsys.readouterr()
    assert main([*argv, "--out", str(tmp_path / "q"), "--ports", "9"]) == 2
    assert "on the ports chosen" in capsys.readouterr().err
    assert main([*argv, "--out", str(tmp_path / "r"), "--ports", "0,x"]) == 2
