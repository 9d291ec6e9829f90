"""Every benchmark script runs in its tiny mode (seconds, small sizes), so that a benchmark cannot
break unseen: each as a subprocess of this checkout, with a timeout, writing its JSON to a
temporary file (never to benchmarks/results/, whose figures are the committed measurement)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BENCH = ROOT / "benchmarks"
#: Modules of benchmarks/ that are not benchmarks: the shared helper, the docs' tables, the
#: NumPy baseline and compiler-flags experiment that bench_online.py imports (run below), and the
#: association's stage timer that bench_association.py runs.
HELPERS = {"common.py", "tables.py", "online_baseline.py", "online_flags.py", "association_stages.py"}
SCRIPTS = sorted(p.name for p in BENCH.glob("*.py") if p.name not in HELPERS)
#: Arguments of a script's tiny run beyond --tiny: bench_online.py runs its compiler-flags
#: experiment (online_flags.py) too.
EXTRA = {"bench_online.py": ["--flags"]}
#: Other paths of a script worth running: (script, extra arguments).
VARIANTS: list[tuple[str, list[str]]] = [("association_table.py", ["--table", "robust"])]
ALL_RUNS = [(s, EXTRA.get(s, [])) for s in SCRIPTS] + VARIANTS
#: The slowest tiny runs (a service, a Dask cluster, a C compilation), in
#: test_benchmarks_tiny_slow.py: a file runs on one test process, so the two files share the work.
SLOW = {"bench_live.py", "bench_archive_workers.py", "bench_online.py", "bench_register.py"}
RUNS = [r for r in ALL_RUNS if r[0] not in SLOW]
#: Seconds a tiny run may take on a loaded 2-core machine (most take a few seconds).
TIMEOUT_S = 600


def run_tiny(script: str, extra: list[str], out: Path) -> subprocess.CompletedProcess:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    env["MPLBACKEND"] = "Agg"
    return subprocess.run(
        [sys.executable, str(BENCH / script), "--tiny", "--json", str(out), *extra],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=TIMEOUT_S,
    )


def test_every_script_is_a_benchmark_or_a_named_helper():
    assert SCRIPTS, "no benchmark found"
    assert HELPERS <= {p.name for p in BENCH.glob("*.py")}, "a helper named here no longer exists"


def check_tiny(script: str, extra: list[str], tmp_path: Path) -> None:
    """The script's tiny run exits 0 and writes a tiny figures file."""
    out = tmp_path / "figures.json"
    proc = run_tiny(script, extra, out)
    assert proc.returncode == 0, f"{script} --tiny failed:\n{proc.stdout[-2000:]}\n{proc.stderr[-4000:]}"
    doc = json.loads(out.read_text())
    assert doc["tiny"] is True
    assert {"benchmark", "date", "machine", "sizes", "figures"} <= set(doc)


@pytest.mark.parametrize(("script", "extra"), RUNS, ids=[" ".join([s, *e]) for s, e in RUNS])
def test_runs_tiny(script, extra, tmp_path):
    check_tiny(script, extra, tmp_path)
