"""Biases per period by one batch solve per period (docs/background/bias-periods.md).

Period ``k`` covers ``[k P, (k+1) P)`` of the plots' reported time (s). Each period's plots, with the
reference positions of the same span whose targets the period's plots name, and the whole navigation
(only interpolated at the plots' times), are registered by :func:`~registration.fleet.solve_batch`
unchanged, started from the whole run's estimate. The periods' estimates are independent (no plot is
used twice), so the difference of a state between consecutive periods has the variance
``sigma_before^2 + sigma_after^2``; :func:`period_changes` tests those differences with
:func:`~registration.fleet.changes.change_test`, the Bonferroni threshold shared by every state and
boundary of the run.

A period without plots of a sensor leaves that sensor's states (and, without plots of any sensor of a
platform, the platform's attitude errors) ``undetermined``: sigma infinite, never tested. A period
without plots, or whose plots are all set aside (targets seen by one sensor only), is left out and
named in :attr:`BiasPeriods.notes`.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from registration.fleet.batch.estimate import solve_batch
from registration.fleet.batch.solver import BatchOptions
from registration.fleet.changes import FALSE_ALARM, ChangeTest, change_test
from registration.fleet.data.problem import FleetProblem, build_problem
from registration.fleet.result import BatchResult

__all__ = [
    "UNDETERMINED",
    "BiasPeriods",
    "PeriodChanges",
    "PeriodResult",
    "period_changes",
    "period_index",
    "solve_periods",
]

#: The status of a state whose sensor (or platform) has no plot in a period.
UNDETERMINED = "undetermined"
#: The status a state needs in both periods to be tested for a change.
TESTED_STATUS = "identifiable"


@dataclass(frozen=True)
class PeriodResult:
    """One period: ``index`` k, its span ``[start_s, end_s)`` (s), the plots read in it
    (``n_plots``, before targets are set aside), its problem and its batch result (states without
    plots of their sensor or platform marked :data:`UNDETERMINED`)."""

    index: int
    start_s: float
    end_s: float
    n_plots: int
    problem: FleetProblem
    result: BatchResult


@dataclass(frozen=True)
class PeriodChanges:
    """Every test of a run, per (boundary, state) tested (K,): ``state`` (index into the layout),
    ``time_s`` the boundary (s, the start of the later period), ``before`` and ``after`` the two
    periods' estimates (rad, m, 1, s) and ``test`` (:class:`~registration.fleet.changes.ChangeTest`,
    its threshold shared by all K tests)."""

    state: np.ndarray
    time_s: np.ndarray
    before: np.ndarray
    after: np.ndarray
    test: ChangeTest

    @property
    def n_tests(self) -> int:
        return int(self.state.size)

    @property
    def found(self) -> np.ndarray:
        """Indices (into the K tests) of the changes declared, by boundary then layout order."""
        return np.flatnonzero(self.test.flagged)


@dataclass(frozen=True)
class BiasPeriods:
    """The per-period registration of a run: ``period_s`` (s), the periods with plots in time order,
    the periods left out (``left_out``: (start, end, reason)) and the changes between consecutive
    periods."""

    period_s: float
    periods: tuple[PeriodResult, ...]
    changes: PeriodChanges
    left_out: tuple[tuple[float, float, str], ...] = field(default_factory=tuple)

    def notes(self) -> list[str]:
        """One line per period left out."""
        return [f"period [{a:g}, {b:g}) s left out: {why}" for a, b, why in self.left_out]


def period_index(time_s: np.ndarray, period_s: float) -> np.ndarray:
    """(N,) int: the period ``floor(t / period_s)`` of each time ``time_s`` (N,) s."""
    if not (np.isfinite(period_s) and period_s > 0):
        raise ValueError(f"period_s: expected a length > 0 s, got {period_s}")
    return np.floor(np.asarray(time_s, dtype=np.float64) / period_s).astype(np.int64)


def _take(table: dict, keep: np.ndarray) -> dict:
    return {k: np.asarray(v)[keep] for k, v in table.items()}


def _references_of(references: dict | None, plots: dict, lo: float, hi: float) -> dict | None:
    """The reference positions in ``[lo, hi)`` of targets the period's ``plots`` name (None: none)."""
    if references is None:
        return None
    t = np.asarray(references["time"], dtype=np.float64)
    named = np.isin(np.asarray(references["target"]).astype(str), np.unique(np.asarray(plots["target"])))
    keep = (t >= lo) & (t < hi) & named
    return _take(references, keep) if keep.any() else None


