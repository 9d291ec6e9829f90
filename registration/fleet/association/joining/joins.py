"""Joining tracks (units, :mod:`..grouping.units`) to the anchor targets (:mod:`.curves`), robustly
(:func:`join_units`).

A pass tests every track not yet joined against every anchor whose span it overlaps
(:mod:`.attach`) and takes joins one by one, most certain first (:func:`choose_joins`):

* a join passes its gate, and its chi-square tail probability is at least ``ambiguity_ratio``
  times that of the track's next candidate and of the same sensor's other tracks that overlap it
  in time for that target (a sensor reports a target once a scan, so those cannot both be it);
* each join taken updates the estimate and its covariance linearly (Kalman), so the tests that
  follow are under what it taught (a passive sensor's bias, say); a sensor with no registered plot
  yet takes one join per round, the most certain, before its other tracks are judged.

The joins are registered (:class:`~registration.fleet.association.solves.Registrar`), and each join's
residuals under the new estimate are tested
(:func:`~registration.fleet.association.joining.checks.failing_joins`): a join whose squared normalised
residuals exceed the chi-square ``1 - drop_probability`` quantile is dropped, the worst of each sensor
first (one wrong join can make good ones fail), the registration made again, until none fails. A dropped
pair is not taken again. Passes repeat until nothing changes. Then the final stage leaves out single
associated plots whose residuals exceed the ``1 - outlier_probability`` quantile
(:func:`~registration.fleet.association.joining.checks.outlier_stage`) and the last registration uses the
accepted plots only.
"""

from __future__ import annotations

import itertools

import numpy as np

from registration.core.distributions import chi2_logsf, chi2_ppf
from registration.core.progress import progress_status
from registration.fleet.association.grouping.confirm import fixing_sensors, new_names
from registration.fleet.association.grouping.units import Units, split_units, unit_conflicts, unit_plots
from registration.fleet.association.joining.attach import (
    Pairs,
    candidate_plots,
    evaluate,
    kalman_update,
    pair_statistics,
    pair_tests,
    verify_plots,
)
from registration.fleet.association.joining.checks import (
    MAX_OUTLIER_SHARE,
    JoinState,
    drop_failing,
    registered_labels,
)
from registration.fleet.association.joining.passcurves import pass_curves
from registration.fleet.association.options import AssociationOptions
from registration.fleet.association.solves import Registrar

__all__ = ["DEFER_SHARE", "choose_joins", "join_units"]

#: Rounds of :func:`choose_joins` at most (each takes at least one join).
MAX_ROUNDS = 50
#: A pair whose first test exceeds this many times its gate is not tested again in that pass (a later
#: join tightens the covariance; it cannot bring such a pair inside its gate).
FAR_OFF = 10.0
#: A pass whose joins add fewer plots than this share of the labelled ones (and none of a sensor not
#: yet registered) is registered with the next joins, or at the end of the joins.
DEFER_SHARE = 0.02
#: Times the units that match no target are split in halves, at most (pieces stay two windows long).
MAX_SPLIT_DEPTH = 6


def _margins(pairs: Pairs, cand: np.ndarray, lp: np.ndarray, conflicts: np.ndarray, log_ratio: float):
    """(positions in ``cand`` of each unit's best candidate, their margin): the log tail-probability
    ratio to the unit's next candidate and to the candidates for the same target of the units that
    conflict with it (:func:`~registration.fleet.association.grouping.units.unit_conflicts`) and have that
    target among their own best (within ``log_ratio`` of their best)."""
    unit, target = pairs.unit[cand], pairs.target[cand]
    best = np.flatnonzero(np.r_[True, unit[1:] != unit[:-1]])
    nxt = best + 1
    has_next = (nxt < cand.size) & (unit[np.minimum(nxt, cand.size - 1)] == unit[best])
    margin = lp[best] - np.where(has_next, lp[np.minimum(nxt, cand.size - 1)], -np.inf)
    own_best = np.repeat(lp[best], np.diff(np.r_[best, cand.size]))  # each candidate's unit's best
    contender = lp >= own_best - log_ratio
    for i, b in enumerate(best):
        rivals = (target == target[b]) & (unit != unit[b]) & contender
        rivals[rivals] = conflicts[unit[b], unit[rivals]]
        if rivals.any():
            margin[i] = min(margin[i], lp[b] - lp[rivals].max())
    return best, margin


def _outlier_limits(probability: float) -> np.ndarray:
    """(4,) the deletion statistic's limit per number of channels (0: none)."""
    return np.r_[np.inf, chi2_ppf(1.0 - probability, [1, 2, 3])]


