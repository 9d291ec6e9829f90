"""A seeded, time-bounded fuzzer of the fleet tables reader (issue 32, 5): small valid tables are
mutated (cells replaced by extreme numbers, text, NaN, empty, huge strings; rows duplicated or
dropped; columns dropped) and read in both ``on_bad_row`` modes, then built into a problem; some
cases run through ``fleet register``. Every outcome is a result or a one-line ValueError naming
the file (and, for a cell, its row and column); no RuntimeWarning, no other exception; the command
exits 0, 2 or 3, never 4. Each test runs a fixed count of seeded cases, the same on every
machine (REGISTRATION_FUZZ_S: as many as that many seconds allow); a failure prints its seed.
The SITES reader of ``import asterix`` is fuzzed the same way through its public API."""

from __future__ import annotations

import os
import random
import re
import warnings
from pathlib import Path

import pandas as pd
import pytest

from registration.cli import main
from registration.fleet import fleet_scenario
from registration.io.fleet.reading.read import read_fleet_tables
from registration.io.fleet.write import write_fleet_tables
from tests.fuzzing import assert_clean, fuzz_seeds, run_campaign

#: Cases of each test (the same on every machine), and its first seed (a longer or another campaign:
#: REGISTRATION_FUZZ_S=600 REGISTRATION_FUZZ_SEED=1 python -m pytest tests/fleet/test_fuzz_tables.py).
CASES_READ, CASES_REGISTER = 200, 100
SEED = int(os.environ.get("REGISTRATION_FUZZ_SEED", "20261203"))
NAMES = ("plots", "navigation", "sensors", "platforms", "reference")
#: What a mutated cell becomes.
CELLS = (
    "1e308",
    "-1e308",
    "1e-300",
    "-1e-300",
    "1e400",
    "inf",
    "-inf",
    "nan",
    "NaN",
    "",
    " ",
    "abc",
    "0",
    "-0",
    "-1",
    "1,5",
    "0x10",
    "1e15",
    "1e-15",
    "9" * 400,
    "x" * 5000,
    "é\u00e9\u202e",
    '"',
    "None",
    "NA",
)


@pytest.fixture(scope="module")
def base(tmp_path_factory) -> dict[str, pd.DataFrame]:
    s = fleet_scenario(0, duration_s=20.0)
    folder = tmp_path_factory.mktemp("base")
    write_fleet_tables(folder, s.plots, s.navigation, s.sensors, s.platforms, s.references, "csv")
    return {n: pd.read_csv(folder / f"{n}.csv", dtype=str, keep_default_na=False) for n in NAMES}


def mutate(frames: dict[str, pd.DataFrame], rng: random.Random) -> dict[str, pd.DataFrame]:
    """One to three mutations of copies of ``frames``."""
    out = {k: v.copy() for k, v in frames.items()}
    for _ in range(rng.randint(1, 3)):
        name = rng.choice(NAMES)
        frame = out[name]
        kind = rng.random()
        if kind < 0.6 and len(frame):
            row, column = rng.randrange(len(frame)), rng.choice(list(frame.columns))
            frame.loc[row, column] = rng.choice(CELLS)
        elif kind < 0.7 and len(frame):
            rows = [rng.randrange(len(frame)) for _ in range(rng.randint(1, 5))]
            out[name] = pd.concat([frame, frame.iloc[rows]], ignore_index=True)
        elif kind < 0.8 and len(frame):
            out[name] = frame.drop(
                index=rng.sample(range(len(frame)), rng.randint(1, len(frame)))
            ).reset_index(drop=True)
        elif kind < 0.9:
            out[name] = frame.drop(columns=[rng.choice(list(frame.columns))])
        elif len(frame):
            column = rng.choice(list(frame.columns))
            out[name][column] = rng.choice(CELLS)  # a whole column
    return out


def write(frames: dict[str, pd.DataFrame], folder: Path) -> dict[str, Path]:
    folder.mkdir(parents=True, exist_ok=True)
    for name, frame in frames.items():
        frame.to_csv(folder / f"{name}.csv", index=False)
    return {n: folder / f"{n}.csv" for n in NAMES}


def check_error(text: str, paths: dict[str, Path], seed: int) -> None:
    """A one-line message naming a file; a cell's row and column named together."""
    assert "\n" not in text, (seed, text)
    assert any(str(p) in text for p in paths.values()), (seed, text)
    if re.search(r"\brow \d+\b", text) and "column" not in text:
        pytest.fail(f"seed {seed}: a row without its column: {text}")


def read_case(paths: dict[str, Path], mode: str, seed: int) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        try:
            tables = read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row=mode)
            tables.problem()
        except ValueError as exc:
            check_error(str(exc), paths, seed)


def test_mutated_fleet_tables_give_a_result_or_one_line_naming_the_file(base, tmp_path):
    for seed in fuzz_seeds(SEED, CASES_READ):
        rng = random.Random(seed)
        paths = write(mutate(base, rng), tmp_path / f"case{seed}")
        for mode in ("stop", "skip"):
            try:
                read_case(paths, mode, seed)
            except Exception as exc:  # the seed reproduces it
                raise AssertionError(f"seed {seed}, on_bad_row={mode}: {type(exc).__name__}: {exc}") from exc


def test_mutated_fleet_tables_through_fleet_register(base, tmp_path, capsys):
    for seed in fuzz_seeds(SEED + 100_000, CASES_REGISTER):
        rng = random.Random(seed)
        folder = tmp_path / f"case{seed}"
        write(mutate(base, rng), folder)
        mode = rng.choice(("stop", "skip"))
        argv = ["fleet", "register", "--tables", str(folder), "--out", str(folder / "out"), "--no-plots"]
        with warnings.catch_warnings(record=True) as caught:  # pytest's capture would hide them from stderr
            warnings.simplefilter("always", RuntimeWarning)
            try:
                code = main([*argv, "--on-bad-row", mode])
            except BaseException as exc:  # a traceback: a bug
                raise AssertionError(f"seed {seed}: {type(exc).__name__}: {exc}") from exc
        runtime = [str(w.message) for w in caught if issubclass(w.category, RuntimeWarning)]
        assert not runtime, (seed, runtime)
        err = capsys.readouterr().err
        assert code in (0, 2, 3), (seed, code, err)
        assert "Traceback" not in err and "RuntimeWarning" not in err, (seed, err)
        if code == 2:
            lines = [ln for ln in err.splitlines() if ln.startswith("registration fleet register: error:")]
            assert len(lines) == 1, (seed, err)


def test_ten_thousand_mutated_plot_and_reference_rows():
    """``REGISTRATION_FUZZ_N`` (default 10 000) mutated rows of the plots and reference files, 250
    to a read in skip mode, in a child process with a time bound per input (tests/fuzzing.py)."""
    report = run_campaign("tests.fleet.fuzz_campaigns:tables")
    assert_clean(report)
    assert report["outcomes"]["rows"] == report["inputs"] and report["outcomes"].get("set_aside", 0) > 0
