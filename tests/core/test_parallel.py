"""registration.core.parallel: refusals that need no dask."""

from __future__ import annotations

import pytest


def test_workers_below_one_are_refused_before_anything_starts():
    from registration.core.parallel import dask_client

    for bad in (0, -2):
        with pytest.raises(ValueError, match="at least 1 worker"):
            with dask_client(workers=bad):
                pass
