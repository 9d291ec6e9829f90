"""What is known of the targets besides their plots, checked and converted (see
:mod:`registration.fleet.data.tables` for the tables' columns and units): reference positions
(:class:`References`, from the references table) and the heights of the surfaces that targets
move on (:class:`SurfaceTargets`, from the targets table). Every error names the table, the row
and the target."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.core.frames import geodetic2ecef
from registration.core.validation import TIME_LIMIT_S, check_range
from registration.fleet.data.tables import DEFAULT_REFERENCE_SIGMA, index_of, read_table

__all__ = ["References", "SurfaceTargets", "read_references", "read_surface"]


@dataclass(frozen=True)
class References:
    """Known target positions: target id (R,), time (R,) s, p_ecef (R, 3) m, sigma (R,) m and
    sigma_up (R,) m (``sigma`` inf: a height only, the position giving the local up). ``sigma``
    is the standard deviation of each ECEF axis when ``sigma_up`` equals
    it (the default: None gives a copy of ``sigma``); otherwise ``sigma`` is the horizontal one
    (east and north) and ``sigma_up`` the one along the local geodetic up at the position."""

    target: np.ndarray
    time: np.ndarray
    p_ecef: np.ndarray
    sigma: np.ndarray
    sigma_up: np.ndarray | None = None
    # (R,) bool: the height carries the common height offset of the flight levels (None: none does)
    offset: np.ndarray | None = None
    # the prior sigma (m) of that offset (inf: none); None when no reference carries it
    offset_prior: float | None = None

    def __post_init__(self) -> None:
        if self.sigma_up is None:
            object.__setattr__(self, "sigma_up", np.array(self.sigma, dtype=np.float64, copy=True))
        if self.offset is None:
            object.__setattr__(self, "offset", np.zeros(np.shape(self.time), dtype=bool))

    @staticmethod
    def empty() -> "References":
        return References(np.array([], dtype=object), np.zeros(0), np.zeros((0, 3)), np.zeros(0), np.zeros(0))

    def subset(self, which: np.ndarray) -> "References":
        """The references selected by ``which``: an (R,) bool mask or an array of indices (in the
        order given), every field taken alike."""
        assert self.offset is not None
        return References(
            self.target[which],
            self.time[which],
            self.p_ecef[which],
            self.sigma[which],
            self.up_sigma[which],
            self.offset[which],
            self.offset_prior,
        )

    @property
    def up_sigma(self) -> np.ndarray:
        """``sigma_up`` (R,) m, never None (a copy of ``sigma`` when it was not given)."""
        return self.sigma if self.sigma_up is None else self.sigma_up


def read_references(references, target_ids) -> References:
    if references is None:
        return References.empty()
    table = read_table("references", references, ("target", "time"))
    target = table.ids("target")
    known = set(target_ids)
    for row, t in enumerate(target):
        if t not in known:
            raise table.error(
                row,
                f"target {str(t)!r} of the reference has no plots (targets: {sorted(str(k) for k in known)})",
            )
    time = table.floats("time")
    if table.has("x"):
        p = np.stack([table.floats(c) for c in "xyz"], axis=1)
        check_range("references.x/y/z", p, -1.0e8, 1.0e8, "m (ECEF)")
    elif table.has("lat"):
        p = geodetic2ecef(table.floats("lat"), table.floats("lon"), table.floats("alt"))
    else:
        raise ValueError(
            "references: give the known position as ECEF x, y, z (m) or as lat, lon (rad), alt (m)"
        )
    sigma = table.floats("sigma", default=DEFAULT_REFERENCE_SIGMA)
    bad = np.flatnonzero(~((np.abs(time) <= TIME_LIMIT_S) & (sigma > 0) & ~np.isnan(sigma)))
    if bad.size:
        r = int(bad[0])
        raise table.error(
            r,
            f"reference of target {str(target[r])!r}: time {time[r]} s must be finite (within "
            f"+-{TIME_LIMIT_S:g} s) and sigma "
            f"{sigma[r]} m > 0 (the accuracy of the known position; inf: a height only)",
        )
    sigma_up = table.floats("sigma_up", default=np.nan)
    sigma_up = np.where(np.isnan(sigma_up), sigma, sigma_up)  # not given: the same as sigma
    bad = np.flatnonzero(~(sigma_up > 0) | (np.isinf(sigma) & ~np.isfinite(sigma_up)))
    if bad.size:
        r = int(bad[0])
        raise table.error(
            r,
            f"sigma_up {sigma_up[r]} m of target {str(target[r])!r} must be > 0, and finite when sigma is "
            "inf (the accuracy of the known position along the local up; NaN: the same as sigma; inf: no "
            "height known; sigma inf with a finite sigma_up: a height only)",
        )
    offset, prior = _height_offset(table, target, sigma, sigma_up)
    return References(target, time, p.reshape(-1, 3), sigma, sigma_up, offset, prior)


def _height_offset(table, target: np.ndarray, sigma: np.ndarray, sigma_up: np.ndarray):
    """(offset (R,) bool, prior sigma m or None) of the optional ``height_offset_prior`` column: a
    number (inf: no prior) on the heights that carry the flight levels' common offset, one value for
    all of them and only on heights alone (``sigma`` inf, finite ``sigma_up``)."""
    if not table.has("height_offset_prior"):
        return None, None
    prior = table.floats("height_offset_prior")
    offset = ~np.isnan(prior)
    if not offset.any():
        return None, None
    bad = np.flatnonzero(offset & ~(np.isinf(sigma) & np.isfinite(sigma_up)))
    if bad.size:
        r = int(bad[0])
        raise table.error(
            r,
            f"reference of target {str(target[r])!r}: a height_offset_prior belongs to a height alone "
            "(sigma inf and a finite sigma_up): the flight level's height that carries the common offset",
        )
    values = np.unique(prior[offset])
    if values.size > 1 or not values[0] >= 0:
        r = int(np.flatnonzero(offset & (prior != prior[offset][0]))[0]) if values.size > 1 else 0
        raise table.error(
            r,
            f"height_offset_prior {prior[r]} m: the prior sigma of the one height offset of the flight "
            f"levels must be >= 0 and the same on every row (got {values.tolist()})",
        )
    return offset, float(values[0])


@dataclass(frozen=True)
class SurfaceTargets:
    """Targets that move on a surface of known height, such as ships on the sea: ``target`` ids
    (K,), ``alt`` (K,) m above the WGS-84 ellipsoid and its standard deviation ``sigma`` (K,) m
    (what the targets table's ``surface_alt`` and ``sigma_surface`` give)."""

    target: np.ndarray
    alt: np.ndarray
    sigma: np.ndarray

    def of(self, target_ids) -> tuple[np.ndarray, np.ndarray]:
        """(alt, sigma), each (T,) m, of the targets ``target_ids``; NaN where not on a surface."""
        row = index_of(np.asarray(target_ids, dtype=str), list(self.target))
        listed = row >= 0
        at = np.where(listed, row, 0)  # read_surface makes none without a target
        return np.where(listed, self.alt[at], np.nan), np.where(listed, self.sigma[at], np.nan)


def read_surface(targets) -> SurfaceTargets | None:
    """The surface targets of the optional ``targets`` table (None: no table, or no row gives a
    ``surface_alt``). A target listed twice, a height further than 10 km from the ellipsoid, or a
    surface height without a finite ``sigma_surface`` > 0 is an error naming the row."""
    if targets is None:
        return None
    table = read_table("targets", targets, ("target",))
    ids = table.ids("target")
    alt = table.floats("surface_alt", default=np.nan)
    sigma = table.floats("sigma_surface", default=np.nan)
    seen: dict = {}
    for row, t in enumerate(ids):
        if t in seen:
            raise table.error(row, f"target {str(t)!r} is listed again (first in row {seen[t]})")
        seen[t] = row
        if np.isnan(alt[row]):
            continue
        if not (np.isfinite(alt[row]) and -1.0e4 <= alt[row] <= 1.0e4):
            raise table.error(
                row,
                f"target {str(t)!r}: surface_alt {alt[row]} m must lie within 10 km of the "
                "WGS-84 ellipsoid (the height of the surface the target moves on)",
            )
        if not (np.isfinite(sigma[row]) and sigma[row] > 0):
            raise table.error(
                row,
                f"target {str(t)!r}: sigma_surface {sigma[row]} m must be finite and > 0 "
                "(the standard deviation of the target's height about surface_alt)",
            )
    on = np.isfinite(alt)
    if not on.any():
        return None
    return SurfaceTargets(ids[on], alt[on], sigma[on])
