"""A Monte Carlo sweep over one scenario parameter: one tidy table (one row per grid point and
reported quantity, final-step values) and a figure of the final RMSE and sqrt(CRLB) against the
parameter. The grid points themselves are run by
:func:`registration.online.distributed.run_montecarlo_jobs`.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from registration.online.mcresult import MonteCarloResult

__all__ = ["SWEEP_COLUMNS", "sweep_table", "write_sweep_table", "plot_sweep"]

#: The columns of :func:`sweep_table`, in order.
SWEEP_COLUMNS = (
    "parameter",
    "value",
    "quantity",
    "kind",
    "unit",
    "runs",
    "rmse",
    "filter_sigma",
    "crlb_sigma",
    "mean_error",
    "nees",
    "nees_low",
    "nees_high",
)


def sweep_table(parameter: str, values, results: list[MonteCarloResult]):
    """A pandas DataFrame with :data:`SWEEP_COLUMNS`: per grid point ``value`` (in the unit the
    ``parameter`` name states) and reported quantity, its final-step RMSE, filter sigma, sqrt(CRLB)
    and mean error in ``unit`` (deg for angles, m for ranges), and the point's final average NEES
    with its 95 % chi-square interval (NaN when no quantity is identifiable)."""
    import pandas as pd

    rows = []
    for value, res in zip(values, results, strict=True):
        if res.nees is None or res.nees_interval is None:  # both None: no quantity in the NEES
            nees, lo, hi = np.nan, np.nan, np.nan
        else:
            (lo, hi), nees = res.nees_interval, float(res.nees[-1])
        for j, q in enumerate(res.quantities):
            s = q.scale
            rows.append(
                (
                    parameter,
                    value,
                    q.name,
                    q.kind,
                    q.unit,
                    res.runs,
                    s * res.rmse[-1, j],
                    s * res.filter_sigma[-1, j],
                    s * res.crlb_sigma[-1, j],
                    s * res.mean_error[-1, j],
                    nees,
                    lo,
                    hi,
                )
            )
    return pd.DataFrame(rows, columns=list(SWEEP_COLUMNS))


def write_sweep_table(table, path, fmt: str = "csv") -> Path:
    """Write the table as ``path`` with the suffix of
    ``fmt`` (``"csv"`` or ``"parquet"``); returns the path."""
    if fmt not in ("csv", "parquet"):
        raise ValueError(f"format: expected 'csv' or 'parquet', got {fmt!r}")
    path = Path(path).with_suffix("." + fmt)
    if fmt == "csv":
        table.to_csv(path, index=False)  # the shortest text that reads back as the same float64
    else:
        table.to_parquet(path, index=False)
    return path


def plot_sweep(table, path) -> None:
    """Final RMSE (markers) and sqrt(CRLB) (line) against the swept parameter, one panel per quantity."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = list(dict.fromkeys(table["quantity"]))
    n = max(len(names), 1)
    cols = min(n, 3)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.2 * rows), squeeze=False)
    parameter = str(table["parameter"].iloc[0]) if len(table) else ""
    for ax, name in zip(axes.flat, names):
        t = table[table["quantity"] == name].sort_values("value")
        ax.plot(t["value"], t["rmse"], "o-", label="RMSE")
        ax.plot(t["value"], t["crlb_sigma"], "kx--", label="sqrt(CRLB)")
        ax.plot(t["value"], t["filter_sigma"], ":", label="filter sigma")
        ax.set_title(name, fontsize=9)
        ax.set_xlabel(parameter)
        ax.set_ylabel(f"final value, {t['unit'].iloc[0]}")
        ax.grid(True, alpha=0.3)
    for ax in list(axes.flat)[len(names) :]:
        ax.set_visible(False)
    axes.flat[0].legend(fontsize=8)
    fig.suptitle(f"Monte Carlo sweep over {parameter}: final RMSE and sqrt(CRLB)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
