"""Work done once per test session and shared by the suite's test processes (pytest-xdist workers):
each result is made by the first process that asks for it, under a file lock, in a folder of the
session's temporary base that every worker of this session sees (and no other session does: pytest
makes a new base per session, or empties the one --basetemp names), and read from there by the
others.

:func:`derivation` is one: ``python -m derive --check`` on this tree (the sympy derivation, about
16 s of CPU), keeping its fresh generation and its specs for the codegen tests."""

from __future__ import annotations

import fcntl
import json
import os
import pickle
import shutil
import subprocess
import sys
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Iterator

ROOT = Path(__file__).resolve().parents[1]


def session_dir(tmp_path_factory) -> Path:
    """A folder this test session's processes share: the parent of the workers' base folders under
    pytest-xdist (``pytest-N/popen-gwK``), the base folder itself in a single process."""
    base = tmp_path_factory.getbasetemp()
    root = base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base
    folder = root / "shared"
    folder.mkdir(exist_ok=True)
    return folder


@contextmanager
def _locked(path: Path) -> Iterator[None]:
    with open(path, "a") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # the other process waits here until the result is written
        try:
            yield
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


def once(folder: Path, name: str, make: Callable[[Path], None]) -> Path:
    """``folder / name``, made by ``make(path)`` in the first process that asks; ``make`` writes
    into a scratch folder renamed into place whole, so a half-made result is never read."""
    done = folder / name
    with _locked(folder / f"{name}.lock"):
        if not done.exists():
            scratch = folder / f".{name}-{os.getpid()}"
            shutil.rmtree(scratch, ignore_errors=True)  # what an earlier attempt that raised left
            scratch.mkdir()
            make(scratch)
            scratch.rename(done)
    return done


#: ``python -m derive --check --fresh FRESH``, run as ``python -m`` runs it (runpy, argv), keeping
#: the specs it derived (pickled; a CasADi-composed spec without its builder, a local function,
#: which no test calls: the check itself built and emitted them all).
DERIVE_AND_KEEP_SPECS = """
import dataclasses, pickle, runpy, sys
import derive.registry as registry

fresh, kept_file = sys.argv[1:3]
derived = []
derive_all = registry.all_specs


def keep_specs():
    derived.extend(derive_all())
    return derived


registry.all_specs = keep_specs
sys.argv = ["derive", "--check", "--fresh", fresh]
try:
    runpy.run_module("derive", run_name="__main__", alter_sys=True)
    code = 0
except SystemExit as exit:
    code = exit.code
finally:
    sys.stdout.flush()
kept = [dataclasses.replace(s, builder=None) if hasattr(s, "builder") else s for s in derived]
with open(kept_file, "wb") as f:
    pickle.dump(kept, f)
sys.exit(code)
"""


@dataclass(frozen=True)
class Derivation:
    """The derive check's exit code and output, its fresh generation and the specs it derived."""

    returncode: int
    stdout: str
    stderr: str
    fresh: Path
    specs_file: Path

    def specs(self) -> dict:
        """Every derive spec by name."""
        return {s.name: s for s in pickle.loads(self.specs_file.read_bytes())}


def derivation(tmp_path_factory) -> Derivation:
    """``python -m derive --check`` on this tree, once per session (see the module docstring)."""

    def make(out: Path) -> None:
        proc = subprocess.run(
            [sys.executable, "-c", DERIVE_AND_KEEP_SPECS, str(out / "generated"), str(out / "specs.pickle")],
            cwd=ROOT,
            capture_output=True,
            text=True,
            env=dict(os.environ, PYTHONPATH=str(ROOT), PYTHONHASHSEED="0"),
        )
        result = {"returncode": proc.returncode, "stdout": proc.stdout, "stderr": proc.stderr}
        (out / "result.json").write_text(json.dumps(result))

    done = once(session_dir(tmp_path_factory), "derivation", make)
    result = json.loads((done / "result.json").read_text())
    return Derivation(**result, fresh=done / "generated", specs_file=done / "specs.pickle")
