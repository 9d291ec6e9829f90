"""Biases per period: every sensor and platform state estimated once per period of ``period_s``
seconds (period k covers ``[k P, (k+1) P)`` of ``time_s``), by one batch solve per period on that
period's plots (:func:`solve_periods`), and the changes between consecutive periods that pass the
run-wide test of :mod:`registration.fleet.changes` (:func:`period_changes`).
See docs/background/bias-periods.md."""

from registration.fleet.periods.solve import (
    UNDETERMINED,
    BiasPeriods,
    PeriodChanges,
    PeriodResult,
    period_changes,
    period_index,
    solve_periods,
)

__all__ = [
    "UNDETERMINED",
    "BiasPeriods",
    "PeriodChanges",
    "PeriodResult",
    "period_changes",
    "period_index",
    "solve_periods",
]
