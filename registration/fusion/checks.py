"""Input checks of the fusion functions: shapes, units and signs of polar measurements, standard
deviations and site positions, with errors naming the field, row and unit; and the row blocks
the vectorised fusers work in.

Measurements and sigmas are (k,) or (N, k) rows of polar components ``[r m, az rad(, el rad)]``;
sites are (d,) positions in metres, frame ``loc``.
"""

from __future__ import annotations

import dataclasses
from typing import NamedTuple

import numpy as np

from registration.core.validation import as_float_array, check_finite, check_positive, check_range
from registration.fusion.polar import COMPONENTS, UNITS, parse_components

__all__ = [
    "SITE_TOL",
    "BLOCK",
    "PairInputs",
    "pair_inputs",
    "radar_inputs",
    "second_inputs",
    "point_rows",
    "sigma_rows",
    "site_position",
    "radar_site",
    "check_polar",
    "as_rows",
    "common_rows",
    "broadcast_rows",
    "check_off_site",
    "in_blocks",
]

#: a point closer than this fraction of the radar range to a site is "at the site"
SITE_TOL = 1e-9
#: pairs processed per block: keeps the temporaries in cache (results do not depend on it)
BLOCK = 16384


def check_polar(name: str, z: np.ndarray, names: tuple[str, ...]) -> None:
    """Ranges > 0 m, azimuths in [-2 pi, 2 pi] rad, elevations
    in [-pi/2, pi/2] rad; column j is ``names[j]``."""
    for j, comp in enumerate(names):
        col = z[..., j]
        field = f"{name}[..., {j}] ({comp})"
        if comp == "range":
            check_positive(field, col, "m")
        elif comp == "azimuth":
            check_range(
                field, col, -2 * np.pi, 2 * np.pi, "rad (azimuth, counter-clockwise from +x)", angle=True
            )
        else:
            check_range(field, col, -np.pi / 2, np.pi / 2, "rad (elevation above the x-y plane)", angle=True)


def as_rows(name: str, value, width: int, what: str) -> np.ndarray:
    """A (width,) or (N, width) float array as (N, width); ``what`` describes the columns in errors."""
    a = as_float_array(name, value)
    if a.ndim == 1 and a.shape[0] == width:
        return a[None, :]
    if a.ndim == 2 and a.shape[1] == width:
        return a
    raise ValueError(f"{name}: expected shape ({width},) or (N, {width}) [{what}], got {a.shape}")


def point_rows(name: str, value, what: str) -> tuple[np.ndarray, int]:
    """A (d,) or (N, d) array with d = 2 or 3 as (N, d), and d; ``what`` completes the error message."""
    a = as_float_array(name, value)
    dim = a.shape[-1] if a.ndim in (1, 2) else -1
    if dim not in COMPONENTS:
        raise ValueError(f"{name}: expected shape (d,) or (N, d) {what}, got {a.shape}")
    return a[None, :] if a.ndim == 1 else a, dim


def sigma_rows(name: str, value, width: int, names: tuple[str, ...]) -> np.ndarray:
    """Standard deviations (N, width) > 0 of the components ``names`` (m for range, rad for angles)."""
    units = ", ".join(f"{n} {UNITS[n]}" for n in names)
    s = as_rows(name, value, width, f"standard deviations: {units}")
    check_positive(name, s, f"(standard deviations: {units})")
    return s


def site_position(name: str, value, dim: int) -> np.ndarray:
    """A finite (dim,) site position in metres, frame loc."""
    s = as_float_array(name, value)
    if s.shape != (dim,):
        raise ValueError(
            f"{name}: expected a position of shape ({dim},) in metres (frame loc), got {s.shape}"
        )
    check_finite(name, s, "m")
    return s


def radar_site(site_radar_loc, dim: int) -> np.ndarray:
    """The radar's site (dim,) in metres; ``None`` is the origin of frame loc."""
    return site_position("site_radar_loc", np.zeros(dim) if site_radar_loc is None else site_radar_loc, dim)


def radar_inputs(z_radar, sigma_radar, site_radar_loc):
    """Checked radar plot rows (N, d), sigmas (N, d), site (d,) (default origin) and the dimension d."""
    z, dim = point_rows("z_radar", z_radar, "with d = 2 or 3 (range m, azimuth rad[, elevation rad])")
    check_polar("z_radar", z, COMPONENTS[dim])
    s = sigma_rows("sigma_radar", sigma_radar, dim, COMPONENTS[dim])
    return z, s, radar_site(site_radar_loc, dim), dim


