"""Settings of the association (:class:`AssociationOptions`), SI units and radians."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration.fleet.batch.solver import BatchOptions

__all__ = ["AssociationOptions"]


@dataclass(frozen=True)
class AssociationOptions:
    """Settings of :func:`~registration.fleet.association.associate.associate_and_register`.

    Anchors and tracklets (docs/background/association.md): window_s: tracklet window (s), also the batch's
    target window. gate_probability: gates are this quantile of chi-square. max_speed (m/s): a new
    track's velocity sigma. accel_sigma (m/s^2): the tracks' white-acceleration noise. max_missed:
    scans in a row without a plot that close a track. min_track_plots, min_tracklet_plots: shorter
    tracks are clutter, shorter pieces are left out. max_iterations: passes of the grouping of the
    position-fixing sensors' plots, the last one included. initial_sigma_attitude,
    initial_sigma_angle_bias (rad), initial_sigma_range_bias (m), initial_sigma_range_gain (1),
    initial_sigma_time_bias (s), initial_sigma_position (m per axis): the covariance of a state
    without a finite prior before any data determine it. channel_sigma_range_bias (m),
    channel_sigma_angle_bias (rad), channel_sigma_range_gain (1): how far a channel's (a radar's
    primary-only plots, ``channel_of``) biases and range gain may differ from its radar's, the
    covariance its states start with while none of its plots is joined
    (:mod:`~registration.fleet.association.channels`). iteration_plots: the grouping passes before
    the last, and the solves between them, use every k-th window, k such that these hold about this
    many plots.

    Tracks and joins: track_gap_s (s): a track (given by the ``track`` column or made by the tracker) is
    split where its plots are further apart in time than this. jump_probability: a given track is split
    where a plot lies outside the ``1 - jump_probability`` gate of the track's prediction by a
    constant-velocity filter with white acceleration ``jump_accel_sigma`` (m/s^2; generous: a 2-D radar's
    plots placed in a rolling deck sway with the roll). test_plots: plots of a track used in one join test
    at most (spread over it). min_join_plots: plots of a track within a target's span needed to test the
    pair. ambiguity_ratio: a join is accepted when its chi-square tail probability is at least this many
    times that of the track's next candidate (and of the sensor's other tracks for that target).
    drop_probability: a join whose residuals under the registration exceed the chi-square ``1 -
    drop_probability`` quantile is dropped. outlier_probability: in the final stage, an associated plot
    whose residuals exceed the ``1 - outlier_probability`` quantile is left out. reference_gap_s (s):
    reference positions further apart are not interpolated between; reference_accel_sigma (m/s^2): the
    acceleration allowed between two reference positions. max_join_passes: attach-register-check passes
    that change the joins at most, from the start and again after each split of tracks and after the
    provisional targets. batch: the solver's options (its window_s is replaced by this window_s).
    """

    window_s: float = 20.0
    gate_probability: float = 0.999
    max_speed: float = 400.0
    accel_sigma: float = 20.0
    max_missed: int = 3
    min_track_plots: int = 5
    min_tracklet_plots: int = 3
    max_iterations: int = 6
    initial_sigma_attitude: float = float(np.radians(1.0))
    initial_sigma_angle_bias: float = float(np.radians(5.0))
    initial_sigma_range_bias: float = 500.0
    initial_sigma_range_gain: float = 1.0e-3
    initial_sigma_time_bias: float = 1.0
    initial_sigma_position: float = 100.0
    channel_sigma_range_bias: float = 300.0
    channel_sigma_angle_bias: float = float(np.radians(0.5))
    channel_sigma_range_gain: float = 1.0e-4
    iteration_plots: int = 20_000
    track_gap_s: float = 60.0
    jump_probability: float = 1.0e-6
    jump_accel_sigma: float = 100.0
    test_plots: int = 20
    min_join_plots: int = 5
    ambiguity_ratio: float = 1.0e3
    drop_probability: float = 1.0e-4
    outlier_probability: float = 1.0e-5
    reference_gap_s: float = 60.0
    reference_accel_sigma: float = 2.0
    max_join_passes: int = 6
    batch: BatchOptions = field(default_factory=BatchOptions)

    def __post_init__(self):
        positive = (
            "window_s",
            "max_speed",
            "accel_sigma",
            "initial_sigma_attitude",
            "initial_sigma_angle_bias",
            "initial_sigma_range_bias",
            "initial_sigma_range_gain",
            "initial_sigma_time_bias",
            "initial_sigma_position",
            "channel_sigma_range_bias",
            "channel_sigma_angle_bias",
            "channel_sigma_range_gain",
            "track_gap_s",
            "reference_gap_s",
            "reference_accel_sigma",
            "jump_accel_sigma",
        )
        checks = {k: getattr(self, k) > 0 for k in positive}
        checks.update(
            {
                k: 0 < getattr(self, k) < 1
                for k in ("gate_probability", "jump_probability", "drop_probability", "outlier_probability")
            }
        )
        checks.update(
            {
                "max_missed": self.max_missed >= 0,
                "min_track_plots": self.min_track_plots >= 2,
                "min_tracklet_plots": self.min_tracklet_plots >= 3,
                "max_iterations": self.max_iterations >= 1,
                "iteration_plots": self.iteration_plots >= 1,
                "test_plots": self.test_plots >= 3,
                "min_join_plots": self.min_join_plots >= 2,
                "ambiguity_ratio": self.ambiguity_ratio >= 1,
                "max_join_passes": self.max_join_passes >= 1,
            }
        )
        bad = [k for k, ok in checks.items() if not ok]
        if bad:
            raise ValueError(
                f"AssociationOptions: invalid {', '.join(f'{k}={getattr(self, k)!r}' for k in bad)} "
                "(windows, sigmas, speeds > 0; probabilities in (0, 1); ambiguity_ratio >= 1; counts >= "
                "their minimum)"
            )

    def initial_sigma(self) -> dict:
        """The starting sigma of each state quantity without a finite prior (rad, m, 1, s); the
        eccentricity terms start with the angle biases' sigma."""
        return {
            "heading_error": self.initial_sigma_attitude,
            "pitch_error": self.initial_sigma_attitude,
            "roll_error": self.initial_sigma_attitude,
            "range_bias": self.initial_sigma_range_bias,
            "bearing_bias": self.initial_sigma_angle_bias,
            "elevation_bias": self.initial_sigma_angle_bias,
            "range_gain": self.initial_sigma_range_gain,
            "time_bias": self.initial_sigma_time_bias,
            **{f"position_{a}": self.initial_sigma_position for a in ("east", "north", "up")},
            "eccentricity_sin": self.initial_sigma_angle_bias,
            "eccentricity_cos": self.initial_sigma_angle_bias,
        }

    def channel_sigma(self) -> dict:
        """The sigma of a channel's difference from its radar per quantity (rad, m, 1)."""
        return {
            "range_bias": self.channel_sigma_range_bias,
            "bearing_bias": self.channel_sigma_angle_bias,
            "elevation_bias": self.channel_sigma_angle_bias,
            "range_gain": self.channel_sigma_range_gain,
        }
