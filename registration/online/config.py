"""Settings of the online registration filter (:class:`RegistrationConfig`).

The linearisation and T-variant names are those that ``derive/`` emitted functions for
(``generated/manifest.json``), so a name the runtime accepts always has its compiled step.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

from registration import _codegen
from registration.online.contract import N_STATE

__all__ = [
    "RegistrationConfig",
    "COVARIANCE_UPDATES",
    "LINEARIZATIONS",
    "DEFAULT_LINEARIZATION",
    "Q_MODES",
    "T_VARIANTS",
]

LINEARIZATIONS = _codegen.variants("linearization")
DEFAULT_LINEARIZATION = "fitted"
Q_MODES = ("fixed", "adaptive")
T_VARIANTS = _codegen.variants("t_variant")
COVARIANCE_UPDATES = _codegen.variants("covariance_update")


def _choice(name: str, value: str, choices: tuple) -> None:
    if value not in choices:
        raise ValueError(f"{name}: expected one of {choices}, got {value!r}")


def _sigmas(name: str, values, n: int, *, zero_ok: bool, what: str) -> tuple:
    values = tuple(float(v) for v in values)
    low_ok = min(values, default=0.0) >= 0 if zero_ok else min(values, default=0.0) > 0
    if len(values) != n or not low_ok or not all(np.isfinite(values)):
        raise ValueError(f"{name}: expected {n} finite values {'>= 0' if zero_ok else '> 0'} ({what})")
    return values


@dataclass
class RegistrationConfig:
    """Filter settings. All sigmas are standard deviations in SI units (m, rad).

    sigma0: measurement noise ``[sr_A, sq_A, se_A, sr_B, sq_B, se_B]`` (R0 of Wang et al. eq. (19)).
    prior_sigma: initial state standard deviations (P0 = diag(prior_sigma^2)), STATE_NAMES order.
    x0: initial estimate (default zeros).
    q_mode: ``fixed`` (Q = diag(q_sigma^2) per step) or ``adaptive`` (eqs. (21)-(22): the sample
        covariance of the last ``q_window`` estimates, plus the fixed Q as a floor).
    linearization: ``paper`` (H, Z at the raw measurements, as printed), ``relinearized`` (at
        the measurements corrected by the current estimate: an extended Kalman filter) or
        ``fitted`` (the default: at the most probable noise-free plots given the row and the
        current estimate with its covariance; see docs/background/online.md).
    t_variant: ``standard`` (orthonormal ENU->ECEF) or ``paper`` (eq. (4) as printed).
    covariance_update: ``joseph`` (the default: Joseph form, ``(I-KH) P (I-KH)^T + K R K^T``) or
        ``carlson`` (the same P from its triangular square root, positive definite by construction,
        about half the covariance arithmetic; equal to Joseph to rounding; see docs/background/online.md).
    """

    sigma0: tuple = (50.0, np.radians(0.5), np.radians(0.5), 50.0, np.radians(0.5), np.radians(0.5))
    prior_sigma: tuple = (
        np.radians(0.5),
        np.radians(0.2),
        np.radians(0.2),
        2000.0,
        np.radians(1.0),
        np.radians(1.0),
    ) * 2
    x0: tuple | None = None
    q_mode: str = "fixed"
    q_sigma: tuple = (1e-6, 1e-6, 1e-6, 0.01, 1e-6, 1e-6) * 2
    q_window: int = 20
    linearization: str = DEFAULT_LINEARIZATION
    t_variant: str = "standard"
    covariance_update: str = "joseph"

    def __post_init__(self):
        self.sigma0 = _sigmas("sigma0", self.sigma0, 6, zero_ok=False, what="[m, rad, rad, m, rad, rad]")
        if max(self.sigma0[i] for i in (1, 2, 4, 5)) > 0.35:
            raise ValueError("sigma0: angle sigmas above 20 deg; pass radians, not degrees")
        self.prior_sigma = _sigmas(
            "prior_sigma", self.prior_sigma, N_STATE, zero_ok=False, what="rad or m, STATE_NAMES order"
        )
        self.q_sigma = _sigmas("q_sigma", self.q_sigma, N_STATE, zero_ok=True, what="rad or m per step")
        if self.x0 is not None:
            self.x0 = tuple(float(v) for v in self.x0)
            if len(self.x0) != N_STATE or not all(np.isfinite(self.x0)):
                raise ValueError(f"x0: expected {N_STATE} finite values")
        _choice("q_mode", self.q_mode, Q_MODES)
        _choice("linearization", self.linearization, LINEARIZATIONS)
        _choice("t_variant", self.t_variant, T_VARIANTS)
        _choice("covariance_update", self.covariance_update, COVARIANCE_UPDATES)
        if int(self.q_window) < 2:
            raise ValueError("q_window: need at least 2 estimates")

    @property
    def step_name(self) -> str:
        """Name of the generated Kalman step for this linearisation, T variant and covariance update
        (the Joseph steps carry no suffix)."""
        suffix = "" if self.covariance_update == "joseph" else f"_{self.covariance_update}"
        return f"kalman_step_{self.linearization}_{self.t_variant}{suffix}"

    def to_json(self) -> dict:
        return asdict(self)
