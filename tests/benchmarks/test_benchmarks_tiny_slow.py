"""The slowest benchmark scripts in their tiny mode (see test_benchmarks_tiny.py), in a file of
their own so that the suite's two processes share the benchmarks."""

from __future__ import annotations

import pytest

from tests.benchmarks.test_benchmarks_tiny import ALL_RUNS, SLOW, check_tiny

RUNS = [r for r in ALL_RUNS if r[0] in SLOW]


def test_every_slow_script_exists():
    assert {s for s, _ in RUNS} == SLOW


@pytest.mark.parametrize(("script", "extra"), RUNS, ids=[" ".join([s, *e]) for s, e in RUNS])
def test_runs_tiny(script, extra, tmp_path):
    check_tiny(script, extra, tmp_path)
