"""The one contract between the fleet tables and the solvers that read them by parts:
:class:`FleetSource`, what :func:`registration.fleet.batch.partitioned.solve_batch_partitioned` and
its outputs pass (:func:`registration.fleet.batch.outputs.archive_outputs`) call on the tables.

Its implementations live with the readers and writers (:mod:`registration.io.fleet`): the tables
in memory (``TablesSource``), a checked folder read whole (``FleetTables``, what
``read_fleet_tables`` gives) and a Parquet or CSV archive read lazily by time range
(``ParquetSource``). Whatever the files hold, a source gives the columns of
:mod:`registration.fleet.data.tables`: SI units (s, m) and radians, ids as text (numpy arrays of
str or, in the first passes over a large archive, ``pandas.Categorical``: no Python string per row).

A column dict (:data:`Columns`) maps a table column name to a 1-D array, every array of one length
(the rows). The plots have ``time`` (s), ``sensor``, ``target``, ``range`` (m), ``bearing``,
``elevation`` (rad); the navigation ``time`` (s), ``platform``, ``lat``, ``lon`` (rad), ``alt``
(m), ``heading``, ``pitch``, ``roll`` (rad); the references ``time`` (s), ``target`` and the known
position (``lat``, ``lon`` rad, ``alt`` m, or ECEF ``x``, ``y``, ``z`` m) with ``sigma`` and
``sigma_up`` (m). A source is pickled to the workers of a ``dask.distributed`` cluster, so it
holds no open file between calls.
"""

from __future__ import annotations

from typing import Any, Iterable, Iterator, Mapping, Protocol, runtime_checkable

__all__ = ["Columns", "FleetSource"]

#: A table as columns: column name -> 1-D array (numpy, or pandas.Categorical for ids), equal lengths.
Columns = Mapping[str, Any]


@runtime_checkable
class FleetSource(Protocol):
    """Fleet tables as a solver reads them by parts (module docstring): whole passes over a few
    columns in batches, then the rows of a time range, per partition."""

    @property
    def in_memory(self) -> bool:
        """True for tables held in memory (a partition's reads cost no file access: the solver keeps
        every partition's design in memory rather than spilling it to disk)."""
        ...

    @property
    def token(self) -> str:
        """A text naming these tables (a new one per source), for the caches of the partitions."""
        ...

    @property
    def sensors(self) -> Columns:
        """The sensors table, whole (``sensor``, ``platform``, ``sigma_*`` m or rad, ``prior_*``
        m, rad, s or dimensionless (inf: no prior), ``lever_*`` m)."""
        ...

    @property
    def platforms(self) -> Columns | None:
        """The platforms table, whole (``platform``, ``prior_heading``, ``prior_pitch``,
        ``prior_roll`` rad), or None when there is none."""
        ...

    @property
    def targets(self) -> Columns | None:
        """The surface targets table, whole (``target``, ``name``, ``surface_alt`` m,
        ``sigma_surface`` m), or None when there is none."""
        ...

    def name(self, table: str) -> str:
        """What errors call ``table`` (``plots``, ``navigation``, ``sensors``, ``platforms``,
        ``reference`` or ``references``, ``targets``): its file, or the table's name in memory."""
        ...

    def plot_batches(self, columns: Iterable[str]) -> Iterator[Columns]:
        """Every plot, in batches of rows, only ``columns`` (table column names)."""
        ...

    def navigation_batches(self, columns: Iterable[str]) -> Iterator[Columns]:
        """Every navigation row, in batches of rows, only ``columns``."""
        ...

    def reference_batches(self, columns: Iterable[str]) -> Iterator[Columns]:
        """Every reference row, in batches of rows, only ``columns`` (those of them the table has:
        the optional ``height_offset_prior`` may be missing); none without references."""
        ...

    def read_plots(self, lo: float, hi: float) -> Columns:
        """The plots with ``lo <= time <= hi`` (s), every column, in the table's order."""
        ...

    def read_references(self, lo: float, hi: float) -> Columns | None:
        """The references with ``lo <= time <= hi`` (s), every column; None without references."""
        ...

    def read_navigation(self, ranges: Mapping[str, tuple[float, float]]) -> Columns:
        """The navigation rows of each platform of ``ranges`` (platform id -> (first, last) time, s)
        within its time range, every column (a source of files sorts them by platform, then time)."""
        ...
