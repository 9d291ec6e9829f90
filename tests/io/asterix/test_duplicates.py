"""Issue 31 items 1 and 5: a feed recorded twice (the A and B LANs: every datagram on two UDP
ports; the same recording given twice) and a raw recording whose first blocks are replayed at its
end import to exactly the plots of the single feed; the duplicates are set aside (``duplicate``)
and counted per source and per file, time going back is counted; ``keep_duplicates`` keeps them.
The recordings are encoded by libasterix (tests/io/asterix/encode.py)."""

from __future__ import annotations

import pandas as pd
import pytest

from registration.cli import main
from registration.io.asterix import import_asterix
from tests.io.asterix.containers import two_lans as _two_lans


def _records(result) -> int:
    return sum(sum(f["records"].values()) for f in result.summary["files"])


@pytest.fixture(scope="module")
def single(files, sites):
    return import_asterix(files["pcap"], sites)


def test_a_b_lans_import_to_the_single_feed(recording, single, sites, tmp_path):
    path = tmp_path / "ab.pcap"
    path.write_bytes(_two_lans(recording))
    result = import_asterix(path, sites)
    pd.testing.assert_frame_equal(result.plots, single.plots)
    pd.testing.assert_frame_equal(result.reference, single.reference)
    dups = result.summary["duplicates"]
    assert dups["records"] == _records(single) and dups["set_aside"]
    assert result.summary["rejected"]["by_reason"]["duplicate"] == dups["records"]
    assert {e["category"] for e in dups["by_source"]} == {"048", "034", "021"}
    assert dups["by_file"] == [{"file": str(path), "records": dups["records"]}]
    assert dups["by_port"] == [{"port": 8601, "records": dups["records"]}]  # LAN B repeats LAN A
    assert "time_going_back" not in result.summary
    # with --ports, one LAN alone is the single feed without duplicates
    lan_a = import_asterix(path, sites, ports=[8600])
    pd.testing.assert_frame_equal(lan_a.plots, single.plots)
    assert "duplicates" not in lan_a.summary
    kept = import_asterix(path, sites, keep_duplicates=True)
    assert len(kept.plots) == 2 * len(single.plots) and kept.summary["duplicates"]["records"] == 0


def test_the_same_recording_given_twice(files, single, sites):
    result = import_asterix([files["pcap"], files["raw.gz"]], sites)
    pd.testing.assert_frame_equal(result.plots, single.plots)
    assert result.summary["duplicates"]["by_file"] == [
        {"file": str(files["raw.gz"]), "records": _records(single)}
    ]


def test_a_replayed_tail_is_set_aside_and_time_going_back_counted(recording, sites, tmp_path):
    n = 40
    plain, replayed = tmp_path / "plain.ast", tmp_path / "replayed.ast"
    plain.write_bytes(recording.raw())
    replayed.write_bytes(recording.raw() + b"".join(recording.blocks[:n]))
    once, twice = import_asterix(plain, sites), import_asterix(replayed, sites)
    pd.testing.assert_frame_equal(twice.plots, once.plots)
    pd.testing.assert_frame_equal(twice.reference, once.reference)
    head = import_asterix_bytes(b"".join(recording.blocks[:n]), sites, tmp_path)
    assert twice.summary["duplicates"]["records"] == _records(head) > 0
    back = twice.summary["time_going_back"]
    assert back and all(e["largest_step_s"] > 10 and e["first_file"] == str(replayed) for e in back)
    assert min(e["first_offset"] for e in back) >= len(recording.raw())
    assert "time_going_back" not in once.summary and "duplicates" not in once.summary


def import_asterix_bytes(data: bytes, sites, folder):
    path = folder / "head.ast"
    path.write_bytes(data)
    return import_asterix(path, sites)


def test_keep_duplicates_on_the_command_line(recording, tmp_path, capsys):
    from tests.io.asterix.scenario import sites_frame

    path = tmp_path / "ab.pcap"
    path.write_bytes(_two_lans(recording))
    sites = tmp_path / "sites.csv"
    sites_frame().to_csv(sites, index=False)
    argv = ["import", "asterix", str(path), "--sites", str(sites)]
    assert main([*argv, "--out", str(tmp_path / "once")]) == 0
    assert main([*argv, "--out", str(tmp_path / "twice"), "--keep-duplicates"]) == 0
    capsys.readouterr()
    once = pd.read_csv(tmp_path / "once" / "plots.csv")
    twice = pd.read_csv(tmp_path / "twice" / "plots.csv")
    assert len(twice) == 2 * len(once)
