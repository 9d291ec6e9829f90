"""The result of :func:`~registration.fleet.association.associate.associate_and_register`:
:class:`AssociationResult`, and the reasons a plot is left out (:data:`REASONS`)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration.fleet.data.problem import FleetProblem
from registration.fleet.result import BatchResult

__all__ = ["AssociationResult", "REASONS", "CLUTTER_REASONS"]

#: Why a plot has no target, or has one but was not registered (the ``reason`` of associations.csv).
REASONS = {
    "clutter": "the tracker put it in no track of min_track_plots plots",
    "short_track": "its track (or the piece of it between gaps and jumps) is shorter than min_track_plots "
    "plots",
    "no_anchor": "no target overlaps its track in time: none with an id given, no reference, none confirmed "
    "by two position-fixing sensors",
    "no_match": "its track failed the gate of every target it overlaps",
    "ambiguous": "its track passed the gates of several targets, or competes with another track of its "
    "sensor for one, without a clear winner",
    "dropped": "its track was joined to a target, then dropped: its residuals failed under the registration",
    "outside_span": "its track was joined to a target, but this plot lies outside the span where the "
    "target's position is known",
    "outlier": "associated, then left out: its residuals exceed the outlier gate under the final "
    "registration",
    "set_aside": "it has a target, but the registration set it aside (a target seen by one sensor only, a "
    "window its plots do not determine, or seen outside its platform's navigation)",
}
#: Reasons counted as clutter in :attr:`AssociationResult.n_clutter`.
CLUTTER_REASONS = ("clutter", "short_track")


@dataclass
class AssociationResult:
    """Target labels of the plots and the registration of the labelled plots.

    Per row of the input plots table: ``labels`` the target ('' none: the id given, or the target the
    plot was associated with: a reference id, a given id, or ``a1``, ``a2``, ... for a target the
    position-fixing sensors confirmed), ``given`` (bool) whether the label is the plot's own id,
    ``reasons`` why a plot has no label or was not registered ('' else; :data:`REASONS`), ``join``
    the mean squared normalised residual of the plot's track piece under the final registration
    (d^2 / dof of its join; NaN where none), ``tracks`` the track (unit) the plot was joined by
    (``track 17``, ``track 17/2`` after a split, ``tracker 5``; '' none). ``batch``: the final
    :class:`BatchResult` (per input row as well); ``problem``: the registered problem.
    ``unassociated_rows`` (rows with no label, sorted), ``unassociated_by_sensor``; of these
    ``n_clutter`` (reasons clutter and short_track) and ``n_unconfirmed`` (the others).
    ``by_sensor``: per sensor id, counts of ``given``, ``associated``, ``unassociated`` and per
    reason. ``notes``: the splits of given tracks, the joins dropped. ``iterations``: grouping
    passes of the position-fixing sensors; ``join_passes``; ``converged``: both stopped changing
    before their limits; ``changes``: plots relabelled per grouping pass. Times (s):
    ``seconds_total``, ``seconds_assignment``, ``seconds_registration``.
    """

    labels: np.ndarray
    batch: BatchResult
    problem: FleetProblem
    unassociated_rows: np.ndarray
    unassociated_by_sensor: dict
    n_clutter: int
    n_unconfirmed: int
    iterations: int
    converged: bool
    changes: list
    seconds_total: float
    seconds_assignment: float
    seconds_registration: float
    given: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=bool))
    reasons: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=str))
    join: np.ndarray = field(default_factory=lambda: np.zeros(0))
    tracks: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=str))
    by_sensor: dict = field(default_factory=dict)
    notes: tuple = ()
    join_passes: int = 0

    @property
    def n_targets(self) -> int:
        return int(np.unique(self.labels[self.labels != ""]).size)

    @property
    def n_associated(self) -> int:
        """Plots given a target by the association (ids given not counted)."""
        return (
            int(np.count_nonzero((self.labels != "") & ~self.given))
            if self.given.size
            else int(np.count_nonzero(self.labels != ""))
        )

    @property
    def assignment_share(self) -> float:
        """Share of the total time spent in the assignments."""
        return self.seconds_assignment / self.seconds_total if self.seconds_total > 0 else 0.0

    def sensor_lines(self) -> list[str]:
        """One line per sensor: plots with ids given, associated, unassociated and why."""
        out = []
        for sid, c in self.by_sensor.items():
            why = ", ".join(f"{k} {v}" for k, v in c.items() if k in REASONS and v)
            out.append(
                f"  sensor {sid}: {c['given']} with ids given, {c['associated']} associated, "
                f"{c['unassociated']} unassociated" + (f" ({why})" if why else "")
            )
        return out

    def lines(self) -> list[str]:
        n_given = int(self.given.sum()) if self.given.size else 0
        out = [
            f"association: {self.n_targets} targets, {self.n_associated} plots associated"
            + (f" (and {n_given} with ids given)" if n_given else "")
            + f", {self.unassociated_rows.size} unassociated ({self.n_clutter} clutter or short tracks, "
            f"{self.n_unconfirmed} not joined to a target), {self.iterations} grouping and "
            f"{self.join_passes} join passes ({'converged' if self.converged else 'NOT converged'}), "
            f"{self.seconds_total:.2f} s ({100 * self.assignment_share:.1f} % in assignment)"
        ]
        out += self.sensor_lines()
        out += [f"  note: {n}" for n in self.notes]
        return out + self.batch.lines()
