"""The registration state of a fleet: per platform the heading, pitch and roll errors, per sensor
one bias per measured channel and, where the sensors table switches them on, the extended errors
(range gain, time bias, position error east/north/up) and the azimuth eccentricity (its sin and
cos terms), with names, labels and units in the user's terms.

State ``i`` is named ``<object>:<quantity>`` (``A:heading_error``, ``A1:range_bias``,
``A1:range_gain``, ``A1:time_bias``, ``A1:position_east``) and labelled ``heading error of
platform A`` / ``range bias of sensor A1``. Units: rad for attitude errors and angle biases, m for
range biases and position errors, ``1`` (dimensionless) for range gains, s for time biases. A prior
standard deviation of 0 holds a state fixed at zero; ``inf`` means no prior.

Each sensor's states as the plot model takes them (``sensor_states``) are its platform's three
attitude errors and its three biases (6 slots) or, when any sensor has an extended error, those
and the five extended errors (11 slots, the order of ``EXTENDED_ERRORS``) or, when any sensor has an
eccentricity, those and its two terms (13 slots); an absent state's slot holds the sink index ``n``.

A *channel* (the sensors table's ``channel_of``: a radar's primary-only plots beside its secondary
ones) has its own biases and range gain; its time bias, position errors and eccentricity slots
hold the indices of its sensor's states: one state, seen through both.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fleet.data.tables import (
    ATTITUDE_ERRORS,
    CHANNEL_UNITS,
    CHANNELS,
    ECCENTRICITY_ERRORS,
    EXTENDED_ERRORS,
    SHARED_EXTENDED,
)

__all__ = [
    "ATTITUDE_COLUMNS",
    "BIAS_COLUMNS",
    "ECCENTRICITY_COLUMNS",
    "ELEVATION_BIAS_COLUMN",
    "POSITION_ERROR_COLUMNS",
    "RANGE_GAIN_COLUMN",
    "TIME_BIAS_COLUMN",
    "EXTENDED_LABELS",
    "EXTENDED_UNITS",
    "FILE_UNITS",
    "HEIGHT_OFFSET_OBJECT",
    "REFERENCE_SCALE",
    "StateLayout",
    "make_layout",
    "with_height_offset",
    "state_scale",
]

#: Scale of a state without prior: 1 deg for angles, 1 km for ranges and positions, 1e-3 (1000 ppm)
#: for range gains, 1 s for time biases.
REFERENCE_SCALE = {"rad": float(np.radians(1.0)), "m": 1000.0, "1": 1.0e-3, "s": 1.0}
#: Units and label words of the extended errors, in EXTENDED_ERRORS order.
EXTENDED_UNITS = ("1", "s", "m", "m", "m")
EXTENDED_LABELS = (
    "range gain",
    "time bias",
    "east position error",
    "north position error",
    "up position error",
)
#: The object of the flight levels' common height offset (the state ``flight_levels:height_offset``):
#: the heights that flight levels give without a learned relation all share one unknown offset.
HEIGHT_OFFSET_OBJECT = "flight_levels"
#: Label words of the eccentricity terms, in ECCENTRICITY_ERRORS order.
ECCENTRICITY_LABELS = ("azimuth eccentricity (sin term)", "azimuth eccentricity (cos term)")
#: Unit of each state unit in files (estimates.csv, history.csv) and on the console, with the factor
#: from the SI value: (file unit, factor, console unit, factor).
FILE_UNITS = {
    "rad": ("deg", float(np.degrees(1.0)), "deg", float(np.degrees(1.0))),
    "m": ("m", 1.0, "m", 1.0),
    "1": ("1", 1.0, "ppm", 1.0e6),
    "s": ("s", 1.0, "s", 1.0),
}


def state_scale(layout) -> np.ndarray:
    """(n,) the prior sigma where finite and > 0, else the reference scale of the state's unit."""
    ref = np.array([REFERENCE_SCALE[u] for u in layout.units])
    p = layout.prior_sigma
    return np.where(np.isfinite(p) & (p > 0), p, ref)


#: The columns of ``StateLayout.sensor_states`` (and so of ``Design.state``): the platform's attitude
#: errors (heading, pitch, roll), the sensor's biases (range, bearing, elevation) and, with the
#: extended errors (EXTENDED_ERRORS order), the range gain, the time bias and the position errors
#: (east, north, up).
ATTITUDE_COLUMNS = slice(0, 3)
BIAS_COLUMNS = slice(3, 6)
ELEVATION_BIAS_COLUMN = 5
RANGE_GAIN_COLUMN = 6
TIME_BIAS_COLUMN = 7
POSITION_ERROR_COLUMNS = slice(8, 11)
#: With an eccentricity (width 13): its sin and cos terms.
ECCENTRICITY_COLUMNS = slice(11, 13)


