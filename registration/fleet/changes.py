"""The test that says a state changed: the difference of two estimates of it against the standard
deviation of that difference, with a threshold that holds the false alarms of a whole run (or a
day of a stream) to a stated probability.

For an estimate ``before`` and an estimate ``after`` of the same state, ``z = (after - before) /
sigma_diff``; with independent estimates ``sigma_diff^2 = sigma_before^2 + sigma_after^2``. Under
"no change" and a correct model ``z`` is standard normal. Of ``n_tests`` tests, the probability that
any ``|z|`` exceeds the threshold ``c`` is at most ``n_tests * P(|z| > c)`` (Bonferroni), so
``c = Phi^-1(1 - false_alarm / (2 n_tests))`` keeps the probability of one false alarm or more at or
below ``false_alarm`` (:data:`FALSE_ALARM`, 1 %). The batch run's changes between periods and the
live service's alarms use this one test (docs/background/changes.md).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.core.distributions import norm_isf

__all__ = ["FALSE_ALARM", "ChangeTest", "change_threshold", "change_test"]

#: The probability of one false alarm or more over all the tests of a run (or of a day of data).
FALSE_ALARM = 0.01


def change_threshold(n_tests: int, false_alarm: float = FALSE_ALARM) -> float:
    """The ``|z|`` above which a change is declared when ``n_tests`` tests share the probability
    ``false_alarm`` of one false alarm or more (two-sided, Bonferroni)."""
    if not (0.0 < false_alarm < 1.0):
        raise ValueError(f"false_alarm: expected a probability in (0, 1), got {false_alarm}")
    return float(norm_isf(false_alarm / (2.0 * max(int(n_tests), 1))))


@dataclass(frozen=True)
class ChangeTest:
    """Per state tested (K,): the difference ``after - before`` (the states' units), its standard
    deviation ``sigma``, ``z`` (NaN where sigma is not finite and positive), the ``threshold`` and
    ``flagged`` (bool)."""

    difference: np.ndarray
    sigma: np.ndarray
    z: np.ndarray
    threshold: float
    flagged: np.ndarray


def change_test(
    difference: np.ndarray, sigma: np.ndarray, n_tests: int, false_alarm: float = FALSE_ALARM
) -> ChangeTest:
    """The test of the module docstring on ``difference`` (K,) with standard deviation ``sigma``
    (K,): for independent estimates ``sigma = sqrt(sigma_before^2 + sigma_after^2)``.
    ``n_tests``: all the tests that share ``false_alarm`` (at least K)."""
    d = np.asarray(difference, dtype=np.float64)
    s = np.asarray(sigma, dtype=np.float64)
    ok = np.isfinite(s) & (s > 0) & np.isfinite(d)
    z = np.full(d.shape, np.nan)
    z[ok] = d[ok] / s[ok]
    c = change_threshold(n_tests, false_alarm)
    return ChangeTest(d, s, z, c, ok & (np.abs(np.nan_to_num(z)) > c))
