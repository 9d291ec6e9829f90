"""Association of plots across sensors, jointly with the registration: :func:`associate_and_register`.

Which plot of one sensor and which of another are the same target is unknown while the biases are
unknown, and the biases cannot be estimated until that is known. Both are found together, in
three stages (docs/background/association.md):

1. **Anchors**: targets fixed without joining tracks to them: the target ids the plots carry
   (some or all rows of a ``target`` column), the reference targets (ADS-B, AIS), and targets
   that two or more position-fixing sensors (range, bearing and elevation) confirm by the
   tracklet grouping of :mod:`.confirm`, iterated with the registration.
2. **Joins**: the other plots, grouped per sensor into tracks (the ``track`` column, split on gaps
   and jumps, or the per-sensor tracker), are joined to the anchors by a test of the whole track in
   the sensor's own channels under the estimate and its covariance, most certain first, each join
   teaching the next; joins whose residuals fail under the registration are dropped again
   (:mod:`.joins`, :mod:`.attach`). A track of a sensor that cannot fix a position alone (a 2-D
   radar, a passive sensor) can only join an anchor.
3. **Final registration** from the accepted plots only, after single plots whose residuals fail
   the outlier gate are left out: maximum likelihood on what was accepted.

The sensors' extended errors (range gain, time bias, position) are handled throughout: a plot of
a sensor with a time bias is placed at the time it was seen, from its platform's navigation then.
"""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np

from registration.core.progress import progress_bar, progress_status
from registration.fleet.association.causes import (
    anchors_of,
    no_anchor_error,
    nothing_associated,
    unanchored_notes,
)
from registration.fleet.association.grouping.confirm import confirm_targets
from registration.fleet.association.grouping.geometry import Assigner
from registration.fleet.association.grouping.units import make_units
from registration.fleet.association.joining.checks import JoinState, outlier_stage
from registration.fleet.association.joining.curves import anchor_curves
from registration.fleet.association.joining.joins import DEFER_SHARE, join_units
from registration.fleet.association.joining.singles import join_single_plots
from registration.fleet.association.options import AssociationOptions
from registration.fleet.association.problems import (
    all_plots_problem,
    anchor_references,
    initial_covariance,
    plot_ids,
)
from registration.fleet.association.references import name_by_references
from registration.fleet.association.report import plot_report, track_notes
from registration.fleet.association.result import AssociationResult
from registration.fleet.association.solves import Registrar
from registration.fleet.batch.estimate import solve_batch
from registration.fleet.data.known_targets import References
from registration.fleet.data.layout import with_height_offset
from registration.fleet.data.problem import FleetProblem

__all__ = ["AssociationOptions", "AssociationResult", "associate_and_register"]


def _check_windows(problem, options: AssociationOptions) -> None:
    """ValueError naming the window option when no sensor puts ``min_tracklet_plots`` plots in one
    window (its median interval between scans): neither a tracklet nor a target window forms."""
    per_window = []
    for s in np.unique(problem.sensor):
        t = np.unique(problem.time[problem.sensor == s])
        if t.size > 1:
            per_window.append(options.window_s / float(np.median(np.diff(t))))
    if per_window and max(per_window) < options.min_tracklet_plots:
        raise ValueError(
            f"association: windows of {options.window_s:g} s hold at most {max(per_window):.2g} plots of "
            f"any sensor, too few to match a target's pieces of track: give longer windows (--window-s, "
            f"AssociationOptions.window_s; 20 s by default)"
        )


def _checked_inputs(plots, sensors, navigation, platforms, references, targets, options):
    """(problem of all plots, ids given (N,), track ids (N,), references, anchors); the cause named
    when nothing can anchor a target (one sensor, no references, no ids), before the windows'."""
    ids = plot_ids(plots)
    problem = all_plots_problem(plots, sensors, navigation, platforms, targets)
    given, track_id = ids.target[problem.row], ids.track[problem.row]
    refs = anchor_references(references)
    problem = replace(problem, layout=with_height_offset(problem.layout, refs.offset_prior))
    anchors = anchors_of(problem, given, ids.has_target, refs)
    error = no_anchor_error(anchors)
    if error is not None:
        raise error
    _check_windows(problem, options)
    return problem, given, track_id, refs, anchors


def single_plots_stage(
    reg: Registrar,
    problem: FleetProblem,
    refs: References,
    labels: np.ndarray,
    free: np.ndarray,
    options: AssociationOptions,
) -> tuple[np.ndarray, np.ndarray]:
    """The plots ``free`` (N,) in no track joined one by one to the anchors' curves: (the labels
    with them, the target of each single plot ('' none)); registered again when they are more than
    ``DEFER_SHARE`` of the labelled plots, else checked by the final solve only."""
    curves = anchor_curves(
        reg.problem_solved,
        reg.x,
        refs,
        reg.between,
        gap_s=options.reference_gap_s,
        accel_sigma=options.reference_accel_sigma,
        fit=reg.labelled_fit() if reg.thinned else reg.cold_fit(reg.problem_solved),
        surface=problem.surface,
    )
    single = join_single_plots(reg, curves, labels, free, options)
    if (single != "").any():
        labels = np.where(single != "", single, labels).astype(str)
        if (single != "").sum() > DEFER_SHARE * (labels != "").sum():
            reg.solve(labels)
    return labels, single


