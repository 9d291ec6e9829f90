"""Fleet tables as files: CSV or Parquet in file units (degrees, metres, seconds), converted to the
long-form tables of :mod:`registration.fleet.data.tables` (SI units, radians); written back by
:mod:`registration.io.fleet.write`.

File columns (one row per item; an empty cell is "not given"):

* ``plots``: ``time_s``, ``sensor``, ``target`` (optional; an empty cell is "no id": the plots
  without one are associated, :mod:`registration.fleet.association.associate`), ``track``
  (optional: a sensor-local track id, such as an ARPA radar's target number; an empty cell is
  none), ``range_m``, ``bearing_deg``, ``elevation_deg`` (an empty cell: the sensor does not measure
  that channel);
* ``navigation``: ``time_s``, ``platform``, ``lat_deg``, ``lon_deg``, ``alt_m``, ``heading_deg``,
  ``pitch_deg``, ``roll_deg`` as reported (one row for a fixed site);
* ``sensors``: ``sensor``, ``platform``, ``sigma_range_m``, ``sigma_bearing_deg``,
  ``sigma_elevation_deg`` (empty: channel not measured); optional prior sigmas of the biases
  ``prior_range_bias_m``, ``prior_bearing_bias_deg``, ``prior_elevation_bias_deg`` (empty or
  ``inf``: no prior; 0: known to be zero, held fixed) and lever arm ``lever_x_m``, ``lever_y_m``,
  ``lever_z_m`` (deck frame: starboard, bow, up; default 0); optional extended errors, each
  modelled only when its column is there: ``prior_range_gain`` (dimensionless, at most 0.1),
  ``prior_time_bias_s``, ``prior_position_m`` (one sigma for east, north and up), same meaning
  (docs/background/fleet-model.md, "Sensor error model");
* ``platforms`` (optional): ``platform``, ``prior_heading_deg``, ``prior_pitch_deg``,
  ``prior_roll_deg`` (same meaning as the bias priors);
* ``reference`` (optional): ``time_s``, ``target`` and the known position as ``lat_deg``,
  ``lon_deg``, ``alt_m`` or as ECEF ``x_m``, ``y_m``, ``z_m``; optional ``sigma_m`` (m per axis,
  default 1 m; the horizontal sigma when ``sigma_up_m`` is given) and ``sigma_up_m`` (m, along the
  local up at the position; an empty cell or no column: the same as ``sigma_m``).

Every cell problem raises a ValueError naming the file, the row (from 0, the first data row), the
column and its unit; a CSV line with fewer or more fields than the header is a bad row too
(``short_row``, ``long_row``; the ``cells`` module). Rows keep their file order, so the row numbers
of the errors of :func:`~registration.fleet.data.problem.build_problem` are file rows too
(:meth:`FleetTables.problem` names the file in them). With ``on_bad_row="skip"`` the bad rows of
the plots and reference files are set aside instead, each with a reason code (``rejects``).
Navigation rows of platforms that carry no sensor are left out with a note
(:attr:`FleetTables.notes`), as are findings that look like radians without proof (``checks``).
"""

from __future__ import annotations

import re
import uuid
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Callable

import numpy as np

from registration.fleet.data.plot_rows import RowProblem
from registration.fleet.data.problem import FleetProblem, build_problem, plot_row_problems
from registration.fleet.data.tables import DEFAULT_REFERENCE_SIGMA
from registration.io.fleet.folder import TABLE_NAMES
from registration.io.fleet.memory import TablesSource
from registration.io.fleet.reading.cells import FILE_COLUMNS, FileRead, read_file
from registration.io.fleet.reading.checks import (
    MIN_UNIT_CHECK_VALUES,
    channel_columns_check,
    missing_channel_notes,
)
from registration.io.fleet.reading.rejects import (
    BadRows,
    NoValidPlotsError,
    RejectedRow,
    check_mode,
    rejected_frame,
)
from registration.io.fleet.reading.setaside import check_duplicates, set_aside_notes, stopping_rows

__all__ = ["FILE_COLUMNS", "FleetTables", "read_fleet_tables", "needs_association", "MIN_UNIT_CHECK_VALUES"]

#: The one target id the file checks put plots without a target id under (they are never set aside).
UNLABELLED = "\x1f(no id)"


def needs_association(plots: dict) -> bool:
    """True when some plots carry no target id (no ``target`` column, or empty cells in it): the plots
    are then associated with targets (:func:`registration.fleet.associate_and_register`), and the
    references are anchors for them rather than targets of the plots' ids."""
    return "target" not in plots or bool(np.any(np.asarray(plots["target"]) == ""))


