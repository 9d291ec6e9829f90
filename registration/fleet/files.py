"""Fleet tables as files: CSV or Parquet in file units (degrees, metres, seconds), converted to the
long-form tables of :mod:`registration.fleet.tables` (SI units, radians); written back by
:mod:`registration.fleet.files_write`.

File columns (one row per item; an empty cell is "not given"):

* ``plots``: ``time_s``, ``sensor``, ``target`` (optional: without it the plots are to be
  associated, :mod:`registration.fleet.association`), ``range_m``, ``bearing_deg``, ``elevation_deg``
  (an empty cell: the sensor does not measure that channel);
* ``navigation``: ``time_s``, ``platform``, ``lat_deg``, ``lon_deg``, ``alt_m``, ``heading_deg``,
  ``pitch_deg``, ``roll_deg`` as reported (one row for a fixed site);
* ``sensors``: ``sensor``, ``platform``, ``sigma_range_m``, ``sigma_bearing_deg``,
  ``sigma_elevation_deg`` (empty: channel not measured); optional prior sigmas of the biases
  ``prior_range_bias_m``, ``prior_bearing_bias_deg``, ``prior_elevation_bias_deg`` (empty or
  ``inf``: no prior; 0: known to be zero, held fixed) and lever arm ``lever_x_m``, ``lever_y_m``,
  ``lever_z_m`` (deck frame: starboard, bow, up; default 0); optional extended errors, each
  modelled only when its column is there: ``prior_range_gain`` (dimensionless, at most 0.1),
  ``prior_time_bias_s``, ``prior_position_m`` (one sigma for east, north and up), same meaning
  (docs/fleet.md, "Sensor error model");
* ``platforms`` (optional): ``platform``, ``prior_heading_deg``, ``prior_pitch_deg``,
  ``prior_roll_deg`` (same meaning as the bias priors);
* ``reference`` (optional): ``time_s``, ``target`` and the known position as ``lat_deg``,
  ``lon_deg``, ``alt_m`` or as ECEF ``x_m``, ``y_m``, ``z_m``; optional ``sigma_m`` (per axis).

Every cell problem raises a ValueError naming the file, the row (from 0, the first data row), the
column and its unit. Rows keep their file order, so the row numbers of the errors of
:func:`~registration.fleet.problem.build_problem` are file rows too (:meth:`FleetTables.problem`
names the file in them). With ``on_bad_row="skip"`` the bad rows of the plots and reference files
are set aside instead, each with a reason code (:mod:`registration.fleet.rejects`).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from registration.fleet.problem import FleetProblem, build_problem, plot_row_problems
from registration.fleet.rejects import BadRows, NoValidPlotsError, RejectedRow, check_mode, rejected_frame
from registration.fleet.tables import DEFAULT_REFERENCE_SIGMA

__all__ = ["FILE_COLUMNS", "FleetTables", "read_fleet_tables",
           "MIN_UNIT_CHECK_VALUES"]

#: Per table: (file column, table column, unit, required, (low, high) accepted in file units).
#: unit "id" = an identifier; "deg" columns are converted to radians.
FILE_COLUMNS = {
    "plots": (("time_s", "time", "s", True, None), ("sensor", "sensor", "id", True, None),
              ("target", "target", "id", False, None), ("range_m", "range", "m", False, (0.0, 1e8)),
              ("bearing_deg", "bearing", "deg", False, (-360.0, 360.0)),
              ("elevation_deg", "elevation", "deg", False, (-90.0, 90.0))),
    "navigation": (("time_s", "time", "s", True, None), ("platform", "platform", "id", True, None),
                   ("lat_deg", "lat", "deg", True, (-90.0, 90.0)), ("lon_deg", "lon", "deg", True, (-360.0, 360.0)),
                   ("alt_m", "alt", "m", True, (-1.2e4, 1e6)), ("heading_deg", "heading", "deg", True, (-360.0, 360.0)),
                   ("pitch_deg", "pitch", "deg", True, (-90.0, 90.0)), ("roll_deg", "roll", "deg", True, (-90.0, 90.0))),
    "sensors": (("sensor", "sensor", "id", True, None), ("platform", "platform", "id", True, None),
                ("sigma_range_m", "sigma_range", "m", False, (0.0, 1e6)),
                ("sigma_bearing_deg", "sigma_bearing", "deg", False, (0.0, 20.0)),
                ("sigma_elevation_deg", "sigma_elevation", "deg", False, (0.0, 20.0)),
                ("prior_range_bias_m", "prior_range", "m", False, (0.0, math.inf)),
                ("prior_bearing_bias_deg", "prior_bearing", "deg", False, (0.0, math.inf)),
                ("prior_elevation_bias_deg", "prior_elevation", "deg", False, (0.0, math.inf)),
                ("lever_x_m", "lever_x", "m", False, (-1e4, 1e4)), ("lever_y_m", "lever_y", "m", False, (-1e4, 1e4)),
                ("lever_z_m", "lever_z", "m", False, (-1e4, 1e4)),
                ("prior_range_gain", "prior_range_gain", "dimensionless", False, (0.0, 0.1)),
                ("prior_time_bias_s", "prior_time_bias", "s", False, (0.0, math.inf)),
                ("prior_position_m", "prior_position", "m", False, (0.0, math.inf))),
    "platforms": (("platform", "platform", "id", True, None),
                  ("prior_heading_deg", "prior_heading", "deg", False, (0.0, math.inf)),
                  ("prior_pitch_deg", "prior_pitch", "deg", False, (0.0, math.inf)),
                  ("prior_roll_deg", "prior_roll", "deg", False, (0.0, math.inf))),
    "reference": (("time_s", "time", "s", True, None), ("target", "target", "id", True, None),
                  ("lat_deg", "lat", "deg", False, (-90.0, 90.0)), ("lon_deg", "lon", "deg", False, (-360.0, 360.0)),
                  ("alt_m", "alt", "m", False, (-1.2e4, 1e8)), ("x_m", "x", "m", False, (-1e8, 1e8)),
                  ("y_m", "y", "m", False, (-1e8, 1e8)), ("z_m", "z", "m", False, (-1e8, 1e8)),
                  ("sigma_m", "sigma", "m", False, (0.0, 1e6))),
}
#: Sigma columns whose value must be > 0 (a prior may be 0: fixed).
_POSITIVE = {"range_m", "sigma_range_m", "sigma_bearing_deg", "sigma_elevation_deg", "sigma_m"}
#: Fewest values of a bearing column (or of lat/lon) for the radians-in-degrees check.
MIN_UNIT_CHECK_VALUES = 100
#: Table name -> the library table name used in build_problem's errors.
_LIBRARY_NAME = {"plots": "plots", "navigation": "navigation", "sensors": "sensors", "platforms": "platforms",
                 "reference": "references"}
#: Table column -> file column, of the plots and reference files (the columns rows are set aside for).
_FILE_COLUMN = {key: column for name in ("plots", "reference") for column, key, *_ in FILE_COLUMNS[name]}


@dataclass
class FleetTables:
    """The tables read from files, in SI units and radians (mappings of column -> array, ready for
    :func:`~registration.fleet.problem.build_problem`), and the file each came from.

    ``rejected``: the rows set aside (``on_bad_row="skip"``), in file order then row order;
    ``file_rows``: per table with rows set aside, the file row (from 0) of each row kept (K,).
    """

    plots: dict
    navigation: dict
    sensors: dict
    platforms: dict | None = None
    references: dict | None = None
    paths: dict = field(default_factory=dict)
    rejected: list[RejectedRow] = field(default_factory=list)
    file_rows: dict = field(default_factory=dict)

    def problem(self) -> FleetProblem:
        """:func:`build_problem` on the tables; its errors name the file the row is in. With rows
        set aside, ``problem.row`` holds file rows and ``problem.n_input_plots`` the plots file's
        data rows (kept and set aside), so per-row outputs line up with the file."""
        try:
            problem = build_problem(self.plots, self.sensors, self.navigation, self.platforms, self.references)
        except ValueError as exc:
            raise _file_error(exc, self.paths, self.file_rows) from exc
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
        tables = {"plots": self.plots, "navigation": self.navigation, "sensors": self.sensors,
                  "platforms": self.platforms, "reference": self.references}
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
            # the library speaks SI units and radians; say so where its message quotes an angle
            text = f"{path}: " + rest + (" (values in SI units and radians)" if re.search(r"\brad\b", rest) else "")
            break
    return ValueError(text)


def _read_frame(path: Path):
    """A CSV or Parquet file as a DataFrame, id columns as text."""
    import pandas as pd

    from registration.recorded.formats import file_format

    fmt = file_format(path)
    if not path.is_file():
        raise ValueError(f"{path}: no such file")
    try:
        if fmt == "csv":
            frame = pd.read_csv(path, dtype={"sensor": str, "platform": str, "target": str}, skipinitialspace=True)
        else:
            frame = pd.read_parquet(path)
    except Exception as exc:  # pandas/pyarrow parse errors of many types
        raise ValueError(f"{path}: cannot read it as {fmt.upper()}: {exc}") from exc
    frame.columns = [str(c).strip() for c in frame.columns]
    return frame


def _id_column(bad: BadRows, frame, column: str) -> np.ndarray:
    values = frame[column]
    bad.add(column, "empty_id", values.isna().to_numpy(), lambda r: "empty; every row needs an id")
    return np.array([str(v).strip() for v in values], dtype=object).astype(str)


def _number_column(bad: BadRows, frame, column: str, unit: str, required: bool, limits) -> np.ndarray:
    """Numbers in file units; NaN for an empty optional cell. Problems name file, row, column, unit."""
    import pandas as pd

    raw = frame[column]
    values = pd.to_numeric(raw, errors="coerce").to_numpy(dtype=np.float64)
    given = raw.notna().to_numpy() & ~raw.astype(str).str.strip().isin(["", "nan", "NaN"]).to_numpy()
    bad.add(column, "non_numeric", given & np.isnan(values), lambda r: f"{raw.iloc[r]!r} is not a number ({unit})")
    if required:
        bad.add(column, "non_finite", np.isnan(values), lambda r: f"empty or NaN; a number ({unit}) is required")
    lo, hi = limits if limits is not None else (-math.inf, math.inf)
    strict = column in _POSITIVE
    finite_only = not (column.startswith("prior_") and hi == math.inf)
    out = ((values <= lo) if strict else (values < lo)) | (values > hi) | (finite_only & np.isinf(values))
    span = f"{'(' if strict else '['}{lo:g}, {hi:g}]"

    def code(r: int) -> str:
        if np.isinf(values[r]):
            return "non_finite"
        return "non_positive_range" if column == "range_m" and values[r] <= 0 else "out_of_range"
    bad.add(column, code, out, lambda r: f"{values[r]:g} {unit} is outside {span} {unit}")
    return values


def _radians_check(path, columns: dict) -> None:
    """Radians in degree columns: every bearing within +-2 pi, or every lat within +-pi/2 and lon
    within +-2 pi, over at least MIN_UNIT_CHECK_VALUES values (degrees span far more)."""
    checks = [("bearing_deg",), ("lat_deg", "lon_deg")]
    for names in checks:
        if not all(n in columns for n in names):
            continue
        vals = [columns[n][np.isfinite(columns[n])] for n in names]
        if min(v.size for v in vals) < MIN_UNIT_CHECK_VALUES or not any(np.any(v != 0) for v in vals):
            continue
        bounds = (2 * math.pi,) if len(names) == 1 else (math.pi / 2, 2 * math.pi)
        if all(np.max(np.abs(v)) <= b for v, b in zip(vals, bounds)):
            col = columns[names[0]]
            r = int(np.nanargmax(np.abs(col)))
            raise ValueError(f"{path}: row {r}, column {names[0]!r}: all {vals[0].size} values of "
                             f"{' and '.join(repr(n) for n in names)} lie within +-{np.max(np.abs(vals[0])):.3g} "
                             f"(the largest here, {col[r]:.4g}): radians? These columns are in degrees")


def _read_one(name: str, path: Path, skip: bool) -> tuple[dict, BadRows]:
    """One file -> table dict in SI units and radians (columns of :mod:`registration.fleet.tables`)
    and its bad rows (``skip`` False: the first bad cell raises)."""
    frame = _read_frame(path)
    spec = FILE_COLUMNS[name]
    missing = [c for c, _, _, req, _ in spec if req and c not in frame.columns]
    if missing:
        raise ValueError(f"{path}: missing column(s) {missing}; the {name} table has columns "
                         f"{[c for c, *_ in spec]} (columns found: {list(frame.columns)})")
    known = {c for c, *_ in spec}
    unknown = [c for c in frame.columns if c not in known]
    if unknown:
        raise ValueError(f"{path}: unknown column(s) {unknown}; the {name} table has columns {sorted(known)}")
    bad = BadRows(path, len(frame), skip)
    numbers, out = {}, {}
    for column, key, unit, required, limits in spec:
        if column not in frame.columns:
            continue
        if unit == "id":
            out[key] = _id_column(bad, frame, column)
            continue
        numbers[column] = _number_column(bad, frame, column, unit, required, limits)
        out[key] = np.radians(numbers[column]) if unit == "deg" else numbers[column]
        if column.startswith("prior_"):
            out[key] = np.where(np.isnan(out[key]), np.inf, out[key])  # empty: no prior
    ok = bad.ok()
    _radians_check(path, {c: np.where(ok, v, np.nan) for c, v in numbers.items()})
    return out, bad


def _check_ids(tables: dict, paths: dict, bads: dict) -> None:
    """Cross references between files: sensors of the plots, platforms of the sensors."""
    checks = [("plots", "sensor", "sensors", "sensor"), ("sensors", "platform", "navigation", "platform")]
    if "platforms" in tables:
        checks.append(("sensors", "platform", "platforms", "platform"))
    for table, column, other, key in checks:
        known = {str(v) for v in tables[other][key]}
        values = tables[table][column]
        bads[table].add(column, f"unknown_{column}", ~np.isin(values, list(known)),
                        lambda r: f"unknown {column} {str(values[r])!r}; {paths[other]} lists {sorted(known)}")


def _take(table: dict, keep: np.ndarray) -> dict:
    return {k: np.asarray(v)[keep] for k, v in table.items()}


def _skip_plot_rows(tables: dict, paths: dict, bad: BadRows) -> np.ndarray:
    """Set aside the plots rows :func:`build_problem` would raise for; (N,) bool of the rows kept."""
    rows = np.flatnonzero(bad.ok())
    if rows.size == 0:
        return bad.ok()
    ref = tables.get("reference")
    ref_targets = ref["target"] if ref is not None else ()
    try:
        problems = plot_row_problems(_take(tables["plots"], rows), tables["sensors"], tables["navigation"],
                                     tables.get("platforms"), ref_targets)
    except ValueError as exc:
        raise _file_error(exc, paths) from exc
    for p in problems:
        bad.add(lambda i, p=p: _FILE_COLUMN[p.at(i)[1]], lambda i, p=p: p.at(i)[0], p.bad, p.message, rows=rows)
    return bad.ok()


def _skip_rows(tables: dict, paths: dict, bads: dict) -> FleetTables:
    """Skip mode: the tables without the rows set aside, which are listed in ``rejected``."""
    keep = _skip_plot_rows(tables, paths, bads["plots"])
    if keep.size and not keep.any():
        rejected = [r for b in bads.values() for r in b.rejected()]
        raise NoValidPlotsError(str(paths["plots"]), keep.size, rejected)
    tables["plots"] = _take(tables["plots"], keep)
    file_rows = {"plots": np.flatnonzero(keep)}
    ref = tables.get("reference")
    if ref is not None:
        targets = set(tables["plots"].get("target", ()))
        bads["reference"].add("target", "unknown_target", bads["reference"].ok() & ~np.isin(ref["target"], list(targets)),
                              lambda r: f"reference target {str(ref['target'][r])!r} has no plots kept "
                                        f"(targets: {sorted(targets)})")
        file_rows["reference"] = np.flatnonzero(bads["reference"].ok())
        tables["reference"] = _take(ref, file_rows["reference"])
    rejected = [r for b in bads.values() for r in b.rejected()]
    return FleetTables(tables["plots"], tables["navigation"], tables["sensors"], tables.get("platforms"),
                       tables.get("reference"), paths, rejected, file_rows)


def read_fleet_tables(plots, navigation, sensors, platforms=None, reference=None, *,
                      on_bad_row: str = "stop") -> FleetTables:
    """Read the fleet files (paths; ``.csv`` or ``.parquet``) into :class:`FleetTables` (SI, radians).

    ValueError naming the file, row (from 0), column and unit for: an unreadable file, a missing or
    unknown column, a cell that is not a number, an empty required cell, a value out of range, a
    degree column that holds radians, an id not listed in the table it refers to.

    ``on_bad_row="skip"``: a row of the plots or reference file with a bad cell (not a number, an
    empty required cell or id, a value out of range, an unknown sensor), and a plot that
    :func:`build_problem` would refuse (no measured channel, a value in a channel the sensor does
    not measure, outside its platform's navigation time span), is set aside in
    ``FleetTables.rejected`` (file, row, column, reason code, reason) instead; a reference of a
    target left with no plots too. The navigation, sensors and platforms files define the problem
    (the platforms, the sensors and what they measure), so their problems still raise, here rather
    than in :meth:`FleetTables.problem`, as do file-level problems (a missing or unknown column,
    radians in a degree column). :class:`~registration.fleet.rejects.NoValidPlotsError` (a
    ValueError carrying the rejected rows) when no plot row is left.
    """
    if check_mode(on_bad_row) == "stop":
        return _first_bad_row_stops(plots, navigation, sensors, platforms, reference)
    skip = True
    paths = {k: Path(v) for k, v in (("plots", plots), ("navigation", navigation), ("sensors", sensors),
                                     ("platforms", platforms), ("reference", reference)) if v is not None}
    read = {name: _read_one(name, path, skip and name in ("plots", "reference")) for name, path in paths.items()}
    tables = {name: table for name, (table, _) in read.items()}
    bads = {name: bad for name, (_, bad) in read.items()}
    ref = tables.get("reference")
    if ref is not None and not ({"lat", "lon", "alt"} <= set(ref) or {"x", "y", "z"} <= set(ref)):
        raise ValueError(f"{paths['reference']}: give the known positions as lat_deg, lon_deg, alt_m or as x_m, y_m, z_m")
    if ref is not None and "sigma" in ref:
        ref["sigma"] = np.where(np.isnan(ref["sigma"]), DEFAULT_REFERENCE_SIGMA, ref["sigma"])
    if skip and ref is not None:
        for key in ("x", "y", "z") if "x" in ref else ("lat", "lon", "alt"):
            column = _FILE_COLUMN[key]
            bads["reference"].add(column, "non_finite", np.isnan(ref[key]),
                                  lambda r, u=column.rsplit("_", 1)[1]: f"empty or NaN; a number ({u}) is required for the position")
    _check_ids(tables, paths, bads)
    return _skip_rows(tables, paths, bads)


def _first_bad_row_stops(plots, navigation, sensors, platforms, reference) -> FleetTables:
    """Stop mode: every row is checked as in skip mode, then the first bad row of the plots file (else
    of the reference file) raises, so the error names the earliest row whatever column is wrong."""
    try:
        tables = read_fleet_tables(plots, navigation, sensors, platforms, reference, on_bad_row="skip")
    except NoValidPlotsError as exc:
        rejected = exc.rejected
    else:
        rejected = tables.rejected
        if not rejected:
            tables.file_rows = {}
            return tables
    order = {str(Path(p)): k for k, p in enumerate((plots, reference)) if p is not None}
    first = min(rejected, key=lambda r: (order.get(r.file, len(order)), r.row))
    raise ValueError(f"{first.file}: row {first.row}, column {first.column!r}: {first.reason}")