def _mark_unseen(problem: FleetProblem, result: BatchResult) -> BatchResult:
    """``result`` with the states of sensors (and platforms) without plots in ``problem`` marked
    :data:`UNDETERMINED` with an infinite sigma (fixed states stay fixed)."""
    layout = result.layout
    sensors = np.unique(problem.sensor)
    platforms = np.unique(problem.sensor_platform[sensors])
    seen = np.zeros(layout.n, dtype=bool)
    indices = [layout.att_index[platforms], layout.bias_index[sensors], layout.extended_index[sensors]]
    if layout.eccentricity_index is not None:  # the azimuth eccentricity's terms too
        indices.append(layout.eccentricity_index[sensors])
    for index in indices:
        i = index.ravel()
        seen[i[i >= 0]] = True
    offset = problem.references.offset
    if layout.height_offset_index >= 0 and offset is not None and offset.any():
        seen[layout.height_offset_index] = True  # the flight levels' heights of the period hold it
    unseen = [i for i in np.flatnonzero(~seen) if result.status.get(layout.names[i]) != "fixed"]
    if not unseen:
        return result
    sigma = result.sigma.copy()
    sigma[unseen] = np.inf
    status = dict(result.status)
    status.update({layout.names[i]: UNDETERMINED for i in unseen})
    return replace(result, sigma=sigma, status=status)


def solve_periods(
    plots: dict,
    sensors: dict,
    navigation: dict,
    platforms: dict | None = None,
    references: dict | None = None,
    targets: dict | None = None,
    *,
    period_s: float,
    options: BatchOptions | None = None,
    x0: np.ndarray | None = None,
    false_alarm: float = FALSE_ALARM,
) -> BiasPeriods:
    """Register the tables (as for :func:`~registration.fleet.build_problem`, SI units and radians)
    once per period of ``period_s`` (s): :func:`~registration.fleet.solve_batch` on each period's
    plots with ``options``, started from ``x0`` (n,; for example the whole run's estimate), and the
    changes between consecutive periods (:func:`period_changes`, ``false_alarm`` over the run)."""
    k_plot = period_index(plots["time"], period_s)
    ks = np.unique(k_plot)
    left_out = [
        (float(k * period_s), float((k + 1) * period_s), "no plots")
        for k in np.setdiff1d(np.arange(ks.min(), ks.max() + 1), ks)
    ]
    done = []
    for k in ks:
        lo, hi = float(k * period_s), float((k + 1) * period_s)
        mine = _take(plots, k_plot == k)
        problem = build_problem(
            mine, sensors, navigation, platforms, _references_of(references, mine, lo, hi), targets
        )
        if problem.n_plots == 0:
            left_out.append((lo, hi, "every target of its plots was set aside (seen by one sensor only)"))
            continue
        result = _mark_unseen(problem, solve_batch(problem, options, x0))
        done.append(PeriodResult(int(k), lo, hi, int(np.size(mine["time"])), problem, result))
    return BiasPeriods(
        float(period_s), tuple(done), period_changes(done, false_alarm), tuple(sorted(left_out))
    )


def period_changes(periods, false_alarm: float = FALSE_ALARM) -> PeriodChanges:
    """The tests between consecutive ``periods`` (:class:`PeriodResult`, time order) of every state
    :data:`TESTED_STATUS` with a finite sigma in both; one Bonferroni threshold over all of them."""
    state, time, before, after, sigma = [], [], [], [], []
    for a, b in zip(periods[:-1], periods[1:]):
        ra, rb = a.result, b.result
        names = ra.layout.names
        ok = np.array(
            [ra.status.get(n) == TESTED_STATUS and rb.status.get(n) == TESTED_STATUS for n in names],
            dtype=bool,
        )
        ok &= np.isfinite(ra.sigma) & np.isfinite(rb.sigma) & (ra.sigma > 0) & (rb.sigma > 0)
        i = np.flatnonzero(ok)
        state.append(i)
        time.append(np.full(i.size, b.start_s))
        before.append(ra.estimate[i])
        after.append(rb.estimate[i])
        sigma.append(np.hypot(ra.sigma[i], rb.sigma[i]))
    cat = lambda parts, kind=np.float64: np.concatenate(parts).astype(kind) if parts else np.zeros(0, kind)  # noqa: E731
    b_, a_ = cat(before), cat(after)
    s = cat(sigma)
    return PeriodChanges(
        cat(state, np.int64), cat(time), b_, a_, change_test(a_ - b_, s, max(s.size, 1), false_alarm)
    )
