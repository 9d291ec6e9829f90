"""Linear combinations of the registration states, and the sums the observability report names.

On a platform that neither pitches nor rolls, the heading error and the bearing biases of its
sensors are determined only as sums (``A:heading_error + A-3D:bearing_bias``): each part alone may
be undetermined (sigma inf) while the sum, which is what correcting the bearings applies, is known
to a few thousandths of a degree. :func:`named_sums` reads those sums from the report,
:func:`linear_combination` gives the value and sigma of any combination (shared by
:class:`~registration.fleet.result.BatchResult` and
:class:`~registration.fleet.online.result.OnlineResult`), and :func:`sum_rows` tabulates the sums
as rows beside the states' rows.

Sigmas are one standard deviation (σ), in the states' SI units (rad, m, 1, s). A sigma the data
leave undetermined is ``inf`` in the API; the files write it as an empty CSV cell and JSON null,
and the console and ``lines()`` print :data:`UNDETERMINED`.
"""

from __future__ import annotations

import numpy as np

from registration.core.observability import ObservabilityReport

__all__ = ["SUM_STATUS", "UNDETERMINED", "linear_combination", "named_sums", "sigma_text", "sum_rows"]

#: How an undetermined sigma (inf: the data and the priors leave the state free) is printed.
UNDETERMINED = "undetermined"
#: The status of a row of :func:`sum_rows` whose sum the data determine (as in the two-ship table).
SUM_STATUS = "identifiable combination"
#: Share of a combination (in scaled units) that may lie along undetermined directions.
_LEAN = 0.01


def sigma_text(sigma: float, spec: str = ".4g") -> str:
    """``sigma`` formatted with ``spec``, or :data:`UNDETERMINED` when it is not finite."""
    return format(sigma, spec) if np.isfinite(sigma) else UNDETERMINED


def linear_combination(
    layout,
    estimate: np.ndarray,
    covariance: np.ndarray,
    coefficients: dict,
    undetermined: np.ndarray | None = None,
    scale: np.ndarray | None = None,
) -> tuple[float, float]:
    """Value and sigma of ``sum_i a_i x_i`` for ``coefficients`` {state name: a_i}, in the states'
    units (rad, m, 1, s; a sum of angles in rad). ``estimate`` (n,) and ``covariance`` (n, n) in
    the order of ``layout.names``. With ``undetermined`` (n_free, k), the directions left out of
    the covariance in coordinates scaled by ``scale`` (n_free,), the sigma is inf when more than
    1 % of the combination (scaled) lies along them."""
    a = np.zeros(layout.n)
    for name, c in coefficients.items():
        a[layout.index(name)] = float(c)
    value = float(a @ estimate)
    if undetermined is not None and undetermined.size:
        a_scaled = a[layout.free] * scale
        lean = np.linalg.norm(undetermined.T @ a_scaled)
        if lean > _LEAN * max(float(np.linalg.norm(a_scaled)), 1e-300):
            return value, float("inf")
    return value, float(np.sqrt(max(float(a @ covariance @ a), 0.0)))


def _pairs(coefficients: dict) -> list[tuple[str, str]]:
    """The sums of a direction with +1 on one state and -1 on every other (in their own units):
    the lead state plus each other one, which are orthogonal to the direction. [] otherwise."""
    lead = [n for n, c in coefficients.items() if abs(c - 1.0) < 0.05]
    rest = [n for n, c in coefficients.items() if abs(c + 1.0) < 0.05]
    if len(lead) == 1 and rest and len(rest) == len(coefficients) - 1:
        return [(lead[0], n) for n in rest]
    return []


def named_sums(report: ObservabilityReport) -> list[tuple[str, str]]:
    """The pairs (x_i, x_j) of which the report says only, or mainly, the sum x_i + x_j is
    determined: each combination's ``identifiable_sum`` and, for a platform with several sensors
    (one direction ``heading - each bearing bias``), the sum of the heading error with each
    sensor's bearing bias. In the report's order, each pair once."""
    out = []
    for comb in report.unobservable + report.weak:
        for pair in [comb.identifiable_sum] if comb.identifiable_sum else _pairs(comb.coefficients):
            if pair not in out:
                out.append(pair)
    return out


def sum_rows(result, truth: dict | None = None) -> list[dict]:
    """One row per sum of :func:`named_sums` of ``result.observability``, with the keys of the
    states' rows: name (``A:heading_error + A-3D:bearing_bias``), object (``A+A-3D``), quantity
    (``heading_error+bearing_bias``), label, unit (the parts' unit), estimate and sigma (from
    ``result.combination``), status (:data:`SUM_STATUS`, or ``not identifiable`` when its sigma is
    inf) and, with ``truth`` {state name: value}, the sum of the parts' true values."""
    layout = result.layout
    rows = []
    for a, b in named_sums(result.observability):
        i, j = layout.index(a), layout.index(b)
        if layout.units[i] != layout.units[j]:
            continue
        value, sigma = result.combination({a: 1.0, b: 1.0})
        row = {
            "name": f"{a} + {b}",
            "object": f"{layout.objects[i]}+{layout.objects[j]}",
            "quantity": f"{layout.quantities[i]}+{layout.quantities[j]}",
            "label": f"{layout.labels[i]} + {layout.labels[j]}",
            "unit": layout.units[i],
            "estimate": value,
            "sigma": sigma,
            "status": SUM_STATUS if np.isfinite(sigma) else "not identifiable",
        }
        if truth is not None:
            row["truth"] = float(truth[a] + truth[b])
        rows.append(row)
    return rows
