"""Issue 32, the decompression blow-up: a small gzip of millions of empty CAT048 records is handled
within a bounded time and memory (measured in a subprocess), and the bounds of
:mod:`registration.io.files.limits` (decompressed bytes, records per input, rejected rows
listed) hold and can be overridden."""

from __future__ import annotations

import gzip
import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from registration.io.asterix import import_asterix
from tests.io.asterix.repro import empty_cat048_gzip, source_only_cat048_gzip

SITES = pd.DataFrame(
    {
        "sensor": ["R1"],
        "sac": [10],
        "sic": [1],
        "lat_deg": [45.0],
        "lon_deg": [15.0],
        "alt_m": [100.0],
        "sigma_range_m": [50.0],
        "sigma_bearing_deg": [0.1],
    }
)
#: Runs the command and prints its own peak resident memory (MiB) last: VmHWM of /proc/self/status,
#: which starts anew at exec (ru_maxrss carries the parent's peak across fork and exec on Linux).
_MEASURE = (
    "import sys\n"
    "from registration.cli import main\n"
    "code = main(sys.argv[1:])\n"
    "kib = [l.split()[1] for l in open('/proc/self/status') if l.startswith('VmHWM:')][0]\n"
    "print('PEAK_MIB', int(kib) / 1024, code)\n"
)


@pytest.mark.parametrize("build", [empty_cat048_gzip, source_only_cat048_gzip])
def test_small_gzip_of_empty_records_in_bounded_time_and_memory(tmp_path, build):
    """The 1.5 KB gzip: at most 10 s and 500 MiB (peak RSS of the command's own process), and a
    rejected.csv of at most 100 001 rows whatever the count."""
    data = build(1_500_000 if build is empty_cat048_gzip else 500_000)
    assert len(data) < 2000
    (tmp_path / "bomb.ast.gz").write_bytes(data)
    SITES.to_csv(tmp_path / "sites.csv", index=False)
    out = tmp_path / "out"
    argv = ["import", "asterix", str(tmp_path / "bomb.ast.gz"), "--sites", str(tmp_path / "sites.csv")]
    start = time.perf_counter()
    done = subprocess.run(
        [sys.executable, "-c", _MEASURE, *argv, "--out", str(out)],
        capture_output=True,
        text=True,
        cwd=Path(__file__).parents[3],
        timeout=120,
    )
    elapsed = time.perf_counter() - start
    assert "Traceback" not in done.stderr, done.stderr
    peak, code = done.stdout.split("PEAK_MIB")[-1].split()
    assert int(code) in (0, 2)
    assert elapsed < 10.0 and float(peak) < 500.0, (elapsed, peak)
    if int(code) == 0:
        rows = sum(1 for _ in open(out / "rejected.csv")) - 1
        summary = json.loads((out / "import_summary.json").read_text())
        assert rows <= 100_001 and summary["rejected"]["total"] >= rows - 1


def test_rejected_rows_beyond_the_bound_are_counted_with_one_row_saying_so(tmp_path):
    (tmp_path / "b.gz").write_bytes(source_only_cat048_gzip(5000))
    result = import_asterix(tmp_path / "b.gz", SITES, max_rejected_rows=100, keep_duplicates=True)
    assert len(result.rejected) == 101
    assert result.summary["rejected"]["total"] == 5000
    assert result.summary["rejected"]["by_reason"] == {"missing_item": 5000}
    last = result.rejected.iloc[-1]
    assert last["reason_code"] == "not_listed" and "4900 more items set aside" in last["reason"]
    assert list(result.rejected["reason_code"][:100].unique()) == ["missing_item"]


def test_records_and_bytes_beyond_the_bounds_are_set_aside(tmp_path):
    (tmp_path / "b.gz").write_bytes(source_only_cat048_gzip(5000))
    result = import_asterix(tmp_path / "b.gz", SITES, max_records=1000, keep_duplicates=True)
    assert result.summary["files"][0]["records"]["048"] == 1000
    over = result.rejected[result.rejected["reason_code"] == "over_limit"]
    assert len(over) == 1 and "max_records" in over["reason"].iloc[0]
    assert over["offset"].iloc[0] == 3 + 3 * 1000
    blocks = bytes([48, 0, 9, 0x80, 10, 1, 0x80, 10, 1]) * 10
    (tmp_path / "b.ast").write_bytes(blocks)
    (tmp_path / "c.ast.gz").write_bytes(gzip.compress(blocks))
    for name in ("b.ast", "c.ast.gz"):
        result = import_asterix(tmp_path / name, SITES, max_bytes=45, keep_duplicates=True)
        summary = result.summary["files"][0]
        assert summary["bytes"] == 45 and summary["records"]["048"] == 10
        assert "max_bytes" in " ".join(summary["notes"])
        assert set(result.rejected["reason_code"]) == {"missing_item", "over_limit"}


