"""Fuzz campaigns of the readers, each in a child process with real time bounds.

A campaign (``module:function``, called with a seed) gives batches of mutated inputs and a check
that runs the reader in-process on one batch and returns the outcomes it counted; the check
raises for anything the reader must never do (an exception other than its one-line ValueError, a
total that does not add up). :func:`run_campaign` runs it in ``python -m tests.fuzzing``:

* each batch runs under ``signal.setitimer``: ``per_input_s`` times its inputs, at most
  :data:`BATCH_S` (a reader that takes many inputs at once, ASTERIX datagrams say, gets them in
  one call; a batch takes well under a second);
* a batch that fails or runs out of time is run again input by input, each under ``per_input_s``,
  to name the input (its label says how to make it again: the campaign's seed and its index);
* the whole child runs under ``total_s`` (``subprocess.run(timeout=...)``): a hang that a Python
  signal cannot interrupt (inside one C call) is caught there.

The child prints one JSON line: inputs run, outcomes, failures (label, what), seconds (the
campaign's, setup aside); the parent adds the child's wall and CPU time.
``REGISTRATION_FUZZ_N`` sets the inputs per campaign (default 10 000),
``REGISTRATION_FUZZ_SEED`` the seed."""

from __future__ import annotations

import importlib
import json
import os
import signal
import subprocess
import sys
import time
import traceback
from collections import Counter
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Iterator

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
N_INPUTS = int(os.environ.get("REGISTRATION_FUZZ_N", "10000"))
SEED = int(os.environ.get("REGISTRATION_FUZZ_SEED", "20261207"))
#: Set (s): a seeded fuzz test (:func:`fuzz_seeds`) runs for this long instead of its fixed count.
CAMPAIGN_S = os.environ.get("REGISTRATION_FUZZ_S")
#: The time one input may take before it counts as a hang (s); the machine may be loaded.
PER_INPUT_S = float(os.environ.get("REGISTRATION_FUZZ_INPUT_S", "5"))
#: The time one batch may take (s), whatever its size.
BATCH_S = 60.0


def fuzz_seeds(first: int, cases: int) -> Iterator[int]:
    """The seeds of a seeded fuzz test: ``cases`` of them from ``first``, the same on every machine
    (a time bound let CI, on a faster machine, reach a failing seed that no run here had tried);
    with ``REGISTRATION_FUZZ_S`` set, as many as that many seconds allow (a longer search)."""
    if CAMPAIGN_S is None:
        yield from range(first, first + cases)
        return
    start, seed = time.monotonic(), first
    while time.monotonic() - start < float(CAMPAIGN_S):
        yield seed
        seed += 1


class Hang(Exception):
    """An input ran past its time bound."""


@dataclass
class Campaign:
    """``batches(n)``: the n inputs in batches, each a list of (label, input); ``check(batch)``:
    the reader on a batch, the outcomes counted (raises for what must not happen)."""

    batches: Callable[[int], Iterator[list]]
    check: Callable[[list], Counter]


