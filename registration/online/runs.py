"""Independent runs of the online filter (Monte Carlo): R sequences of K rows each, all runs of
the compiled Kalman step in one call, and the information at each run's final estimate in another.

Run ``r`` gives bit for bit what :func:`registration.online.register` gives for its rows: the same
generated functions, the same initial state, the same order of operations.
"""

from __future__ import annotations

import numpy as np

from registration import _codegen
from registration.online.config import RegistrationConfig
from registration.online.contract import N_STATE, cell_problems, check_rows
from registration.online.filter import STEP_CARRY, OnlineRegistrar
from registration.online.information import information_at_estimate

__all__ = ["check_run_rows", "filter_runs", "information_at_estimates"]

#: A run's information sum at least this large (or not finite) is recomputed by
#: :func:`information_at_estimate`, which leaves out rows that make it unusable; looser than its own
#: test, so every run it would treat specially is sent to it.
_SUSPICIOUS_INFORMATION = 1e150


def check_run_rows(rows: np.ndarray) -> None:
    """Check (R, K, 18) rows like :func:`register` does; ValueError naming the first bad run's row."""
    codes = cell_problems(rows.reshape(-1, rows.shape[-1]))
    if codes.any():
        run = int(np.argmax(codes.reshape(rows.shape[0], -1).any(axis=1)))
        try:
            check_rows(rows[run])
        except ValueError as exc:
            raise ValueError(f"run {run}: {exc}") from None


def filter_runs(config: RegistrationConfig, rows: np.ndarray) -> dict:
    """Every run's filter from the configured initial state over its rows (R, K, 18).

    Returns ``x`` (R, K, 12), ``P`` (R, K, 12, 12), ``nis`` (R, K) after each row and ``info``
    (R, 12, 12) after the last. Fixed Q: one compiled call for all runs; adaptive Q: each run
    through :meth:`OnlineRegistrar.update_block`. A non-finite step raises RuntimeError naming
    the run and the row, as :meth:`OnlineRegistrar.update_block` does.
    """
    runs, k = rows.shape[:2]
    if config.q_mode != "fixed":
        outs = [_one_run(config, rows, r) for r in range(runs)]
        return {key: np.stack([o[key] for o in outs]) for key in ("x", "P", "nis", "info")}
    start = OnlineRegistrar(config)
    inputs = {
        "x": start.x,
        "P": start.P,
        "info": start.info,
        "Q": start.process_noise(),
        "row": rows,
        "sigma0": np.array(config.sigma0),
    }
    out = _codegen.get(config.step_name).scan_runs(
        runs, k, STEP_CARRY, inputs, keep_last=("info_new", "nu", "S")
    )
    x, P, info = out["x_new"], out["P_new"], out["info_new"]
    with np.errstate(
        over="ignore", invalid="ignore"
    ):  # a sum is finite when every term is (or it overflowed)
        total = x.sum(axis=(1, 2)) + P.sum(axis=(1, 2, 3)) + info.sum(axis=(1, 2))
    for r in np.flatnonzero(~np.isfinite(total)):
        if not (np.isfinite(x[r]).all() and np.isfinite(P[r]).all() and np.isfinite(info[r]).all()):
            _one_run(config, rows, int(r))  # raises, naming the row
    return {"x": x, "P": P, "nis": out["nis"], "info": info}


def _one_run(config: RegistrationConfig, rows: np.ndarray, r: int) -> dict:
    reg = OnlineRegistrar(config)
    try:
        out = reg.update_block(rows[r])
    except RuntimeError as exc:
        raise RuntimeError(f"run {r}: {exc}") from None
    return {"x": out["x"], "P": out["P"], "nis": out["nis"], "info": reg.info}


def information_at_estimates(rows: np.ndarray, x: np.ndarray, sigma0, t_variant: str) -> np.ndarray:
    """Per run, sum_k H_k^T R_k^-1 H_k at its rows (R, K, 18) corrected by its estimate x (R, 12).

    The generated ``information_step`` for all runs in one compiled call; a run whose sum is not
    usable is recomputed by :func:`information_at_estimate` (as :func:`register` does). (R, 12, 12).
    """
    runs, k = rows.shape[:2]
    step = _codegen.get(f"information_step_{t_variant}")
    sigma0 = np.asarray(sigma0, dtype=float)
    J = step.scan_runs(
        runs,
        k,
        {"info": "info_new"},
        {
            "info": np.zeros((N_STATE, N_STATE)),
            "x": np.asarray(x, dtype=float),
            "row": rows,
            "sigma0": sigma0,
        },
        keep_last=("info_new",),
    )["info_new"]
    with np.errstate(invalid="ignore"):
        suspicious = ~(np.abs(J) < _SUSPICIOUS_INFORMATION).all(axis=(1, 2))
    for r in np.flatnonzero(suspicious):
        J[r] = information_at_estimate(rows[r], x[r], sigma0, t_variant)[0]
    return J