@pytest.mark.parametrize("bad", [0, -1, 1.5, True])
def test_bounds_must_be_positive_integers(tmp_path, bad):
    (tmp_path / "b.gz").write_bytes(source_only_cat048_gzip(10))
    with pytest.raises(ValueError, match="max_records: expected a positive integer"):
        import_asterix(tmp_path / "b.gz", SITES, max_records=bad)


def test_the_command_warns_when_a_bound_is_reached(tmp_path, capsys):
    from registration.cli import main

    (tmp_path / "b.gz").write_bytes(source_only_cat048_gzip(5000))
    SITES.to_csv(tmp_path / "sites.csv", index=False)
    argv = ["import", "asterix", str(tmp_path / "b.gz"), "--sites", str(tmp_path / "sites.csv")]
    assert (
        main([*argv, "--out", str(tmp_path / "o"), "--max-records", "1000", "--max-rejected-rows", "10"]) == 0
    )
    captured = capsys.readouterr()
    assert "warning: " in captured.err and "--max-records" in captured.err
    assert "set aside 1001 records" in captured.out  # the summary total (1000 records, 1 over_limit)
    assert sum(1 for _ in open(tmp_path / "o" / "rejected.csv")) == 1 + 11


def test_the_record_bound_cuts_every_category_at_the_same_place_in_the_file(tmp_path):
    """A recording interleaves categories (plots, sector messages, ADS-B): the bound keeps the
    first records of the file, all categories together, so the import covers one span of the
    recording; before, CAT048 was decoded to the end and the later categories lost."""
    cat048 = bytes([48, 0, 9, 0x80, 10, 1, 0x80, 10, 1])  # two records (I048/010 only)
    cat034 = bytes([34, 0, 6, 0x80, 10, 1])  # one record
    (tmp_path / "b.ast").write_bytes((cat048 + cat034) * 10)
    result = import_asterix(tmp_path / "b.ast", SITES, max_records=15, keep_duplicates=True)
    records = result.summary["files"][0]["records"]
    assert (records["048"], records["034"]) == (10, 5)
    over = result.rejected[result.rejected["reason_code"] == "over_limit"]
    assert sorted(over["category"]) == [34, 48]
    block = len(cat048 + cat034)
    assert dict(zip(over["category"], over["offset"])) == {48: 5 * block + 3, 34: 5 * block + len(cat048) + 3}
    assert "of every category" in " ".join(result.summary["files"][0]["notes"])


@pytest.mark.parametrize("form", ["raw", "pcap.gz", "pcapng"])
def test_the_record_bound_keeps_the_first_records_of_a_libasterix_recording(files, form):
    """The standard recording (CAT048 plots, CAT034 sector messages, CAT021 reports interleaved,
    encoded by libasterix; raw, or in capture wrappers): with the bound at half its records, what is
    decoded is exactly the records of the whole decode that come first in the file, of every
    category together."""
    from registration.io.asterix.decode.reader import decode_file
    from registration.io.files.limits import Limits

    whole = decode_file(files[form])
    offsets = {cat: r.offset for cat, r in whole.records.items()}
    total = sum(o.size for o in offsets.values())
    bound = total // 2
    cut = decode_file(files[form], limits=Limits(max_records=bound))
    first = np.sort(np.concatenate(list(offsets.values())))[:bound]
    kept = 0
    for cat, o in offsets.items():
        np.testing.assert_array_equal(cut.records[cat].offset, o[np.isin(o, first)])
        kept += cut.records[cat].size
    assert kept == bound
    assert sum(cut.records[c].size > 0 for c in (48, 34, 21)) == 3  # every category, not only the first
    assert "of every category" in " ".join(cut.capture.notes)
