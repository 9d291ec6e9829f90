"""Change alarms for the online fleet filter: has a state moved beyond its uncertainty?

After each epoch, the epochs of the last ``window_s`` seconds of data are taken on their own and
compared with the filter's estimate before them (``x_pre``, ``P_pre``), with the test of
:mod:`registration.fleet.changes`. With ``L_k``, ``b_k`` the information and gradient of epoch k
at the estimate ``x_k`` it started from (:class:`~registration.fleet.online.options.EpochUpdate`):

* the window's information ``I = sum L_k`` and its gradient at ``x_pre``,
  ``g = sum (b_k + L_k (x_k - x_pre))``;
* the window's estimate of the change ``d = A g`` with ``A = (I + w P_pre^-1)^-1``: the data of
  the window alone, a weak share ``w`` (:data:`WEAK_PRIOR`) of the prior keeping the directions the
  window does not determine at zero change;
* under "no change" (the linear Gaussian model) ``g = -I e_pre + n`` with ``e_pre`` the error of
  ``x_pre`` (covariance ``P_pre``) and ``n`` of covariance ``I``, so ``cov d = A (I P_pre I + I) A^T``,
  and ``z = d / sqrt(diag cov d)``.

The threshold holds the probability of one false alarm or more to ``false_alarm`` (1 %) per day of
data over all states tested (Bonferroni over states x epochs per day). After an alarm the window
starts again; the caller may open the state's covariance (:func:`open_states`) so that the filter
follows the new value at once rather than by its random walk.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass

import numpy as np

from registration.fleet.changes import FALSE_ALARM, change_test
from registration.fleet.online.options import EpochUpdate

__all__ = ["Change", "ChangeDetector", "WEAK_PRIOR", "open_states"]

#: The share of the prior information kept in the window's own estimate (module docstring).
WEAK_PRIOR = 1e-3
_DAY_S = 86400.0


@dataclass(frozen=True)
class Change:
    """A state that moved: ``index`` in the layout, the data ``time_s`` of the alarm (the end of the
    window), the estimate ``before`` the window and the window's ``after`` (SI: rad, m, 1, s), the
    ``sigma`` of the difference, ``z`` and the ``threshold``."""

    index: int
    time_s: float
    before: float
    after: float
    sigma: float
    z: float
    threshold: float


class ChangeDetector:
    """The sliding-window test of the module docstring over the states ``tested`` (indices; default:
    the free states of ``layout``). ``window_s``: the data time (s) a window spans; ``epoch_s``: the
    filter's epoch length (s), to count the tests per day; ``false_alarm``: per day of data."""

    def __init__(
        self,
        layout,
        window_s: float = 60.0,
        epoch_s: float = 20.0,
        false_alarm: float = FALSE_ALARM,
        tested: np.ndarray | None = None,
    ) -> None:
        if not (window_s > 0 and epoch_s > 0):
            raise ValueError(f"window_s, epoch_s: expected > 0 s, got {window_s}, {epoch_s}")
        self.layout = layout
        self.window_s = float(window_s)
        self.free = np.asarray(layout.free)
        self.tested = self.free if tested is None else np.asarray(tested, dtype=np.int64)
        self.n_tests_per_day = int(np.ceil(_DAY_S / epoch_s)) * max(int(self.tested.size), 1)
        self.false_alarm = float(false_alarm)
        self.epochs: deque[EpochUpdate] = deque()
        self.last: np.ndarray | None = None  # z of the latest window, per tested state

    def reset(self) -> None:
        """Start a new window (after an alarm, or a gap in the data)."""
        self.epochs.clear()

    def observe(self, update: EpochUpdate) -> list[Change]:
        """Add an epoch, test the window, and return the states that moved (empty: none)."""
        self.epochs.append(update)
        while self.epochs and update.t_end - self.epochs[0].t_end >= self.window_s:
            self.epochs.popleft()
        first = self.epochs[0]
        f, scale = self.free, np.asarray(self.layout.scale)[self.free]
        x_pre = first.x_before
        info = np.zeros((f.size, f.size))
        grad = np.zeros(f.size)
        for e in self.epochs:
            L = e.L[np.ix_(f, f)] * scale[:, None] * scale[None, :]
            info += L
            grad += scale * e.b[f] + L @ ((e.x_before - x_pre)[f] / scale)
        P = first.P_before[np.ix_(f, f)] / scale[:, None] / scale[None, :]
        prior_info = np.linalg.pinv(0.5 * (P + P.T), hermitian=True)
        A = np.linalg.pinv(info + WEAK_PRIOR * prior_info, hermitian=True)
        d = A @ grad
        cov = A @ (info @ P @ info + info) @ A.T
        pos = np.searchsorted(f, self.tested)
        sigma = np.sqrt(np.clip(np.diag(cov)[pos], 0.0, None)) * scale[pos]
        test = change_test(d[pos] * scale[pos], sigma, self.n_tests_per_day, self.false_alarm)
        self.last = test.z
        changes = [
            Change(
                int(self.tested[k]),
                float(update.t_end),
                float(x_pre[self.tested[k]]),
                float(x_pre[self.tested[k]] + test.difference[k]),
                float(test.sigma[k]),
                float(test.z[k]),
                test.threshold,
            )
            for k in np.flatnonzero(test.flagged)
        ]
        if changes:
            self.reset()
        return changes


def open_states(P: np.ndarray, changes: list[Change]) -> np.ndarray:
    """``P`` with the variance of each changed state raised by the square of its change (a copy),
    so that the next epochs set its new value (the filter then follows a step within a few epochs
    instead of by its random walk)."""
    P = P.copy()
    for c in changes:
        P[c.index, c.index] += (c.after - c.before) ** 2
    return P
