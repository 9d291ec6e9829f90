"""``fleet register --cat063 FILE``: the run's estimates as CAT063, read back by libasterix (the
independent decoder) to their LSB; without the import's summary, exit 2 before any solve."""

from __future__ import annotations

import subprocess
import sys

import pandas as pd
import pytest

from tests.live.running import SAMPLES

pytest.importorskip("asterix")
AZ_LSB_DEG = 360.0 / 65536.0


def _run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "registration", *args], capture_output=True, text=True, timeout=300
    )


def test_the_estimates_as_cat063_read_back_by_libasterix(tmp_path):
    from asterix.base import Bits, RawDatablock
    from asterix.generated import Cat_063_1_6

    tables, out, status = tmp_path / "t", tmp_path / "r", tmp_path / "status.ast"
    r = _run(
        "import",
        "asterix",
        str(SAMPLES / "atc.pcap.gz"),
        "--sites",
        str(SAMPLES / "SITES.csv"),
        "--out",
        str(tables),
    )
    assert r.returncode == 0, r.stderr
    r = _run(
        "fleet", "register", "--tables", str(tables), "--out", str(out), "--no-plots", "--cat063", str(status)
    )
    assert r.returncode == 0, r.stderr
    assert str(status) in r.stdout
    est = pd.read_csv(out / "estimates.csv").set_index(["object", "state"])["estimate"]
    blocks = RawDatablock.parse(Bits.from_bytes(status.read_bytes()))
    records = Cat_063_1_6.cv_uap.parse(blocks[0].get_raw_records())
    assert not isinstance(records, ValueError) and len(records) == 3
    for rec, name in zip(records, ["R1", "R2", "R3"], strict=True):
        items = rec.items_regular
        assert items["050"].unparse().to_bytes() == bytes([30, int(name[1])])
        raw = int.from_bytes(items["081"].unparse().to_bytes(), "big", signed=True)
        assert abs(raw * AZ_LSB_DEG - est[(name, "bearing_bias")]) <= AZ_LSB_DEG / 2
        raw = int.from_bytes(items["070"].unparse().to_bytes(), "big", signed=True)
        assert abs(raw * 1e-3 - est[(name, "time_bias")]) <= 0.5e-3


def test_without_the_import_summary_it_exits_2_naming_the_option(tmp_path):
    tables = tmp_path / "t"
    r = _run(
        "import",
        "asterix",
        str(SAMPLES / "atc.pcap.gz"),
        "--sites",
        str(SAMPLES / "SITES.csv"),
        "--out",
        str(tables),
    )
    assert r.returncode == 0
    (tables / "import_summary.json").unlink()
    r = _run(
        "fleet",
        "register",
        "--tables",
        str(tables),
        "--out",
        str(tmp_path / "r"),
        "--cat063",
        str(tmp_path / "s.ast"),
    )
    assert r.returncode == 2 and "--cat063" in r.stderr
    assert not (tmp_path / "r").exists() and not (tmp_path / "s.ast").exists()
