"""Single plots joined to targets (:func:`join_single_plots`): the last step of the joins, for the
plots that are in no track that joined (a primary radar's plots of an aircraft whose other plots
carry its Mode S address, scattered too thinly to form tracks; the leftovers of tracks that were
split).

By then the sensor's errors are known from its joined tracks, so one plot is tested alone against
every anchor whose span holds it (:func:`~registration.fleet.association.joining.attach.pair_statistics`
with one plot), under the estimate and its covariance. It is joined when it passes its gate and its
chi-square tail probability is at least ``ambiguity_ratio`` times that of any other target, and
when its sensor has no other plot of that target in the same scan. Sensors without any registered
plot yet are left out (their errors are still unknown), except a radar's channel when the radar
has registered plots: its errors start from the radar's (association/channels.py).

Most candidates are clutter, or plots of another target, kilometres off: on the 10-radar benchmark
1 069 of 221 829 pass their gate. A lower bound of the statistic
(:func:`~registration.fleet.association.joining.attach.lower_bounds`, from the residual and a bound of
the trace of its covariance) settles those beyond the gate for certain before the full test; the
plots joined are the same (there the statistic was at least 3.4 and typically 17 times the bound).
"""

from __future__ import annotations

import numpy as np

from registration.core.distributions import chi2_logsf, chi2_ppf
from registration.fleet.association.joining.attach import lower_bounds, pair_statistics
from registration.fleet.association.joining.curves import Curves
from registration.fleet.association.options import AssociationOptions
from registration.fleet.association.solves import Registrar

__all__ = ["join_single_plots"]


def _candidates(reg: Registrar, curves: Curves, free: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(plot (C,), target (C,)) every free plot with every anchor whose span holds it."""
    problem = reg.problem
    at = np.flatnonzero(free)
    t_seen = problem.seen(reg.x, at)[0]
    plots, targets = [], []
    for j in range(curves.n_targets):
        hit = at[curves.covered(j, problem.time[at], t_seen)]
        plots.append(hit)
        targets.append(np.full(hit.size, j))
    return np.concatenate(plots), np.concatenate(targets)


def _same_scan(problem, labels: np.ndarray, plot: np.ndarray, name: np.ndarray) -> np.ndarray:
    """(C,) bool: the plot's sensor already has a plot of that target at that time."""
    have = (labels != "") & np.isin(problem.time, problem.time[plot])
    taken = set(zip(problem.sensor[have].tolist(), problem.time[have].tolist(), labels[have].tolist()))
    return np.array(
        [
            (s, t, n) in taken
            for s, t, n in zip(problem.sensor[plot].tolist(), problem.time[plot].tolist(), name.tolist())
        ],
        dtype=bool,
    )


def join_single_plots(
    reg: Registrar, curves: Curves, labels: np.ndarray, free: np.ndarray, options: AssociationOptions
) -> np.ndarray:
    """(N,) the target each free plot (``free`` (N,) bool) is joined to, '' none (module docstring);
    ``labels`` (N,) the plots' labels so far."""
    problem = reg.problem
    out = np.full(problem.n_plots, "", dtype=object)
    registered = np.bincount(problem.sensor[labels != ""], minlength=len(problem.sensor_ids)) > 0
    parent = problem.layout.channel_of
    if parent is not None:  # a channel's states start from its radar's (association/channels.py)
        registered |= (parent >= 0) & registered[np.maximum(parent, 0)]
    free = free & registered[problem.sensor]
    if not free.any() or curves.n_targets == 0:
        return out
    plot, target = _candidates(reg, curves, free)
    if plot.size == 0:
        return out
    # most candidates are clutter kilometres from the target: a bound of d^2 settles them first
    bound, dof = lower_bounds(problem, reg.x, curves, target, plot[:, None], reg.P)
    gate = chi2_ppf(options.gate_probability, np.maximum(dof, 1))
    near = np.flatnonzero(~(bound >= gate))
    d2 = np.full(plot.size, np.inf)
    d2[near], dof[near] = pair_statistics(
        problem, reg.x, curves, plot[near], target[near], plot[near][:, None], np.zeros(reg.x.size), reg.P
    )
    ok = (dof > 0) & (d2 < gate)
    lp = np.where(ok, chi2_logsf(d2, np.maximum(dof, 1)), -np.inf)
    order = np.lexsort((-lp, plot))
    plot, target, lp = plot[order], target[order], lp[order]
    first = np.flatnonzero(np.r_[True, plot[1:] != plot[:-1]])
    nxt = np.minimum(first + 1, plot.size - 1)
    second = np.where((first + 1 < plot.size) & (plot[nxt] == plot[first]), lp[nxt], -np.inf)
    with np.errstate(invalid="ignore"):
        take = np.isfinite(lp[first]) & (lp[first] - second >= np.log(options.ambiguity_ratio))
    best = first[take]
    names = np.array(curves.names, dtype=object)[target[best]]
    clash = _same_scan(problem, labels, plot[best], names)
    # two free plots of one scan for one target: neither is taken (which one is the target is not known)
    key = np.stack(
        [problem.sensor[plot[best]], np.round(problem.time[plot[best]] * 1e6).astype(np.int64), target[best]]
    )
    _, inverse, counts = np.unique(key, axis=1, return_inverse=True, return_counts=True)
    clash |= counts[inverse.reshape(-1)] > 1
    out[plot[best][~clash]] = names[~clash]
    return out
