"""What ``registration fleet simulate`` and ``fleet register`` print and write: the estimates per
sensor and platform, the observability report, the consistency check and its gate (batch: the
chi-square of the residuals; online: the normalised innovations), ``estimates.csv``,
``summary.json`` (online: also ``history.csv``, the estimates over time) and the plots."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from registration.cli.errors import consistency_gate, consistency_line, writing
from registration.core.consistency import ConsistencyReport
from registration.fleet.layout import FILE_UNITS

__all__ = ["chi_square_report", "estimate_rows", "print_report", "write_outputs", "gate"]


def is_online(result) -> bool:
    """True for a result of the online filter (it has a history), False for a batch result."""
    return hasattr(result, "history")


def chi_square_report(result) -> ConsistencyReport | None:
    """The run's consistency report: batch, the chi-square check as the mean squared normalised
    residual per degree of freedom (expected 1); online, the normalised innovations squared per
    degree of freedom. The gate fails when it exceeds 10 times its expectation."""
    return result.consistency if is_online(result) else result.chi_square.report


def estimate_rows(result, truth: dict | None = None) -> list[dict]:
    """One row per state in file units: object, state, unit (m, deg, 1 for a range gain, s for a
    time bias), estimate, sigma, status (and truth when given); a state fixed by a zero prior has
    sigma 0 and status ``fixed``."""
    rows = []
    for r in result.rows(truth):
        unit, k, _, _ = FILE_UNITS[r["unit"]]
        row = {"object": r["object"], "state": r["quantity"], "unit": unit,
               "estimate": r["estimate"] * k, "sigma": r["sigma"] * k, "status": r["status"]}
        if truth is not None:
            row["truth"] = r["truth"] * k
        rows.append(row)
    return rows


def print_report(result, rows: list[dict], header: list[str]) -> None:
    """Header lines, the estimate table (estimate, 2 sigma, truth if known, unit, status; range gains
    in ppm), the observability report and the chi-square/consistency lines."""
    for line in header:
        print(line)
    for w in getattr(result, "warnings", ()):
        print(f"WARNING: {w}")
    has_truth = bool(rows) and "truth" in rows[0]
    print(f"\n  {'object':<8}{'state':<16}{'estimate':>12}{'± 2σ':>10}{'truth' if has_truth else '':>{10 if has_truth else 0}}  unit  status")
    for r in rows:
        k, unit = (1e6, "ppm") if r["unit"] == "1" else (1.0, r["unit"])
        truth = f"{k * r['truth']:10.4g}" if has_truth else ""
        print(f"  {r['object']:<8}{r['state']:<16}{k * r['estimate']:12.4g}{2 * k * r['sigma']:10.3g}{truth}  "
              f"{unit:<4}  {r['status']}")
    print("\nObservability:")
    for line in result.observability.lines():
        print(line)
    for e in result.excluded:
        print(f"  excluded: {e.text()}")
    if is_online(result):
        print(f"\nonline: {result.history.time.size} epochs, {result.n_plots_used} of {result.n_plots_read} plots used")
        if result.fit_check is not None:
            print(f"residuals at the final estimate: {result.fit_check.text()}")
    else:
        print()  # the batch's chi-square check is the consistency line below
    report = chi_square_report(result)
    print(consistency_line(report) if report is not None else "consistency: no informative epoch to check")


def _finite(v):
    return v if np.isfinite(v) else None


def _check_json(check) -> dict:
    return {"chi2": float(check.chi2), "dof": int(check.dof), "mean": _finite(float(check.mean)),
            "interval_95": [_finite(float(v)) for v in check.interval], "consistent": bool(check.ok)}


def _summary(result, rows: list[dict], inputs: dict) -> dict:
    report = chi_square_report(result)
    out = {
        "method": "online" if is_online(result) else "batch",
        "estimates": [{k: (_finite(v) if isinstance(v, float) else v) for k, v in r.items()} for r in rows],
        "observability": result.observability.to_json(),
        "consistency": report.to_json() if report is not None else None,
        "excluded": [{"target": e.target, "reason": e.reason, "plots": e.n_plots, "t_start_s": e.t_start,
                      "t_end_s": e.t_end} for e in result.excluded],
        "warnings": list(getattr(result, "warnings", ())),
        "inputs": inputs,
    }
    if is_online(result):
        out["online"] = {"epochs": int(result.history.time.size), "plots_used": int(result.n_plots_used),
                         "plots_read": int(result.n_plots_read)}
        if result.fit_check is not None:
            out["residuals_at_final_estimate"] = _check_json(result.fit_check)
        return out
    out.update({
        "converged": bool(result.converged), "iterations": int(result.iterations),
        "chi_square": _check_json(result.chi_square),
        "residuals_by_sensor": {k: {"mean_square": v[0], "values": v[1]} for k, v in result.residual_check("sensor").items()},
        "residuals_by_target": {k: {"mean_square": v[0], "values": v[1]} for k, v in result.residual_check("target").items()},
    })
    return out


def _history_frame(result):
    """The online estimates over time, long form: time_s, object, state, unit (as estimates.csv),
    estimate, sigma."""
    import pandas as pd

    layout, h = result.layout, result.history
    free = layout.free
    k = np.array([FILE_UNITS[layout.units[i]][1] for i in free])
    n_t = h.time.size
    return pd.DataFrame({
        "time_s": np.repeat(h.time, free.size),
        "object": np.tile(np.array(layout.objects)[free], n_t),
        "state": np.tile(np.array(layout.quantities)[free], n_t),
        "unit": np.tile(np.array([FILE_UNITS[layout.units[i]][0] for i in free]), n_t),
        "estimate": (h.estimate[:, free] * k).reshape(-1),
        "sigma": (h.sigma[:, free] * k).reshape(-1),
    })


def write_outputs(out: Path, problem, result, rows: list[dict], inputs: dict, *, plots: bool,
                  truth: dict | None = None) -> list[Path]:
    """estimates.csv, summary.json, history.csv (online) and (with ``plots``) estimates.png,
    map.png, residuals.png in ``out``."""
    import pandas as pd

    from registration.recorded.formats import write_frame

    online = is_online(result)
    frames = [("estimates.csv", pd.DataFrame(rows))] + ([("history.csv", _history_frame(result))] if online else [])
    written = []
    for name, frame in frames:
        with writing(out / name):
            write_frame(frame, out / name, "csv")
        written.append(out / name)
    path = out / "summary.json"
    with writing(path):
        path.write_text(json.dumps(_summary(result, rows, inputs), indent=2, allow_nan=False) + "\n")
    written.append(path)
    if plots:
        written += _plots(out, problem, result, truth)
    return written


def _plots(out: Path, problem, result, truth) -> list[Path]:
    from registration.fleet.plots import plot_estimates, plot_history, plot_map, plot_residuals

    online = is_online(result)
    draws = [("estimates.png", lambda p: (plot_history if online else plot_estimates)(result, p, truth)),
             ("map.png", lambda p: plot_map(problem, result, p))]
    if result.residuals is not None:
        title = ("at the final online estimate: " + result.fit_check.text()) if online else None
        draws.append(("residuals.png", lambda p: plot_residuals(result, p, title)))
    written = []
    for name, draw in draws:
        with writing(out / name):
            written.append(draw(out / name))
    return written


def gate(prog: str, result, allow: bool) -> int:
    """Exit code after the outputs are written: 3 when the data grossly contradict the model."""
    report = chi_square_report(result)
    return 0 if report is None else consistency_gate(prog, report, allow)