def choose_joins(
    pairs: Pairs,
    names: tuple,
    P: np.ndarray,
    state: JoinState,
    units: Units,
    conflicts: np.ndarray,
    fresh: np.ndarray,
    options: AssociationOptions,
):
    """The joins of one pass (module docstring): a list of (unit, target index, d^2/dof), and the
    states' correction and covariance after them (n,), (n, n). ``fresh`` (S,): the sensors with no
    registered plot yet."""
    if pairs.size == 0:
        return [], np.zeros(P.shape[0]), P
    target_names = np.array(names, dtype=object)
    unit, pname = pairs.unit, target_names[pairs.target]
    state.tested[unit] = True
    allowed = state.target[unit] == ""
    if state.tabu:  # the pairs dropped before (few)
        allowed &= ~np.array([(int(u), n) in state.tabu for u, n in zip(unit, pname)])
    joined = np.flatnonzero(state.target != "")
    if joined.size:
        allowed &= ~(conflicts[unit][:, joined] & (state.target[joined][None, :] == pname[:, None])).any(
            axis=1
        )
    active = np.flatnonzero(allowed)
    dx, Pk, fresh, out = np.zeros(P.shape[0]), P.copy(), fresh.copy(), []
    log_ratio, limits = float(np.log(options.ambiguity_ratio)), _outlier_limits(options.outlier_probability)
    max_trim = int(np.floor(MAX_OUTLIER_SHARE * pairs.plots.shape[1]))
    trimmed = pairs.plots >= 0
    for round_ in range(MAX_ROUNDS):
        if active.size == 0:
            break
        if round_ == 0:  # the outlying plots of each pair, found once; the later rounds test the rest
            d2, _, keep, dof = evaluate(pairs.take(active), dx, Pk, outlier_limit=limits, max_trim=max_trim)
            trimmed[active] = keep
            hopeless = d2 > FAR_OFF * chi2_ppf(options.gate_probability, np.maximum(dof, 1))
            np.minimum.at(state.best, unit[active[hopeless]], d2[hopeless] / np.maximum(dof[hopeless], 1))
            # d2 is that of the plots kept, under this round's dx and Pk: the round's test
            active, d2, keep, dof = (v[~hopeless] for v in (active, d2, keep, dof))
            if active.size == 0:
                break
        else:
            d2, _, keep, dof = evaluate(pairs.take(active), dx, Pk, keep=trimmed[active])
        np.minimum.at(state.best, unit[active], d2 / np.maximum(dof, 1))
        passed = (dof > 0) & (d2 < chi2_ppf(options.gate_probability, np.maximum(dof, 1)))
        state.gated[unit[active[passed]]] = True
        at = np.flatnonzero(passed)
        cand, lp = active[at], chi2_logsf(d2[at], dof[at])
        if cand.size == 0:
            break
        order = np.lexsort((-lp, unit[cand]))
        cand, lp, at = cand[order], lp[order], at[order]
        best, margin = _margins(pairs, cand, lp, conflicts, log_ratio)
        ok = margin >= log_ratio
        if not ok.any():
            break
        rank = best[ok][np.lexsort((-lp[best[ok]], -margin[ok]))]
        claimed = np.zeros((conflicts.shape[0], len(names)), dtype=bool)  # (unit, target): a rival took it
        sensors_now: set[int] = set()
        for b in rank:
            c = int(cand[b])
            u, j = int(unit[c]), int(pairs.target[c])
            s = int(units.sensor[u])
            if (fresh[s] and s in sensors_now) or claimed[u, j]:
                continue
            dx, Pk = kalman_update(pairs, c, dx, Pk, keep[at[b]])
            state.target[u] = str(target_names[j])  # taken; labelled once its plots are verified
            out.append((u, j, float(d2[at[b]] / dof[at[b]])))
            claimed[:, j] |= conflicts[:, u]
            sensors_now.add(s)
        fresh[list(sensors_now)] = False
        remove = (state.target[unit[active]] != "") | claimed[unit[active], pairs.target[active]]
        active = active[~remove]
    return out, dx, Pk