@dataclass(frozen=True)
class StateLayout:
    """Names and indices of the registration states.

    ``att_index`` (P, 3): the state index of each platform's heading, pitch and roll error.
    ``bias_index`` (S, 3): the state index of each sensor's range, bearing and elevation bias, -1
    for a channel the sensor does not measure. ``extended_index`` (S, 5): the index of each
    sensor's range gain, time bias and east, north, up position errors, -1 where not modelled.
    ``prior_sigma`` (n,): 0 = fixed, inf = no prior. ``eccentricity_index`` (S, 2): the index of
    each sensor's eccentricity terms (sin, cos), -1 where not modelled (None: no sensor has one).
    A channel's shared slots hold its sensor's indices (module docstring); ``channel_of`` (S,) the
    sensor each sensor is a channel of (-1: none; None: no sensor is a channel).
    """

    names: tuple[str, ...]
    labels: tuple[str, ...]
    units: tuple[str, ...]
    objects: tuple[str, ...]  # the platform or sensor id of each state
    quantities: tuple[str, ...]  # heading_error, ..., range_bias, ...
    prior_sigma: np.ndarray
    att_index: np.ndarray
    bias_index: np.ndarray
    extended_index: np.ndarray
    eccentricity_index: np.ndarray | None = None
    # the index of the flight levels' common height offset (HEIGHT_OFFSET_OBJECT), -1: not modelled
    height_offset_index: int = -1
    # (S,) the sensor each sensor is a channel of (-1: none; None: no sensor is a channel)
    channel_of: np.ndarray | None = None

    @property
    def n(self) -> int:
        return len(self.names)

    @property
    def extended(self) -> bool:
        """True when the plot model is the extended one: any sensor has an extended error (range
        gain, time bias, position) or an eccentricity."""
        return bool((self.extended_index >= 0).any()) or self.eccentric

    @property
    def eccentric(self) -> bool:
        """True when any sensor has an azimuth eccentricity (estimated or fixed)."""
        return self.eccentricity_index is not None and bool((self.eccentricity_index >= 0).any())

    @property
    def width(self) -> int:
        """States per sensor in the plot model: 6, 11 with the extended errors, 13 with an eccentricity."""
        return 13 if self.eccentric else 11 if self.extended else 6

    @property
    def time_bias_index(self) -> np.ndarray:
        """(S,) the state index of each sensor's time bias, -1 where not modelled."""
        return self.extended_index[:, 1]

    @property
    def time_biased(self) -> bool:
        """True when any sensor has a time-bias state (estimated or fixed)."""
        return bool((self.time_bias_index >= 0).any())

    def sensor_states(
        self, sensor: np.ndarray, sensor_platform: np.ndarray, absent: int | None = None
    ) -> np.ndarray:
        """(M, width) state indices of sensors ``sensor`` (M,) as the plot model takes them
        (module docstring); where a state is absent ``absent``, by default ``n`` (the sink)."""
        parts = [self.att_index[sensor_platform[sensor]], self.bias_index[sensor]]
        if self.extended or self.eccentric:
            parts.append(self.extended_index[sensor])
        if self.eccentric:
            assert self.eccentricity_index is not None
            parts.append(self.eccentricity_index[sensor])
        idx = np.concatenate(parts, axis=1)
        return np.where(idx < 0, self.n if absent is None else absent, idx)

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


class _States:
    """The states in the order they are added: names, labels, units, objects, quantities, priors."""

    def __init__(self) -> None:
        self.names: list[str] = []
        self.labels: list[str] = []
        self.units: list[str] = []
        self.objects: list[str] = []
        self.quantities: list[str] = []
        self.prior: list[float] = []

    def add(self, kind: str, obj: str, quantity: str, label: str, unit: str, sigma: float) -> int:
        """Index of the new state ``obj:quantity`` (prior sigma ``sigma`` in ``unit``)."""
        self.names.append(f"{obj}:{quantity}")
        self.labels.append(f"{label} of {kind} {obj}")
        self.units.append(unit)
        self.objects.append(obj)
        self.quantities.append(quantity)
        self.prior.append(sigma)
        return len(self.names) - 1

    def layout(
        self, att_index, bias_index, extended_index, ecc_index, offset_index: int, channel_of=None
    ) -> StateLayout:
        return StateLayout(
            tuple(self.names),
            tuple(self.labels),
            tuple(self.units),
            tuple(self.objects),
            tuple(self.quantities),
            np.array(self.prior, dtype=np.float64),
            att_index,
            bias_index,
            extended_index,
            ecc_index,
            offset_index,
            channel_of,
        )