def mutate_octets(data: bytes, rng: np.random.Generator, max_span: int = 64) -> bytes:
    """One to three mutations: octets overwritten, a stretch cut, inserted (random), repeated or
    moved, a 16-bit field set to an extreme, the end cut off."""
    out = bytearray(data)
    for _ in range(int(rng.integers(1, 4))):
        n = len(out)
        if n < 4:
            break
        kind = int(rng.integers(0, 7))
        at = int(rng.integers(0, n))
        span = int(rng.integers(1, min(max_span, n) + 1))
        if kind == 0:
            for k in rng.integers(0, n, size=int(rng.integers(1, 16))):
                out[int(k)] = int(rng.integers(0, 256))
        elif kind == 1:
            del out[at : at + span]
        elif kind == 2:
            out[at:at] = rng.bytes(span)
        elif kind == 3:
            out[at:at] = out[max(at - span, 0) : at]
        elif kind == 4 and at + 2 <= n:
            out[at : at + 2] = bytes(rng.choice([b"\x00\x00", b"\x00\x03", b"\xff\xff", b"\x80\x00"]))
        elif kind == 5:
            del out[int(rng.integers(n // 2, n + 1)) :]
        else:
            piece = bytes(out[at : at + span])
            del out[at : at + span]
            to = int(rng.integers(0, len(out) + 1))
            out[to:to] = piece
    return bytes(out)


def _on_alarm(signum, frame):
    raise Hang()


def _timed(check: Callable[[list], Counter], batch: list, seconds: float) -> Counter:
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        return check(batch)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)


def _isolate(campaign: Campaign, batch: list, per_input_s: float, error: str) -> dict:
    """The first input of a failed batch that fails alone (or the batch and its ``error``, when
    none does)."""
    for item in batch:
        try:
            _timed(campaign.check, [item], per_input_s)
        except Hang:
            return {"input": item[0], "what": f"hang: more than {per_input_s:g} s"}
        except Exception as exc:  # noqa: BLE001 - the report names it
            return {"input": item[0], "what": f"{type(exc).__name__}: {exc}", "trace": traceback.format_exc()}
    return {"input": f"batch of {len(batch)} from {batch[0][0]}", "what": f"fails together only: {error}"}


def child(spec: str, n: int, seed: int, per_input_s: float) -> dict:
    module, name = spec.split(":")
    campaign: Campaign = getattr(importlib.import_module(module), name)(seed)
    signal.signal(signal.SIGALRM, _on_alarm)
    outcomes: Counter = Counter()
    failures: list = []
    done, start = 0, time.perf_counter()
    for batch in campaign.batches(n):
        try:
            outcomes += _timed(campaign.check, batch, min(per_input_s * len(batch), BATCH_S))
        except Exception as exc:  # noqa: BLE001 - isolated and reported
            error = "hang" if isinstance(exc, Hang) else f"{type(exc).__name__}: {exc}"
            failures.append(_isolate(campaign, batch, per_input_s, error))
            if len(failures) >= 3:
                break
        done += len(batch)
    return {
        "inputs": done,
        "outcomes": dict(outcomes),
        "failures": failures,
        "seconds": time.perf_counter() - start,
    }


def run_campaign(
    spec: str, n: int = N_INPUTS, seed: int = SEED, total_s: float = 600.0, per_input_s: float = PER_INPUT_S
) -> dict:
    """Run the campaign ``spec`` (``module:function``) in a child process; its report. A child
    that outlives ``total_s`` is a hang (AssertionError)."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    env["MPLBACKEND"] = "Agg"
    argv = [sys.executable, "-m", "tests.fuzzing", spec, str(n), str(seed), str(per_input_s)]
    t0, cpu0 = time.perf_counter(), _children_cpu()
    try:
        done = subprocess.run(argv, cwd=ROOT, env=env, capture_output=True, text=True, timeout=total_s)
    except subprocess.TimeoutExpired:
        raise AssertionError(f"{spec}: hang: the campaign ran past {total_s:g} s") from None
    assert done.returncode == 0, f"{spec}: the child failed ({done.returncode}):\n{done.stderr[-4000:]}"
    report = json.loads(done.stdout.strip().splitlines()[-1])
    report["wall_s"] = time.perf_counter() - t0
    report["cpu_s"] = _children_cpu() - cpu0  # the child's, setup included
    return report


def _children_cpu() -> float:
    import resource

    use = resource.getrusage(resource.RUSAGE_CHILDREN)
    return use.ru_utime + use.ru_stime


def assert_clean(report: dict, n: int = N_INPUTS) -> None:
    """No failure, every input run."""
    assert not report["failures"], json.dumps(report["failures"], indent=1)[:6000]
    assert report["inputs"] >= n, report


if __name__ == "__main__":
    import tempfile

    spec, n, seed, per_input = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])
    with tempfile.TemporaryDirectory(prefix="fuzz-") as scratch:
        tempfile.tempdir = scratch  # the campaigns' files go here, and are removed with it
        report = child(spec, n, seed, per_input)
    print(json.dumps(report))
