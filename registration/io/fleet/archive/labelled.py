"""The plots of an archive with the targets an association by partitions gave them, as Parquet files
the partitioned solver reads: :func:`write_labelled_tables`.

Each partition's own plots (:mod:`registration.fleet.association.partitioned`) that have a target
are copied row for row from the archive's files (the file's columns and units, bit for bit), the
``target`` column replaced by the label and the ``track`` column left out, into one Parquet file per
partition (``plots/part-00000.parquet``, ...; one row group each, so a partition of the solver
reads only the files whose time range it meets). Plots left without a target are not copied, and
of the references only the positions of labelled targets within their plots' time span (and a
window beyond) are (``reference/part-...``): the registration then uses what a run in memory
uses after its association.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from registration.core.progress import progress_bar
from registration.io.fleet.archive.parquet import ParquetSource
from registration.io.fleet.reading.cells import FILE_COLUMNS

__all__ = ["write_labelled_tables"]


def _file_column(table: str, column: str) -> str:
    return next(f for f, c, *_ in FILE_COLUMNS[table] if c == column)


def _part_table(rows: dict, keep: np.ndarray, schema, labels: np.ndarray | None = None):
    """A pyarrow table of the file rows ``rows`` (file column -> array) at ``keep``, in ``schema``
    (its columns that ``rows`` has; ``track`` left out when ``labels`` replace ``target``)."""
    import pyarrow as pa

    cols, fields = {}, []
    for field in schema:
        if labels is not None and field.name == "target":
            cols["target"], field = pa.array(labels.astype(str), pa.string()), pa.field("target", pa.string())
        elif field.name in rows and not (labels is not None and field.name == "track"):
            cols[field.name] = pa.array(np.asarray(rows[field.name])[keep], field.type, from_pandas=True)
        else:
            continue
        fields.append(field)
    if labels is not None and "target" not in cols:
        cols["target"], fields = (
            pa.array(labels.astype(str), pa.string()),
            [*fields, pa.field("target", pa.string())],
        )
    return pa.table(cols, schema=pa.schema(fields))


def _write_part(folder: Path, k: int, table) -> None:
    import pyarrow.parquet as pq

    folder.mkdir(parents=True, exist_ok=True)
    pq.write_table(table, str(folder / f"part-{k:05d}.parquet"))


def _plots(source: ParquetSource, association, k: int, folder: Path) -> int:
    """Write partition ``k``'s labelled plots; their number."""
    plan = association.plan
    lo, hi = plan.read_ranges[k]
    rows = source.read_file_rows("plots", lo, hi)
    time = np.asarray(rows[_file_column("plots", "time")], dtype=np.float64)
    mine = np.flatnonzero(plan.owned(k, time))
    labels = association.owned[k]
    if mine.size != labels.size:
        raise RuntimeError(
            f"{source.name('plots')}: partition {k} read {mine.size} plots, its association {labels.size}: "
            "the plots table changed during the run"
        )
    has = labels != ""
    if has.any():
        _write_part(folder, k, _part_table(rows, mine[has], source.file_schema("plots"), labels[has]))
    return int(np.count_nonzero(has))


def _references(source: ParquetSource, association, k: int, folder: Path) -> int:
    """Write partition ``k``'s references of labelled targets (module docstring); their number."""
    plan, spans = association.plan, association.spans
    lo, hi = plan.read_ranges[k]
    rows = source.read_file_rows("reference", lo - spans.margin_s - 1.0, hi + spans.margin_s + 1.0)
    if not rows:
        return 0
    time = np.asarray(rows[_file_column("reference", "time")], dtype=np.float64)
    target = np.asarray(rows[_file_column("reference", "target")], dtype=object).astype(str)
    keep = np.flatnonzero(plan.owned(k, time) & spans.keep_references(target, time))
    if keep.size:
        _write_part(folder, k, _part_table(rows, keep, source.file_schema("reference")))
    return int(keep.size)


def write_labelled_tables(
    source: ParquetSource, association, folder, *, progress: bool = False
) -> ParquetSource:
    """Write the labelled plots of ``association`` (a
    :class:`~registration.fleet.association.partitioned.PartitionedAssociation` of ``source``) and
    the references they use into ``folder`` (module docstring); ``source`` with them as its plots
    and references."""
    folder = Path(folder)
    plots, refs = 0, 0
    n = association.plan.n_partitions
    with progress_bar(progress, "labelled plots", total=n, unit="partition") as bar:
        for k in range(n):
            plots += _plots(source, association, k, folder / "plots")
            if source.file_schema("reference") is not None:
                refs += _references(source, association, k, folder / "reference")
            bar.update(1)
    if plots == 0:
        raise ValueError(
            f"{source.name('plots')}: the association gave no plot a target, so there is nothing to register"
        )
    tables = {"plots": folder / "plots"}
    if source.file_schema("reference") is not None:
        tables["reference"] = folder / "reference"
        if refs == 0:  # no reference of a labelled target: an empty table
            _write_part(folder / "reference", 0, source.file_schema("reference").empty_table())
    return source.with_tables(**tables)
