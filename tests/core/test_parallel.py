"""registration.core.parallel: refusals that need no dask."""

from __future__ import annotations

import pytest


def test_workers_below_one_are_refused_before_anything_starts():
    from registration.core.parallel import dask_client

    for bad in (0, -2):
        with pytest.raises(ValueError, match="at least 1 worker"):
            with dask_client(workers=bad):
                pass


def test_a_local_cluster_listens_on_the_loopback_only():
    """--workers N starts the scheduler, its dashboard and the workers on 127.0.0.1, never on every
    interface (the dashboard was bound to 0.0.0.0 once)."""
    pytest.importorskip("distributed")
    psutil = pytest.importorskip("psutil")
    from registration.core.parallel import dask_client

    with dask_client(workers=1) as client:
        assert client.dashboard_link.startswith("http://127.0.0.1:")
        me = psutil.Process()
        pids = {me.pid} | {p.pid for p in me.children(recursive=True)}
        listening = [
            c.laddr.ip
            for c in psutil.net_connections(kind="inet")
            if c.status == psutil.CONN_LISTEN and c.pid in pids
        ]
    assert listening and all(ip in ("127.0.0.1", "::1") for ip in listening), listening
