"""The batch problem's plots laid out for evaluation (:class:`Design`): in padded block order, with
their navigation, measurements, weights and state indices, the reference positions' whitening and
the surface targets' height constraints (the model: :mod:`registration.fleet.batch.normal`).

A reference whose vertical sigma ``s_up`` differs from its horizontal one is whitened in its local
frame: ``L = diag(1/s, 1/s, 1/s_up) R_enu_ecef(lat, lon of y)`` (:func:`reference_whitening`).
A *surface target* (a ship on the sea: the targets table's ``surface_alt``, ``sigma_surface``)
adds to each of its windows height constraints at the window's ``K`` Gauss-Legendre nodes (K its
used coefficients; :class:`SurfaceRows`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.polynomial import legendre
from numpy.typing import ArrayLike

from registration.core.frames import ecef2geodetic, enu2ecef_rotation
from registration.fleet.batch.blocks import Blocks
from registration.fleet.batch.reference_terms import ReferenceInformation
from registration.fleet.data.layout import ATTITUDE_COLUMNS, BIAS_COLUMNS, TIME_BIAS_COLUMN
from registration.fleet.data.navigation import SeenNavigation
from registration.fleet.data.problem import FleetProblem

__all__ = ["Design", "SurfaceRows", "make_design", "plot_model_inputs", "reference_whitening", "surface_rows"]


def plot_model_inputs(nav: np.ndarray, lever: np.ndarray, meas: np.ndarray) -> dict[str, np.ndarray]:
    """The inputs every generated plot model (``fleet_rows_*``, ``fleet_plot2ecef*``) shares, by
    their names: the platform's navigation ``nav`` (M, 6: lat, lon rad, alt m, heading, pitch,
    roll rad), the lever arm ``lever`` (M, 3) m in the deck frame and the measurement ``meas``
    (M, 3): range m, bearing and elevation rad."""
    lat, lon, alt, heading, pitch, roll = nav.T
    return dict(
        lat=lat,
        lon=lon,
        alt=alt,
        heading=heading,
        pitch=pitch,
        roll=roll,
        lever_deck=lever,
        r=meas[:, 0],
        q=meas[:, 1],
        e=meas[:, 2],
    )


@dataclass(frozen=True)
class SurfaceRows:
    """The height constraints of the surface targets' windows (module docstring): per constraint
    its block (S,), the masked basis values at its node (S, n_coef), the surface height ``alt``
    (S,) m above WGS-84 and ``weight`` (S,) 1 / sigma (1/m)."""

    block: np.ndarray
    basis: np.ndarray
    alt: np.ndarray
    weight: np.ndarray

    @property
    def size(self) -> int:
        return int(self.block.size)


def surface_rows(problem: FleetProblem, blocks: Blocks) -> SurfaceRows | None:
    """The :class:`SurfaceRows` of the windows of ``problem``'s surface targets: each window's ``K``
    Gauss-Legendre nodes (K = its used coefficients); None when no window is a surface target's."""
    surface = problem.surface_of_targets()
    if surface is None:
        return None
    alt, sigma = surface
    on = np.flatnonzero(np.isfinite(alt[blocks.block_target]))
    if on.size == 0:
        return None
    used = blocks.coef_mask[on].sum(axis=1)
    blocks_k, taus_k = [], []
    for k in np.unique(used):
        which = on[used == k]
        nodes = legendre.leggauss(int(k))[0]
        blocks_k.append(np.repeat(which, k))
        taus_k.append(np.tile(nodes, which.size))
    block, tau = np.concatenate(blocks_k), np.concatenate(taus_k)
    order = np.argsort(block, kind="stable")
    block, tau = block[order], tau[order]
    time = blocks.block_centre[block] + tau * blocks.block_half[block]
    target = blocks.block_target[block]
    return SurfaceRows(block, blocks.basis_at(block, time), alt[target], 1.0 / sigma[target])


