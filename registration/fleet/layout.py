"""The registration state of a fleet: per platform the heading, pitch and roll errors, per sensor
one bias per measured channel, with names, labels and units in the user's terms.

State ``i`` is named ``<object>:<quantity>`` (``A:heading_error``, ``A1:range_bias``) and labelled
``heading error of platform A`` / ``range bias of sensor A1``. Units: rad for attitude errors and
angle biases, m for range biases. A prior standard deviation of 0 holds a state fixed at zero;
``inf`` means no prior.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fleet.tables import ATTITUDE_ERRORS, CHANNEL_UNITS, CHANNELS

__all__ = ["REFERENCE_SCALE", "StateLayout", "make_layout", "state_scale"]

#: Scale of a state without prior: 1 deg for angles, 1 km for ranges.
REFERENCE_SCALE = {"rad": float(np.radians(1.0)), "m": 1000.0}


def state_scale(layout) -> np.ndarray:
    """(n,) the prior sigma where finite and > 0, else the reference scale of the state's unit."""
    ref = np.array([REFERENCE_SCALE[u] for u in layout.units])
    p = layout.prior_sigma
    return np.where(np.isfinite(p) & (p > 0), p, ref)



@dataclass(frozen=True)
class StateLayout:
    """Names and indices of the registration states.

    ``att_index`` (P, 3): the state index of each platform's heading, pitch and roll error.
    ``bias_index`` (S, 3): the state index of each sensor's range, bearing and elevation bias, -1
    for a channel the sensor does not measure. ``prior_sigma`` (n,): 0 = fixed, inf = no prior.
    """

    names: tuple[str, ...]
    labels: tuple[str, ...]
    units: tuple[str, ...]
    objects: tuple[str, ...]  # the platform or sensor id of each state
    quantities: tuple[str, ...]  # heading_error, ..., range_bias, ...
    prior_sigma: np.ndarray
    att_index: np.ndarray
    bias_index: np.ndarray

    @property
    def n(self) -> int:
        return len(self.names)

    @property
    def free(self) -> np.ndarray:
        """Indices of the estimated (not fixed) states."""
        return np.flatnonzero(self.prior_sigma > 0)

    @property
    def fixed(self) -> np.ndarray:
        return np.flatnonzero(self.prior_sigma == 0)

    @property
    def scale(self) -> np.ndarray:
        """(n,) the prior sigma where finite and > 0, else the reference scale (see state_scale)."""
        return state_scale(self)

    def index(self, name: str) -> int:
        """The index of state ``name``; ValueError listing the known names otherwise."""
        try:
            return self.names.index(name)
        except ValueError:
            raise ValueError(f"unknown state {name!r}; states are {list(self.names)}") from None


def make_layout(platform_ids, platform_priors: np.ndarray, sensor_ids, sensor_channels: np.ndarray,
                sensor_priors: np.ndarray) -> StateLayout:
    """The layout for platforms (priors (P, 3), rad) and sensors (channels (S, 3) bool, priors (S, 3))."""
    names, labels, units, objects, quantities, prior = [], [], [], [], [], []
    att_index = np.zeros((len(platform_ids), 3), dtype=np.int64)
    for p, pid in enumerate(platform_ids):
        for k, what in enumerate(ATTITUDE_ERRORS):
            att_index[p, k] = len(names)
            names.append(f"{pid}:{what}_error")
            labels.append(f"{what} error of platform {pid}")
            units.append("rad")
            objects.append(pid)
            quantities.append(f"{what}_error")
            prior.append(platform_priors[p, k])
    bias_index = np.full((len(sensor_ids), 3), -1, dtype=np.int64)
    for s, sid in enumerate(sensor_ids):
        for k, channel in enumerate(CHANNELS):
            if not sensor_channels[s, k]:
                continue
            bias_index[s, k] = len(names)
            names.append(f"{sid}:{channel}_bias")
            labels.append(f"{channel} bias of sensor {sid}")
            units.append(CHANNEL_UNITS[k])
            objects.append(sid)
            quantities.append(f"{channel}_bias")
            prior.append(sensor_priors[s, k])
    return StateLayout(tuple(names), tuple(labels), tuple(units), tuple(objects), tuple(quantities),
                       np.array(prior, dtype=np.float64), att_index, bias_index)
