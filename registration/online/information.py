"""Fisher information of the online registration: sum H^T R^-1 H over rows, and target positions.

H and R come from the generated pair model (``pseudo_measurement_<variant>``) or, for the sum at
one estimate, from the generated ``information_step`` run as one compiled loop.
"""

from __future__ import annotations

import numpy as np

from registration import _codegen
from registration._generated import api as generated
from registration.online.contract import N_STATE, PLOT, SENSOR_ROW, correct_rows

__all__ = [
    "information_matrix",
    "information_skipping_bad_rows",
    "information_at_estimate",
    "target_positions",
    "pair_model",
]


def information_matrix(H: np.ndarray, R: np.ndarray) -> np.ndarray:
    """sum_k H_k^T R_k^-1 H_k for H (K, 3, 12) and R (K, 3, 3) in m^2, by Cholesky solves.

    W_k = L_k^-1 H_k by forward substitution written over the whole batch (numpy's batched
    ``solve`` pays a LAPACK call per 3x3 system), then J = W^T W in one matrix product.
    """
    L = np.linalg.cholesky(R)
    W = np.empty(np.shape(H), dtype=float)
    W[:, 0] = H[:, 0] / L[:, 0, 0, None]
    W[:, 1] = (H[:, 1] - L[:, 1, 0, None] * W[:, 0]) / L[:, 1, 1, None]
    W[:, 2] = (H[:, 2] - L[:, 2, 0, None] * W[:, 0] - L[:, 2, 1, None] * W[:, 1]) / L[:, 2, 2, None]
    W_rows = W.reshape(-1, H.shape[-1])
    J = W_rows.T @ W_rows
    return 0.5 * (J + J.T)


def _usable(J: np.ndarray) -> bool:
    return bool(np.isfinite(J).all() and np.abs(J).max() < 1e200)


def information_skipping_bad_rows(H: np.ndarray, R: np.ndarray) -> tuple[np.ndarray, int]:
    """sum H^T R^-1 H over the rows, leaving out rows whose R is not positive definite or whose term
    is not finite (possible only for extreme accepted values); returns (J, rows used)."""
    try:
        J = information_matrix(H, R)
        if _usable(J):
            return J, len(H)
    except np.linalg.LinAlgError:
        pass
    J, used = np.zeros((N_STATE, N_STATE)), 0
    for k in range(len(H)):
        try:
            Jk = information_matrix(H[k : k + 1], R[k : k + 1])
        except np.linalg.LinAlgError:
            continue
        if _usable(Jk) and np.isfinite(J + Jk).all():
            J, used = J + Jk, used + 1
    return J, used


def pair_model(rows: np.ndarray, sigma0, t_variant: str) -> dict:
    """The generated pair model at rows (K, 18): Z, H, M, R ... by output name (SI units)."""
    a, b = rows[:, SENSOR_ROW["a"]], rows[:, SENSOR_ROW["b"]]
    out = generated.pseudo_measurement(
        t_variant=t_variant,
        nav_a=a[:, 0:3],
        att_a=a[:, 3:6],
        meas_a=a[:, PLOT],
        nav_b=b[:, 0:3],
        att_b=b[:, 3:6],
        meas_b=b[:, PLOT],
        sigma0=np.asarray(sigma0, dtype=float),
    )
    return out._asdict()


def information_at_estimate(
    rows: np.ndarray, x: np.ndarray, sigma0, t_variant: str
) -> tuple[np.ndarray, int]:
    """sum_k H_k^T R_k^-1 H_k with H, R at the rows (K, 18) corrected by one estimate x (12,).

    One compiled loop of the generated ``information_step``. If any row makes the sum
    non-finite (possible only for extreme accepted values), the NumPy path recomputes it and
    leaves such rows out. Returns (J, rows used).
    """
    if len(rows) == 0:
        return np.zeros((N_STATE, N_STATE)), 0
    step = _codegen.get(f"information_step_{t_variant}")
    out = step.scan(
        len(rows),
        {"info": "info_new"},
        {
            "info": np.zeros((N_STATE, N_STATE)),
            "x": np.asarray(x, dtype=float),
            "row": rows,
            "sigma0": np.asarray(sigma0, dtype=float),
        },
        keep_last=("info_new",),
    )
    J = out["info_new"]
    if _usable(J):
        return J, len(rows)
    pair = pair_model(correct_rows(rows, np.broadcast_to(x, (len(rows), N_STATE))), sigma0, t_variant)
    return information_skipping_bad_rows(pair["H"], pair["R"])


def target_positions(rows: np.ndarray, t_variant: str) -> tuple[np.ndarray, np.ndarray]:
    """Target ECEF (K, 3) in m as radar A and as radar B place it (Wang et al. eq. (3)), from rows (K, 18)."""
    names = ("lat", "lon", "alt", "heading", "pitch", "roll", "r", "q", "e")  # SENSOR_COLUMNS' order
    p_a, p_b = (
        generated.plot2ecef(t_variant=t_variant, **dict(zip(names, rows[:, SENSOR_ROW[s]].T))).p_ecef
        for s in ("a", "b")
    )
    return np.asarray(p_a).reshape(-1, 3), np.asarray(p_b).reshape(-1, 3)
