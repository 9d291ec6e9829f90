"""Targets the position-fixing sensors confirmed that are reference targets (ADS-B, AIS):
:func:`name_by_references` gives them the reference's id, so that the reference positions enter the
registration and the id carries over to the plots."""

from __future__ import annotations

import numpy as np

from registration.fleet.association.grouping.units import Units
from registration.fleet.association.joining.attach import candidate_plots, pair_tests
from registration.fleet.association.joining.checks import JoinState
from registration.fleet.association.joining.curves import anchor_curves
from registration.fleet.association.joining.joins import choose_joins
from registration.fleet.association.options import AssociationOptions
from registration.fleet.association.solves import Registrar

__all__ = ["name_by_references"]


def name_by_references(
    reg: Registrar, labels: np.ndarray, given: np.ndarray, options: AssociationOptions
) -> np.ndarray:
    """(N,) ``labels`` with each target the position-fixing sensors confirmed (not an id given) renamed
    to the reference target it is (ADS-B, AIS): the target's plots, all its sensors together, are
    tested against each reference target as a track is (:func:`choose_joins`, the targets that exist
    at the same time competing for a reference), under the latest estimate."""
    confirmed = (labels != "") & ~given
    if reg.refs.time.size == 0 or not confirmed.any():
        return labels
    names, of_plot = np.unique(labels[confirmed], return_inverse=True)
    unit = np.full(labels.size, -1, dtype=np.int64)
    unit[confirmed] = of_plot.reshape(-1)
    t = reg.problem.time
    t0, t1 = np.full(names.size, np.inf), np.full(names.size, -np.inf)
    np.minimum.at(t0, unit[confirmed], t[confirmed])
    np.maximum.at(t1, unit[confirmed], t[confirmed])
    none = np.zeros(labels.size, dtype=bool)
    units = Units(
        unit,
        np.zeros(names.size, dtype=np.int64),
        names,
        t0,
        t1,
        np.zeros(names.size, dtype=bool),
        none,
        none,
        (),
    )
    conflicts = (np.minimum(t1[:, None], t1[None, :]) - np.maximum(t0[:, None], t0[None, :])) > 0
    np.fill_diagonal(conflicts, False)
    curves = anchor_curves(
        None,
        reg.x,
        reg.refs,
        reg.between,
        gap_s=options.reference_gap_s,
        accel_sigma=options.reference_accel_sigma,
        surface=reg.problem.surface,
    )
    u, j, plots, _ = candidate_plots(
        reg.problem,
        reg.x,
        unit,
        np.arange(names.size),
        curves,
        k=options.test_plots,
        min_plots=options.min_join_plots,
    )
    pairs = pair_tests(reg.problem, reg.x, curves, u, j, plots)
    state = JoinState.empty(names.size, labels.size)
    choose_joins(pairs, curves.names, reg.P, state, units, conflicts, np.zeros(1, dtype=bool), options)
    rename = {str(n): str(r) for n, r in zip(names, state.target) if r != ""}
    out = labels.astype(object)
    out[confirmed] = np.array([rename.get(str(v), str(v)) for v in names], dtype=object)[of_plot.reshape(-1)]
    return out.astype(str)
