"""Online ECEF registration of two ship radars: a Kalman filter over attitude errors and radar biases.

Wang et al. 2011 (see docs/background/online.md): the state, the pseudo-measurement of eqs. (7)-(19) and
the filter of eqs. (18)-(23), with an observability report and a Monte Carlo against the
Cramér-Rao bound. Modules: ``contract`` (state, row layout, limits, checks), ``config``,
``filter`` (streaming :class:`OnlineRegistrar`), ``dataset`` (:func:`register`), ``result``,
``information``, ``scenario`` (the paper's two-ship scenario), ``montecarlo``, ``plots``.
"""

from registration.online.config import (
    DEFAULT_LINEARIZATION,
    LINEARIZATIONS,
    Q_MODES,
    T_VARIANTS,
    RegistrationConfig,
)
from registration.online.contract import validate_data
from registration.online.dataset import register
from registration.online.filter import OnlineRegistrar
from registration.online.result import RegistrationResult, difference_statistics, estimate_rows

__all__ = [
    "DEFAULT_LINEARIZATION",
    "LINEARIZATIONS",
    "Q_MODES",
    "T_VARIANTS",
    "OnlineRegistrar",
    "RegistrationConfig",
    "RegistrationResult",
    "difference_statistics",
    "estimate_rows",
    "register",
    "validate_data",
]
