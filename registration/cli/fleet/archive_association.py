"""``fleet register`` on an archive whose plots lack target ids for some rows: the association by
partitions (:mod:`registration.fleet.association.partitioned`) before the partitioned solve, its
labelled plots written into the run's work folder
(:func:`registration.io.fleet.archive.labelled.write_labelled_tables`) and its figures in ``summary.json``
(docs/howto/register-an-archive.md, "Plots without target ids")."""

from __future__ import annotations

import argparse
from pathlib import Path

__all__ = ["associated_source"]


def associated_source(args: argparse.Namespace, source, work: str, client) -> tuple:
    """(the source to register, the association or None): ``source`` itself when every plot carries a
    target id, else the archive with the plots the association labelled (partitions of
    ``--partition-s``, at most MAX_ASSOCIATION_PARTITION_S, on the Dask ``client``'s workers when
    there is one)."""
    from registration.fleet import AssociationOptions
    from registration.fleet.association.partitioned import associate_partitioned, parts
    from registration.io.fleet.archive.labelled import write_labelled_tables

    association = associate_partitioned(
        source,
        AssociationOptions(window_s=args.window_s),
        partition_s=min(args.partition_s, parts.MAX_ASSOCIATION_PARTITION_S),
        client=client,
        progress=True,
    )
    if association is None:
        return source, None
    s = association.summary()
    print(
        f"association: {s['plots_without_id']} of {s['plots']} plots without a target id, associated in "
        f"{s['partitions']} partitions of {s['partition_s']:g} s (each reading {s['overlap_s']:g} s more on "
        f"both sides): {s['plots_labelled']} plots of {s['targets']} targets labelled"
    )
    labelled = write_labelled_tables(source, association, Path(work) / "labelled_plots", progress=True)
    return labelled, association
