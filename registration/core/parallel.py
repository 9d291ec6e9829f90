"""Map a function over chunks of work, in this process or on a ``dask.distributed`` cluster.

The work is cut into chunks whose boundaries depend only on the problem (never on the number of
workers), each chunk is computed by one call, and the results come back in chunk order, so a
caller that merges them in that order gets the same answer, bit for bit, however many workers ran
them. Dask is optional (``pip install "dask[distributed]"``); without a scheduler address
or a worker count nothing of it is imported.
"""

from __future__ import annotations

import contextlib

__all__ = ["DASK_MISSING", "chunk_ranges", "dask_client", "map_chunks", "require_distributed"]

#: What a missing dask installation is reported as.
DASK_MISSING = (
    'dask.distributed is not installed: pip install "dask[distributed]" (from a checkout of this '
    'package: pip install ".[dask]") to use --scheduler or --workers'
)


def require_distributed():
    """The ``dask.distributed`` module, or ImportError with :data:`DASK_MISSING`."""
    try:
        import dask.distributed as distributed
    except ImportError as exc:
        raise ImportError(DASK_MISSING) from exc
    return distributed


def chunk_ranges(n: int, chunk: int, start: int = 0) -> list[tuple[int, int]]:
    """``[(start, stop), ...]`` covering ``start .. start
    + n - 1`` in consecutive pieces of at most ``chunk``."""
    n, chunk = int(n), int(chunk)
    if chunk < 1:
        raise ValueError(f"chunk: expected at least 1 item per chunk, got {chunk}")
    return [(start + i, start + min(i + chunk, n)) for i in range(0, n, chunk)]


@contextlib.contextmanager
def dask_client(scheduler: str | None = None, workers: int | None = None):
    """A ``dask.distributed.Client`` for the block, or None (work in this process).

    ``scheduler``: the address of a running scheduler (e.g. ``tcp://host:8786``); ``workers``: the
    number of worker processes of a ``LocalCluster`` on this machine, one thread each. Neither:
    None. The local cluster is closed when the block ends.
    """
    if scheduler and workers is not None:
        raise ValueError(
            "--scheduler and --workers: give one or the other (--workers starts a cluster on this machine)"
        )
    if workers is not None and int(workers) < 1:
        raise ValueError(f"--workers: expected at least 1 worker, got {workers}")
    if not scheduler and workers is None:
        yield None
        return
    distributed = require_distributed()
    if scheduler:
        with distributed.Client(scheduler) as client:
            yield client
        return
    assert workers is not None  # neither a scheduler nor workers: returned above
    import dask

    with (
        # the workers' statistical profiler samples their threads every 10 ms; nothing here reads it
        dask.config.set({"distributed.worker.profile.enabled": False}),
        distributed.LocalCluster(
            n_workers=int(workers), threads_per_worker=1, processes=True, dashboard_address="127.0.0.1:0"
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        yield client


def map_chunks(func, items, client=None, *, progress: bool = False, desc: str = "chunks") -> list:
    """``[func(item) for item in items]``, in the order of ``items``.

    With a ``client`` the calls run on its workers (each item is one task; ``func`` and the items
    must pickle); progress, if asked for, is a bar on standard error that advances as chunks
    finish. An exception in a chunk is raised here, as the in-process loop would raise it.
    """
    items = list(items)
    bar = _bar(len(items), progress, desc)
    try:
        if client is None:
            results = []
            for item in items:
                results.append(func(item))
                bar.update(1)
            return results
        distributed = require_distributed()
        futures = client.map(func, items, pure=False)
        index = {f.key: i for i, f in enumerate(futures)}
        results = [None] * len(items)
        for future in distributed.as_completed(futures):
            results[index[future.key]] = future.result()  # raises the chunk's exception
            bar.update(1)
        return results
    finally:
        bar.close()


def _bar(total: int, progress: bool, desc: str):
    from registration.core.progress import progress_bar

    return progress_bar(progress, desc, total=total, unit="chunk")
