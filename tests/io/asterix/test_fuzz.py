"""A seeded, time-bounded fuzz target for the ASTERIX reader (issue 32 item 5): mutations of a small
valid recording (raw, pcap, pcapng, gzip) and the reproduction files of issue 32, each imported
through the API. Every outcome is an import whose totals add up, or an AsterixImportError (a
ValueError) of one line naming the file; never another exception.

``REGISTRATION_FUZZ_N`` (default 300) sets the number of inputs, ``REGISTRATION_FUZZ_S`` (default
20) the time bound in seconds; the seed is fixed, so a failure names the input that failed."""

from __future__ import annotations

import gzip
import os
import time

import numpy as np
import pytest

from registration.io.asterix import AsterixImportError, import_asterix
from tests.fuzzing import assert_clean, mutate_octets, run_campaign
from tests.io.asterix.repro import (
    empty_cat048_gzip,
    out_of_range_time,
    short_last_epb,
    source_only_cat048_gzip,
)

N_INPUTS = int(os.environ.get("REGISTRATION_FUZZ_N", "300"))
TIME_BOUND_S = float(os.environ.get("REGISTRATION_FUZZ_S", "20"))


def _mutate(data: bytes, rng: np.random.Generator) -> bytes:
    """The campaigns' octet mutations (:func:`tests.fuzzing.mutate_octets`), stretches up to 64 octets."""
    return mutate_octets(data, rng, max_span=64)


@pytest.fixture(scope="module")
def seeds(recording) -> list[tuple[str, bytes]]:
    from tests.io.asterix.encode import Recording

    small = Recording(recording.blocks[:24], recording.times[:24], [], recording.date)
    small.datagrams = [g for g in recording.datagrams if max(g) < 24]
    raw, pcap, pcapng = small.raw(), small.pcap(), small.pcapng()
    return [("raw", raw), ("pcap", pcap), ("pcapng", pcapng), ("gz", gzip.compress(raw))]


def _corpus() -> list[tuple[str, bytes]]:
    """The reproductions of issue 32 (and the two LANs' duplicates are in test_duplicates.py)."""
    return [
        *[(f"short{n}.pcapng", short_last_epb(n)) for n in (12, 16, 20)],
        ("late.pcapng", out_of_range_time()),
        ("empty.gz", empty_cat048_gzip(100_000)),
        ("source.gz", source_only_cat048_gzip(20_000)),
    ]


def _check(path, sites) -> str:
    try:
        result = import_asterix(path, sites, max_rejected_rows=1000)
    except AsterixImportError as exc:
        text = str(exc)
        assert text.startswith(str(path)) and "\n" not in text, text
        return "refused"
    summary = result.summary
    assert summary["rejected"]["total"] >= len(result.rejected) - 1
    assert summary["plots"]["total"] == len(result.plots)
    return "imported"


def test_mutated_recordings_never_raise_anything_else(tmp_path, sites, seeds):
    rng = np.random.default_rng(20260)
    outcomes: dict[str, int] = {}
    start = time.perf_counter()
    inputs = [(name, data) for name, data in _corpus()]
    while len(inputs) < N_INPUTS:
        name, data = seeds[int(rng.integers(len(seeds)))]
        inputs.append((f"{len(inputs)}-{name}", _mutate(data, rng)))
    for k, (name, data) in enumerate(inputs):
        if time.perf_counter() - start > TIME_BOUND_S:
            break
        path = tmp_path / name
        path.write_bytes(data)
        try:
            outcome = _check(path, sites)
        except Exception as exc:  # the input that failed, for the report
            raise AssertionError(f"input {k} ({name}): {type(exc).__name__}: {exc}") from exc
        outcomes[outcome] = outcomes.get(outcome, 0) + 1
        path.unlink()
    assert sum(outcomes.values()) >= min(N_INPUTS, 50)
    assert outcomes.get("imported", 0) > 0


#: Mutated whole recordings (every framing) per run of the campaign below; each is one call of the
#: reader (about 10 ms), where the datagrams go 250 to a call.
N_RECORDINGS = int(os.environ.get("REGISTRATION_FUZZ_FILES", "2000"))


def test_ten_thousand_mutated_datagrams_of_every_category():
    """CAT048, CAT034, CAT021, CAT001 and CAT002 datagrams (``REGISTRATION_FUZZ_N``, default 10 000),
    in a child process with a time bound per input (tests/fuzzing.py)."""
    report = run_campaign("tests.io.asterix.fuzz_campaigns:datagrams")
    assert_clean(report)
    assert report["outcomes"]["datagrams"] == report["inputs"] and report["outcomes"]["records"] > 0


def test_mutated_recordings_of_every_framing():
    """Raw, pcap, pcapng, gzip, GPS, IOSS, ORADIS, RFF, HDLC and CAT001 recordings
    (``REGISTRATION_FUZZ_FILES``, default 2000), each read alone under its time bound."""
    report = run_campaign("tests.io.asterix.fuzz_campaigns:recordings", N_RECORDINGS)
    assert_clean(report, N_RECORDINGS)
    assert report["outcomes"].get("read", 0) > 0 and report["outcomes"].get("refused", 0) > 0
