"""What ``registration fleet simulate`` and ``fleet register`` print and write: the estimates per
sensor and platform, the observability report, the consistency check and its gate (batch: the
chi-square of the residuals; online: the same at the final estimate, with the normalised
innovations as information), ``estimates.csv``,
``summary.json`` (online: also ``history.csv``, the estimates over time) and the plots."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from registration.cli.errors import consistency_gate, consistency_line, writing
from registration.core.consistency import ConsistencyReport
from registration.fleet.combinations import sigma_text
from registration.fleet.data.layout import FILE_UNITS
from registration.io.files.jsonfile import write_json

__all__ = [
    "chi_square_report",
    "estimate_table",
    "excluded_lines",
    "print_report",
    "write_outputs",
    "gate",
    "redundancy_check",
]


def is_online(result) -> bool:
    """True for a result of the online filter (it has a history), False for a batch result."""
    return hasattr(result, "history")


def chi_square_report(result) -> ConsistencyReport | None:
    """The run's one consistency verdict, which the gate judges: batch, the chi-square check as the
    mean squared normalised residual per degree of freedom (expected 1); online, the same of every
    plot and reference position at the final estimate (``OnlineResult.verdict``; the normalised
    innovations only where those residuals were not computed). The gate fails when it exceeds 10
    times its expectation."""
    return result.verdict if is_online(result) else result.chi_square.report


def estimate_table(rows: list[dict]) -> list[str]:
    """The console table of :func:`~registration.io.fleet.estimates.estimate_rows`: object, state,
    estimate, σ (one standard deviation, or ``undetermined``), truth when known, unit, status;
    range gains in ppm."""
    has_truth = bool(rows) and "truth" in rows[0]
    wo = max([8, *(len(r["object"]) + 2 for r in rows)])
    ws = max([16, *(len(r["state"]) + 2 for r in rows)])
    out = [
        f"  {'object':<{wo}}{'state':<{ws}}{'estimate':>12}{'σ':>14}"
        f"{'truth' if has_truth else '':>{10 if has_truth else 0}}  unit  status"
    ]
    for r in rows:
        k, unit = (1e6, "ppm") if r["unit"] == "1" else (1.0, r["unit"])
        sigma = sigma_text(np.inf if r["sigma"] is None else k * r["sigma"], ".3g")
        truth = f"{k * r['truth']:10.4g}" if has_truth else ""
        out.append(
            f"  {r['object']:<{wo}}{r['state']:<{ws}}{k * r['estimate']:12.4g}{sigma:>14}{truth}  "
            f"{unit:<4}  {r['status']}"
        )
    return out


#: Excluded targets listed on the terminal; the rest are counted (summary.json lists every one).
EXCLUDED_SHOWN = 10


def excluded_lines(excluded) -> list[str]:
    """One line per excluded target, at most :data:`EXCLUDED_SHOWN`, then one that counts the rest."""
    out = [f"  excluded: {e.text()}" for e in excluded[:EXCLUDED_SHOWN]]
    if len(excluded) > EXCLUDED_SHOWN:
        out.append(
            f"  excluded: {len(excluded) - EXCLUDED_SHOWN} more targets (summary.json lists all "
            f"{len(excluded)} under 'excluded')"
        )
    return out


def print_report(result, rows: list[dict], header: list[str]) -> None:
    """Header lines, the estimate table (:func:`estimate_table`), the observability report and the
    chi-square/consistency lines."""
    for line in header:
        print(line)
    for w in getattr(result, "warnings", ()):
        print(f"WARNING: {w}")
    print()
    for line in estimate_table(rows):
        print(line)
    print("\nObservability:")
    for line in result.observability.lines():
        print(line)
    for line in excluded_lines(result.excluded):
        print(line)
    check = result.fit_check if is_online(result) else result.chi_square
    if is_online(result):
        print()  # the epochs and plots used are in the header (the run line)
        if (
            check is not None and result.consistency is not None
        ):  # information only: the verdict is the line below
            print(result.innovation_text())
    else:
        print()  # the batch's chi-square check is the consistency line below
    if check is not None and check.parts:
        refs = (
            ""
            if is_online(result)
            else (f" ({result.reference_target.size} of {result.references_given} reference positions used)")
        )
        print(f"residual terms (mean square per value): {check.parts_text()}{refs}")
        for line in _term_hints(check.parts):
            print(line)
    report = chi_square_report(result)
    print(consistency_line(report) if report is not None else "consistency: no informative epoch to check")


#: A term of the chi-square whose mean square per value exceeds this is pointed out by name.
TERM_HINT_ABOVE = 10.0
_TERM_CAUSES = {
    "plots": "the sensors' noise sigmas are stated too small, or the plots carry an unmodelled error",
    "references": "the reference file's sigma_m is stated too small (or its vertical sigma_up_m), or its "
    "positions or times do not match the plots' targets",
    "priors": "the priors are too tight for the errors there are",
}


def _term_hints(parts: dict) -> list[str]:
    """A line per term of the chi-square far above 1 (TERM_HINT_ABOVE), naming its likely cause."""
    return [
        f"  the {name} term is {ss / n:.3g} per value (about 1 where the sigmas are right): "
        f"{_TERM_CAUSES.get(name, 'check its sigmas')}"
        for name, (ss, n) in parts.items()
        if n and ss / n > TERM_HINT_ABOVE
    ]


def _finite(v):
    return v if np.isfinite(v) else None


def estimates_json(rows: list[dict]) -> list[dict]:
    """The rows of :func:`~registration.io.fleet.estimates.estimate_rows` for summary.json:
    non-finite numbers (an undetermined sigma) as null."""
    return [{k: (_finite(v) if isinstance(v, float) else v) for k, v in r.items()} for r in rows]


def _check_json(check) -> dict:
    parts = {
        k: {"sum_of_squares": ss, "values": n, "mean_square": ss / n if n else None}
        for k, (ss, n) in check.parts.items()
    }
    return {
        "chi2": float(check.chi2),
        "dof": int(check.dof),
        "mean": _finite(float(check.mean)),
        "interval_95": [_finite(float(v)) for v in check.interval],
        "consistent": bool(check.ok),
        "parts": parts,
    }


def _references_json(result) -> dict:
    """The reference positions' term of a batch result: how many were given and used, their mean
    squared normalised residual (3 values per position, 2 without a height), per reference target too."""
    by_target = {
        k: {"mean_square": _finite(v[0]), "values": v[1]}
        for k, v in result.residual_check("reference").items()
    }
    e = result.reference_residuals[np.isfinite(result.reference_residuals)]
    n = int(e.size)
    return {
        "positions_given": int(result.references_given),
        "positions_used": int(result.reference_target.size),
        "mean_square": float(np.mean(e**2)) if n else None,
        "values": n,
        "by_target": by_target,
    }


def _by_target_json(result) -> dict:
    """Per target, its plots' mean squared normalised residual, and its reference positions' beside it."""
    refs = result.residual_check("reference")
    out = {}
    for k, (ms, n) in result.residual_check("target").items():
        out[k] = {"mean_square": ms, "values": n}
        if k in refs:
            out[k].update(reference_mean_square=refs[k][0], reference_values=refs[k][1])
    return out


def _summary(result, rows: list[dict], inputs: dict) -> dict:
    report = chi_square_report(result)
    out = {
        "method": "online" if is_online(result) else "batch",
        "estimates": estimates_json(rows),
        "observability": result.observability.to_json(),
        "consistency": report.to_json() if report is not None else None,
        "consistency_basis": (
            result.verdict_basis if is_online(result) else "residuals (chi-square) at the solution"
        ),
        "excluded": [
            {
                "target": e.target,
                "reason": e.reason,
                "plots": e.n_plots,
                "t_start_s": e.t_start,
                "t_end_s": e.t_end,
            }
            for e in result.excluded
        ],
        "warnings": list(getattr(result, "warnings", ())),
        "inputs": inputs,
    }
    if is_online(result):
        out["online"] = {
            "epochs": int(result.history.time.size),
            "plots_used": int(result.n_plots_used),
            "plots_read": int(result.n_plots_read),
        }
        if result.fit_check is not None:
            out["residuals_at_final_estimate"] = _check_json(result.fit_check)
        if result.consistency is not None:  # information, subordinate to the verdict
            out["innovations"] = result.consistency.to_json()
        return out
    out.update(
        {
            "converged": bool(result.converged),
            "iterations": int(result.iterations),
            "chi_square": _check_json(result.chi_square),
            "residuals_by_sensor": {
                k: {"mean_square": v[0], "values": v[1]} for k, v in result.residual_check("sensor").items()
            },
            "residuals_by_target": _by_target_json(result),
            "residuals_of_references": _references_json(result),
        }
    )
    return out


def _history_frame(result):
    """The online estimates over time, long form: time_s, object, state, unit (as estimates.csv),
    estimate, sigma."""
    import pandas as pd

    layout, h = result.layout, result.history
    free = layout.free
    k = np.array([FILE_UNITS[layout.units[i]][1] for i in free])
    n_t = h.time.size
    return pd.DataFrame(
        {
            "time_s": np.repeat(h.time, free.size),
            "object": np.tile(np.array(layout.objects)[free], n_t),
            "state": np.tile(np.array(layout.quantities)[free], n_t),
            "unit": np.tile(np.array([FILE_UNITS[layout.units[i]][0] for i in free]), n_t),
            "estimate": (h.estimate[:, free] * k).reshape(-1),
            "sigma": (h.sigma[:, free] * k).reshape(-1),
        }
    )


def write_outputs(
    out: Path,
    problem,
    result,
    rows: list[dict],
    inputs: dict,
    *,
    plots: bool,
    truth: dict | None = None,
    extra: dict | None = None,
    kinds: np.ndarray | None = None,
) -> list[Path]:
    """estimates.csv, summary.json (with the parts ``extra`` adds), history.csv (online) and (with
    ``plots``) estimates.png, map.png, residuals.png, diagnostics_<sensor>.png in ``out``; the
    residual diagnostics printed (:mod:`registration.cli.fleet.diagnostics`; ``kinds``: the plot
    kind per plots-file row)."""
    import pandas as pd

    from registration.cli.fleet.diagnostics import run_diagnostics, write_diagnostics_figures
    from registration.io.files.tablefile import write_frame

    report = chi_square_report(result)
    diagnostics = run_diagnostics(
        problem, result, kinds, consistent=report is None or report.status == "consistent"
    )
    online = is_online(result)
    frames = [("estimates.csv", pd.DataFrame(rows))] + (
        [("history.csv", _history_frame(result))] if online else []
    )
    written = []
    for name, frame in frames:
        with writing(out / name):
            write_frame(frame, out / name, "csv")
        written.append(out / name)
    path = out / "summary.json"
    with writing(path):
        summary = {**_summary(result, rows, inputs), **(extra or {})}
        if diagnostics is not None:
            summary["diagnostics"] = diagnostics.to_json()
        write_json(path, summary)
    written.append(path)
    if plots:
        written += _plots(out, problem, result, truth)
        if diagnostics is not None:
            written += write_diagnostics_figures(out, diagnostics)
    return written


def _plots(out: Path, problem, result, truth) -> list[Path]:
    from registration.fleet.plots import plot_estimates, plot_history, plot_map, plot_residuals

    online = is_online(result)
    draws = [
        ("estimates.png", lambda p: (plot_history if online else plot_estimates)(result, p, truth)),
        ("map.png", lambda p: plot_map(problem, result, p)),
    ]
    if result.residuals is not None:
        title = ("at the final online estimate: " + result.fit_check.text()) if online else None
        draws.append(("residuals.png", lambda p: plot_residuals(result, p, title)))
    written = []
    for name, draw in draws:
        with writing(out / name):
            written.append(draw(out / name))
    return written


def redundancy_check(result, n_plots: int, window_s: float) -> None:
    """A ValueError (exit 2, before any report) when the solve left nothing to check the fit with:
    the plots fix the states exactly (no degree of freedom), so the estimates mean nothing; or the
    online filter used no plot."""
    if is_online(result) and result.n_plots_used == 0:
        raise ValueError(
            f"the online filter used none of the {result.n_plots_read} plots: every target was excluded "
            "(seen by one sensor only, without a reference, or its position not determined by its plots); "
            "--method batch names the cause per target"
        )
    report = chi_square_report(result)
    if report is None or (report.samples >= 1 and np.isfinite(report.mean)):
        return
    cause = (
        f"--window-s {window_s:g}: a window of {window_s:g} s gives each target a position per window, "
        "which takes up the plots; give a longer --window-s"
        if window_s < 1.0
        else f"{n_plots} plot(s) are too few for the states they must fix; give more plots"
    )
    raise ValueError(f"no redundancy: the fit has {report.samples} degrees of freedom left ({cause})")


def gate(prog: str, result, allow: bool) -> int:
    """Exit code after the outputs are written: 3 when the data grossly contradict the model."""
    report = chi_square_report(result)
    return 0 if report is None else consistency_gate(prog, report, allow)
