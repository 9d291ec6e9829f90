"""``fleet register`` on plots without target ids for some or all rows (or with a ``track`` column):
the association (:func:`registration.fleet.associate_and_register`, a batch method), then, with
``--method online``, the online filter on the labels it gave; ``associations.csv``; the summary's
association part. See docs/background/association.md."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from registration.cli.errors import writing

__all__ = [
    "ASSOCIATION_COLUMNS",
    "associate",
    "labelled_tables",
    "association_summary",
    "online_note",
    "write_associations",
]

#: Columns of associations.csv (``track`` only when the plots file has one).
ASSOCIATION_COLUMNS = ("row", "time_s", "sensor", "track", "target", "join", "reason")
#: Printed when --method online runs on the association's labels.
ONLINE_NOTE = (
    "--method online: the association is a batch method (it registers while it joins plots to targets), "
    "so the batch associated the plots first; the online filter then ran on the targets it gave"
)


def labelled_tables(tables, association) -> tuple[dict, dict | None]:
    """The plots the association labelled, the labels as their target ids, and the references of
    those targets."""
    keep = association.labels != ""
    plots = {k: np.asarray(v)[keep] for k, v in tables.plots.items() if k not in ("target", "track")}
    plots["target"] = association.labels[keep]
    refs = tables.references
    if refs is not None:
        mine = np.isin(np.asarray(refs["target"]).astype(str), np.unique(plots["target"]))
        refs = {k: np.asarray(v)[mine] for k, v in refs.items()} if mine.any() else None
    return plots, refs


def associate(tables, window_s: float, method: str):
    """(association, problem, result): the association of the tables' plots (a batch method) and the
    batch result, or with ``method == "online"`` the online filter's result on its labels."""
    from registration.fleet import AssociationOptions, OnlineOptions, associate_and_register, register_online

    if window_s <= 0:
        raise ValueError(
            f"--window-s: plots without target ids are associated in windows; expected a length > 0 s, "
            f"got {window_s}"
        )
    association = associate_and_register(
        tables.plots,
        tables.sensors,
        tables.navigation,
        tables.platforms,
        tables.references,
        AssociationOptions(window_s=window_s),
        progress=True,
        targets=tables.targets,
    )
    if method != "online":
        return association, association.problem, association.batch
    plots, refs = labelled_tables(tables, association)
    result = register_online(
        plots,
        tables.sensors,
        tables.navigation,
        tables.platforms,
        refs,
        options=OnlineOptions(window_s=window_s),
        targets=tables.targets,
    )
    return association, association.problem, result


def online_note(method: str) -> list[str]:
    """The line that says what ran, for --method online with the association."""
    return [ONLINE_NOTE] if method == "online" else []


def association_summary(association, method: str) -> dict:
    """The association's part of summary.json: counts, per sensor, notes, passes."""
    out = {
        "targets": association.n_targets,
        "plots_associated": association.n_associated,
        "plots_with_ids_given": int(association.given.sum()),
        "plots_unassociated": int(association.unassociated_rows.size),
        "unassociated_by_sensor": {k: int(v) for k, v in association.unassociated_by_sensor.items()},
        "by_sensor": association.by_sensor,
        "notes": list(association.notes),
        "passes": association.iterations,
        "join_passes": association.join_passes,
        "converged": bool(association.converged),
    }
    if method == "online":
        out["online"] = ONLINE_NOTE
    return out


def write_associations(out: Path, tables, association) -> Path:
    """associations.csv: per plots-file row its time, sensor, track (if the file has them), the target
    it has (given or associated; '' none), the join's normalised distance (d^2/dof of its track piece
    under the final registration) and the reason it was left out or not registered ('' when it was)."""
    import pandas as pd

    from registration.io.files.tablefile import write_frame

    rows = tables.file_rows.get("plots", np.arange(association.labels.size))
    columns = {"row": rows, "time_s": tables.plots["time"], "sensor": tables.plots["sensor"]}
    if "track" in tables.plots:
        columns["track"] = tables.plots["track"]
    columns.update(target=association.labels, join=association.join, reason=association.reasons)
    path = out / "associations.csv"
    with writing(path):
        write_frame(pd.DataFrame(columns), path, "csv")
    return path
