"""The association of an archive out of core, partition by partition with overlaps
(docs/howto/register-an-archive.md)."""

from registration.fleet.association.partitioned.run import PartitionedAssociation, associate_partitioned

__all__ = ["PartitionedAssociation", "associate_partitioned"]