#: Table name -> the library table name used in build_problem's errors.
_LIBRARY_NAME = {
    "plots": "plots",
    "navigation": "navigation",
    "sensors": "sensors",
    "platforms": "platforms",
    "reference": "references",
    "targets": "targets",
}
#: Table column -> file column, of the plots and reference files (the columns rows are set aside for).
_FILE_COLUMN = {key: column for name in ("plots", "reference") for column, key, *_ in FILE_COLUMNS[name]}


@dataclass
class FleetTables(TablesSource):
    """The tables read from files, in SI units and radians (mappings of column -> array, ready for
    :func:`~registration.fleet.data.problem.build_problem`), and the file each came from: a checked
    folder, a :class:`~registration.fleet.data.source.FleetSource` whose errors name the files.

    ``rejected``: the rows set aside (``on_bad_row="skip"``), in file order then row order;
    ``file_rows``: per table with rows set aside (or, for the navigation, rows of platforms without
    sensors left out), the file row (from 0) of each row kept (K,); ``notes``: what the reader
    ignored or found suspicious without refusing it (navigation of platforms without sensors,
    sigmas or attitudes that look like radians), one text each, naming the file.
    """

    plots: dict
    navigation: dict
    sensors: dict
    platforms: dict | None = None
    references: dict | None = None
    paths: dict = field(default_factory=dict)
    rejected: list[RejectedRow] = field(default_factory=list)
    file_rows: dict = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    targets: dict | None = None
    token: str = field(default_factory=lambda: uuid.uuid4().hex, repr=False, compare=False)

    def name(self, table: str) -> str:
        """The file of ``table`` (``references``: the reference file), else the table's name."""
        path = self.paths.get("reference" if table == "references" else table)
        return table if path is None else str(path)

    def problem(self) -> FleetProblem:
        """:func:`build_problem` on the tables; its errors name the file the row is in. With rows
        set aside, ``problem.row`` holds file rows and ``problem.n_input_plots`` the plots file's
        data rows (kept and set aside), so per-row outputs line up with the file. The reader's
        ``notes`` come first in ``problem.notes``."""
        try:
            problem = build_problem(
                self.plots, self.sensors, self.navigation, self.platforms, self.references, self.targets
            )
        except ValueError as exc:
            raise _file_error(exc, self.paths, self.file_rows) from exc
        problem = replace(problem, notes=(*self.notes, *problem.notes))
        rows = self.file_rows.get("plots")
        if rows is None:
            return problem
        return replace(problem, row=rows[problem.row], n_input_plots=self.rows_read()["plots"])

    def rows(self) -> dict:
        """Rows per table kept."""
        return {name: int(len(next(iter(t.values())))) for name, t in self._tables().items()}

    def rows_read(self) -> dict:
        """Data rows per file read: kept plus set aside."""
        out = self.rows()
        for r in self.rejected:
            name = next(n for n, p in self.paths.items() if str(p) == r.file)
            out[name] = out.get(name, 0) + 1
        return out

    def rejected_frame(self):
        """The rows set aside as a pandas DataFrame with columns ``file``, ``row``, ``column``,
        ``code``, ``reason`` (no rows when none was set aside)."""
        return rejected_frame(self.rejected)

    def _tables(self) -> dict:
        tables = {
            "plots": self.plots,
            "navigation": self.navigation,
            "sensors": self.sensors,
            "platforms": self.platforms,
            "reference": self.references,
            "targets": self.targets,
        }
        return {k: v for k, v in tables.items() if v is not None}


def _file_error(exc: ValueError, paths: dict, file_rows: dict | None = None) -> ValueError:
    """A :func:`build_problem` error with the table's name replaced by its file's, and a row of a
    table with rows set aside given as its file row."""
    text = str(exc)
    for name, path in paths.items():
        lib = _LIBRARY_NAME[name]
        m = re.match(rf"{lib}( row (\d+))?[ :]", text)
        if m:
            rest = re.sub(rf"^{lib} ", "", text)
            if m.group(2) and file_rows and name in file_rows:
                rest = re.sub(r"^row \d+", f"row {int(file_rows[name][int(m.group(2))])}", rest)
            named = re.match(r"^row (\d+): (\w+) ", rest)
            files = {key: column for column, key, *_ in FILE_COLUMNS[name]}
            if named and named.group(2) in files:  # the row's column, as the file names it
                rest = f"row {named.group(1)}, column {files[named.group(2)]!r}: " + rest[named.end(1) + 2 :]
            # the library speaks SI units and radians; say so where its message quotes an angle
            text = (
                f"{path}: "
                + rest
                + (" (values in SI units and radians)" if re.search(r"\brad\b", rest) else "")
            )
            break
    return ValueError(text)