def _label_verified(
    reg: Registrar,
    curves,
    state: JoinState,
    units: Units,
    taken: list,
    covered: dict,
    dx: np.ndarray,
    Pk: np.ndarray,
    options: AssociationOptions,
) -> list[int]:
    """Label the plots of the joins ``taken`` that pass the per-plot gate under the states after them
    (:func:`~registration.fleet.association.joining.attach.verify_plots`); a join with more than
    MAX_OUTLIER_SHARE of its plots failing is not taken (a track that swapped targets): it is marked
    failed, and split later. Returns the units labelled."""
    if not taken:
        return []
    problem = reg.problem
    plots = []
    for u, j, _ in taken:  # a target's covered plots are in the order of their units
        lo, hi = np.searchsorted(units.of_plot[covered[j]], [u, u + 1])
        plots.append(covered[j][lo:hi])
    # a position-fixing sensor's plots fix the target themselves: its whole track is the target's,
    # the part outside the target's span extends it (those plots are checked once registered)
    fixing = fixing_sensors(problem)
    order, bound = unit_plots(units.of_plot, units.n)
    extra = [
        np.setdiff1d(order[bound[u] : bound[u + 1]], p) if fixing[units.sensor[u]] else np.zeros(0, dtype=int)
        for (u, _, _), p in zip(taken, plots)
    ]
    u_rep = np.concatenate([np.full(p.size, u) for (u, _, _), p in zip(taken, plots)])
    j_rep = np.concatenate([np.full(p.size, j) for (_, j, _), p in zip(taken, plots)])
    ok = verify_plots(
        problem, reg.x, curves, u_rep, j_rep, np.concatenate(plots), dx, Pk, options.outlier_probability
    )
    labelled, start = [], 0
    for (u, j, test), p, more in zip(taken, plots, extra):
        good = ok[start : start + p.size]
        start += p.size
        if good.sum() < (1.0 - MAX_OUTLIER_SHARE) * p.size:
            state.tabu.add((int(u), str(state.target[u])))
            state.target[u], state.failed[u] = "", True
            continue
        state.join(u, str(state.target[u]), np.concatenate([p[good], more]), test)
        state.outlier[p[~good]] = True
        labelled.append(int(u))
    return labelled


def _split(units: Units, state: JoinState, problem, options: AssociationOptions):
    """Split in halves (:func:`~registration.fleet.association.grouping.units.split_units`) the units not
    joined that failed, matched no target or stayed ambiguous, and have at least twice
    ``min_join_plots`` plots over at least two windows: (units, number split). The halves of a
    track that holds two objects can each join theirs (the report notes a given track whose pieces
    joined different targets)."""
    count = np.bincount(units.of_plot[units.of_plot >= 0], minlength=units.n)
    bad = (state.target == "") & (state.failed | state.tested)
    which = np.flatnonzero(
        bad & (count >= 2 * options.min_join_plots) & (units.t1 - units.t0 >= 2 * options.window_s)
    )
    if which.size == 0:
        return units, 0
    units, _, _ = split_units(units, problem, which)
    state.extend(units.n)
    return units, int(which.size)


def _provisional(units: Units, state: JoinState, problem, labels: np.ndarray, options: AssociationOptions):
    """(N,) provisional targets: each track of a position-fixing sensor that joined no anchor, under
    a new name; the units that hold them (they are then no longer joiners)."""
    fixing = fixing_sensors(problem)
    count = np.bincount(units.of_plot[units.of_plot >= 0], minlength=units.n)
    which = np.flatnonzero(
        (state.target == "") & fixing[units.sensor] & (count >= 2 * options.min_join_plots)
    )
    name = np.full(units.n + 1, "", dtype=object)  # the last: no unit
    name[which] = new_names(which.size, set(labels) | set(state.target))
    return name[units.of_plot], which


