"""A channel's biases start from its radar's in the association (:func:`channel_start`).

A channel (the sensors table's ``channel_of``: a radar's primary-only plots beside its secondary
ones, docs/background/fleet-model.md) has range and azimuth biases and a range gain of its own, but
they differ from its radar's by the PSR/SSR alignment only: tens to a few hundred metres, a tenth
of a degree or so. Its plots carry no target id, and an SSR aircraft's primary-only plots (a reply
missed now and then) are too scattered to form tracks; tested alone under the starting covariance
of an unknown sensor (5 deg, 500 m) they match every aircraft within kilometres, and the sensor
would never have a plot registered to narrow it.

So while a channel has no plot in the latest solve, its own states are taken as its radar's plus a
difference of zero mean and the sigmas of :class:`~registration.fleet.association.options.AssociationOptions`
(``channel_sigma_range_bias``, ``channel_sigma_angle_bias``, ``channel_sigma_range_gain``): the
estimate is the radar's, the covariance the radar's plus the difference's, fully correlated with
the radar's. Once plots of the channel are joined, its plots determine its states and this starting
point is no longer used; the final registration has no such prior (the channel's states are
estimated from its plots alone).
"""

from __future__ import annotations

import numpy as np

__all__ = ["channel_pairs", "channel_start"]


def channel_pairs(layout) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(sensor (K,), own state (K,), the radar's state of the same quantity (K,)) of every channel's
    own range bias, bearing bias, elevation bias and range gain that its radar has too; empty
    without channels."""
    parent = layout.channel_of
    empty = np.zeros(0, dtype=np.int64)
    if parent is None:
        return empty, empty, empty
    sensors, own, theirs = [], [], []
    for c in np.flatnonzero(np.asarray(parent) >= 0):
        p = int(parent[c])
        for mine, its in (
            (layout.bias_index[c], layout.bias_index[p]),
            (layout.extended_index[c, :1], layout.extended_index[p, :1]),
        ):
            ok = (mine >= 0) & (its >= 0) & (mine != its)
            own.extend(mine[ok].tolist())
            theirs.extend(its[ok].tolist())
            sensors.extend([int(c)] * int(ok.sum()))
    return np.array(sensors, dtype=np.int64), np.array(own, dtype=np.int64), np.array(theirs, dtype=np.int64)


def channel_start(
    x: np.ndarray, P: np.ndarray, layout, solved_sensors: np.ndarray, difference_sigma: dict
) -> tuple[np.ndarray, np.ndarray]:
    """(x, P) with the own states of each channel without plots among ``solved_sensors`` (sensor
    indices of the latest solve's plots) set to its radar's plus the difference (module docstring);
    ``difference_sigma``: quantity -> sigma (rad, m, 1)."""
    sensor, own, theirs = channel_pairs(layout)
    if sensor.size == 0:
        return x, P
    keep = ~np.isin(sensor, solved_sensors) & np.isin(layout.channel_of[sensor], solved_sensors)
    if not keep.any():
        return x, P
    own, theirs = own[keep], theirs[keep]
    x, P = x.copy(), P.copy()
    x[own] = x[theirs]
    P[own, :] = P[theirs, :]
    P[:, own] = P[:, theirs]
    quantity = np.array(layout.quantities, dtype=object)[own]
    P[own, own] += np.array([difference_sigma[q] for q in quantity]) ** 2
    return x, P
