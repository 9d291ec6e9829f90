"""What the batch solvers set aside, and why: the windows whose position their plots do not
determine (:func:`exclude_singular`), the plots that a sensor's time bias moves outside their
platform's navigation (:func:`outside_when_seen`, :func:`set_aside_outside`), and the warning for
time biases too long for the windows (:func:`time_bias_warnings`).
"""

from __future__ import annotations

from dataclasses import replace
from typing import Protocol

import numpy as np

from registration.fleet.batch.design import Design
from registration.fleet.data.layout import StateLayout
from registration.fleet.data.problem import Exclusion, FleetProblem

__all__ = [
    "PlotsOfTargets",
    "exclude_singular",
    "singular_exclusions",
    "outside_exclusions",
    "outside_weight",
    "outside_when_seen",
    "set_aside_outside",
    "time_bias_warnings",
]


class PlotsOfTargets(Protocol):
    """Plots by target: ``target`` (N,) index into ``target_ids``, ``time`` (N,) reported time (s)."""

    @property
    def target(self) -> np.ndarray: ...

    @property
    def time(self) -> np.ndarray: ...

    @property
    def target_ids(self) -> tuple[str, ...]: ...


def exclude_singular(
    problem: FleetProblem, design: Design, bad: np.ndarray, outside: np.ndarray | None = None
) -> FleetProblem:
    """The problem without the plots of the windows ``bad`` (``solver.singular_blocks``), each recorded
    as an exclusion. ``outside`` (N,) bool, given when the windows were found at the solution: the
    plots seen outside their platform's navigation there (:func:`outside_when_seen`), which weighed
    0; a window left undetermined by setting them aside says so."""
    drop, exclusions = singular_exclusions(problem, design, bad, outside)
    return problem.drop_plots(drop, exclusions)


def singular_exclusions(
    problem: FleetProblem, design: Design, bad: np.ndarray, outside: np.ndarray | None = None
) -> tuple[np.ndarray, list[Exclusion]]:
    """(the plots of the windows ``bad`` (N,) bool, one exclusion per window saying why): the
    reasons of :func:`exclude_singular`."""
    blk = design.blocks
    drop = np.zeros(problem.n_plots, dtype=bool)
    exclusions: list[Exclusion] = []
    for b in bad:
        end = blk.block_start[b + 1] if b + 1 < blk.n_blocks else blk.order.size
        plots = blk.order[blk.block_start[b] : end]
        drop[plots] = True
        n_out = int(outside[plots].sum()) if outside is not None else 0
        held = plots[~outside[plots]] if outside is not None and n_out else plots
        sensors = sorted({problem.sensor_ids[s] for s in problem.sensor[held]})
        why = (
            f"its position is not determined by the plots of {', '.join(sensors) or 'no sensor'} "
            "in this window"
        )
        if n_out:
            why = (
                f"{why}, once its {n_out} plots seen outside their platform's navigation (reported time - "
                "time bias) are set aside at the solution"
            )
        elif outside is not None:
            why += " at the solution (its geometry at the estimate; it was determined at the start)"
        t = problem.time[plots]
        exclusions.append(
            Exclusion(
                problem.target_ids[blk.block_target[b]],
                f"singular geometry: {why}",
                int(plots.size),
                float(t.min()),
                float(t.max()),
            )
        )
    return drop, exclusions


def outside_when_seen(design: Design, x: np.ndarray) -> np.ndarray:
    """(N,) bool per plot of the design's problem: seen (reported time minus its sensor's time
    bias under states ``x``) outside its platform's navigation time span."""
    blk = design.blocks
    out = np.zeros(blk.order.size, dtype=bool)
    if design.time_biased:
        out[blk.order] = design.seen_at(design.seen_time(x))[2][design.slot]
    return out


def outside_weight(design: Design, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(the plots seen outside their navigation under states ``x`` (N,) bool
    (:func:`outside_when_seen`), the design's weights (rows, 3) with those plots' rows at 0)."""
    outside = outside_when_seen(design, x)
    rows = np.zeros(design.weight.shape[0], dtype=bool)
    rows[design.slot] = outside[design.blocks.order]
    return outside, np.where(rows[:, None], 0.0, design.weight)


def outside_exclusions(problem: PlotsOfTargets, outside: np.ndarray) -> tuple[Exclusion, ...]:
    """One exclusion per target of the plots ``outside`` (N,) of ``problem`` (a FleetProblem or
    what the partitioned passes keep of one)."""
    out = []
    for k in np.unique(problem.target[outside]):
        sel = outside & (problem.target == k)
        t = problem.time[sel]
        out.append(
            Exclusion(
                problem.target_ids[k],
                "seen outside its platform's navigation once its sensor's time "
                "bias is applied (reported time - time bias)",
                int(sel.sum()),
                float(t.min()),
                float(t.max()),
            )
        )
    return tuple(out)


def time_bias_warnings(layout: StateLayout, x: np.ndarray, window_s: float) -> tuple[str, ...]:
    """A warning per sensor whose time bias estimate exceeds half the window length ``window_s``
    (s): the windows' polynomials then extrapolate far and the estimate is not to be trusted."""
    out = []
    for s in np.flatnonzero(layout.time_bias_index >= 0):
        i = int(layout.time_bias_index[s])
        if window_s > 0 and abs(x[i]) > 0.5 * window_s:
            out.append(
                f"{layout.labels[i]} is {x[i]:+.3g} s, more than half the {window_s:g} s windows: "
                f"not to be trusted; register again with longer windows (window_s >= {4 * abs(x[i]):.3g} s)"
            )
    return tuple(out)


def set_aside_outside(
    problem: FleetProblem, design: Design, x: np.ndarray
) -> tuple[FleetProblem, Design] | None:
    """After a fit with time biases (states ``x``), the plots seen outside their navigation, which
    weighed 0 in the evaluations (registration.fleet.batch.normal), set aside for good: (problem
    with their exclusions recorded, design with their weights 0), or None when that would leave a
    window undetermined (then the caller drops the plots and solves anew)."""
    outside, weight = outside_weight(design, x)
    if not outside.any():
        return problem, design
    design = replace(design, weight=weight)
    if np.any(design.block_sums(design.weight.any(axis=1).astype(np.int64)) == 0):
        return None
    return replace(problem, excluded=problem.excluded + outside_exclusions(problem, outside)), design
