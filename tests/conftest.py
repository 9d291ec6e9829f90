"""Shared fixtures: the derive specs (sympy) and random points inside each spec's domain."""

from __future__ import annotations

import json
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest

from tests import shared


@lru_cache(maxsize=1)
def emitted() -> dict:
    """The functions generated/manifest.json records, by name (inputs, outputs, jacobians): the
    names to parametrize over without deriving. test_every_spec_is_emitted checks they are the
    derive specs' (and tests/codegen/test_freshness.py that generated/ is fresh)."""
    return json.loads((Path(__file__).resolve().parents[1] / "generated" / "manifest.json").read_text())[
        "functions"
    ]


def port_size(port) -> int:
    r, c = port.shape
    return r * c


def sample_inputs(spec, n: int, rng: np.random.Generator) -> list[np.ndarray]:
    """Uniform random inputs in the spec's domain, one array per input, leading axis n."""
    out = []
    for port in spec.inputs:
        dom = spec.domain.get(port.name)
        size = port_size(port)
        if dom is None:
            raise KeyError(f"{spec.name}: no test domain for input {port.name}")
        bounds = [dom] if size == 1 and isinstance(dom[0], (int, float)) else list(dom)
        cols = [rng.uniform(lo, hi, n) for lo, hi in bounds]
        arr = np.stack(cols, axis=-1)
        r, c = port.shape
        out.append(arr[:, 0] if size == 1 else (arr if c == 1 else arr.reshape(n, c, r).transpose(0, 2, 1)))
    return out


@pytest.fixture(scope="session")
def derivation(tmp_path_factory) -> shared.Derivation:
    """``python -m derive --check`` on this tree, run once for the session's test processes: its
    exit code and output, its fresh generation of generated/ and the specs it derived."""
    return shared.derivation(tmp_path_factory)


@pytest.fixture(scope="session")
def specs(derivation) -> dict:
    """Every derive spec by name: the whole sympy derivation (about 16 s of CPU), made once per
    session (:func:`derivation`), so only in a test, never while collecting (parametrize over
    :func:`emitted` instead)."""
    return derivation.specs()


#: The files that take longest on one test process (30 s to two minutes each on the loaded 2-core
#: machine), run first: the two processes take files one at a time, so a long file taken last leaves
#: the other process idle. test_freshness.py makes the session's derivation (tests/shared.py) that
#: the codegen tests, collected later, read.
LONGEST_FIRST = (
    "tests/benchmarks/test_benchmarks_tiny.py",
    "tests/benchmarks/test_benchmarks_tiny_slow.py",
    "tests/live/test_serve_nmea.py",
    "tests/cli/test_fleet.py",
    "tests/fleet/test_association_partitioned.py",
    "tests/io/asterix/test_flight_levels.py",
    "tests/live/test_estimator.py",
    "tests/io/asterix/test_fuzz.py",
    "tests/fleet/test_fuzz_tables.py",
    "tests/codegen/test_freshness.py",
    "tests/io/test_publication.py",
    "tests/test_lint.py",
    "tests/fleet/test_archive_spill.py",
    "tests/io/test_import_cli.py",
    "tests/recorded/test_register_outfolder.py",
    "tests/io/test_acceptance_asterix.py",
    "tests/io/test_fuzz_sites.py",
    "tests/fleet/test_association_robust.py",
    "tests/recorded/test_register.py",
    "tests/live/test_serve.py",
)


def pytest_collection_modifyitems(session, config, items) -> None:
    rank = {name: k for k, name in enumerate(LONGEST_FIRST)}
    items.sort(
        key=lambda item: rank.get(item.nodeid.split("::")[0], len(rank))
    )  # stable: the rest keeps its order
