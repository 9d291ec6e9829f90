"""The shared simulated bridge log (generated once per session)."""

from __future__ import annotations

import pytest

from registration.io.nmea import import_nmea
from tests.io.nmea.bridgelog import PLATFORM, BridgeLogConfig, simulate_bridge_log


@pytest.fixture(scope="session")
def bridge(tmp_path_factory):
    """The default 10-minute log (14 vessels on radar, 11 on AIS, tag blocks), written and imported."""
    log = simulate_bridge_log(BridgeLogConfig(seed=0))
    path = log.write(tmp_path_factory.mktemp("bridge") / "bridge.nmea")
    return log, path, import_nmea(path, PLATFORM, log.sensors)
