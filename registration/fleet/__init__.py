"""Fleet registration: the attitude errors of any number of platforms (ships, shore sites) and the
biases of any number of sensors on them (3-D and 2-D radars, passive angle sensors, bearing-only
and range-only sensors), estimated jointly from long-form plot tables.

Modules: ``tables`` (the input tables, their columns and units), ``problem`` (:class:`FleetProblem`,
checked and built by :func:`build_problem`), ``layout`` (the state), ``blocks`` (the target
windows), ``normal``/``schur``/``solver`` (Levenberg-Marquardt with the targets eliminated by the
Schur complement), ``batch`` (:func:`solve_batch`), ``result`` (:class:`BatchResult`),
``covariance``, ``observability``, ``online`` (:class:`FleetFilter`, :func:`register_online`: the
same model epoch by epoch as plots arrive; ``online_epoch``, ``online_result``), ``scenario`` (:func:`fleet_scenario`), ``files`` (CSV/Parquet tables in
degrees: :func:`read_fleet_tables`, :func:`write_fleet_tables`), ``plots`` (PNG figures of a result). See docs/fleet.md.
``association`` (:func:`associate_and_register`: plots without target ids associated across sensors jointly
with the registration; docs/association.md), ``clutter`` (:func:`association_scenario`: simulated plots
without ids, with misses and clutter, and :func:`association_scores`).
"""

from registration.fleet.association import AssociationOptions, AssociationResult, associate_and_register
from registration.fleet.batch import solve_batch
from registration.fleet.clutter import AssociationScenario, association_scenario, association_scores
from registration.fleet.covariance import FusedTargets
from registration.fleet.files import FleetTables, read_fleet_tables
from registration.fleet.files_write import write_fleet_tables
from registration.fleet.online import FleetFilter, OnlineOptions, register_online
from registration.fleet.online_result import OnlineHistory, OnlineResult
from registration.fleet.problem import Exclusion, FleetProblem, build_problem
from registration.fleet.result import BatchResult, ChiSquareCheck
from registration.fleet.scenario import FleetScenario, fleet_scenario
from registration.fleet.solver import BatchOptions

__all__ = ["BatchOptions", "BatchResult", "ChiSquareCheck", "Exclusion", "FleetFilter", "FleetProblem", "FleetScenario",
           "FleetTables", "OnlineHistory", "OnlineOptions", "OnlineResult", "register_online",
           "FusedTargets", "build_problem", "fleet_scenario", "read_fleet_tables", "solve_batch", "write_fleet_tables"]
__all__ += ["AssociationOptions", "AssociationResult", "AssociationScenario", "associate_and_register",
            "association_scenario", "association_scores"]
