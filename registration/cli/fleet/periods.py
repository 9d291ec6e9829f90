"""``fleet register --bias-period-s P``: the states estimated once per period of P seconds
(:func:`registration.fleet.periods.solve_periods`), beside the whole run's estimate; the changes
between consecutive periods; ``estimates_by_period.csv``, ``changes.csv``, ``bias_periods.png`` and
the summary's ``bias_periods``. See docs/background/bias-periods.md."""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from registration.cli.errors import writing
from registration.fleet.changes import FALSE_ALARM
from registration.fleet.data.layout import FILE_UNITS

__all__ = [
    "CHANGE_COLUMNS",
    "PERIOD_COLUMNS",
    "PERIOD_OUTPUTS",
    "add_period_argument",
    "change_rows",
    "check_period_options",
    "change_lines",
    "period_rows",
    "periods_summary",
    "solve_bias_periods",
    "write_period_outputs",
]

#: Columns of estimates_by_period.csv (the period, then those of estimates.csv).
PERIOD_COLUMNS = ("period_start_s", "period_end_s", "object", "state", "unit", "estimate", "sigma", "status")
#: Columns of changes.csv.
CHANGE_COLUMNS = ("object", "state", "unit", "time_s", "before", "after", "sigma", "z")
#: What --bias-period-s adds to --out.
PERIOD_OUTPUTS = frozenset({"estimates_by_period.csv", "changes.csv", "bias_periods.png"})


def add_period_argument(reg: argparse.ArgumentParser) -> None:
    """--bias-period-s P."""
    reg.add_argument(
        "--bias-period-s",
        type=float,
        default=None,
        metavar="P",
        help="also estimate every sensor's and platform's states once per period of P s (period k: "
        "time_s in [kP, (k+1)P)), one batch solve per period, into estimates_by_period.csv, and test "
        "them for changes between consecutive periods (changes.csv, 1 %% false-alarm probability over "
        "the run); P at least two --window-s (docs/background/bias-periods.md)",
    )


def check_period_options(args: argparse.Namespace, archive: bool) -> None:
    """ValueError (exit 2) for a --bias-period-s the run cannot use."""
    period = getattr(args, "bias_period_s", None)
    if period is None:
        return
    if not (np.isfinite(period) and period > 0):
        raise ValueError(f"--bias-period-s: expected a length > 0 s, got {period}")
    if period < 2.0 * args.window_s:
        raise ValueError(
            f"--bias-period-s: a period of {period:g} s is shorter than two target windows "
            f"(--window-s {args.window_s:g}); expected at least {2.0 * args.window_s:g} s"
        )
    if args.method == "online":
        raise ValueError(
            "--bias-period-s: not with --method online (the online history is per window already)"
        )
    if archive:
        raise ValueError("--bias-period-s: not with --partition-s (the archive path); register in memory")


def solve_bias_periods(tables, association, result, args: argparse.Namespace):
    """The :class:`~registration.fleet.periods.BiasPeriods` of the run, each period started from the
    whole run's estimate; with an association, on the plots it labelled."""
    from registration.cli.fleet.association import labelled_tables
    from registration.fleet import BatchOptions
    from registration.fleet.periods import solve_periods

    plots, refs = (
        (tables.plots, tables.references) if association is None else labelled_tables(tables, association)
    )
    return solve_periods(
        plots,
        tables.sensors,
        tables.navigation,
        tables.platforms,
        refs,
        tables.targets,
        period_s=args.bias_period_s,
        options=BatchOptions(window_s=args.window_s),
        x0=result.estimate,
    )


def period_rows(bias_periods) -> list[dict]:
    """The rows of estimates_by_period.csv: per period, its span and the rows of
    :func:`~registration.io.fleet.estimates.estimate_rows` of its result."""
    from registration.io.fleet.estimates import estimate_rows

    return [
        {"period_start_s": p.start_s, "period_end_s": p.end_s, **row}
        for p in bias_periods.periods
        for row in estimate_rows(p.result)
    ]


