"""The association's inputs: the ids the plots carry (``target``, ``track``; an empty cell, NaN or
None is "no id"), the checked problem of all plots (:func:`all_plots_problem`), the reference
targets (:func:`anchor_references`), the starting covariance and the problem of the labelled plots
that each registration solves (:func:`labelled_problem`)."""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from registration.fleet.association.options import AssociationOptions
from registration.fleet.data.known_targets import References, read_references
from registration.fleet.data.layout import REFERENCE_SCALE
from registration.fleet.data.problem import Exclusion, FleetProblem, build_problem
from registration.fleet.data.tables import read_table

__all__ = [
    "PLACEHOLDER",
    "PlotIds",
    "id_column",
    "plot_ids",
    "all_plots_problem",
    "anchor_references",
    "initial_covariance",
    "labelled_problem",
]

#: The one target all plots are put under in :func:`all_plots_problem`.
PLACEHOLDER = "?"


def id_column(values) -> np.ndarray:
    """(N,) ids as text, '' where none: empty or blank text, NaN, None. Integral floats lose
    their '.0' (a track number read as 17.0 is '17')."""
    arr = np.asarray(values)
    if arr.dtype.kind == "f":
        whole = np.isfinite(arr) & (arr == np.round(arr))
        text = np.where(whole, np.round(np.nan_to_num(arr)).astype(np.int64).astype(str), arr.astype(str))
        return np.where(np.isnan(arr), "", text).astype(str)
    if arr.dtype.kind in "iub":
        return arr.astype(str)
    if arr.dtype.kind in "US":
        return np.char.strip(arr.astype(str))
    out = []
    for v in arr:  # an object column (text with None or NaN cells): one pass over the ids
        if v is None or (isinstance(v, (float, np.floating)) and np.isnan(v)):
            out.append("")
        elif isinstance(v, (float, np.floating)):
            out.append(str(int(v)) if float(v).is_integer() else str(v))
        else:
            out.append(str(v).strip())
    return np.array(out, dtype=object).astype(str) if out else np.zeros(0, dtype=str)


@dataclass(frozen=True)
class PlotIds:
    """Per row of the plots table: ``target`` the id given ('' none), ``track`` the sensor-local track
    id ('' none); ``has_target``, ``has_track``: whether the table has those columns."""

    target: np.ndarray
    track: np.ndarray
    has_target: bool
    has_track: bool


def plot_ids(plots) -> PlotIds:
    table = read_table("plots", plots, ("time", "sensor"))
    empty = np.full(table.n_rows, "")
    target = id_column(table.columns["target"]) if table.has("target") else empty
    track = id_column(table.columns["track"]) if table.has("track") else empty
    return PlotIds(target, track, table.has("target"), table.has("track"))


def all_plots_problem(plots, sensors, navigation, platforms, targets=None) -> FleetProblem:
    """The checked problem of every plot, all under one placeholder target (the ``target`` and
    ``track`` columns are not used here): the plots' geometry, navigation and state layout, and the
    surface targets of ``targets`` by id (the problems of the labelled plots find theirs there).
    ValueError for an empty table and every error of :func:`build_problem`."""
    table = read_table("plots", plots, ("time", "sensor"))
    if table.n_rows == 0:
        raise ValueError("plots: no plots to associate (the table is empty)")
    columns = {k: v for k, v in table.columns.items() if k not in ("target", "track")}
    columns["target"] = np.full(table.n_rows, PLACEHOLDER)
    # a placeholder reference keeps the target when one sensor made every plot (build_problem sets
    # aside a target seen by one sensor only, unless it is a reference); it is removed at once
    t0 = float(np.nanmin(table.floats("time")))
    dummy = {"target": [PLACEHOLDER], "time": [t0], "x": [0.0], "y": [0.0], "z": [6.4e6]}
    problem = build_problem(columns, sensors, navigation, platforms, dummy, targets)
    return replace(problem, references=References.empty(), ref_target=np.zeros(0, dtype=np.int64))


def anchor_references(references) -> References:
    """The reference positions of every reference target (ECEF m, sigma m per axis)."""
    if references is None:
        return References.empty()
    table = read_table("references", references, ("target", "time"))
    targets = list(dict.fromkeys(table.ids("target")))
    return read_references(references, targets)


