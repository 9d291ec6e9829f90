"""The partitioned batch solve of an archive (docs/howto/register-an-archive.md):
:func:`solve_batch_partitioned`.

Modules: ``plan`` (the archive cut into partitions), ``task`` (one partition read and built),
``partition_passes`` (what each pass computes on one partition), ``spill`` (the disk cache between
passes), ``equations`` (the partitions' sums as the Levenberg-Marquardt engine's normal equations)
and ``estimate`` (the solve and its result).
"""

from registration.fleet.batch.partitioned.estimate import (
    PartitionedResult,
    remove_spill,
    solve_batch_partitioned,
)

__all__ = ["PartitionedResult", "remove_spill", "solve_batch_partitioned"]
