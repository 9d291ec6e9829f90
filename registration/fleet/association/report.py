"""What the association reports per plot and per sensor (:func:`plot_report`): the reason a plot has
no target or was not registered (:data:`~registration.fleet.association.result.REASONS`), the
normalised distance of its join under the final registration, and the counts per sensor."""

from __future__ import annotations

import numpy as np

from registration.fleet.association.grouping.units import Units
from registration.fleet.association.joining.checks import JoinState
from registration.fleet.association.result import CLUTTER_REASONS, REASONS
from registration.fleet.data.problem import FleetProblem

__all__ = ["plot_report", "track_notes"]


def _reasons(
    labels: np.ndarray, registered: np.ndarray, outliers: np.ndarray, units: Units, state: JoinState
) -> np.ndarray:
    """(N,) the reason code of each plot ('' for a registered plot with a label)."""
    out = np.full(labels.size, "", dtype=object)
    lab = labels != ""
    out[lab & ~registered] = "set_aside"
    unl = ~lab
    u = units.of_plot
    has = unl & (u >= 0)
    if has.any():
        uu = u[has]
        out[has] = np.where(
            state.target[uu] != "",
            "outside_span",
            np.where(
                state.dropped[uu],
                "dropped",
                np.where(~state.tested[uu], "no_anchor", np.where(state.gated[uu], "ambiguous", "no_match")),
            ),
        )
    out[unl & units.short] = "short_track"
    out[unl & units.clutter] = "clutter"
    out[unl & (out == "")] = "no_anchor"  # in no unit (cannot happen for a plot without id; kept total)
    out[unl & outliers] = "outlier"
    return out.astype(str)


def _join_values(
    problem: FleetProblem,
    labels: np.ndarray,
    given: np.ndarray,
    e: np.ndarray,
    units: Units,
    state: JoinState,
    track: np.ndarray,
    single: np.ndarray,
) -> np.ndarray:
    """(N,) mean squared normalised residual of each labelled plot's piece: its unit (joins), the
    plot alone (single plots), its track and target (confirmed targets) or its sensor and target
    (ids given); NaN where none."""
    lab = labels != ""
    _, target = np.unique(labels, return_inverse=True)
    kind = np.where(given, 0, np.where(single, 3, np.where(state.label != "", 1, 2)))
    a = np.where(
        kind == 0,
        problem.sensor,
        np.where(kind == 1, units.of_plot, np.where(kind == 3, np.arange(labels.size), track)),
    )
    t = np.where(kind == 1, 0, target.reshape(-1))
    out = np.full(labels.size, np.nan)
    if not lab.any():
        return out
    # one integer per (kind, a, target), in their lexicographic order (a may be -1)
    key = (kind.astype(np.int64) * (int(a.max()) + 2) + (a + 1)) * (int(t.max()) + 1) + t
    _, piece = np.unique(key[lab], return_inverse=True)
    piece = piece.reshape(-1)
    ss = np.bincount(piece, np.nansum(e[lab] ** 2, axis=1))
    cnt = np.bincount(piece, np.isfinite(e[lab]).sum(axis=1))
    with np.errstate(invalid="ignore", divide="ignore"):
        out[lab] = np.where(cnt[piece] > 0, ss[piece] / cnt[piece], np.nan)
    return out


def plot_report(
    problem: FleetProblem,
    labels: np.ndarray,
    given: np.ndarray,
    outliers: np.ndarray,
    units: Units,
    state: JoinState,
    track: np.ndarray,
    batch,
    single: np.ndarray,
) -> dict:
    """Per input row: ``labels``, ``given``, ``reasons``, ``join``, ``tracks``; ``unassociated_rows``,
    ``unassociated_by_sensor``, ``n_clutter``, ``n_unconfirmed``, ``by_sensor`` (the fields of
    :class:`AssociationResult`), from the final labels (N,) of the problem's plots, the ids given
    (N,) bool, the outliers (N,), the units and joins, the fixing sensors' tracks (N,), the final
    batch result and the plots joined alone (N,) bool."""
    n_rows = problem.n_input_plots
    e = batch.residuals[problem.row]
    registered = np.isfinite(e).any(axis=1)
    reasons = _reasons(labels, registered, outliers, units, state)
    join = _join_values(problem, labels, given, e, units, state, track, single)
    names = (
        np.where((state.label != "") & (units.of_plot >= 0), units.name[np.maximum(units.of_plot, 0)], "")
        if units.n
        else np.full(labels.size, "", dtype=object)
    )
    names = np.where(single, "plot", names)

    def rows(values, fill, dtype):
        out = np.full(n_rows, fill, dtype=dtype)
        out[problem.row] = values
        return out

    unl = labels == ""
    n_sensors = len(problem.sensor_ids)
    per_sensor = {
        "given": np.bincount(problem.sensor[given], minlength=n_sensors),
        "associated": np.bincount(problem.sensor[~given & ~unl], minlength=n_sensors),
        "unassociated": np.bincount(problem.sensor[unl], minlength=n_sensors),
    }
    per_sensor.update({k: np.bincount(problem.sensor[reasons == k], minlength=n_sensors) for k in REASONS})
    by_sensor = {
        sid: {k: int(v[s]) for k, v in per_sensor.items()} for s, sid in enumerate(problem.sensor_ids)
    }
    clutter = int(np.isin(reasons[unl], CLUTTER_REASONS).sum())
    return {
        "labels": rows(labels, "", object).astype(str),
        "given": rows(given, False, bool),
        "reasons": rows(reasons, "", object).astype(str),
        "join": rows(join, np.nan, float),
        "tracks": rows(names, "", object).astype(str),
        "unassociated_rows": np.sort(problem.row[unl]),
        "unassociated_by_sensor": {sid: c["unassociated"] for sid, c in by_sensor.items()},
        "n_clutter": clutter,
        "n_unconfirmed": int(unl.sum()) - clutter,
        "by_sensor": by_sensor,
    }


def track_notes(
    problem: FleetProblem, track_id: np.ndarray, given: np.ndarray, labels: np.ndarray
) -> list[str]:
    """One note per given track (``track_id`` (N,), '' none; rows without a target id given) whose
    plots were associated with more than one target: the id was reused for another object, or the
    track jumped from one object to another; the note names the targets and their time spans."""
    sel = np.flatnonzero((track_id != "") & ~given & (labels != ""))
    if sel.size == 0:
        return []
    key = np.char.add(np.char.add(np.array(problem.sensor_ids)[problem.sensor[sel]], "\x1f"), track_id[sel])
    pairs, inverse = np.unique(np.stack([key, labels[sel]]), axis=1, return_inverse=True)
    inverse = inverse.reshape(-1)
    tracks, count = np.unique(pairs[0], return_counts=True)
    notes = []
    for tr in tracks[count > 1]:
        parts = []
        for k in np.flatnonzero(pairs[0] == tr):
            t = problem.time[sel[inverse == k]]
            parts.append((float(t.min()), f"{pairs[1, k]} ({t.min():g} to {t.max():g} s)"))
        sensor, number = tr.split("\x1f", 1)
        notes.append(
            f"sensor {sensor} track {number}: its plots were associated with {len(parts)} targets, "
            + ", ".join(p for _, p in sorted(parts))
            + ": an id reused for another object or a track that "
            "jumped, split"
        )
    return notes
