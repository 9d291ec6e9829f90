"""The standard recording (tests/io/asterix/scenario.py), encoded once per session with
libasterix and written as raw, pcap and pcapng, plain and gzip."""

from __future__ import annotations

import importlib.util

import pytest

from tests.io.asterix.scenario import sites_frame, standard_recording

if importlib.util.find_spec("asterix") is None:  # libasterix (pip install libasterix) encodes the fixtures
    collect_ignore_glob = ["test_*.py"]


@pytest.fixture(scope="session")
def recording():
    return standard_recording()


@pytest.fixture(scope="session")
def files(recording, tmp_path_factory) -> dict:
    """form -> path: 'raw', 'pcap', 'pcapng' and the same with '.gz'."""
    folder = tmp_path_factory.mktemp("asterix")
    out = dict(recording.write(folder))
    out.update({f"{k}.gz": v for k, v in recording.write(folder, gz=True).items()})
    return out


@pytest.fixture(scope="session")
def sites():
    return sites_frame()


@pytest.fixture(scope="session")
def imported(files, sites) -> dict:
    """form -> AsterixImport of the standard recording."""
    from registration.io.asterix import import_asterix

    return {form: import_asterix(path, sites) for form, path in files.items()}
