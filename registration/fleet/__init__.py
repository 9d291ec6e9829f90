"""Fleet registration: the attitude errors of any number of platforms (ships, shore sites) and the
biases of any number of sensors on them (3-D and 2-D radars, passive angle sensors, bearing-only
and range-only sensors), estimated jointly from long-form plot tables.

Modules: ``result`` (:class:`BatchResult`), ``observability``, ``combinations``, ``corrected``,
``plots`` (PNG figures of a result), and the subpackages ``data`` (the input tables, their checks,
navigation, the state layout, :class:`FleetProblem` built by :func:`build_problem`),
``simulation`` (:func:`fleet_scenario`), ``batch`` (target windows, normal equations, the Schur complement,
Levenberg-Marquardt, covariance, residuals, :func:`solve_batch` in ``batch.estimate``), ``online``
(:class:`FleetFilter`, :func:`register_online`: the same model epoch by epoch as plots arrive) and
``association`` (:func:`associate_and_register`: plots without target ids associated across sensors
jointly with the registration, and the simulated clutter scenarios). The table files (CSV/Parquet in
degrees) are read and written by :mod:`registration.io.fleet`. See docs/reference/fleet-files.md,
docs/background/fleet-online.md,
docs/background/association.md.
"""

from registration.fleet.association.associate import (
    AssociationOptions,
    AssociationResult,
    associate_and_register,
)
from registration.fleet.association.simulated.clutter import (
    AssociationScenario,
    association_scenario,
    association_scores,
)
from registration.fleet.batch.estimate import solve_batch
from registration.fleet.batch.solver import BatchOptions
from registration.fleet.data.problem import Exclusion, FleetProblem, build_problem
from registration.fleet.online.filter import FleetFilter, OnlineOptions
from registration.fleet.online.register import register_online
from registration.fleet.online.result import OnlineHistory, OnlineResult
from registration.fleet.result import BatchResult, ChiSquareCheck, FusedTargets
from registration.fleet.simulation.scenario import FleetScenario, fleet_scenario

__all__ = [
    "BatchOptions",
    "BatchResult",
    "ChiSquareCheck",
    "Exclusion",
    "FleetFilter",
    "FleetProblem",
    "FleetScenario",
    "OnlineHistory",
    "OnlineOptions",
    "OnlineResult",
    "register_online",
    "FusedTargets",
    "build_problem",
    "fleet_scenario",
    "solve_batch",
]
__all__ += [
    "AssociationOptions",
    "AssociationResult",
    "AssociationScenario",
    "associate_and_register",
    "association_scenario",
    "association_scores",
]
