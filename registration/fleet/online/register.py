"""``register_online``: the online fleet filter (:class:`~registration.fleet.online.filter.FleetFilter`)
run over a whole plots table, with the residuals at its final estimate."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from registration.fleet.batch.residuals import residuals_at
from registration.fleet.data.problem import build_problem
from registration.fleet.data.tables import read_table
from registration.fleet.online.filter import FleetFilter, OnlineOptions
from registration.fleet.online.result import OnlineResult

__all__ = ["register_online"]


def register_online(
    plots,
    sensors,
    navigation,
    platforms=None,
    references=None,
    *,
    options: OnlineOptions | None = None,
    prior=None,
    residuals: bool = True,
    targets=None,
) -> OnlineResult:
    """Run :class:`FleetFilter` over a whole plots table (sorted by time here) and return its result;
    with ``residuals``, also the normalised residuals of every plot at the final estimate
    (:func:`registration.fleet.batch.residuals.residuals_at`)."""
    filt = FleetFilter(
        sensors, navigation, platforms, references, options=options, prior=prior, targets=targets
    )
    table = read_table("plots", plots, ("time", "sensor", "target"))
    order = np.argsort(table.floats("time"), kind="stable")
    filt.update({k: v[order] for k, v in table.columns.items()})
    filt.flush()
    result = filt.result()
    if residuals and result.n_plots_used:
        problem = build_problem(plots, sensors, navigation, platforms, references, targets)
        res, check, _ = residuals_at(problem, result.estimate, filt.options.batch())
        result = replace(result, residuals=res, fit_check=check)
    return result