@dataclass(frozen=True, kw_only=True)
class Design:
    """The problem's plots in padded rows, ready for evaluation.

    Rows are the plots of each group (a sensor in a block) cut into chunks, in the order of
    ``blocks.chunks`` (:mod:`registration.fleet.batch.chunks`), and padded with copies of a real
    plot of weight zero (``real`` False), so the products of a chunk are one dense matrix product
    without any copying. ``slot`` (N,) is the row of each sorted plot; ``chunk_block`` the block of
    each chunk. A block's rows need not be adjacent (the chunks are in classes of one size): sum
    over blocks with :meth:`block_sums`.
    """

    blocks: Blocks
    n_state: int
    slot: np.ndarray  # (N,)
    real: np.ndarray  # (rows,) bool
    block: np.ndarray  # (rows,)
    basis: np.ndarray  # (rows, n_coef)
    chunk_block: np.ndarray  # (n_chunks,)
    nav: np.ndarray  # (rows, 6)
    meas: np.ndarray  # (rows, 3)
    weight: np.ndarray  # (rows, 3) mask / sigma, 1/m and 1/rad; 0 for padding
    lever: np.ndarray  # (rows, 3)
    state: np.ndarray  # (rows, w) state indices of each row's sensor (layout.sensor_states; n = none)
    ref_p: np.ndarray  # (R', 3) ECEF m
    ref_weight: np.ndarray  # (R',) 1 / sigma (1/m)
    prior_weight: np.ndarray  # (n,) 1 / prior sigma (0: no prior; fixed states are not free)
    # (n,) prior or reference sigma of each state (registration.fleet.data.layout.state_scale)
    scale: np.ndarray
    time: np.ndarray  # (rows,) reported plot time (s)
    # with time biases: times (rows,) -> (nav, rate, outside) (navigation.SeenNavigation); else None
    seen_at: Any = None
    # the seen basis and navigation of the latest time biases
    seen_cache: dict = field(default_factory=dict)
    # (R', 3, 3) 1/m: L of reference_whitening; None: every sigma_up == sigma
    ref_whiten: np.ndarray | None = None
    # the surface targets' height constraints; None: no surface target
    surface: SurfaceRows | None = None
    # (R', 3) the local geodetic up (ECEF) of each reference whose height carries the flight levels'
    # common height offset, zeros for the others; None: no offset state
    ref_offset_up: np.ndarray | None = None
    offset_state: int = -1  # the offset's state index (layout.height_offset_index)
    # the references' share of the window blocks, the same at every point, with the arrays it holds
    # for (reference_terms.ReferenceInformation); None: computed at each normal equations
    ref_information: ReferenceInformation | None = None

    @property
    def n_reference_values(self) -> int:
        """The reference values the design uses: 3 per reference position, 2 for one without a
        height (``sigma_up`` inf)."""
        if self.ref_whiten is None:
            return 3 * int(self.ref_p.shape[0])
        return int(np.count_nonzero(np.any(self.ref_whiten != 0.0, axis=2)))

    def block_sums(self, values: ArrayLike) -> np.ndarray:
        """(B, ...) sums over each block's plots of ``values`` (rows, ...) in the rows' order: the
        plots' in block order, so the sums are those over the blocks' rows when the rows were in
        block order (padding left out: it weighs 0 in every sum the solver takes)."""
        return np.add.reduceat(np.asarray(values)[self.slot], self.blocks.block_start, axis=0)

    @property
    def att_state(self) -> np.ndarray:
        """(rows, 3) state indices of the platform's attitude errors."""
        return self.state[:, ATTITUDE_COLUMNS]

    @property
    def bias_state(self) -> np.ndarray:
        """(rows, 3) state indices of the sensor's biases."""
        return self.state[:, BIAS_COLUMNS]

    @property
    def extended(self) -> bool:
        return self.state.shape[1] > 6

    @property
    def time_biased(self) -> bool:
        """True when some row's sensor has a time bias that is estimated (not held at 0)."""
        return self.seen_at is not None

    def seen_time(self, x: np.ndarray) -> np.ndarray:
        """(rows,) the time (s) each row's target and platform are seen at under states ``x`` (n,):
        the reported time minus the sensor's time bias."""
        if not self.time_biased:
            return self.time
        return self.time - np.append(x, 0.0)[self.state[:, TIME_BIAS_COLUMN]]


