"""The anchors' curves the join passes test tracks against (:func:`pass_curves`): the registered
targets, the provisional ones and the references, kept while neither the estimate nor the
provisional targets change, and their windows fitted again only for the targets whose plots
changed."""

from __future__ import annotations

import numpy as np

from registration.fleet.association.joining.curves import Curves, anchor_curves
from registration.fleet.association.joining.windowfit import WindowFit, join_fits
from registration.fleet.association.options import AssociationOptions
from registration.fleet.association.problems import labelled_problem
from registration.fleet.association.solves import Registrar

__all__ = ["pass_curves"]


def pass_curves(
    reg: Registrar, labels: np.ndarray, prov: np.ndarray, options: AssociationOptions, cache: dict
) -> Curves:
    """The anchors' curves: the registered targets, the provisional ones and the references (the same
    as the last ones while neither the estimate nor the provisional targets changed, ``cache``: joins
    since the last solve barely move a curve)."""
    lab = np.where((prov != "") & (labels == ""), prov, labels)
    key = (reg.solves, tuple(np.unique(prov[prov != ""])))
    if cache.get("key") == key:
        return cache["curves"]
    fit = _fit(reg, lab, cache)
    cache["key"], cache["curves"] = (
        key,
        anchor_curves(
            None,
            reg.x,
            reg.refs,
            reg.between,
            fit=fit,
            gap_s=options.reference_gap_s,
            accel_sigma=options.reference_accel_sigma,
            surface=reg.problem.surface,
        ),
    )
    return cache["curves"]


def _fit(reg: Registrar, lab: np.ndarray, cache: dict) -> WindowFit:
    """The windows of the targets labelled in ``lab`` (N,) fitted under the latest estimate. Under the
    same estimate as the last fit, the targets whose plots did not change keep their windows (with the
    states held, each target's windows are fitted to its own plots) and only the others are fitted
    (the provisional targets, say). After a solve of a subsample, its targets' windows fitted to all
    their plots (for the checks) are such a last fit."""
    last: WindowFit | None = None
    last_lab: np.ndarray | None = None
    missing: set = set()
    if cache.get("fit") is not None and cache.get("solves") == reg.solves:
        last, last_lab = cache["fit"], cache["lab"]
    elif reg.thinned:
        last, last_lab = reg.labelled_fit(), reg.labels
        missing = set(lab.tolist()) - set(last.names) - {""}  # targets it sets aside: seen by one sensor only
    if last is not None and last_lab is not None:  # set together
        changed = lab != last_lab
        names = (set(lab[changed].tolist()) | set(last_lab[changed].tolist()) | missing) - {""}
        redo = np.where(np.isin(lab, list(names)), lab, "") if names else np.full(lab.size, "", dtype=object)
        fit = join_fits(last.without(names), _fit_windows(reg, redo))
    else:
        fit = _fit_windows(reg, lab)
    cache["fit"], cache["lab"], cache["solves"] = fit, lab.copy(), reg.solves
    return fit


def _fit_windows(reg: Registrar, lab: np.ndarray) -> WindowFit:
    problem = None
    if (lab != "").any():
        problem = labelled_problem(reg.problem, lab, reg.refs, reg.margin_s, keep_lone=True)
    return reg.cold_fit(problem)
