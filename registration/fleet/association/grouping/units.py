"""The tracks the association joins to targets ("units"): per sensor, the plots without a target
id grouped into tracks, given by the plots' ``track`` column (a sensor-local id: an ARPA radar's
target number, a tracker's track number) or made by the per-sensor tracker
(:func:`~registration.fleet.association.grouping.tracks.sensor_tracks`).

Plots with the same (sensor, track) are one object; ids of different sensors are unrelated. A
track is split where its plots are more than ``track_gap_s`` apart (an id reused for another object
after a gap) and, for a given track, where a plot lies outside the gate of the track's prediction
(a constant-velocity filter in ECEF, :func:`~registration.fleet.association.grouping.tracks.track_breaks`:
an id that jumps to another object). Each split of a given track is noted. Pieces of fewer than
``min_track_plots`` plots are not joined (too short to be tested; reported as such).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fleet.association.grouping.geometry import Assigner, plot_geometry
from registration.fleet.association.grouping.tracks import sensor_tracks, track_breaks
from registration.fleet.association.options import AssociationOptions
from registration.fleet.data.problem import FleetProblem

__all__ = ["Units", "make_units", "split_units", "unit_conflicts", "unit_plots"]


@dataclass(frozen=True)
class Units:
    """``of_plot`` (N,): the unit of each plot of the problem, -1 for none; per unit (U,): ``sensor``
    index, ``name`` (``track 17`` for a given track, its piece ``track 17/2``; ``tracker 5``), ``t0``,
    ``t1`` (s, first and last plot), ``given`` (from the ``track`` column). ``short`` (N,): plots in a
    track piece too short to test; ``clutter`` (N,): plots the tracker put in no track.
    ``notes``: the splits of given tracks, one text each."""

    of_plot: np.ndarray
    sensor: np.ndarray
    name: np.ndarray
    t0: np.ndarray
    t1: np.ndarray
    given: np.ndarray
    short: np.ndarray
    clutter: np.ndarray
    notes: tuple

    @property
    def n(self) -> int:
        return int(self.sensor.size)


def unit_plots(of_plot: np.ndarray, n_units: int) -> tuple[np.ndarray, np.ndarray]:
    """(order (N,), start (U + 1,)): the plots of unit u, ascending, are ``order[start[u]:start[u + 1]]``
    (``np.flatnonzero(of_plot == u)`` for all units in one sort; -1 is no unit)."""
    order = np.argsort(of_plot, kind="stable")
    return order, np.searchsorted(of_plot[order], np.arange(n_units + 1))


def _pieces(key: np.ndarray, time: np.ndarray, breaks: np.ndarray) -> np.ndarray:
    """(M,) piece index: ``key`` groups cut where ``breaks`` (M,) starts a new piece; plots sorted
    by time within a key."""
    order = np.lexsort((time, key))
    new = np.r_[True, key[order][1:] != key[order][:-1]] | breaks[order]
    out = np.empty(key.size, dtype=np.int64)
    out[order] = np.cumsum(new) - 1
    return out


def _gap_breaks(key: np.ndarray, time: np.ndarray, gap_s: float) -> np.ndarray:
    """(M,) True where a plot follows the previous plot of its key by more than ``gap_s`` seconds."""
    order = np.lexsort((time, key))
    k, t = key[order], time[order]
    brk = np.r_[False, (k[1:] == k[:-1]) & (np.diff(t) > gap_s)]
    out = np.zeros(key.size, dtype=bool)
    out[order] = brk
    return out


def _split_notes(
    problem: FleetProblem,
    key: np.ndarray,
    names: np.ndarray,
    time: np.ndarray,
    gaps: np.ndarray,
    jumps: np.ndarray,
    d2: np.ndarray,
    plots: np.ndarray,
) -> list[str]:
    """One note per given track that was split: where and why."""
    notes = []
    for k in np.unique(key[gaps | jumps]):
        sel = np.flatnonzero(key == k)
        sel = sel[np.argsort(time[sel])]
        why = []
        for i in sel[gaps[sel] | jumps[sel]]:
            j = sel[np.searchsorted(time[sel], time[i]) - 1]
            reason = (
                "gap of %.3g s" % (time[i] - time[j])
                if gaps[i]
                else "jump: %.3g sigma off its prediction" % np.sqrt(d2[i])
            )
            why.append(f"at {time[i]:g} s ({reason})")
        sensor = problem.sensor_ids[problem.sensor[plots[sel[0]]]]
        notes.append(
            f"sensor {sensor} {names[sel[0]]}: split into {len(why) + 1} pieces, "
            + ", ".join(why)
            + " (an id reused for another object, or a track that jumped)"
        )
    return notes


def _given_pieces(
    problem: FleetProblem,
    plots: np.ndarray,
    track_id: np.ndarray,
    time: np.ndarray,
    geom,
    rows: np.ndarray,
    options: AssociationOptions,
) -> tuple[np.ndarray, np.ndarray, list[str]]:
    """The pieces of the given tracks: for the ``plots`` (M,) of the problem with their ``track_id``
    and ``time`` (M,) (rows ``rows`` of the plot geometry ``geom``), (piece key (M,), piece name
    (M,), one note per split track); a track is split at gaps and jumps."""
    labels = np.char.add(np.char.add(np.array(problem.sensor_ids)[problem.sensor[plots]], "\x1f"), track_id)
    _, gkey = np.unique(labels, return_inverse=True)
    gaps = _gap_breaks(gkey, time, options.track_gap_s)
    gpiece = _pieces(gkey, time, gaps)
    jumps, d2 = track_breaks(
        time,
        gpiece,
        _geometry_rows(geom, rows),
        max_speed=options.max_speed,
        accel_sigma=options.jump_accel_sigma,
        probability=options.jump_probability,
    )
    gnames = np.char.add("track ", track_id)
    notes = _split_notes(problem, gkey, gnames, time, gaps, jumps, d2, plots)
    key = _pieces(gkey, time, gaps | jumps)
    first = np.full(int(gkey.max()) + 1, np.iinfo(np.int64).max)
    np.minimum.at(first, gkey, key)
    last = np.zeros_like(first)
    np.maximum.at(last, gkey, key)
    split = (last > first)[gkey]
    ordinal = (key - first[gkey] + 1).astype(str)
    return key, np.where(split, np.char.add(np.char.add(gnames, "/"), ordinal), gnames), notes


def make_units(
    problem: FleetProblem,
    track_id: np.ndarray,
    free: np.ndarray,
    x: np.ndarray,
    options: AssociationOptions,
    assigner: Assigner,
) -> Units:
    """The units of the plots ``free`` (N,) bool (those without a target label) of the problem,
    from their ``track_id`` (N,; '' none: made by the tracker) and the estimate ``x`` (n,; the plots
    are placed corrected by it)."""
    n = problem.n_plots
    at = np.flatnonzero(free)
    if at.size == 0:
        none = np.zeros(n, dtype=bool)
        return Units(
            np.full(n, -1, dtype=np.int64),
            np.zeros(0, dtype=np.int64),
            np.zeros(0, dtype=str),
            np.zeros(0),
            np.zeros(0),
            np.zeros(0, dtype=bool),
            none,
            none.copy(),
            (),
        )
    geom = plot_geometry(problem, x, at)
    time = geom.time
    given = track_id[at] != ""
    key = np.full(at.size, -1, dtype=np.int64)
    names = np.full(at.size, "", dtype=object)
    notes: list[str] = []
    if given.any():
        g = np.flatnonzero(given)
        key[g], names[g], split_notes = _given_pieces(
            problem, at[g], track_id[at[g]], time[g], geom, g, options
        )
        notes += split_notes
    clutter = np.zeros(n, dtype=bool)
    rest = np.flatnonzero(~given)
    if rest.size:
        tracks = sensor_tracks(
            time[rest],
            problem.sensor[at[rest]],
            _geometry_rows(geom, rest),
            assigner,
            max_speed=options.max_speed,
            accel_sigma=options.accel_sigma,
            gate_probability=options.gate_probability,
            max_missed=options.max_missed,
            min_plots=options.min_track_plots,
        )
        clutter[at[rest[tracks < 0]]] = True
        ok = tracks >= 0
        tkey = np.where(ok, tracks, -1)
        offset = int(key.max()) + 1 if given.any() else 0
        pieces = _pieces(tkey[ok], time[rest[ok]], _gap_breaks(tkey[ok], time[rest[ok]], options.track_gap_s))
        key[rest[ok]] = offset + pieces
        names[rest[ok]] = np.char.add("tracker ", tracks[ok].astype(str))
    return _collect(problem, at, key, names, time, given, clutter, notes, options)


def _geometry_rows(geom, rows: np.ndarray):
    """The plot geometry of the rows ``rows`` of ``geom`` (a PlotGeometry of the same kind)."""
    return type(geom)(
        *(
            getattr(geom, f)[rows]
            for f in ("p_ecef", "info", "cov", "dp_dx", "J", "weight", "plots", "time", "nav", "rate")
        )
    )


def _collect(problem, at, key, names, time, given, clutter, notes, options) -> Units:
    """Units from the piece keys (-1: none): pieces shorter than ``min_track_plots`` are not units."""
    n = problem.n_plots
    valid = key >= 0
    ids, inverse, counts = np.unique(key[valid], return_inverse=True, return_counts=True)
    long_enough = counts >= options.min_track_plots
    short = np.zeros(n, dtype=bool)
    short[at[valid][~long_enough[inverse]]] = True
    new_id = np.cumsum(long_enough) - 1
    unit = np.full(at.size, -1, dtype=np.int64)
    unit[np.flatnonzero(valid)] = np.where(long_enough[inverse], new_id[inverse], -1)
    of_plot = np.full(n, -1, dtype=np.int64)
    of_plot[at] = unit
    m = int(long_enough.sum())
    sensor, t0, t1 = np.zeros(m, dtype=np.int64), np.full(m, np.inf), np.full(m, -np.inf)
    inside = unit >= 0
    sensor[unit[inside]] = problem.sensor[at[inside]]
    np.minimum.at(t0, unit[inside], time[inside])
    np.maximum.at(t1, unit[inside], time[inside])
    name = np.full(m, "", dtype=object)
    is_given = np.zeros(m, dtype=bool)
    name[unit[inside]] = names[inside]
    is_given[unit[inside]] = given[inside]
    return Units(of_plot, sensor, name.astype(str), t0, t1, is_given, short, clutter, tuple(notes))


def _shared_scans(units: Units, problem: FleetProblem, sensor: int) -> np.ndarray:
    """(K, 2) pairs of units of ``sensor`` that have plots at the same time (one scan) at least twice."""
    plots = np.flatnonzero((units.of_plot >= 0) & (problem.sensor == sensor))
    t, u = problem.time[plots], units.of_plot[plots]
    order = np.lexsort((u, t))
    t, u = t[order], u[order]
    first = np.r_[True, (t[1:] != t[:-1]) | (u[1:] != u[:-1])]  # each (time, unit) once
    t, u = t[first], u[first]
    found = []
    for d in range(1, t.size):
        same = t[d:] == t[:-d]
        if not same.any():
            break
        found.append(np.stack([u[:-d][same], u[d:][same]], axis=1))
    if not found:
        return np.zeros((0, 2), dtype=np.int64)
    pairs = np.sort(np.concatenate(found), axis=1)
    code, count = np.unique(pairs[:, 0] * np.int64(units.n) + pairs[:, 1], return_counts=True)
    code = code[count >= 2]
    return np.stack([code // units.n, code % units.n], axis=1)


def unit_conflicts(units: Units, problem: FleetProblem, previous: np.ndarray | None = None) -> np.ndarray:
    """(U, U) bool: units that cannot be the same target. A sensor reports a target once a scan, so
    two units of one sensor with plots in the same scan (the same time) twice or more are two
    targets. For a sensor whose plots all have different times (per-plot times), units whose spans
    overlap by more than three of its typical plot intervals are taken for two targets.
    ``previous``: the conflicts of the units before some were split (:func:`split_units` appends the
    halves): only the sensors with new units are looked at again (units of different sensors never
    conflict)."""
    out = np.zeros((units.n, units.n), dtype=bool)
    sensors = np.unique(units.sensor)
    if previous is not None:
        old = previous.shape[0]
        out[:old, :old] = previous
        sensors = np.unique(units.sensor[old:])
    for s in sensors:
        mine = np.flatnonzero(units.sensor == s)
        out[np.ix_(mine, mine)] = False
        t = problem.time[problem.sensor == s]
        unique = np.unique(t)
        if unique.size < 0.8 * t.size:  # scans of several plots
            pairs = _shared_scans(units, problem, int(s))
            out[pairs[:, 0], pairs[:, 1]] = out[pairs[:, 1], pairs[:, 0]] = True
            continue
        interval = float(np.median(np.diff(unique))) if unique.size > 1 else 0.0
        overlap = np.minimum(units.t1[mine][:, None], units.t1[mine][None, :]) - np.maximum(
            units.t0[mine][:, None], units.t0[mine][None, :]
        )
        out[np.ix_(mine, mine)] = overlap > 3.0 * interval
    np.fill_diagonal(out, False)
    return out


def split_units(
    units: Units, problem: FleetProblem, which: np.ndarray
) -> tuple[Units, np.ndarray, list[str]]:
    """``units`` with each unit of ``which`` cut in two halves at its median plot time (the halves
    are new units at the end, named ``<name>.1`` and ``<name>.2``; the unit itself is left without
    plots). Returns (units, (K, 2) the new units of each, notes)."""
    of_plot = units.of_plot.copy()
    sensor, name, t0, t1, given = (
        list(v) for v in (units.sensor, units.name, units.t0, units.t1, units.given)
    )
    halves, notes = [], []
    order, start = unit_plots(units.of_plot, units.n)  # the units of ``which`` are distinct
    for u in which:
        plots = order[start[u] : start[u + 1]]
        t = problem.time[plots]
        cut = np.median(t)
        first = t <= cut
        if first.all() or not first.any():
            first = np.arange(t.size) < t.size // 2
        ids = []
        for part, suffix in ((first, ".1"), (~first, ".2")):
            ids.append(len(sensor))
            of_plot[plots[part]] = ids[-1]
            sensor.append(units.sensor[u])
            name.append(f"{units.name[u]}{suffix}")
            t0.append(float(t[part].min()))
            t1.append(float(t[part].max()))
            given.append(units.given[u])
        halves.append(ids)
        notes.append(
            f"sensor {problem.sensor_ids[units.sensor[u]]} {units.name[u]}: matched no target as a whole; "
            f"split at {cut:g} s and its halves tested apart (it may hold two objects)"
        )
    out = Units(
        of_plot,
        np.array(sensor, dtype=np.int64),
        np.array(name, dtype=object).astype(str),
        np.array(t0),
        np.array(t1),
        np.array(given, dtype=bool),
        units.short,
        units.clutter,
        units.notes,
    )
    return out, np.array(halves, dtype=np.int64).reshape(-1, 2), notes