def associate_and_register(
    plots,
    sensors,
    navigation,
    platforms=None,
    references=None,
    options: AssociationOptions | None = None,
    *,
    progress: bool = False,
    joins: dict | None = None,
    targets=None,
    final_registration: bool = True,
) -> AssociationResult:
    """Associate the plots without target ids with targets, and register the fleet with them.

    ``plots``, ``sensors``, ``navigation``, ``platforms``, ``references``: the long-form tables of
    :mod:`registration.fleet.data.tables` (SI units, radians). ``plots`` needs ``time``, ``sensor``
    and the measured channels; optional ``target`` (the ids some or all plots carry: a row with one
    keeps it, an empty cell, NaN or None is no id) and ``track`` (a sensor-local track id: plots
    with the same sensor and track are one object; ids of different sensors are unrelated). A
    reference target's id may equal a plot id (the same target) or be the id of a target no plot
    names (its plots are associated to it). ``joins``: for tests, joins to start from, {(sensor id,
    track id): target}; a wrong one is dropped by the checks. ``targets``: the optional targets table
    (targets on a surface of known height, by the ids the association gives: the plots' and the
    references'). ValueError for an empty plots table, any error of
    :func:`~registration.fleet.data.problem.build_problem` (unknown sensor, bad values; the message
    names the table and row), and when nothing can be associated (:mod:`.causes`). ``progress``: bars on
    standard error on a terminal. ``final_registration`` False: ``batch`` is a solve between passes
    (a subsample, looser stops), not the full registration, for a caller that registers the labels
    itself (the association by partitions); the labels are the same. The method: module docstring.
    """
    t0 = time.perf_counter()
    options = options or AssociationOptions()
    problem, given, track_id, refs, anchors = _checked_inputs(
        plots, sensors, navigation, platforms, references, targets, options
    )
    reg = Registrar(problem, refs, initial_covariance(problem, options), options, progress, solver=_solve)
    assigner = Assigner()
    total = options.max_iterations + options.max_join_passes
    with progress_bar(progress, "association passes", total=total, unit="pass") as bar:
        if (given != "").any():
            progress_status(bar, "registering the plots with ids")
            reg.solve(given)
        conf = confirm_targets(problem, given, track_id, reg.x, reg.P, options, assigner, reg.register, bar)
        base = name_by_references(reg, conf.labels, given != "", options)
        progress_status(bar, "registering the anchors")
        reg.solve(base)
        units = make_units(problem, track_id, base == "", reg.x, options, assigner)
        state = _start_joins(problem, units, joins)
        state, units, join_passes, joined_ok = join_units(reg, units, base, options, bar, state)
        labels = np.where(base != "", base, state.label).astype(str)
        progress_status(bar, "single plots")
        labels, single = single_plots_stage(
            reg, problem, refs, labels, (labels == "") & ~state.outlier, options
        )
        outliers = outlier_stage(reg, labels, given, options) | state.outlier
        labels[outliers] = ""
        progress_status(bar, "final registration")
        result = reg.solve(labels, final=final_registration)
        if result is None or result.chi_square.dof < 1:  # nothing, or more trajectory terms than values
            raise nothing_associated(anchors, options.window_s)
    report = plot_report(
        problem, labels, given != "", outliers, units, state, conf.track, result, single != ""
    )
    notes = (*units.notes, *state.notes, *track_notes(problem, track_id, given != "", labels))
    notes += tuple(unanchored_notes(anchors, report["by_sensor"]))
    assert reg.problem_solved is not None  # the final solve registered the labelled plots
    return AssociationResult(
        batch=result,
        problem=reg.problem_solved,
        iterations=conf.passes,
        converged=conf.converged and joined_ok,
        changes=conf.changes,
        seconds_total=time.perf_counter() - t0,
        seconds_assignment=assigner.seconds,
        seconds_registration=reg.seconds,
        notes=notes,
        join_passes=join_passes,
        **report,
    )


def _solve(problem, options=None, x0=None, **kwargs):
    """:func:`solve_batch`, looked up here at each call (a test may watch this module's solve_batch)."""
    return solve_batch(problem, options, x0, **kwargs)


def _start_joins(problem, units, joins: dict | None) -> JoinState | None:
    """The :class:`JoinState` of the joins {(sensor id, track id or unit name): target} given (tests)."""
    if not joins:
        return None
    state = JoinState.empty(units.n, problem.n_plots)
    sensor_ids = np.array(problem.sensor_ids)
    for (sid, track), target in joins.items():
        name = track if str(track).startswith(("track ", "tracker ")) else f"track {track}"
        hit = np.flatnonzero((sensor_ids[units.sensor] == sid) & (units.name == name))
        for u in hit:
            state.join(int(u), str(target), np.flatnonzero(units.of_plot == u), np.nan)
    return state