def _check_ids(tables: dict, paths: dict, bads: dict) -> None:
    """Cross references between files: sensors of the plots, platforms of the sensors."""
    checks = [("plots", "sensor", "sensors", "sensor"), ("sensors", "platform", "navigation", "platform")]
    if "platforms" in tables:
        checks.append(("sensors", "platform", "platforms", "platform"))
    for table, column, other, key in checks:
        known = {str(v) for v in tables[other][key]}
        values = tables[table][column]
        bads[table].add(
            column,
            f"unknown_{column}",
            ~np.isin(values, list(known)),
            lambda r: f"unknown {column} {str(values[r])!r}; {paths[other]} lists {sorted(known)}",
        )


def _take(table: dict, keep: np.ndarray) -> dict:
    return {k: np.asarray(v)[keep] for k, v in table.items()}


def _skip_plot_rows(tables: dict, paths: dict, bad: BadRows, file_rows: dict) -> np.ndarray:
    """Set aside the plots rows :func:`build_problem` would raise for; (N,) bool of the rows kept.
    ``file_rows``: the file rows of the tables with rows left out, for the other tables' errors."""
    rows = np.flatnonzero(bad.ok())
    if rows.size == 0:
        return bad.ok()
    ref = tables.get("reference")
    ref_targets = list(ref["target"]) if ref is not None else []
    plots = _take(tables["plots"], rows)
    if needs_association(plots):
        # the association uses every plot (none is set aside as its target's only sensor's): all are
        # checked as one target that is never set aside
        plots["target"] = np.full(rows.size, UNLABELLED)
        ref_targets.append(UNLABELLED)
    try:
        problems = plot_row_problems(
            plots, tables["sensors"], tables["navigation"], tables.get("platforms"), ref_targets
        )
    except ValueError as exc:
        raise _file_error(exc, paths, file_rows) from exc
    for p in problems:
        bad.add(_column_of(p), _code_of(p), p.bad, p.message, rows=rows)
    return bad.ok()


def _always(reason: str) -> Callable[[int], str]:
    """The same reason for every row."""
    return lambda r: reason


def _column_of(problem: RowProblem) -> Callable[[int], str]:
    """The file column of each row of a :class:`RowProblem`."""
    return lambda i: _FILE_COLUMN[problem.at(i)[1]]


def _code_of(problem: RowProblem) -> Callable[[int], str]:
    """The reason code of each row of a :class:`RowProblem`."""
    return lambda i: problem.at(i)[0]


def _skip_rows(tables: dict, paths: dict, bads: dict, file_rows: dict) -> FleetTables:
    """Skip mode: the tables without the rows set aside, which are listed in ``rejected``;
    ``file_rows``: as :attr:`FleetTables.file_rows`, of the tables with rows left out so far."""
    keep = _skip_plot_rows(tables, paths, bads["plots"], file_rows)
    if keep.size and not keep.any():
        rejected = [r for b in bads.values() for r in b.rejected()]
        raise NoValidPlotsError(str(paths["plots"]), keep.size, rejected)
    tables["plots"] = _take(tables["plots"], keep)
    file_rows = {**file_rows, "plots": np.flatnonzero(keep)}
    ref = tables.get("reference")
    if ref is not None:
        if not needs_association(tables["plots"]):  # else the references are anchors for the association
            targets = set(tables["plots"].get("target", ()))
            bads["reference"].add(
                "target",
                "unknown_target",
                bads["reference"].ok() & ~np.isin(ref["target"], list(targets)),
                lambda r: (
                    f"reference target {str(ref['target'][r])!r} has no plots kept "
                    f"(targets: {sorted(targets)})"
                ),
            )
        file_rows["reference"] = np.flatnonzero(bads["reference"].ok())
        tables["reference"] = _take(ref, file_rows["reference"])
    rejected = [r for b in bads.values() for r in b.rejected()]
    return FleetTables(
        tables["plots"],
        tables["navigation"],
        tables["sensors"],
        tables.get("platforms"),
        tables.get("reference"),
        paths,
        rejected,
        file_rows,
    )


