"""The result of :func:`~registration.fleet.association.associate.associate_and_register`:
:class:`AssociationResult`."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fleet.data.problem import FleetProblem
from registration.fleet.result import BatchResult

__all__ = ["AssociationResult"]


@dataclass
class AssociationResult:
    """Target labels found for the plots and the registration of the associated plots.

    ``labels`` (rows of the input plots table,): the target each plot was given, '' for a plot
    left unassociated. ``batch``: the :class:`BatchResult` of the final registration (its
    ``residuals``, ``plot_target`` and ``plot_sensor`` are per input row too). ``problem``: the
    registered problem. ``unassociated_rows``: input rows left unassociated; per sensor id
    ``unassociated_by_sensor``; of these ``n_clutter`` were in no track or piece long enough and
    ``n_unconfirmed`` in a piece that no other sensor's matched, or that only sensors lacking a
    channel matched (2-D radars, passive sensors: the target's height is then barely determined),
    or in a chain of one window. ``iterations``: association passes;
    ``converged``: a pass repeated the one before; ``changes``: plots whose label changed, per pass
    after the first (on the windows of ``iteration_plots``; the last pass, over all windows with the
    tracks made again from the corrected plots, is counted in ``iterations``, not in ``changes``). Times (s): ``seconds_total``, ``seconds_assignment`` (inside
    ``linear_sum_assignment``), ``seconds_registration`` (inside ``solve_batch``).
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

    @property
    def n_targets(self) -> int:
        return int(np.unique(self.labels[self.labels != ""]).size)

    @property
    def n_associated(self) -> int:
        return int(np.count_nonzero(self.labels != ""))

    @property
    def assignment_share(self) -> float:
        """Share of the total time spent in the assignments."""
        return self.seconds_assignment / self.seconds_total if self.seconds_total > 0 else 0.0

    def lines(self) -> list[str]:
        out = [f"association: {self.n_targets} targets, {self.n_associated} plots associated, "
               f"{self.unassociated_rows.size} unassociated ({self.n_clutter} clutter or short, "
               f"{self.n_unconfirmed} not confirmed by a second sensor), {self.iterations} passes "
               f"({'converged' if self.converged else 'NOT converged'}), {self.seconds_total:.2f} s "
               f"({100 * self.assignment_share:.1f} % in assignment)"]
        out += [f"  unassociated plots of sensor {s}: {n}" for s, n in self.unassociated_by_sensor.items() if n]
        return out + self.batch.lines()