def initial_covariance(problem: FleetProblem, options: AssociationOptions) -> np.ndarray:
    """(n, n) diagonal: the tables' finite prior sigmas, else the options' starting sigmas (squared)."""
    layout = problem.layout
    default = options.initial_sigma()
    prior = layout.prior_sigma
    start = [default.get(q, REFERENCE_SCALE[u]) for q, u in zip(layout.quantities, layout.units)]
    sigma = np.where(np.isfinite(prior), prior, start)
    return np.diag(sigma**2)


def _first_seen(labels: np.ndarray, row: np.ndarray) -> tuple[tuple[str, ...], np.ndarray]:
    """(the distinct labels in order of first row, each label's index into them)."""
    order = np.argsort(row, kind="stable")
    unique, first, inverse = np.unique(labels.astype(str)[order], return_index=True, return_inverse=True)
    rank = np.argsort(first)
    position = np.empty(rank.size, dtype=np.int64)
    position[rank] = np.arange(rank.size)
    index = np.empty(labels.size, dtype=np.int64)
    index[order] = position[inverse.reshape(-1)]
    return tuple(str(u) for u in unique[rank]), index


def labelled_problem(
    problem: FleetProblem,
    labels: np.ndarray,
    refs: References,
    margin_s: float = 0.0,
    keep_lone: bool = False,
) -> FleetProblem:
    """The problem of the plots with a label ``labels`` (N,; '' none), the labels as target ids
    (in order of first row), with the reference positions of those targets that lie within their
    plots' time span (+- ``margin_s``). A target seen by one sensor only and not a reference is set
    aside with its reason (it carries no registration information), as :func:`build_problem` does,
    unless ``keep_lone`` (for the targets' curves only).
    ValueError when no plot is left."""
    keep = labels != ""
    sub = problem.drop_plots(~keep, ())
    lab = labels[keep]
    names, target = _first_seen(lab, sub.row) if lab.size else ((), np.zeros(0, dtype=np.int64))
    ref_names = set(refs.target.astype(str))
    n_sensors_all = max(len(problem.sensor_ids), 1)
    pairs = (
        np.unique(target * n_sensors_all + sub.sensor) // n_sensors_all
    )  # the target of each (target, sensor)
    n_sensors = np.bincount(pairs, minlength=len(names))
    lone = [] if keep_lone else [k for k in np.flatnonzero(n_sensors == 1) if names[k] not in ref_names]
    exclusions = []
    for k in lone:
        t = sub.time[target == k]
        exclusions.append(
            Exclusion(
                names[k],
                "seen by one sensor only and not a reference: its plots fit any "
                "registration errors, so they carry no registration information",
                int(t.size),
                float(t.min()),
                float(t.max()),
            )
        )
    drop = np.isin(target, lone)
    if drop.all():
        raise ValueError("association: no target is seen by two sensors or is a reference")
    sub = replace(sub.drop_plots(drop, exclusions), target=target[~drop])
    used = np.unique(sub.target)
    names_kept = tuple(names[k] for k in used)
    sub = replace(sub, target=np.searchsorted(used, sub.target), target_ids=names_kept)
    return replace(sub, **_references_of(sub, refs, margin_s))


def _references_of(problem: FleetProblem, refs: References, margin_s: float) -> dict:
    """``references`` and ``ref_target`` of the problem's targets, within each target's plot span."""
    names = np.array(problem.target_ids, dtype=str)
    t0 = np.full(names.size, np.inf)
    t1 = np.full(names.size, -np.inf)
    np.minimum.at(t0, problem.target, problem.time)
    np.maximum.at(t1, problem.target, problem.time)
    lookup = {t: k for k, t in enumerate(names)}
    k = np.array([lookup.get(str(t), -1) for t in refs.target], dtype=np.int64)
    inside = k >= 0
    inside[inside] = (refs.time[inside] >= t0[k[inside]] - margin_s) & (
        refs.time[inside] <= t1[k[inside]] + margin_s
    )
    kept = refs.subset(inside)
    return {"references": kept, "ref_target": k[inside]}
