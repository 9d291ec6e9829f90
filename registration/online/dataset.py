"""Batch registration of a whole data set (:func:`register`) with the online filter."""

from __future__ import annotations

from typing import Mapping

import numpy as np

from registration.core.observability import observability_report
from registration.online.config import RegistrationConfig
from registration.online.contract import STATE_LABELS, STATE_NAMES, STATE_UNITS, correct_rows, validate_data
from registration.online.filter import OnlineRegistrar
from registration.online.information import information_at_estimate, target_positions
from registration.online.result import RegistrationResult

__all__ = ["register"]

#: rows per filter call when a progress bar is shown (the results do not depend on it)
_PROGRESS_BLOCK = 2000


def _run_filter(registrar: OnlineRegistrar, time: np.ndarray, rows: np.ndarray, progress: bool) -> dict:
    """All rows through the filter, in one block (or in blocks with a progress bar); arrays per row."""
    k = len(time)
    if not progress or k <= _PROGRESS_BLOCK:
        return registrar.update_block(rows, time)
    from registration.core.progress import progress_bar

    parts = []
    with progress_bar(progress, "registering", total=k, unit="row") as bar:
        for s in range(0, k, _PROGRESS_BLOCK):
            parts.append(registrar.update_block(rows[s : s + _PROGRESS_BLOCK], time[s : s + _PROGRESS_BLOCK]))
            bar.update(parts[-1]["n"])
    return {key: np.concatenate([p[key] for p in parts]) for key in ("x", "P", "nu", "S", "nis")}


def register(
    data: Mapping, config: RegistrationConfig | None = None, *, progress: bool = False
) -> RegistrationResult:
    """Run the registration filter over a whole data set (batch).

    ``data``: dict of arrays or pandas DataFrame following the data contract (``time`` in s and
    for prefixes ``a_``/``b_``: lat, lon, alt, heading, pitch, roll, range, bearing, elevation;
    SI units, radians). The data are validated before any estimation. With ``q_mode='fixed'``
    the whole run is one compiled loop; the adaptive mode steps row by row.
    """
    config = config or RegistrationConfig()
    time, rows = validate_data(data)
    registrar = OnlineRegistrar(config)
    out = _run_filter(registrar, time, rows, progress)
    estimates = out["x"]
    raw_a, raw_b = target_positions(rows, config.t_variant)
    corrected_a, corrected_b = target_positions(correct_rows(rows, estimates), config.t_variant)
    info_final, _ = information_at_estimate(rows, estimates[-1], config.sigma0, config.t_variant)
    report = observability_report(
        info_final, np.array(config.prior_sigma), STATE_NAMES, STATE_LABELS, STATE_UNITS
    )
    return RegistrationResult(
        config=config,
        time=time,
        estimates=estimates,
        covariances=out["P"],
        innovations=out["nu"],
        innovation_covariances=out["S"],
        nis=out["nis"],
        information=registrar.info,
        information_at_estimate=info_final,
        raw_difference_ecef=raw_a - raw_b,
        corrected_difference_ecef=corrected_a - corrected_b,
        corrected_a_ecef=corrected_a,
        corrected_b_ecef=corrected_b,
        observability=report,
    )
