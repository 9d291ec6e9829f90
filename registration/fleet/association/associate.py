"""Association of plots across sensors without target ids, jointly with the registration:
:func:`associate_and_register`.

Which plot of one radar and which of another are the same aircraft is unknown while the biases
are unknown, and the biases cannot be estimated until that is known. Both are found together
by iterating: associate under the current estimate and its covariance, register the associated
plots with :func:`~registration.fleet.batch.solve.solve_batch`, and associate again under the new
estimate and covariance, until the association stops changing (at most ``max_iterations``
passes).

Sensors plot at their own times, so plots of different sensors never share an instant. The
association therefore works on tracklets, not on plots:

1. **Tracks per sensor** (:mod:`registration.fleet.association.tracks`). A sensor's errors are
   the same for all its plots, so its plots are linked over time without the registration, by
   constant-velocity Kalman tracks in ECEF with one global assignment per scan.
2. **Tracklets across sensors, per window** (:mod:`registration.fleet.association.match`,
   :mod:`~registration.fleet.association.groups`, :mod:`~registration.fleet.association.cost`).
   Each track is cut into windows of ``window_s`` s, on a grid common to all sensors. Each piece
   is fitted by a quadratic in ECEF, with its covariance and its sensitivity to the registration
   states. In every window the sensors' pieces are grouped by global assignments whose cost is
   the negative log-likelihood of being the same target. That cost carries the registration
   covariance through the Jacobians of the generated ``fleet_residual``, so the gates include
   the bias uncertainty. Groups of consecutive windows that share sensor tracks are chained into
   targets.
3. **Registration** of the plots of confirmed groups. The rest are reported unassociated:
   clutter, short pieces, and targets that one sensor alone, or only 2-D sensors, saw.

**Extended errors** (sensors-table columns ``prior_range_gain``, ``prior_time_bias``,
``prior_position``): a sensor's plots then depend on 11 states instead of 6 (range gain, time
bias and east, north, up position error besides the attitude errors and biases), the positions
come from ``fleet_plot2ecef_ext`` and the Jacobians from ``fleet_residual_ext``. A plot of a
sensor with a time bias is placed from its platform's navigation at the time it was seen (its
reported time minus the estimated bias) and carries that time into the tracks and the tracklets,
so that every sensor's curves are on one time axis (:mod:`registration.fleet.association.geometry`
for the sensitivity to the time bias). In the first pass, under a zero estimate, a time bias on a
rolling ship puts each plot where the deck pointed a moment earlier or later: the plots sway
with the roll rate times the bias (up to 2.3 deg per second of bias under 4 deg of roll at 11 s),
which breaks sensor tracks as an angle bias does; the passes that follow, and the tracks made
again from the corrected plots in the last pass, recover them.

Assumptions: quadratic motion over a window (20 s by default; the tracks themselves follow
turns); a sensor reports each target at most once per scan; the starting covariance
(``initial_sigma_*`` or the tables' finite priors) covers the true errors.
See docs/association.md for the method and its measured performance.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field, replace

import numpy as np

from registration.fleet.association.geometry import Assigner, PlotGeometry, plot_geometry
from registration.fleet.association.groups import group_tracklets
from registration.fleet.association.match import chain_groups, make_tracklets
from registration.fleet.association.result import AssociationResult
from registration.fleet.association.tracks import sensor_tracks
from registration.fleet.batch.solve import solve_batch
from registration.fleet.data.problem import FleetProblem, build_problem
from registration.fleet.batch.solver import BatchOptions, progress_bar, progress_status
from registration.fleet.data.tables import read_table

__all__ = ["AssociationOptions", "AssociationResult", "associate_and_register"]

#: Stopping tolerance (chi-square units) of the solves between association passes: their estimate
#: only sets the next gates, so a remaining change of about sqrt(0.01) = 0.1 sigma is enough.
INTERMEDIATE_TOLERANCE = 1e-2
#: Iterations per phase of those solves at most (a window that only 2-D radars determine can make
#: Levenberg-Marquardt crawl along its poorly determined height).
INTERMEDIATE_ITERATIONS = 25


@dataclass(frozen=True)
class AssociationOptions:
    """Settings of :func:`associate_and_register` (SI units, radians).

    window_s: tracklet window (s), also the batch's target window. gate_probability: gates are this
    quantile of chi-square. max_speed (m/s): a new track's velocity sigma. accel_sigma (m/s^2): the
    tracks' white-acceleration noise. max_missed: scans in a row without a plot that close a track.
    min_track_plots, min_tracklet_plots: shorter tracks are clutter, shorter pieces are left out.
    max_iterations: association passes at most, the last one included (1: a single pass under
    the starting covariance). initial_sigma_attitude, initial_sigma_angle_bias
    (rad), initial_sigma_range_bias (m) and, for the extended errors, initial_sigma_range_gain
    (dimensionless), initial_sigma_time_bias (s), initial_sigma_position (m per east, north, up
    axis): the covariance of the first pass for states without a finite prior in the tables.
    iteration_plots: the passes, and the solves between them, use only every k-th window, k such
    that these hold about this many plots; once the association stops changing there, one last
    pass covers all windows, with the sensors' tracks made again from the plots corrected by the
    estimate. The solves between passes stop at
    :data:`INTERMEDIATE_TOLERANCE` or :data:`INTERMEDIATE_ITERATIONS`; the final solve uses all the
    associated plots and ``batch``'s settings. batch: the solver's options
    (its window_s is replaced by this window_s).
    """

    window_s: float = 20.0
    gate_probability: float = 0.999
    max_speed: float = 400.0
    accel_sigma: float = 20.0
    max_missed: int = 3
    min_track_plots: int = 5
    min_tracklet_plots: int = 3
    max_iterations: int = 6
    initial_sigma_attitude: float = float(np.radians(1.0))
    initial_sigma_angle_bias: float = float(np.radians(5.0))
    initial_sigma_range_bias: float = 500.0
    initial_sigma_range_gain: float = 1.0e-3
    initial_sigma_time_bias: float = 1.0
    initial_sigma_position: float = 100.0
    iteration_plots: int = 20_000
    batch: BatchOptions = field(default_factory=BatchOptions)

    def __post_init__(self):
        checks = {"window_s": self.window_s > 0, "gate_probability": 0 < self.gate_probability < 1,
                  "max_speed": self.max_speed > 0, "accel_sigma": self.accel_sigma > 0,
                  "max_missed": self.max_missed >= 0, "min_track_plots": self.min_track_plots >= 2,
                  "min_tracklet_plots": self.min_tracklet_plots >= 3, "max_iterations": self.max_iterations >= 1,
                  "initial_sigma_attitude": self.initial_sigma_attitude > 0,
                  "initial_sigma_angle_bias": self.initial_sigma_angle_bias > 0,
                  "initial_sigma_range_bias": self.initial_sigma_range_bias > 0,
                  "initial_sigma_range_gain": self.initial_sigma_range_gain > 0,
                  "initial_sigma_time_bias": self.initial_sigma_time_bias > 0,
                  "initial_sigma_position": self.initial_sigma_position > 0,
                  "iteration_plots": self.iteration_plots >= 1}
        bad = [k for k, ok in checks.items() if not ok]
        if bad:
            raise ValueError(f"AssociationOptions: invalid {', '.join(f'{k}={getattr(self, k)!r}' for k in bad)} "
                             "(windows, sigmas, speeds > 0; gate_probability in (0, 1); counts >= their minimum)")


def _placeholder_problem(plots, sensors, navigation, platforms) -> FleetProblem:
    """The checked problem of all plots under one placeholder target (the ``target`` column, if
    any, is ignored)."""
    table = read_table("plots", plots, ("time", "sensor"))
    if table.n_rows == 0:
        raise ValueError("plots: no plots to associate (the table is empty)")
    columns = {k: v for k, v in table.columns.items() if k != "target"}
    columns["target"] = np.full(table.n_rows, "?")
    problem = build_problem(columns, sensors, navigation, platforms, None)
    if problem.n_plots == 0:
        raise ValueError(f"plots: association needs plots of at least two sensors; all {table.n_rows} plots are of "
                         f"sensor {str(table.ids('sensor')[0])!r}")
    return problem


def _initial_covariance(problem: FleetProblem, options: AssociationOptions) -> np.ndarray:
    layout = problem.layout
    default = {"heading_error": options.initial_sigma_attitude, "pitch_error": options.initial_sigma_attitude,
               "roll_error": options.initial_sigma_attitude, "range_bias": options.initial_sigma_range_bias,
               "bearing_bias": options.initial_sigma_angle_bias, "elevation_bias": options.initial_sigma_angle_bias,
               "range_gain": options.initial_sigma_range_gain, "time_bias": options.initial_sigma_time_bias,
               **{f"position_{a}": options.initial_sigma_position for a in ("east", "north", "up")}}
    prior = layout.prior_sigma
    sigma = np.where(np.isfinite(prior), prior, [default[q] for q in layout.quantities])
    return np.diag(sigma**2)


def _labels(problem: FleetProblem, tl, group: np.ndarray, chain: np.ndarray, min_windows: int) -> np.ndarray:
    """(N,) label of each plot, numbered by first input row; '' unless its group holds two or more
    sensors of which one measures range, bearing and elevation (confirmed), and its chain holds
    confirmed groups in ``min_windows`` windows or more. A chain of one window is mostly a target's tracklets
    that missed their group by chance (a 0.1 % gate) and grouped apart: a second target at the same
    place, which the batch solver fits only slowly."""
    n_groups = chain.size
    if group.size == 0:  # no tracklet was formed (windows too short for a piece of track, say)
        return np.full(problem.n_plots, "", dtype=str)
    sensors_in, full_in = np.zeros(n_groups, dtype=np.int64), np.zeros(n_groups, dtype=bool)
    pairs = np.unique(np.stack([group, tl.sensor]), axis=1) if group.size else np.zeros((2, 0), dtype=np.int64)
    np.add.at(sensors_in, pairs[0], 1)
    full_in[pairs[0][(problem.layout.bias_index[pairs[1]] >= 0).all(axis=1)]] = True
    confirmed = (sensors_in >= 2) & full_in
    windows_in = np.zeros(n_groups, dtype=np.int64)
    np.add.at(windows_in, chain[confirmed], 1)  # one group per window in a chain
    confirmed &= windows_in[chain] >= min_windows
    plot_group = np.where(tl.of_plot >= 0, group[np.maximum(tl.of_plot, 0)], -1)
    g = np.maximum(plot_group, 0)
    ok = (plot_group >= 0) & confirmed[g]
    plot_chain = np.where(ok, chain[g], -1)
    out = np.full(problem.n_plots, "", dtype=object)
    order = np.argsort(problem.row, kind="stable")
    seen = plot_chain[order]
    chains, first = np.unique(seen[seen >= 0], return_index=True)
    names = {int(c): f"a{k + 1}" for k, c in enumerate(chains[np.argsort(first)])}
    out[ok] = [names[int(c)] for c in plot_chain[ok]]
    return out.astype(str)


def _tracks(problem: FleetProblem, x: np.ndarray, options: AssociationOptions, assigner: Assigner,
            sel: np.ndarray | None = None) -> tuple[np.ndarray, PlotGeometry]:
    """(N,) the sensors' tracks (:func:`sensor_tracks`) of the plots ``sel`` (bool, default all)
    corrected by the states ``x``, -1 for the other plots; and the geometry of those plots under
    ``x`` (the association pass under the same ``x`` reuses it)."""
    sel = np.ones(problem.n_plots, dtype=bool) if sel is None else sel
    at = np.flatnonzero(sel)
    out = np.full(problem.n_plots, -1, dtype=np.int64)
    geom = plot_geometry(problem, x, at)
    out[at] = sensor_tracks(geom.time, problem.sensor[at], geom, assigner,
                            max_speed=options.max_speed, accel_sigma=options.accel_sigma,
                            gate_probability=options.gate_probability, max_missed=options.max_missed,
                            min_plots=options.min_track_plots)
    return out, geom


def _window_subset(problem: FleetProblem, options: AssociationOptions) -> np.ndarray:
    """(N,) the plots of the windows the passes before the last one use: every k-th window, k such
    that they hold about ``options.iteration_plots`` plots (all windows when the data are fewer)."""
    k = int(np.ceil(problem.n_plots / options.iteration_plots))
    return np.floor(problem.time / options.window_s).astype(np.int64) % k == 0


def _labelled(problem: FleetProblem, labels: np.ndarray) -> FleetProblem:
    """The problem of the labelled plots, their labels as target ids."""
    keep = labels != ""
    if not keep.any():
        raise ValueError("association: no plots could be associated across two sensors; with windows of a few "
                         "seconds a target's pieces of track are too short to match: give longer windows "
                         "(--window-s, AssociationOptions.window_s; 20 s by default), or check the gate and the "
                         "initial sigmas (AssociationOptions)")
    sub = problem.drop_plots(~keep, ())
    ids, index = np.unique(labels[keep], return_inverse=True)
    return replace(sub, target=index.astype(np.int64), target_ids=tuple(str(i) for i in ids))


def _associate(problem: FleetProblem, track: np.ndarray, x: np.ndarray, P: np.ndarray, options: AssociationOptions,
               assigner: Assigner, screen: bool, last: bool,
               geom: PlotGeometry | None = None) -> tuple[np.ndarray, np.ndarray]:
    """One association pass under the estimate ``x`` and covariance ``P``: (labels (N,), tracklet of
    each plot (N,), -1 for none). ``screen``: leave out the pieces no quadratic fits; ``last``: the
    last pass, over all windows, where a target needs two windows (the passes before see every
    k-th window only). ``geom``: the geometry under ``x`` of (at least) the tracks' plots, if known."""
    geom = plot_geometry(problem, x, np.flatnonzero(track >= 0)) if geom is None else geom
    tl = make_tracklets(problem, geom, track, options.window_s, options.min_tracklet_plots,
                        options.gate_probability if screen else None)
    group = group_tracklets(problem, x, tl, P, options.gate_probability, assigner)
    chain = chain_groups(tl, group, assigner)
    return _labels(problem, tl, group, chain, 2 if last else 1), tl.of_plot


