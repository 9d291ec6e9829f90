"""Online ECEF registration of two ship radars (Kalman filter over attitude errors and radar biases).

Wang et al., "ECEF registration of ship-borne radars": the state, the pseudo-measurement of
eqs. (7)-(19) and the filter of eqs. (18)-(23), with an observability report and a Monte Carlo
against the Cramér-Rao bound.
"""

from registration.online.filter import (
    DEFAULT_LINEARIZATION, LINEARIZATIONS, OnlineRegistrar, RegistrationConfig, RegistrationResult, difference_statistics,
    register, validate_data,
)

__all__ = ["DEFAULT_LINEARIZATION", "LINEARIZATIONS", "OnlineRegistrar", "RegistrationConfig", "RegistrationResult",
           "difference_statistics", "register", "validate_data"]
