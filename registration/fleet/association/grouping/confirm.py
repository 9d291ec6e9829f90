"""Targets confirmed among the position-fixing sensors (those that measure range, bearing and
elevation): the tracklet grouping of :mod:`.match`, :mod:`.groups` and :mod:`.cost`, iterated with
the registration (:func:`confirm_targets`).

Each pass cuts the fixing sensors' tracks (without target ids) into windows, groups the pieces
across sensors under the current estimate and covariance, chains the groups of consecutive windows
into targets, and registers the labelled plots (the ids given and these targets, with the
references); the next pass uses the new estimate. A group is confirmed when it holds two or more
sensors. The passes before the last use every k-th window only (``iteration_plots``); the last pass
covers all windows with the tracks made again from the plots corrected by the estimate, and there
a target needs confirmed groups in two windows. Sensors lacking a channel take no part here: their
tracks are joined to the confirmed targets afterwards (:mod:`.joins`).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from registration.core.progress import progress_status
from registration.fleet.association.grouping.geometry import Assigner, PlotGeometry, plot_geometry
from registration.fleet.association.grouping.groups import group_tracklets
from registration.fleet.association.grouping.match import chain_groups, make_tracklets
from registration.fleet.association.grouping.units import make_units
from registration.fleet.association.options import AssociationOptions
from registration.fleet.data.problem import FleetProblem

__all__ = ["Confirmed", "confirm_targets", "fixing_sensors", "merge_fragments", "new_names"]


def fixing_sensors(problem: FleetProblem) -> np.ndarray:
    """(S,) bool: the sensors that measure range, bearing and elevation (a plot fixes a position)."""
    return np.asarray((problem.layout.bias_index >= 0).all(axis=1))


def new_names(count: int, taken: set) -> list[str]:
    """``count`` target names ``a1``, ``a2``, ... that are not in ``taken``."""
    out: list[str] = []
    k = 0
    while len(out) < count:
        k += 1
        if f"a{k}" not in taken:
            out.append(f"a{k}")
    return out


@dataclass
class Confirmed:
    """The outcome: ``labels`` (N,) of the plots (ids given, confirmed targets; '' none), the
    estimate ``x`` and covariance ``P`` of the last registration, ``track`` (N,) the fixing sensors'
    tracks of the last pass (-1 none), ``piece`` (N,) their tracklet (-1: in no piece long enough),
    ``passes``, ``converged``, ``changes`` (plots relabelled per pass), ``seconds_registration``."""

    labels: np.ndarray
    x: np.ndarray
    P: np.ndarray
    track: np.ndarray
    piece: np.ndarray
    passes: int = 0
    converged: bool = True
    changes: list = field(default_factory=list)
    seconds_registration: float = 0.0


def _group_labels(
    problem: FleetProblem, tl, group: np.ndarray, chain: np.ndarray, min_windows: int, taken: set
) -> np.ndarray:
    """(N,) the label of each plot ('' none): a group is confirmed when it holds two or more sensors,
    a chain when it holds confirmed groups in ``min_windows`` windows or more (a chain of one window
    is mostly a target's pieces that missed their group by chance); names by first row, not in
    ``taken``."""
    out = np.full(problem.n_plots, "", dtype=object)
    if group.size == 0:
        return out.astype(str)
    n_groups = chain.size
    sensors_in = np.zeros(n_groups, dtype=np.int64)
    pairs = np.unique(np.stack([group, tl.sensor]), axis=1)
    np.add.at(sensors_in, pairs[0], 1)
    confirmed = sensors_in >= 2
    windows_in = np.zeros(n_groups, dtype=np.int64)
    np.add.at(windows_in, chain[confirmed], 1)  # one group per window in a chain
    confirmed &= windows_in[chain] >= min_windows
    plot_group = np.where(tl.of_plot >= 0, group[np.maximum(tl.of_plot, 0)], -1)
    g = np.maximum(plot_group, 0)
    ok = (plot_group >= 0) & confirmed[g]
    plot_chain = np.where(ok, chain[g], -1)
    seen = plot_chain[np.argsort(problem.row, kind="stable")]
    chains, first = np.unique(seen[seen >= 0], return_index=True)
    names = dict(zip(chains[np.argsort(first)].tolist(), new_names(chains.size, taken)))
    out[ok] = [names[int(c)] for c in plot_chain[ok]]
    return out.astype(str)


def merge_fragments(problem: FleetProblem, labels: np.ndarray, track: np.ndarray) -> np.ndarray:
    """(N,) ``labels`` with the targets that are pieces of one object merged: a sensor track (``track``
    (N,), -1 none) whose plots carry two targets one after the other (their time spans do not overlap)
    links them (the grouping's chains break where a window holds no confirmed group). Targets that
    exist at the same time are never merged (a track that swapped targets where two crossed). The
    merged target keeps the name of its first piece."""
    sel = (labels != "") & (track >= 0)
    if not sel.any():
        return labels
    names, index = np.unique(labels[sel], return_inverse=True)
    index = index.reshape(-1)
    t0, t1 = np.full(names.size, np.inf), np.full(names.size, -np.inf)
    np.minimum.at(t0, index, problem.time[sel])
    np.maximum.at(t1, index, problem.time[sel])
    root = np.arange(names.size)

    def find(a: int) -> int:
        while root[a] != a:
            a = root[a]
        return a

    pairs = np.unique(np.stack([track[sel], index]), axis=1)
    for tr in np.unique(pairs[0]):
        mine = pairs[1][pairs[0] == tr]
        mine = mine[np.argsort(t0[mine])]
        for a, b in zip(mine[:-1], mine[1:]):
            if t0[b] >= t1[a]:  # one after the other
                ra, rb = find(int(a)), find(int(b))
                root[max(ra, rb)] = min(ra, rb) if t0[min(ra, rb)] <= t0[max(ra, rb)] else max(ra, rb)
    first: dict[int, int] = {}
    out = labels.astype(object)
    merged = np.array([find(k) for k in range(names.size)])
    for k in range(names.size):  # the earliest piece names the merged target
        r = merged[k]
        if r not in first or t0[k] < t0[first[r]]:
            first[r] = k
    rename = {names[k]: names[first[merged[k]]] for k in range(names.size)}
    lab = labels != ""
    present, inverse = np.unique(labels[lab], return_inverse=True)
    out[lab] = np.array([rename.get(v, v) for v in present], dtype=object)[inverse.reshape(-1)]
    return out.astype(str)


def _window_subset(problem: FleetProblem, options: AssociationOptions) -> np.ndarray:
    """(N,) the plots of every k-th window, k such that they hold about ``iteration_plots`` plots."""
    k = int(np.ceil(problem.n_plots / options.iteration_plots))
    return np.floor(problem.time / options.window_s).astype(np.int64) % k == 0


def _group_pass(
    problem,
    track,
    x,
    P,
    options,
    assigner,
    screen: bool,
    last: bool,
    taken: set,
    geom: PlotGeometry | None = None,
):
    """One grouping pass: (labels (N,), tracklet of each plot (N,))."""
    geom = plot_geometry(problem, x, np.flatnonzero(track >= 0)) if geom is None else geom
    tl = make_tracklets(
        problem,
        geom,
        track,
        options.window_s,
        options.min_tracklet_plots,
        options.gate_probability if screen else None,
    )
    group = group_tracklets(problem, x, tl, P, options.gate_probability, assigner)
    chain = chain_groups(tl, group, assigner)
    return _group_labels(problem, tl, group, chain, 2 if last else 1, taken), tl.of_plot


def confirm_targets(
    problem: FleetProblem,
    given: np.ndarray,
    track_id: np.ndarray,
    x: np.ndarray,
    P: np.ndarray,
    options: AssociationOptions,
    assigner: Assigner,
    register,
    bar,
) -> Confirmed:
    """Targets among the fixing sensors' plots without a label in ``given`` (N,), their tracks from
    ``track_id`` (N,; '' : made by the tracker), from the estimate ``x`` and covariance ``P``;
    ``register(labels, subset) -> (x, P)`` registers the labelled plots (``subset``: only those
    plots, None: all) and returns the estimate and its covariance (the same when nothing is
    labelled). ``bar``: the progress bar (:func:`~registration.core.progress.progress_bar`)."""
    free = (given == "") & fixing_sensors(problem)[problem.sensor]
    none = np.full(problem.n_plots, -1, dtype=np.int64)
    if np.unique(problem.sensor[free]).size < 2:
        return Confirmed(given.copy(), x, P, none, none.copy())
    taken = set(given[given != ""])
    subset = _window_subset(problem, options)
    track = make_units(problem, track_id, free & subset, x, options, assigner).of_plot
    labels, previous, changes, t_solve, converged, passes = None, None, [], 0.0, False, 0
    for passes in range(1, options.max_iterations):
        progress_status(bar, f"pass {passes}: grouping the position-fixing sensors' plots")
        labels, _ = _group_pass(problem, track, x, P, options, assigner, passes > 1, False, taken)
        if previous is not None:
            changes.append(int(np.count_nonzero(labels != previous)))
            if changes[-1] == 0:
                converged = True
                break
        previous = labels
        progress_status(bar, f"pass {passes}: registering")
        t1 = time.perf_counter()
        x, P = register(np.where(given != "", given, labels), subset)
        t_solve += time.perf_counter() - t1
        bar.update()
    progress_status(bar, "last grouping pass: all windows")
    if passes or not subset.all():
        track = make_units(problem, track_id, free, x, options, assigner).of_plot
    labels, piece = _group_pass(problem, track, x, P, options, assigner, passes > 0, True, taken)
    labels = merge_fragments(problem, labels, track)
    return Confirmed(
        np.where(given != "", given, labels), x, P, track, piece, passes + 1, converged, changes, t_solve
    )
