"""The residual diagnostics of a ``fleet register`` / ``fleet simulate`` run
(:mod:`registration.fleet.diagnostics`): the significant findings printed as warnings, one line
each; for a run outside its consistency band, which sensors and bins carry the excess; the bins and
fits for summary.json; ``diagnostics_<sensor>.png`` with the plots."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from registration.cli.errors import writing

__all__ = ["kinds_by_row", "run_diagnostics", "write_diagnostics_figures"]


def kinds_by_row(tables) -> np.ndarray | None:
    """The plots file's ``kind`` per data row of the file ('' where not given or the row was set
    aside), or None when the file has no kind column."""
    kind = tables.plots.get("kind") if tables is not None else None
    if kind is None:
        return None
    rows = tables.file_rows.get("plots")
    out = np.full(tables.rows_read()["plots"], "", dtype=object)
    out[np.arange(len(kind)) if rows is None else rows] = np.asarray(kind, dtype=object)
    return out


def run_diagnostics(problem, result, kinds: np.ndarray | None = None, *, consistent: bool = True):
    """The diagnostics of the run, their lines printed (the findings as warnings; with
    ``consistent`` false, the sensors and bins that carry the chi-square's excess); None when the
    result has no residuals per plot row of ``problem``."""
    from registration.fleet.diagnostics import diagnose

    e = getattr(result, "residuals", None)
    if e is None or problem.row.size == 0 or int(problem.row.max()) >= e.shape[0]:
        return None
    d = diagnose(problem, result, kinds)
    print(
        f"\nDiagnostics: residuals per sensor binned by azimuth, range, time, plot kind and target; "
        f"{d.n_tests} tests, |z| above {d.threshold:.2f} is significant (false alarms about 1 % per run)"
    )
    lines = d.finding_lines()
    for line in lines:
        print(f"WARNING: {line}")
    if not lines:
        print("  no significant finding")
    if not consistent:
        for line in d.excess_lines():
            print(line)
    return d


def write_diagnostics_figures(out: Path, d) -> list[Path]:
    """``diagnostics_<sensor>.png`` per sensor (characters other than letters, digits, ``.-_`` of
    the sensor id as ``_``)."""
    from registration.core.plotting import save_figure
    from registration.fleet.diagnostics.figure import diagnostics_figure

    written = []
    for sensor in d.plots:
        path = out / f"diagnostics_{re.sub(r'[^A-Za-z0-9._-]', '_', sensor)}.png"
        with writing(path):
            written.append(save_figure(diagnostics_figure(d, sensor), path))
    return written
