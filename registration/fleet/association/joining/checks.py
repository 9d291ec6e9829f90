"""The checks of the joins under the registration (:func:`drop_failing`, :func:`failing_joins`) and
the final outlier stage (:func:`outlier_stage`); the labels a registration takes
(:func:`registered_labels`). See :mod:`registration.fleet.association.joining.joins` for the joins."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration.core.distributions import chi2_ppf
from registration.fleet.association.grouping.units import Units
from registration.fleet.association.options import AssociationOptions
from registration.fleet.association.solves import Registrar

__all__ = [
    "MAX_DROP_ROUNDS",
    "MAX_OUTLIER_SHARE",
    "JoinState",
    "drop_failing",
    "failing_joins",
    "outlier_stage",
    "registered_labels",
]

#: Registrations after drops within one pass, at most (then every failing join is dropped at once).
MAX_DROP_ROUNDS = 4
#: A join fails when more than this share of its plots are outliers under the registration.
MAX_OUTLIER_SHARE = 0.2


@dataclass
class JoinState:
    """Per unit (U,): ``target`` joined ('' none), ``test`` its d^2/dof when taken, ``best`` the best
    d^2/dof of its tests, ``tested`` (it had a candidate), ``gated`` (some candidate passed its gate),
    ``dropped`` (a join of it was dropped), ``failed`` (dropped, or too many of its plots failed their
    gate: it may be split); ``tabu`` the (unit, target) pairs not to take again; ``label`` (N,) the
    target each plot got by a join ('' none), ``outlier`` (N,) the plots of joins left out as
    outliers, ``notes`` what was dropped or split and why."""

    target: np.ndarray
    test: np.ndarray
    best: np.ndarray
    tested: np.ndarray
    gated: np.ndarray
    dropped: np.ndarray
    failed: np.ndarray
    label: np.ndarray
    outlier: np.ndarray
    tabu: set = field(default_factory=set)
    notes: list = field(default_factory=list)

    _PER_UNIT = (
        ("target", ""),
        ("test", np.nan),
        ("best", np.inf),
        ("tested", False),
        ("gated", False),
        ("dropped", False),
        ("failed", False),
    )

    @classmethod
    def empty(cls, n_units: int, n_plots: int) -> "JoinState":
        col = {
            name: np.full(n_units, v, dtype=object if isinstance(v, str) else type(v))
            for name, v in cls._PER_UNIT
        }
        return cls(
            target=col["target"],
            test=col["test"],
            best=col["best"],
            tested=col["tested"],
            gated=col["gated"],
            dropped=col["dropped"],
            failed=col["failed"],
            label=np.full(n_plots, "", dtype=object),
            outlier=np.zeros(n_plots, dtype=bool),
        )

    def extend(self, n_units: int) -> None:
        """Room for units up to ``n_units`` (new units: not joined, not tested)."""
        for name, v in self._PER_UNIT:
            old = getattr(self, name)
            add = np.full(n_units - old.size, v, dtype=old.dtype)
            setattr(self, name, np.concatenate([old, add]))

    def join(self, unit: int, name: str, plots: np.ndarray, test: float) -> None:
        self.target[unit], self.test[unit] = name, test
        self.label[plots] = name

    def drop(self, unit: int, of_plot: np.ndarray, why: str) -> None:
        self.tabu.add((int(unit), str(self.target[unit])))
        self.notes.append(why)
        self.label[of_plot == unit] = ""
        self.target[unit], self.dropped[unit], self.failed[unit] = "", True, True


def registered_labels(base: np.ndarray, state: JoinState, prov: np.ndarray) -> np.ndarray:
    """(N,) the labels to register: ``base``, the joins, and the provisional targets some track joined."""
    lab = np.where(base != "", base, state.label).astype(object)
    at = np.flatnonzero((prov != "") & (lab == ""))
    if at.size:
        joined = np.unique(state.target[state.target != ""].astype(str))
        at = at[np.isin(prov[at].astype(str), joined)]
        lab[at] = prov[at]
    return lab


def failing_joins(reg: Registrar, state: JoinState, units: Units, options: AssociationOptions):
    """(units (F,), excess (F,), outliers (N,) bool): the joins that fail under the latest
    registration, with excess = (sum - dof) / sqrt(2 dof) of their squared normalised residuals, and
    the single plots of the other joins whose residuals exceed the chi-square ``1 -
    outlier_probability`` quantile. A join fails when more than :data:`MAX_OUTLIER_SHARE` of its plots
    are such outliers (a wrong join, a track that swapped targets) or when its other plots' sum
    exceeds the ``1 - drop_probability`` quantile (a few stray plots a tracker took do not fail it)."""
    problem = reg.problem
    plots = np.flatnonzero(state.label != "")
    outliers = np.zeros(problem.n_plots, dtype=bool)
    if reg.result is None or plots.size == 0:
        return np.zeros(0, dtype=np.int64), np.zeros(0), outliers
    e = reg.plot_residuals()[plots]
    ss, cnt = np.nansum(e * e, axis=1), np.isfinite(e).sum(axis=1)
    out = (cnt > 0) & (ss > chi2_ppf(1.0 - options.outlier_probability, np.maximum(cnt, 1)))
    u = units.of_plot[plots]
    n = np.bincount(u, cnt > 0, minlength=units.n)
    n_out = np.bincount(u, out, minlength=units.n)
    ss_in = np.bincount(u, np.where(out, 0.0, ss), minlength=units.n)
    cnt_in = np.bincount(u, np.where(out, 0, cnt), minlength=units.n)
    ss_all, cnt_all = np.bincount(u, ss, minlength=units.n), np.bincount(u, cnt, minlength=units.n)
    joined = (state.target != "") & (n > 0)
    fail = joined & (
        (n_out > MAX_OUTLIER_SHARE * n)
        | (ss_in > chi2_ppf(1.0 - options.drop_probability, np.maximum(cnt_in, 1)))
    )
    bad = np.flatnonzero(fail)
    outliers[plots[out & ~fail[u]]] = True
    return bad, (ss_all[bad] - cnt_all[bad]) / np.sqrt(2.0 * cnt_all[bad]), outliers


def drop_failing(
    reg: Registrar,
    state: JoinState,
    units: Units,
    base: np.ndarray,
    prov: np.ndarray,
    options: AssociationOptions,
) -> int:
    """Drop failing joins (the worst per sensor, then register again) until none fails; then leave
    out the single outlying plots of the joins kept (and register again). Returns the joins dropped."""
    dropped = 0
    for round_ in range(2 * MAX_DROP_ROUNDS + 1):
        bad, excess, outliers = failing_joins(reg, state, units, options)
        if bad.size:
            if round_ < MAX_DROP_ROUNDS:  # the worst of each sensor
                order = np.lexsort((-excess, units.sensor[bad]))
                bad, excess = bad[order], excess[order]
                first = np.r_[True, units.sensor[bad][1:] != units.sensor[bad][:-1]]
                bad, excess = bad[first], excess[first]
            for u, z in zip(bad, excess):
                sensor = reg.problem.sensor_ids[units.sensor[u]]
                state.drop(
                    int(u),
                    units.of_plot,
                    f"sensor {sensor} {units.name[u]}: join to target {state.target[u]} "
                    f"dropped, its residuals {z:.3g} sigma above their chi-square mean",
                )
            dropped += bad.size
        elif outliers.any():
            state.label[outliers], state.outlier[outliers] = "", True
        else:
            break
        reg.solve(registered_labels(base, state, prov))
    return dropped


def outlier_stage(
    reg: Registrar, labels: np.ndarray, given: np.ndarray, options: AssociationOptions
) -> np.ndarray:
    """(N,) bool: the associated plots (labelled, no id given) whose squared normalised residuals under
    the latest registration exceed the chi-square ``1 - outlier_probability`` quantile."""
    out = np.zeros(labels.size, dtype=bool)
    if reg.result is None:
        return out
    e = reg.plot_residuals()
    cnt = np.isfinite(e).sum(axis=1)
    ss = np.nansum(e * e, axis=1)
    limit = chi2_ppf(1.0 - options.outlier_probability, np.maximum(cnt, 1))
    return (labels != "") & (given == "") & (cnt > 0) & (ss > limit)
