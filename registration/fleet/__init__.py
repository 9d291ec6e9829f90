"""Fleet registration: the attitude errors of any number of platforms (ships, shore sites) and the
biases of any number of sensors on them (3-D and 2-D radars, passive angle sensors, bearing-only
and range-only sensors), estimated jointly from long-form plot tables.

Modules: ``tables`` (the input tables, their columns and units), ``problem`` (:class:`FleetProblem`,
checked and built by :func:`build_problem`), ``layout`` (the state), ``blocks`` (the target
windows), ``normal``/``schur``/``solver`` (Levenberg-Marquardt with the targets eliminated by the
Schur complement), ``batch`` (:func:`solve_batch`), ``result`` (:class:`BatchResult`),
``covariance``, ``observability``, ``scenario`` (:func:`fleet_scenario`), ``files`` (CSV/Parquet tables in
degrees: :func:`read_fleet_tables`, :func:`write_fleet_tables`), ``plots`` (PNG figures of a result). See docs/fleet.md.
"""

from registration.fleet.batch import solve_batch
from registration.fleet.covariance import FusedTargets
from registration.fleet.files import FleetTables, read_fleet_tables, write_fleet_tables
from registration.fleet.problem import Exclusion, FleetProblem, build_problem
from registration.fleet.result import BatchResult, ChiSquareCheck
from registration.fleet.scenario import FleetScenario, fleet_scenario
from registration.fleet.solver import BatchOptions

__all__ = ["BatchOptions", "BatchResult", "ChiSquareCheck", "Exclusion", "FleetProblem", "FleetScenario",
           "FleetTables",
           "FusedTargets", "build_problem", "fleet_scenario", "read_fleet_tables", "solve_batch", "write_fleet_tables"]
