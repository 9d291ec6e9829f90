"""A worker lost in the middle of a partitioned solve, and again in the output pass, is replaced by
Dask and its task run again: the estimate and the outputs equal the undisturbed run's bit for bit
(the passes are pure functions of their arguments, registration.fleet.batch.partitioned.partition_passes).

The loss is made deterministic with files: every read of a partition's plots claims the next call
number by creating ``call-<n>`` exclusively, and the read that claims KILL_AT (the first reduce pass,
after the setup pass has read every partition once) ends its own process with ``os._exit``; before
the output pass the test creates ``kill-next``, and the first read that removes it ends its process
too. Each kill writes a ``killed-<n>`` file, so the test knows both happened."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("dask.distributed")

from registration.core.parallel import dask_client  # noqa: E402
from registration.fleet import BatchOptions, fleet_scenario  # noqa: E402
from registration.fleet.batch.outputs import archive_outputs  # noqa: E402
from registration.fleet.batch.partitioned import solve_batch_partitioned  # noqa: E402
from registration.io.fleet.memory import TablesSource  # noqa: E402

PARTITIONS = 3
KILL_AT = PARTITIONS + 1  # a read of the first reduce pass


class KillingSource(TablesSource):
    """Tables in memory whose plot reads end their process once, as the files in ``flags`` say."""

    def __init__(self, sc, flags: Path):
        super().__init__(sc.plots, sc.sensors, sc.navigation, sc.platforms, sc.references)
        self.flags = str(flags)

    def _claim(self) -> int:
        n = 0
        while True:
            try:
                os.close(os.open(os.path.join(self.flags, f"call-{n}"), os.O_CREAT | os.O_EXCL | os.O_WRONLY))
                return n
            except FileExistsError:
                n += 1

    def _die(self, n: int) -> None:
        open(os.path.join(self.flags, f"killed-{n}"), "w").close()
        os._exit(1)

    def read_plots(self, lo: float, hi: float) -> dict:
        n = self._claim()
        if n == KILL_AT:
            self._die(n)
        try:
            os.remove(os.path.join(self.flags, "kill-next"))
        except FileNotFoundError:
            pass
        else:
            self._die(n)
        return super().read_plots(lo, hi)


def test_a_lost_worker_changes_no_bit(tmp_path):
    sc = fleet_scenario(0)
    options = BatchOptions()
    quiet = tmp_path / "quiet"
    quiet.mkdir()
    undisturbed = KillingSource(sc, quiet)
    (quiet / f"call-{KILL_AT}").touch()  # claimed already: no read kills here
    ref = solve_batch_partitioned(undisturbed, options, partitions=PARTITIONS, cache=0)
    ref_out = archive_outputs(ref, undisturbed, options)
    assert not list(quiet.glob("killed-*"))

    flags = tmp_path / "flags"
    flags.mkdir()
    source = KillingSource(sc, flags)
    with dask_client(workers=2) as client:
        got = solve_batch_partitioned(source, options, partitions=PARTITIONS, client=client)
        assert [p.name for p in flags.glob("killed-*")] == [f"killed-{KILL_AT}"]
        (flags / "kill-next").touch()
        out = archive_outputs(got, source, options, client=client)
    assert len(list(flags.glob("killed-*"))) == 2 and not (flags / "kill-next").exists()

    assert np.array_equal(got.estimate, ref.estimate)
    assert np.array_equal(got.sigma, ref.sigma)
    assert got.chi_square.chi2 == ref.chi_square.chi2 and got.iterations == ref.iterations
    assert all(np.array_equal(a, b) for a, b in zip(got.coefficients, ref.coefficients))
    for name in ("count", "squares", "hist"):
        assert np.array_equal(getattr(out, name), getattr(ref_out, name))
    assert out.parts == ref_out.parts and out.by_target == ref_out.by_target
    for a, b in zip(out.tables, ref_out.tables):
        assert all(np.array_equal(a[k], b[k]) for k in a)