def read_fleet_tables(
    plots, navigation, sensors, platforms=None, reference=None, *, targets=None, on_bad_row: str = "stop"
) -> FleetTables:
    """Read the fleet files (paths; ``.csv`` or ``.parquet``) into :class:`FleetTables` (SI, radians).

    ValueError naming the file, row (from 0), column and unit for: an unreadable file, a missing or
    unknown column, a file without data rows, a line with fewer or more fields than the header, a
    cell that is not a number, an empty required cell, a value out of range, a degree column that
    holds radians, an id not listed in the table it refers to, plots with values in a channel
    whose sigma column the sensors file lacks (the sensors file's error).

    ``on_bad_row="skip"``: a row of the plots or reference file with a bad cell (not a number, an
    empty required cell or id, a value out of range, an unknown sensor), and a plot that
    :func:`build_problem` would refuse (no measured channel, a value in a channel the sensor does
    not measure, outside its platform's navigation time span), is set aside in
    ``FleetTables.rejected`` (file, row, column, reason code, reason) instead; a reference of a
    target left with no plots too. The navigation, sensors and platforms files define the problem
    (the platforms, the sensors and what they measure), so their problems still raise, here rather
    than in :meth:`FleetTables.problem`, as do file-level problems (a missing or unknown column,
    radians in a degree column); so do the optional ``targets`` file's (``target``, ``name``,
    ``surface_alt_m``, ``sigma_surface_m``: targets on a surface of known height).
    :class:`~registration.io.fleet.reading.rejects.NoValidPlotsError` (a
    ValueError carrying the rejected rows) when no plot row is left. ``FleetTables.notes``: the
    navigation rows left out (platforms without sensors) and what looks like radians without proof.
    """
    if check_mode(on_bad_row) == "stop":
        return _first_bad_row_stops(plots, navigation, sensors, platforms, reference, targets)
    given = zip(TABLE_NAMES, (plots, navigation, sensors, platforms, reference, targets))
    paths = {k: Path(v) for k, v in given if v is not None}
    files = _read_files(paths)
    tables = {name: f.table for name, f in files.items()}
    bads = {name: f.bad for name, f in files.items()}
    channel_columns_check(
        paths["plots"],
        files["plots"].numbers,
        tables["plots"]["sensor"],
        paths["sensors"],
        files["sensors"].columns,
    )
    if "reference" in tables:
        _check_reference_positions(tables["reference"], paths["reference"], bads["reference"])
    _check_ids(tables, paths, bads)
    check_duplicates(tables["plots"], bads["plots"])
    left_out = {k: f.file_rows for k, f in files.items() if f.file_rows is not None}  # unused platforms
    out = _skip_rows(tables, paths, bads, left_out)
    out.notes = [n for f in files.values() for n in f.notes] + set_aside_notes(out.rejected, paths["plots"])
    out.notes += missing_channel_notes(
        paths["plots"],
        files["plots"].columns,
        paths["sensors"],
        files["sensors"].numbers,
        tables["sensors"]["sensor"],
    )
    out.targets = tables.get("targets")
    return out


def _read_files(paths: dict[str, Path]) -> dict[str, FileRead]:
    """Each file of ``paths`` read and checked cell by cell, the plots' and reference's bad rows
    set aside; the navigation's rows of the platforms the sensors and platforms use."""
    files: dict[str, FileRead] = {}
    for name in ("plots", "sensors", "platforms", "navigation", "reference", "targets"):
        if name not in paths:
            continue
        used = None
        if name == "navigation":
            used = {
                str(p) for k in ("sensors", "platforms") if k in files for p in files[k].table["platform"]
            }
        files[name] = read_file(name, paths[name], name in ("plots", "reference"), used)
    return files


def _check_reference_positions(ref: dict, path: Path, bad: BadRows) -> None:
    """A reference position as lat/lon/alt or x/y/z, every cell of it given (a bad row else); an
    empty sigma is the default one."""
    if not ({"lat", "lon", "alt"} <= set(ref) or {"x", "y", "z"} <= set(ref)):
        raise ValueError(f"{path}: give the known positions as lat_deg, lon_deg, alt_m or as x_m, y_m, z_m")
    if "sigma" in ref:
        ref["sigma"] = np.where(np.isnan(ref["sigma"]), DEFAULT_REFERENCE_SIGMA, ref["sigma"])
    for key in ("x", "y", "z") if "x" in ref else ("lat", "lon", "alt"):
        column = _FILE_COLUMN[key]
        reason = f"empty or NaN; a number ({column.rsplit('_', 1)[1]}) is required for the position"
        bad.add(column, "non_finite", np.isnan(ref[key]), _always(reason))


def _first_bad_row_stops(plots, navigation, sensors, platforms, reference, targets=None) -> FleetTables:
    """Stop mode: every row is checked as in skip mode, then the first bad row of the plots file (else
    of the reference file) raises, so the error names the earliest row whatever column is wrong."""
    try:
        tables = read_fleet_tables(
            plots, navigation, sensors, platforms, reference, targets=targets, on_bad_row="skip"
        )
    except NoValidPlotsError as exc:
        rejected = exc.rejected
        if not stopping_rows(rejected):
            raise
    else:
        rejected = tables.rejected
        if not rejected:
            tables.file_rows = {k: v for k, v in tables.file_rows.items() if k == "navigation"}
            return tables
        if not stopping_rows(rejected):
            return tables  # only plots that cannot be used were set aside, with a note
    rejected = stopping_rows(rejected)
    order = {str(Path(p)): k for k, p in enumerate((plots, reference)) if p is not None}
    first = min(rejected, key=lambda r: (order.get(r.file, len(order)), r.row))
    raise ValueError(f"{first.file}: row {first.row}, column {first.column!r}: {first.reason}")
