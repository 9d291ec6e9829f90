"""Why the association anchors nothing, or leaves a sensor's plots without a target, in words: one
sensor, no references, no target ids (:func:`anchors_of`, :func:`no_anchor_error`,
:func:`nothing_associated`, :func:`unanchored_notes`).

A target is anchored by the ids the plots carry, by a reference target (ADS-B, AIS) or by two
position-fixing sensors (range, bearing and elevation) that see it together; a track that meets no
anchor stays without a target, whatever the windows (docs/background/association.md)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fleet.association.grouping.confirm import fixing_sensors
from registration.fleet.data.known_targets import References
from registration.fleet.data.problem import FleetProblem

__all__ = ["Anchors", "anchors_of", "no_anchor_error", "nothing_associated", "unanchored_notes"]


@dataclass(frozen=True)
class Anchors:
    """What could anchor a target: ``n_ids`` plots with a target id given (``id_column``: the plots
    have a ``target`` column), ``n_reference_targets`` reference targets of which ``references_meet``
    tells whether their times meet the plots' span, the ``sensors`` with plots and of them the
    position-fixing ones (``fixing``), ``n_plots`` and the plots' span ``t0``, ``t1`` (s)."""

    n_ids: int
    id_column: bool
    n_reference_targets: int
    references_meet: bool
    reference_span: tuple[float, float]
    sensors: tuple[str, ...]
    fixing: tuple[str, ...]
    n_plots: int
    t0: float
    t1: float

    @property
    def ids_text(self) -> str:
        if self.n_ids:
            return f"target ids on {self.n_ids} plots"
        return "no target ids (" + ("empty target column" if self.id_column else "no target column") + ")"

    @property
    def references_text(self) -> str:
        if self.n_reference_targets == 0:
            return "no references (ADS-B, AIS)"
        if not self.references_meet:
            r0, r1 = self.reference_span
            return f"references at {r0:g} to {r1:g} s, plots at {self.t0:g} to {self.t1:g} s"
        return f"references of {self.n_reference_targets} targets"


def _names(ids, limit: int = 3) -> str:
    ids = [repr(str(i)) for i in ids]
    return ", ".join(ids) if len(ids) <= limit else ", ".join(ids[:limit]) + f" and {len(ids) - limit} more"


def anchors_of(problem: FleetProblem, given: np.ndarray, id_column: bool, refs: References) -> Anchors:
    """The anchors of the problem of all plots, the ids given (N,; '' none) and the references."""
    present = np.unique(problem.sensor)
    fixing = fixing_sensors(problem)
    t0, t1 = float(problem.time.min()), float(problem.time.max())
    span = (float(refs.time.min()), float(refs.time.max())) if refs.time.size else (np.nan, np.nan)
    return Anchors(
        n_ids=int((given != "").sum()),
        id_column=id_column,
        n_reference_targets=int(np.unique(refs.target.astype(str)).size),
        references_meet=bool(refs.time.size and span[0] <= t1 and span[1] >= t0),
        reference_span=span,
        sensors=tuple(problem.sensor_ids[s] for s in present),
        fixing=tuple(problem.sensor_ids[s] for s in present if fixing[s]),
        n_plots=problem.n_plots,
        t0=t0,
        t1=t1,
    )


def _sensors_text(a: Anchors) -> str:
    if len(a.sensors) == 1:
        return f"all {a.n_plots} plots are of one sensor, {a.sensors[0]!r}"
    return f"no sensor of the {len(a.sensors)} with plots fixes a position alone"


def no_anchor_error(a: Anchors) -> ValueError | None:
    """The error when nothing can anchor a target, else None: no ids, no reference that meets the
    plots, and one sensor only (its targets are seen by it alone) or no position-fixing sensor (a
    track of one becomes a provisional target that the other sensors' tracks can join)."""
    if a.n_ids or (a.n_reference_targets and a.references_meet) or (len(a.sensors) > 1 and a.fixing):
        return None
    second = "a second sensor's plots" if len(a.sensors) == 1 else "a position-fixing sensor's plots"
    return ValueError(
        f"association: nothing anchors a target: {_sensors_text(a)}; {a.references_text}; {a.ids_text}: "
        f"give references, target ids or {second}"
    )


def nothing_associated(a: Anchors, window_s: float) -> ValueError:
    """The error when anchors were there but no plot could be associated: what there was, and what
    to check."""
    fixing = f"fixing sensors {_names(a.fixing)}" if len(a.fixing) >= 2 else "no two fixing sensors"
    return ValueError(
        f"association: no plot matched an anchor ({a.ids_text}; {a.references_text}; {fixing}): check "
        f"the references' times and positions, the gate and initial sigmas (AssociationOptions) or the "
        f"windows ({window_s:g} s)"
    )


def unanchored_notes(a: Anchors, by_sensor: dict) -> list[str]:
    """One note per sensor with plots whose tracks met no anchor (reason ``no_anchor``), naming what
    was missing near them."""
    notes = []
    for sid, counts in by_sensor.items():
        n = counts.get("no_anchor", 0)
        if not n:
            continue
        missing = ["no target id on them" if a.n_ids else a.ids_text]
        missing.append(
            "no reference near them" if a.n_reference_targets and a.references_meet else a.references_text
        )
        if len(a.sensors) == 1:
            missing.append(f"{sid!r} the only sensor with plots")
        elif sid in a.fixing and len(a.fixing) == 1:
            missing.append(f"{sid!r} the only position-fixing sensor")
        elif sid not in a.fixing:
            missing.append(f"{sid!r} fixes no position alone, no confirmed target near them")
        else:
            missing.append("no target confirmed by two position-fixing sensors near them")
        notes.append(
            f"sensor {sid!r}: {n} plots without a target, no anchor near their tracks "
            f"({'; '.join(missing)}): give references or target ids for those targets"
        )
    return notes