def _prescreen(
    reg: Registrar,
    curves,
    unit: np.ndarray,
    target: np.ndarray,
    plots: np.ndarray,
    options: AssociationOptions,
) -> np.ndarray:
    """(C,) bool: the pairs worth the full test, by a test of three of their plots (first, middle,
    last; one may be an outlier) under the latest estimate: within FAR_OFF times its gate."""
    if unit.size == 0:
        return np.zeros(0, dtype=bool)
    n = (plots >= 0).sum(axis=1)
    rows = np.arange(unit.size)
    three = np.stack([plots[:, 0], plots[rows, (n - 1) // 2], plots[rows, n - 1]], axis=1)
    d2, dof = pair_statistics(
        reg.problem,
        reg.x,
        curves,
        unit,
        target,
        three,
        np.zeros(reg.x.size),
        reg.P,
        outlier_limit=_outlier_limits(options.outlier_probability),
        max_trim=1,
    )
    return (dof > 0) & (d2 < FAR_OFF * chi2_ppf(options.gate_probability, np.maximum(dof, 1)))


def _pass_joins(
    reg: Registrar,
    units: Units,
    state: JoinState,
    labels: np.ndarray,
    prov: np.ndarray,
    sources: np.ndarray | None,
    conflicts: np.ndarray,
    options: AssociationOptions,
    cache: dict,
) -> tuple[list[int], np.ndarray]:
    """The joins of one pass: the free units (not joined, not a provisional target's ``sources``)
    tested against the anchors' curves of the registered ``labels`` and the provisional targets
    ``prov`` (a position-fixing sensor's track never joins a provisional target), prescreened, then
    chosen and labelled in ``state``. Returns (the units joined, (S,) True for the sensors with no
    registered plot yet)."""
    problem = reg.problem
    fixing = fixing_sensors(problem)
    curves = pass_curves(reg, labels, prov, options, cache)
    free = np.flatnonzero(
        (state.target == "") & ~np.isin(np.arange(units.n), sources if sources is not None else [])
    )
    u, t, plots, covered = candidate_plots(
        problem, reg.x, units.of_plot, free, curves, k=options.test_plots, min_plots=options.min_join_plots
    )
    provisional = np.isin(np.array(curves.names, dtype=object)[t], np.unique(prov[prov != ""]))
    keep = ~(provisional & fixing[units.sensor[u]]) if u.size else np.zeros(0, dtype=bool)
    keep[keep] = _prescreen(reg, curves, u[keep], t[keep], plots[keep], options)
    pairs = pair_tests(problem, reg.x, curves, u[keep], t[keep], plots[keep])
    fresh = np.bincount(problem.sensor[labels != ""], minlength=len(problem.sensor_ids)) == 0
    taken, dx, Pk = choose_joins(pairs, curves.names, reg.P, state, units, conflicts, fresh, options)
    taken = _label_verified(reg, curves, state, units, taken, covered, dx, Pk, options)
    return taken, fresh


def join_units(
    reg: Registrar,
    units: Units,
    base: np.ndarray,
    options: AssociationOptions,
    bar,
    state: JoinState | None = None,
) -> tuple[JoinState, Units, int, bool]:
    """Join the units to the anchors (module docstring) from the registration ``reg`` of the
    ``base`` labels (N,; ids given and confirmed targets, '' none). ``state``: joins to start from
    (default none; a wrong one is dropped by the checks). Units that match no target as a whole, or
    whose join failed, are split in halves (up to MAX_SPLIT_DEPTH times) and their halves tested.
    Once nothing changes, the tracks of position-fixing sensors that joined no anchor become
    provisional targets that the other sensors' tracks may join (a target one 3-D radar sees with
    2-D radars or passive sensors); those no track joined are dropped again. The passes that change
    the joins are counted from the start, again after each split and after the provisional targets:
    ``max_join_passes`` of them at most each time. Returns (state, units (with the splits), passes,
    converged: a pass changed nothing before the limit, with no split or provisional target left)."""
    problem = reg.problem
    state = state or JoinState.empty(units.n, problem.n_plots)
    conflicts = unit_conflicts(units, problem)
    passes, converged, splits, prov, sources = 0, False, 0, np.full(problem.n_plots, "", dtype=object), None
    cache: dict = {}
    deferred = False
    if state.label.any():
        reg.solve(registered_labels(base, state, prov))
        drop_failing(reg, state, units, base, prov, options)
    changing = 0  # passes that changed the joins since the start, the last split or the provisional targets
    for passes in itertools.count(1):
        progress_status(bar, f"join pass {passes}: testing tracks against targets")
        labels = registered_labels(base, state, prov)
        taken, fresh = _pass_joins(reg, units, state, labels, prov, sources, conflicts, options, cache)
        dropped = 0
        if taken:
            added = np.isin(units.of_plot, taken) & (state.label != "")
            if fresh[units.sensor[taken]].any() or added.sum() > DEFER_SHARE * (labels != "").sum():
                progress_status(bar, f"join pass {passes}: registering")
                reg.solve(registered_labels(base, state, prov))
                dropped = drop_failing(reg, state, units, base, prov, options)
                deferred = False
            else:  # a few plots more: registered and checked with the next joins, or at the end
                deferred = True
        bar.update()
        if taken or dropped:
            changing += 1
            if changing < options.max_join_passes:
                continue
            break  # still changing at the limit: not converged
        changing = 0
        if splits < MAX_SPLIT_DEPTH:
            units, n_split = _split(units, state, problem, options)
            if n_split:
                splits += 1
                conflicts = unit_conflicts(units, problem, conflicts)
                continue
        if sources is None:
            prov, sources = _provisional(units, state, problem, labels, options)
            if sources.size:
                continue
        converged = True
        break
    order, start = unit_plots(units.of_plot, units.n)
    joined = set(state.target)
    for u in sources if sources is not None else []:  # provisional targets some track joined
        plots = order[start[u] : start[u + 1]]
        if prov[plots[0]] in joined:
            state.join(int(u), str(prov[plots[0]]), plots, np.nan)
    if deferred:
        reg.solve(registered_labels(base, state, prov))
        drop_failing(reg, state, units, base, prov, options)
    return state, units, passes, converged
