"""What ``registration fleet simulate`` and ``fleet register`` print and write: the estimates per
sensor and platform, the observability report, the chi-square check and its gate, ``estimates.csv``,
``summary.json`` and the plots."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from registration.cli.errors import consistency_gate, consistency_line, writing
from registration.core.consistency import ConsistencyReport

__all__ = ["chi_square_report", "estimate_rows", "print_report", "write_outputs", "gate"]


def chi_square_report(result) -> ConsistencyReport:
    """The batch chi-square check as a consistency report: the mean squared normalised residual
    per degree of freedom (expected 1), so the gate fails when it exceeds 10."""
    return result.chi_square.report


def estimate_rows(result, truth: dict | None = None) -> list[dict]:
    """One row per state in file units: object, state, unit (m or deg), estimate, sigma, status
    (and truth when given); a state fixed by a zero prior has sigma 0 and status ``fixed``."""
    rows = []
    for r in result.rows(truth):
        k = np.degrees(1.0) if r["unit"] == "rad" else 1.0
        row = {"object": r["object"], "state": r["quantity"], "unit": "deg" if r["unit"] == "rad" else "m",
               "estimate": r["estimate"] * k, "sigma": r["sigma"] * k, "status": r["status"]}
        if truth is not None:
            row["truth"] = r["truth"] * k
        rows.append(row)
    return rows


def print_report(result, rows: list[dict], header: list[str]) -> None:
    """Header lines, the estimate table (estimate, 2 sigma, truth if known, unit, status), the
    observability report and the chi-square/consistency lines."""
    for line in header:
        print(line)
    has_truth = bool(rows) and "truth" in rows[0]
    print(f"\n  {'object':<8}{'state':<16}{'estimate':>12}{'± 2σ':>10}{'truth' if has_truth else '':>10}  unit  status")
    for r in rows:
        truth = f"{r['truth']:10.4g}" if has_truth else ""
        print(f"  {r['object']:<8}{r['state']:<16}{r['estimate']:12.4g}{2 * r['sigma']:10.3g}{truth:>10}  "
              f"{r['unit']:<4}  {r['status']}")
    print("\nObservability:")
    for line in result.observability.lines():
        print(line)
    for e in result.excluded:
        print(f"  excluded: {e.text()}")
    print(f"\nchi-square: {result.chi_square.text()}")
    print(consistency_line(chi_square_report(result)))


def _summary(result, rows: list[dict], inputs: dict) -> dict:
    def finite(v):
        return v if np.isfinite(v) else None

    return {
        "estimates": [{k: (finite(v) if isinstance(v, float) else v) for k, v in r.items()} for r in rows],
        "converged": bool(result.converged), "iterations": int(result.iterations),
        "observability": result.observability.to_json(),
        "chi_square": {"chi2": float(result.chi_square.chi2), "dof": int(result.chi_square.dof),
                       "mean": finite(float(result.chi_square.mean)),
                       "interval_95": [finite(float(v)) for v in result.chi_square.interval],
                       "consistent": bool(result.chi_square.ok)},
        "consistency": chi_square_report(result).to_json(),
        "residuals_by_sensor": {k: {"mean_square": v[0], "values": v[1]} for k, v in result.residual_check("sensor").items()},
        "residuals_by_target": {k: {"mean_square": v[0], "values": v[1]} for k, v in result.residual_check("target").items()},
        "excluded": [{"target": e.target, "reason": e.reason, "plots": e.n_plots, "t_start_s": e.t_start,
                      "t_end_s": e.t_end} for e in result.excluded],
        "inputs": inputs,
    }


def write_outputs(out: Path, problem, result, rows: list[dict], inputs: dict, *, plots: bool,
                  truth: dict | None = None) -> list[Path]:
    """estimates.csv, summary.json and (with ``plots``) estimates.png, map.png, residuals.png in ``out``."""
    import pandas as pd

    from registration.recorded.formats import write_frame

    path = out / "estimates.csv"
    with writing(path):
        write_frame(pd.DataFrame(rows), path, "csv")
    written = [path]
    path = out / "summary.json"
    with writing(path):
        path.write_text(json.dumps(_summary(result, rows, inputs), indent=2, allow_nan=False) + "\n")
    written.append(path)
    if plots:
        from registration.fleet.plots import plot_estimates, plot_map, plot_residuals

        for name, draw in (("estimates.png", lambda p: plot_estimates(result, p, truth)),
                           ("map.png", lambda p: plot_map(problem, result, p)),
                           ("residuals.png", lambda p: plot_residuals(result, p))):
            with writing(out / name):
                written.append(draw(out / name))
    return written


def gate(prog: str, result, allow: bool) -> int:
    """Exit code after the outputs are written: 3 when the data grossly contradict the model."""
    return consistency_gate(prog, chi_square_report(result), allow)