def reference_whitening(p_ecef: np.ndarray, sigma: np.ndarray, sigma_up: np.ndarray) -> np.ndarray:
    """(R, 3, 3) whitening matrices ``L = diag(1/sigma, 1/sigma, 1/sigma_up) R_enu_ecef`` (1/m) of
    reference positions ``p_ecef`` (R, 3) ECEF m with horizontal sigma ``sigma`` (R,) m (east and
    north) and vertical sigma ``sigma_up`` (R,) m (along the local geodetic up at the position):
    ``L (y - p)`` is the east, north, up residual of an ECEF difference, each over its sigma."""
    p = np.asarray(p_ecef, dtype=np.float64).reshape(-1, 3)
    if p.shape[0] == 0:
        return np.zeros((0, 3, 3))
    lat, lon, _ = ecef2geodetic(p)
    R_enu_ecef = enu2ecef_rotation(lat, lon).transpose(0, 2, 1)
    inverse = 1.0 / np.stack([sigma, sigma, sigma_up], axis=1)
    return inverse[:, :, None] * R_enu_ecef


def make_design(problem: FleetProblem, blocks: Blocks) -> Design:
    """The :class:`Design` of ``problem``'s plots in the padded rows of ``blocks.chunks``."""
    chunks = blocks.chunks
    source = np.full(chunks.n_rows, -1, dtype=np.int64)
    source[chunks.slot] = np.arange(blocks.order.size)
    real = source >= 0
    source = np.where(real, source, source[chunks.chunk_first_of_rows()])  # padding: its chunk's first plot
    o = blocks.order[source]
    layout = problem.layout
    sensor = problem.sensor[o]
    state = layout.sensor_states(sensor, problem.sensor_platform)
    with np.errstate(divide="ignore", invalid="ignore"):
        weight = np.where(problem.mask[o] & real[:, None], 1.0 / problem.sensor_sigma[sensor], 0.0)
        prior_weight = np.where(
            np.isfinite(layout.prior_sigma) & (layout.prior_sigma > 0), 1.0 / layout.prior_sigma, 0.0
        )
    refs = problem.references
    seen_at = None
    tb = layout.time_bias_index[np.unique(sensor)]
    if layout.extended and (layout.prior_sigma[tb[tb >= 0]] > 0).any():
        if blocks.n_coef == 1:
            raise ValueError(
                "a time bias needs target windows (window_s > 0): the targets' velocities come from the "
                "windows' polynomials; give window_s > 0 or drop the prior_time_bias column"
            )

        assert problem.tracks is not None  # a problem with time biases has its navigation tracks
        seen_at = SeenNavigation(
            problem.tracks, problem.platform_ids, problem.platform[o], sensor, problem.time[o]
        )
    used = blocks.ref_index
    sigma = refs.sigma[used]
    sigma_up = sigma if refs.sigma_up is None else refs.sigma_up[used]
    whiten = (
        None if np.array_equal(sigma, sigma_up) else reference_whitening(refs.p_ecef[used], sigma, sigma_up)
    )
    offset_up = None
    if layout.height_offset_index >= 0 and whiten is not None:
        assert refs.offset is not None
        lat, lon, _ = ecef2geodetic(refs.p_ecef[used])
        up = enu2ecef_rotation(lat, lon)[:, :, 2] if used.size else np.zeros((0, 3))
        offset_up = up * refs.offset[used][:, None]
    ref_weight = 1.0 / sigma
    return Design(
        blocks=blocks,
        n_state=layout.n,
        slot=chunks.slot,
        real=real,
        block=blocks.block[source],
        basis=blocks.basis[source],
        chunk_block=blocks.block[source[chunks.first_rows()]],
        nav=problem.nav[o],
        meas=problem.meas[o],
        weight=weight,
        lever=problem.sensor_lever[sensor],
        state=state,
        ref_p=refs.p_ecef[used],
        ref_weight=ref_weight,
        prior_weight=prior_weight,
        scale=layout.scale,
        time=problem.time[o],
        seen_at=seen_at,
        ref_whiten=whiten,
        surface=surface_rows(problem, blocks),
        ref_offset_up=offset_up,
        offset_state=layout.height_offset_index,
        ref_information=ReferenceInformation.of(blocks, ref_weight, whiten),
    )