def change_rows(bias_periods) -> list[dict]:
    """The rows of changes.csv in file units (deg, m, 1, s): the changes declared."""
    changes = bias_periods.changes
    if not bias_periods.periods:
        return []
    layout = bias_periods.periods[0].result.layout
    rows = []
    for j in changes.found:
        i = int(changes.state[j])
        unit, k, _, _ = FILE_UNITS[layout.units[i]]
        rows.append(
            {
                "object": layout.objects[i],
                "state": layout.quantities[i],
                "unit": unit,
                "time_s": float(changes.time_s[j]),
                "before": float(changes.before[j] * k),
                "after": float(changes.after[j] * k),
                "sigma": float(changes.test.sigma[j] * k),
                "z": float(changes.test.z[j]),
            }
        )
    return rows


def periods_summary(bias_periods) -> dict:
    """The summary's ``bias_periods``: P, the periods, the tests, the threshold and the changes."""
    changes = bias_periods.changes
    return {
        "period_s": bias_periods.period_s,
        "method": "one batch solve per period on its plots (docs/background/bias-periods.md)",
        "periods": [
            {
                "start_s": p.start_s,
                "end_s": p.end_s,
                "plots": p.n_plots,
                "plots_used": p.problem.n_plots,
                "converged": bool(p.result.converged),
                "consistent": bool(p.result.chi_square.ok),
            }
            for p in bias_periods.periods
        ],
        "left_out": bias_periods.notes(),
        "tests": changes.n_tests,
        "false_alarm": FALSE_ALARM,
        "threshold_z": changes.test.threshold,
        "changes": change_rows(bias_periods),
    }


def change_lines(bias_periods) -> list[str]:
    """The printed report: periods, tests, threshold, then a table of the changes found."""
    changes = bias_periods.changes
    n = len(bias_periods.periods)
    out = [
        f"\nBiases per period of {bias_periods.period_s:g} s: {n} period{'s' if n != 1 else ''}, "
        f"{changes.n_tests} tests "
        f"between consecutive periods, |z| > {changes.test.threshold:.2f} (1 % false alarms over the run)"
    ]
    out += [f"  note: {note}" for note in bias_periods.notes()]
    rows = change_rows(bias_periods)
    if not rows:
        return [*out, "  no change between periods"]
    out.append(
        f"  {'object':<10}{'state':<18}{'time_s':>10}{'before':>12}{'after':>12}{'σ':>10}{'z':>8}  unit"
    )
    out += [
        f"  {r['object']:<10}{r['state']:<18}{r['time_s']:10g}{r['before']:12.4g}{r['after']:12.4g}"
        f"{r['sigma']:10.3g}{r['z']:8.2f}  {r['unit']}"
        for r in rows
    ]
    return out


def _frame(rows: list[dict], columns: tuple[str, ...]):
    import pandas as pd

    frame = pd.DataFrame(rows, columns=list(columns))
    text = {"object", "state", "unit", "status"}
    return frame.astype({c: (str if c in text else float) for c in columns})


def write_period_outputs(out: Path, bias_periods, *, plots: bool) -> list[Path]:
    """estimates_by_period.csv, changes.csv (its header even without a change) and, with ``plots``,
    bias_periods.png in ``out``."""
    from registration.io.files.tablefile import write_frame

    written = []
    for name, rows, columns in (
        ("estimates_by_period.csv", period_rows(bias_periods), PERIOD_COLUMNS),
        ("changes.csv", change_rows(bias_periods), CHANGE_COLUMNS),
    ):
        with writing(out / name):
            write_frame(_frame(rows, columns), out / name, "csv")
        written.append(out / name)
    if plots and bias_periods.periods:
        from registration.fleet.periods.figure import plot_bias_periods

        with writing(out / "bias_periods.png"):
            written.append(plot_bias_periods(bias_periods, out / "bias_periods.png"))
    return written
