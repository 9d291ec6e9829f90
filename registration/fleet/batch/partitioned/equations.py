"""The normal equations of an archive as sums over its partitions (:class:`PartitionedEquations`), the
provider of the Levenberg-Marquardt engine (:mod:`registration.fleet.batch.levenberg_marquardt`)
for the partitioned solve (:mod:`registration.fleet.batch.partitioned.estimate`).

Each trial is two passes over the partitions (:mod:`registration.fleet.batch.partitioned.partition_passes`):
*map* each partition's Schur-reduced contribution ``S_p``, ``r_p``, its share ``U_p``, ``b_x,p`` of
the states' block and its sum of squares at the current estimate; *reduce* them by adding in
partition order (so the result does not depend on where each partition ran); solve the damped
reduced system on the free states as :func:`registration.fleet.batch.schur.damped_step` does; then
map each partition's back-substitution ``dc_b = V_b^-1 (b_b - W_b dx)`` with its trial sum of
squares.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from registration.core.parallel import map_chunks
from registration.fleet.batch.partitioned.partition_passes import ReduceTerms, reduce_pass, step_pass
from registration.fleet.batch.partitioned.task import PartitionTask
from registration.fleet.batch.schur import determined_directions, solve_reduced
from registration.fleet.data.layout import StateLayout

__all__ = ["PartitionedEquations", "PassPoint", "PassStep", "ReducedSums", "run_pass"]


def _call(item):
    func, task, args = item
    return func(task, *args)


def run_pass(func, tasks: list, args: list, client: Any = None) -> list:
    """``[func(task, *a) for task, a in zip(tasks, args)]`` in this process or on ``client``'s workers,
    in partition order."""
    return map_chunks(_call, [(func, t, a) for t, a in zip(tasks, args)], client)


@dataclass(frozen=True)
class ReducedSums:
    """The partitions' terms at a point, added in partition order, priors included: the states'
    block ``U`` (n + 1, n + 1) and right-hand side ``b_x`` (n + 1,) and, per damping ``lam``, the
    Schur-reduced ``S`` (n + 1, n + 1) and ``r`` (n + 1,) (row/column n: the sink of absent states).
    ``S`` and ``r`` grow as further damping values are asked for."""

    U: np.ndarray
    b_x: np.ndarray
    S: dict[float, np.ndarray]
    r: dict[float, np.ndarray]


@dataclass(frozen=True)
class PassPoint:
    """A point of the partitioned problem: states ``x`` (n,), each partition's window coefficients
    (B_p, n_coef, 3) ECEF m, the sum of squares and, once linearized, the reduced sums there."""

    x: np.ndarray
    coefs: list[np.ndarray]
    cost: float
    reduced: ReducedSums | None = None


@dataclass(frozen=True)
class PassStep:
    """A damped step: states ``dx`` (n,), coefficients per partition, its predicted reduction and
    the sum of squares at the trial point (the step pass computes both at once)."""

    dx: np.ndarray
    dcs: list[np.ndarray]
    predicted: float
    cost: float


class PartitionedEquations:
    """The normal equations of an archive as sums over its partitions' passes (module docstring), for
    the Levenberg-Marquardt engine (:class:`registration.fleet.batch.levenberg_marquardt.NormalEquations`):
    the tasks, the client and the prior terms."""

    def __init__(self, tasks: list[PartitionTask], client, layout: StateLayout):
        self.tasks, self.client, self.layout = tasks, client, layout
        with np.errstate(divide="ignore"):
            p = layout.prior_sigma
            self.pw2 = np.append(np.where(np.isfinite(p) & (p > 0), 1.0 / p**2, 0.0), 0.0)

    def reduce(self, x: np.ndarray, coefs: list[np.ndarray], lams: tuple[float, ...]) -> PassPoint:
        """The point (x, coefs) with its reduced sums for damping values ``lams`` (one pass)."""
        parts = run_pass(reduce_pass, self.tasks, [(x, c, lams) for c in coefs], self.client)
        return self.add(x, coefs, parts, lams)

    def add(
        self, x: np.ndarray, coefs: list[np.ndarray], parts: list[ReduceTerms], lams: tuple[float, ...]
    ) -> PassPoint:
        """The point (x, coefs) with the partitions' reduce terms ``parts`` (for damping values
        ``lams``) added in partition order, with the priors."""
        U = sum(p.U for p in parts) + np.diag(self.pw2)
        xs = np.append(x, 0.0)
        b_x = sum(p.b_x for p in parts) - self.pw2 * xs
        prior = float(np.sum(self.pw2 * xs * xs))
        S = {lam: U + sum(p.S[i] for p in parts) for i, lam in enumerate(lams)}
        r = {lam: b_x - sum(p.b_x - p.r[i] for p in parts) for i, lam in enumerate(lams)}
        cost = sum(p.cost for p in parts) + prior
        return PassPoint(x, coefs, cost, ReducedSums(U, b_x, S, r))

    def scale(self, free: np.ndarray) -> np.ndarray:
        return self.layout.scale[free]

    def linearize(self, point: PassPoint, lams: tuple[float, ...]) -> PassPoint:
        return self.reduce(point.x, point.coefs, lams)

    def determined(self, at: PassPoint, free: np.ndarray, scale: np.ndarray) -> np.ndarray:
        assert at.reduced is not None
        S0 = at.reduced.S[0.0]
        return determined_directions(0.5 * (S0 + S0.T)[np.ix_(free, free)], scale)

    def step(
        self, at: PassPoint, lam: float, free: np.ndarray, scale: np.ndarray, determined: np.ndarray
    ) -> PassStep:
        """The damped step ``lam`` at ``at`` and the cost at its trial point (one pass; one more to
        reduce for ``lam`` if not done yet)."""
        red, x = at.reduced, at.x
        assert red is not None
        if lam not in red.S:
            more = self.reduce(x, at.coefs, (lam,)).reduced
            assert more is not None
            red.S[lam], red.r[lam] = more.S[lam], more.r[lam]
        U = red.U
        S = red.S[lam] + lam * np.diag(np.diag(U))
        S = 0.5 * (S + S.T)
        n = x.size
        dx = np.zeros(n + 1)
        dx[free] = solve_reduced(S[np.ix_(free, free)], red.r[lam][free], scale, determined)
        parts = run_pass(step_pass, self.tasks, [(x, c, dx, lam) for c in at.coefs], self.client)
        b_dot = float(dx[free] @ red.b_x[free]) + sum(p.b_dot for p in parts)
        damp = lam * (float(np.sum(np.diag(U)[free] * dx[free] ** 2)) + sum(p.damp for p in parts))
        xs = np.append(x + dx[:n], 0.0)
        cost = sum(p.cost for p in parts) + float(np.sum(self.pw2 * xs * xs))
        return PassStep(dx[:n], [p.dc for p in parts], b_dot + damp, cost)

    def trial(self, at: PassPoint, step: PassStep) -> PassPoint:
        return PassPoint(at.x + step.dx, [c + d for c, d in zip(at.coefs, step.dcs)], step.cost)
