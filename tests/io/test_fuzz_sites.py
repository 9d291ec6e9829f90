"""A seeded, time-bounded fuzzer of the SITES reader of ``import asterix`` (issue 32, 5), through its
public API (:func:`registration.io.asterix.tables.sites.read_sites`): a small valid SITES.csv is
mutated (cells replaced by extreme numbers, text, NaN, empty, huge strings; rows duplicated or
dropped; columns dropped) and read. Every outcome is a table or a one-line ValueError naming the
file, and a cell's row with its column; no other exception, no RuntimeWarning."""

from __future__ import annotations

import math
import os
import random
import re
import warnings
from pathlib import Path

import pandas as pd
import pytest

from registration.io.asterix.tables.sites import read_sites
from registration.io.fleet.schema import HELD
from tests.fuzzing import assert_clean, fuzz_seeds, run_campaign

CASES = 2000  # the same on every machine; REGISTRATION_FUZZ_S: as many as that many seconds allow
SEED = int(os.environ.get("REGISTRATION_FUZZ_SEED", "20261203"))
CELLS = (
    "1e308",
    "-1e308",
    "1e-300",
    "1e400",
    "inf",
    "-inf",
    "nan",
    "NaN",
    "",
    " ",
    "abc",
    "0",
    "-1",
    "255",
    "256",
    "1.5",
    "1,5",
    "9" * 400,
    "x" * 5000,
    "é\u202e",
    '"',
    "None",
)


def base() -> pd.DataFrame:
    return pd.DataFrame(
        {
            "sensor": ["R1", "R2", "R3"],
            "sac": ["1", "1", "2"],
            "sic": ["2", "3", "2"],
            "lat_deg": ["45.1", "45.3", "44.9"],
            "lon_deg": ["5.1", "5.6", "4.8"],
            "alt_m": ["120", "80", "300"],
            "sigma_range_m": ["30", "40", "50"],
            "sigma_bearing_deg": ["0.1", "0.12", "0.15"],
            "prior_range_bias_m": ["", "100", "inf"],
            "prior_time_bias_s": ["1", "", "0"],
            "prior_heading_deg": ["0", "0.5", ""],
        }
    )


def mutate(frame: pd.DataFrame, rng: random.Random) -> pd.DataFrame:
    out = frame.copy()
    for _ in range(rng.randint(1, 3)):
        kind = rng.random()
        if kind < 0.6 and len(out):
            out.loc[rng.randrange(len(out)), rng.choice(list(out.columns))] = rng.choice(CELLS)
        elif kind < 0.75 and len(out):
            out = pd.concat([out, out.iloc[[rng.randrange(len(out))]]], ignore_index=True)
        elif kind < 0.85 and len(out):
            out = out.drop(index=rng.randrange(len(out))).reset_index(drop=True)
        elif len(out.columns) > 1:
            out = out.drop(columns=[rng.choice(list(out.columns))])
    return out


def test_mutated_sites_give_a_table_or_one_line_naming_the_file(tmp_path):
    for seed in fuzz_seeds(SEED, CASES):
        path = tmp_path / f"SITES-{seed}.csv"
        mutate(base(), random.Random(seed)).to_csv(path, index=False)
        with warnings.catch_warnings():
            warnings.simplefilter("error", RuntimeWarning)
            try:
                read_sites(path)
            except ValueError as exc:
                text = str(exc)
                assert "\n" not in text and text.startswith(f"{path}: "), (seed, text)
                if re.search(r"\brow \d+\b", text):
                    assert "column" in text, (seed, text)
            except Exception as exc:
                raise AssertionError(f"seed {seed}: {type(exc).__name__}: {exc}") from exc


@pytest.mark.parametrize(
    "column, value",
    [("prior_range_bias_m", "1e308"), ("prior_time_bias_s", "1e-300"), ("sigma_range_m", "1e-300")],
)
def test_sites_refuse_values_beyond_float64(tmp_path, column, value):
    frame = base()
    frame.loc[0, column] = value
    path = tmp_path / "SITES.csv"
    frame.to_csv(path, index=False)
    assert not HELD[0] <= abs(float(value)) <= HELD[1] and math.isfinite(float(value))
    with pytest.raises(ValueError, match=rf"row 0, column '{column}'"):
        read_sites(Path(path))


def test_a_repeated_column_is_named(tmp_path):
    """Found by the 10 000-input campaign (tests/io/fuzz_campaigns.py): a header naming a column
    twice raised AttributeError ('DataFrame' object has no attribute 'tolist')."""
    frame = base()
    path = tmp_path / "SITES.csv"
    path.write_text(frame.to_csv(index=False).replace("sac,", "sac,sac,", 1).replace("R1,", "R1,1,", 1)
                    .replace("R2,", "R2,1,", 1).replace("R3,", "R3,2,", 1))  # fmt: skip
    with pytest.raises(
        ValueError, match=r"^" + re.escape(f"{path}: column(s) ['sac'] appear more than once")
    ):
        read_sites(path)


def test_ten_thousand_mutated_sites_tables():
    """``REGISTRATION_FUZZ_N`` (default 10 000) mutated SITES tables, each read alone, in a child
    process with a time bound per input (tests/fuzzing.py)."""
    report = run_campaign("tests.io.fuzz_campaigns:sites")
    assert_clean(report)
    assert report["outcomes"].get("read", 0) > 0 and report["outcomes"].get("refused", 0) > 0