def _report(problem: FleetProblem, labels: np.ndarray, of_plot: np.ndarray) -> dict:
    """The unassociated plots: input rows, counts per sensor, clutter and single-sensor counts."""
    out = labels == ""
    rows = np.sort(problem.row[out])
    per_sensor = np.bincount(problem.sensor[out], minlength=len(problem.sensor_ids))
    clutter = int(np.count_nonzero(out & (of_plot < 0)))
    return {"unassociated_rows": rows, "n_clutter": clutter, "n_unconfirmed": int(out.sum()) - clutter,
            "unassociated_by_sensor": {s: int(n) for s, n in zip(problem.sensor_ids, per_sensor)}}


def associate_and_register(plots, sensors, navigation, platforms=None, references=None,
                           options: AssociationOptions | None = None, *, progress: bool = False) -> AssociationResult:
    """Associate plots that carry no target ids across sensors and register the fleet with them.

    ``plots``, ``sensors``, ``navigation``, ``platforms``: the long-form tables of
    :mod:`registration.fleet.data.tables` (SI units, radians); ``plots`` needs ``time``, ``sensor`` and
    the measured channels, and a ``target`` column, if present, is ignored. ``references`` is not
    supported yet (their targets have no link to the plots): passing one is an error. ValueError
    for an empty plots table, plots of one sensor only, or any error of
    :func:`~registration.fleet.data.problem.build_problem` (unknown sensor, bad values; the message names
    the table and row). Returns an :class:`AssociationResult`; the method is in the module docstring.
    ``progress``: a bar over the association passes, and one over each solve's iterations, on
    standard error, shown only on a terminal and after about a second
    (:func:`registration.fleet.batch.solver.progress_bar`).
    """
    t0 = time.perf_counter()
    if references is not None:
        raise ValueError("references: not supported by associate_and_register (plots without target ids cannot be "
                         "tied to a reference target); register without them or give the plots target ids")
    options = options or AssociationOptions()
    batch_options = replace(options.batch, window_s=options.window_s)
    between = replace(batch_options, tolerance=max(batch_options.tolerance, INTERMEDIATE_TOLERANCE),
                      max_iterations=min(batch_options.max_iterations, INTERMEDIATE_ITERATIONS))
    problem = _placeholder_problem(plots, sensors, navigation, platforms)
    assigner = Assigner()
    x, P = np.zeros(problem.layout.n), _initial_covariance(problem, options)
    subset = _window_subset(problem, options)
    with progress_bar(progress, "association passes", total=options.max_iterations, unit="pass") as bar:
        progress_status(bar, "sensor tracks")
        track, geom = _tracks(problem, x, options, assigner, subset)
        labels, previous, changes, t_solve, converged, passes = None, None, [], 0.0, False, 0
        for passes in range(1, options.max_iterations):  # the passes before the last, on the windows of ``subset``
            progress_status(bar, f"pass {passes}: associating")
            labels, of_plot = _associate(problem, track, x, P, options, assigner, passes > 1, False, geom)
            if previous is not None:
                changes.append(int(np.count_nonzero(labels != previous)))
                if changes[-1] == 0:
                    converged = True
                    break
            previous = labels
            progress_status(bar, f"pass {passes}: registering")
            t1 = time.perf_counter()
            step = solve_batch(_labelled(problem, labels), between, x0=x, progress=progress)  # warm start
            t_solve += time.perf_counter() - t1
            x, P, geom = step.estimate, step.covariance, None
            bar.update()
        # the last pass: all windows, the sensors' tracks again from the plots corrected by the estimate
        # (an angle bias in a rolling deck sways them)
        progress_status(bar, "last pass: all windows")
        if passes or not subset.all():
            track, geom = _tracks(problem, x, options, assigner)
        labels, of_plot = _associate(problem, track, x, P, options, assigner, passes > 0, True, geom)
        final = _labelled(problem, labels)
        progress_status(bar, "last pass: registering")
        t1 = time.perf_counter()
        result = solve_batch(final, batch_options, x0=x, progress=progress)
        t_solve += time.perf_counter() - t1
        bar.update()
    n_rows = problem.n_input_plots
    row_labels = np.full(n_rows, "", dtype=object)
    row_labels[problem.row] = labels
    return AssociationResult(labels=row_labels.astype(str), batch=result, problem=final,
                             iterations=passes + 1,
                             converged=converged, changes=changes, seconds_total=time.perf_counter() - t0,
                             seconds_assignment=assigner.seconds, seconds_registration=t_solve,
                             **_report(problem, labels, of_plot))
