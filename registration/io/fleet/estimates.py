"""The estimates of a registration as rows in file units (``estimates.csv``, the live service's
``/api/estimates``): one row per state and per identifiable sum, angles in degrees."""

from __future__ import annotations

import numpy as np

from registration.fleet.data.layout import FILE_UNITS

__all__ = ["estimate_rows"]


def estimate_rows(result, truth: dict | None = None) -> list[dict]:
    """One row per state, then one per sum the observability report names (``result.rows``), in
    file units: object, state, unit (m, deg, 1 for a range gain, s for a time bias), estimate,
    sigma (one standard deviation, σ), status (and truth when given). A state fixed by a zero prior
    has sigma 0 and status ``fixed``; an undetermined sigma is None (an empty CSV cell, JSON null).
    A sum's object and state join its parts' with ``+``: object ``A+A-3D``, state
    ``heading_error+bearing_bias``, status ``identifiable combination``."""
    rows = []
    for r in result.rows(truth):
        unit, k, _, _ = FILE_UNITS[r["unit"]]
        row = {
            "object": r["object"],
            "state": r["quantity"],
            "unit": unit,
            "estimate": r["estimate"] * k,
            "sigma": r["sigma"] * k if np.isfinite(r["sigma"]) else None,
            "status": r["status"],
        }
        if truth is not None:
            row["truth"] = r["truth"] * k
        rows.append(row)
    return rows