def make_layout(
    platform_ids,
    platform_priors: np.ndarray,
    sensor_ids,
    sensor_channels: np.ndarray,
    sensor_priors: np.ndarray,
    extended_priors: np.ndarray | None = None,
    eccentricity_priors: np.ndarray | None = None,
    channel_of: np.ndarray | None = None,
    height_offset_prior: float | None = None,
) -> StateLayout:
    """The layout for platforms (priors (P, 3), rad) and sensors (channels (S, 3) bool, priors (S, 3));
    ``extended_priors`` (S, 5) the priors of the extended errors (EXTENDED_ERRORS order; NaN = not
    modelled); ``eccentricity_priors`` (S,) rad, the prior of both eccentricity terms (NaN or None:
    not modelled); ``channel_of`` (S,) the sensor each one is a channel of (-1 or None: none), whose
    time bias, position errors and eccentricity it shares (its own priors for them are not used). A
    sensor without range has no range gain. ``height_offset_prior`` (m; None: not modelled): the prior
    of the one height offset that the references' flight-level heights share, the last state
    (``flight_levels:height_offset``)."""
    states = _States()
    add = states.add
    n_sensors = len(sensor_ids)
    parent = np.full(n_sensors, -1, dtype=np.int64) if channel_of is None else np.asarray(channel_of)
    att_index = np.zeros((len(platform_ids), 3), dtype=np.int64)
    for p, pid in enumerate(platform_ids):
        for k, what in enumerate(ATTITUDE_ERRORS):
            att_index[p, k] = add(
                "platform", pid, f"{what}_error", f"{what} error", "rad", platform_priors[p, k]
            )
    bias_index = np.full((n_sensors, 3), -1, dtype=np.int64)
    extended_index = np.full((n_sensors, len(EXTENDED_ERRORS)), -1, dtype=np.int64)
    ecc_index = np.full((n_sensors, len(ECCENTRICITY_ERRORS)), -1, dtype=np.int64)
    if extended_priors is None:
        extended_priors = np.full((n_sensors, len(EXTENDED_ERRORS)), np.nan)
    if eccentricity_priors is None:
        eccentricity_priors = np.full(n_sensors, np.nan)
    for s, sid in enumerate(sensor_ids):
        channel = parent[s] >= 0
        for k, what in enumerate(CHANNELS):
            if sensor_channels[s, k]:
                bias_index[s, k] = add(
                    "sensor", sid, f"{what}_bias", f"{what} bias", CHANNEL_UNITS[k], sensor_priors[s, k]
                )
        for k, what in enumerate(EXTENDED_ERRORS):
            if np.isnan(extended_priors[s, k]) or (what == "range_gain" and not sensor_channels[s, 0]):
                continue
            if channel and SHARED_EXTENDED[k]:
                continue
            extended_index[s, k] = add(
                "sensor", sid, what, EXTENDED_LABELS[k], EXTENDED_UNITS[k], extended_priors[s, k]
            )
        if not channel and not np.isnan(eccentricity_priors[s]):
            for k, what in enumerate(ECCENTRICITY_ERRORS):
                ecc_index[s, k] = add(
                    "sensor", sid, what, ECCENTRICITY_LABELS[k], "rad", eccentricity_priors[s]
                )
    channels = np.flatnonzero(parent >= 0)
    shared = np.flatnonzero(SHARED_EXTENDED)
    extended_index[channels[:, None], shared] = extended_index[parent[channels][:, None], shared]
    ecc_index[channels] = ecc_index[parent[channels]]
    offset_index = -1
    if height_offset_prior is not None:
        offset_index = add("", HEIGHT_OFFSET_OBJECT, "height_offset", "", "m", height_offset_prior)
        states.labels[-1] = "common height offset of the flight levels"
    ecc = ecc_index if (ecc_index >= 0).any() else None
    return states.layout(
        att_index, bias_index, extended_index, ecc, offset_index, parent if (parent >= 0).any() else None
    )


def with_height_offset(layout: StateLayout, prior: float | None) -> StateLayout:
    """``layout`` with the flight levels' common height offset (prior sigma ``prior`` m) as its last
    state; ``layout`` itself when ``prior`` is None or it has the state already."""
    if prior is None or layout.height_offset_index >= 0:
        return layout
    return StateLayout(
        (*layout.names, f"{HEIGHT_OFFSET_OBJECT}:height_offset"),
        (*layout.labels, "common height offset of the flight levels"),
        (*layout.units, "m"),
        (*layout.objects, HEIGHT_OFFSET_OBJECT),
        (*layout.quantities, "height_offset"),
        np.append(layout.prior_sigma, prior),
        layout.att_index,
        layout.bias_index,
        layout.extended_index,
        layout.eccentricity_index,
        layout.n,
        layout.channel_of,
    )