def second_inputs(z_second, sigma_second, components, dim: int):
    """Component indices (k,), checked rows (N, k) of the second sensor's measurements and sigmas."""
    idx = parse_components(components, dim)
    k = idx.size
    names = tuple(COMPONENTS[dim][i] for i in idx)
    z2 = as_rows("z_second", z_second, k, ", ".join(f"{n} {UNITS[n]}" for n in names))
    check_polar("z_second", z2, names)
    s2 = sigma_rows("sigma_second", sigma_second, k, names)
    return idx, z2, s2


class PairInputs(NamedTuple):
    """Checked inputs of a fuser, every row array broadcast to ``n`` rows."""

    #: radar polar measurements (n, d) and their standard deviations (n, d)
    z_radar: np.ndarray
    sigma_radar: np.ndarray
    #: the second sensor's components (n, k) and standard deviations (n, k)
    z_second: np.ndarray
    sigma_second: np.ndarray
    #: indices (k,) of the second sensor's components in ``COMPONENTS[d]``
    idx: np.ndarray
    #: site positions (d,), metres, frame loc
    site_radar: np.ndarray
    site_second: np.ndarray
    n: int


def pair_inputs(
    z_radar, sigma_radar, z_second, sigma_second, components, site_second_loc, site_radar_loc
) -> PairInputs:
    """Check the arguments shared by :func:`~registration.fusion.fuse_paper` and
    :func:`~registration.fusion.fuse_optimal` and broadcast them to a common number of rows."""
    z_a, s_a, site_a, dim = radar_inputs(z_radar, sigma_radar, site_radar_loc)
    site_b = site_position("site_second_loc", site_second_loc, dim)
    idx, z_b, s_b = second_inputs(z_second, sigma_second, components, dim)
    n = common_rows(z_radar=z_a, sigma_radar=s_a, z_second=z_b, sigma_second=s_b)
    z_a, s_a, z_b, s_b = (broadcast_rows(a, n) for a in (z_a, s_a, z_b, s_b))
    return PairInputs(z_a, s_a, z_b, s_b, idx, site_a, site_b, n)


def common_rows(**arrays: np.ndarray) -> int:
    """The common row count N of arrays with 1 or N rows; ValueError naming the first mismatch."""
    n, first = 1, None
    for key, a in arrays.items():
        if a.shape[0] == 0:
            raise ValueError(f"{key}: has no rows; expected at least one measurement pair")
        if a.shape[0] != 1:
            if first is None:
                n, first = a.shape[0], key
            elif a.shape[0] != n:
                raise ValueError(f"{key}: has {a.shape[0]} rows but {first} has {n}; lengths must match")
    return n


def broadcast_rows(a: np.ndarray, n: int) -> np.ndarray:
    """A 1-row array repeated (as a view) to ``n`` rows; an ``n``-row array unchanged."""
    return np.broadcast_to(a, (n,) + a.shape[1:]) if a.shape[0] != n else a


def check_off_site(name: str, range_m: np.ndarray, scale_m: np.ndarray, offset: int = 0) -> None:
    """ValueError if a target is at a site: ``range_m`` <= SITE_TOL * max(``scale_m``, 1 m).

    ``offset`` is added to the row number in the message (rows of a block).
    """
    bad = range_m <= SITE_TOL * np.maximum(scale_m, 1.0)
    if bad.any():
        i = int(np.argwhere(bad)[0][0])
        raise ValueError(
            f"{name}: the target at row {offset + i} is at the sensor's site (distance {range_m[i]:.3g} m); "
            "bearings from a site to itself are undefined"
        )


def in_blocks(block, n: int, result_type):
    """``block(rows, offset)`` for consecutive row slices of at most BLOCK rows, joined into one result.

    ``result_type`` is the frozen dataclass ``block`` returns; its fields are concatenated along
    the leading axis.
    """
    parts = [block(slice(i, i + BLOCK), i) for i in range(0, n, BLOCK)]
    if len(parts) == 1:
        return parts[0]
    return result_type(
        **{
            f.name: np.concatenate([getattr(p, f.name) for p in parts])
            for f in dataclasses.fields(result_type)
        }
    )
