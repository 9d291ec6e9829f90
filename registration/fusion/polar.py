"""Polar components and the generated polar <-> Cartesian transforms the fusion is built on.

A point seen from a site has polar coordinates ``[r, az(, el)]``: range in metres, azimuth
counter-clockwise from +x, elevation above the x-y plane, radians, in the local Cartesian frame
``loc`` shared by both sensors. The transforms and their Jacobians are the generated
``polar2cartesian{2,3}`` / ``cartesian2polar{2,3}`` functions (derive/polar.py).
"""

from __future__ import annotations

import numpy as np

from registration._generated import api as generated

__all__ = ["COMPONENTS", "UNITS", "parse_components", "polar2cartesian", "cartesian2polar"]

#: polar components in generated-function order, per dimension
COMPONENTS = {2: ("range", "azimuth"), 3: ("range", "azimuth", "elevation")}
#: unit of each component
UNITS = {"range": "m", "azimuth": "rad", "elevation": "rad"}
_ALIASES = {"bearing": "azimuth", "r": "range", "az": "azimuth", "el": "elevation"}


def polar2cartesian(polar: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """polar (N, d) -> point p (N, d) in metres relative to the site, and J = dp/dpolar (N, d, d)."""
    by_dim = {2: generated.polar2cartesian2, 3: generated.polar2cartesian3}
    return by_dim[polar.shape[-1]](polar=polar)


def cartesian2polar(p_rel: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Point relative to a site (N, d) in metres -> polar (N, d), and J = dpolar/dp (N, d, d)."""
    by_dim = {2: generated.cartesian2polar2, 3: generated.cartesian2polar3}
    return by_dim[p_rel.shape[-1]](p=p_rel)


def parse_components(components, dim: int) -> np.ndarray:
    """Indices (into ``COMPONENTS[dim]``) of the named components, in the order given.

    ``components``: names or one comma/space separated string; aliases ``bearing`` (azimuth),
    ``r``, ``az``, ``el``. Raises ValueError for an unknown or duplicated name, an empty list, or
    ``elevation`` in 2-D.
    """
    if dim not in COMPONENTS:
        raise ValueError(f"dim: expected 2 or 3 polar components (range, azimuth[, elevation]), got {dim}")
    if isinstance(components, str):
        components = [c for c in components.replace(",", " ").split() if c]
    names = list(components)
    if not names:
        raise ValueError(f"components: the second sensor must measure at least one of {COMPONENTS[dim]}")
    allowed = COMPONENTS[dim]
    idx = []
    for raw in names:
        if not isinstance(raw, str):
            raise ValueError(f"components: expected component names from {allowed}, got {raw!r}")
        name = _ALIASES.get(raw.strip().lower(), raw.strip().lower())
        if name not in allowed:
            raise ValueError(
                f"components: unknown component {raw!r} for a {dim}-D problem; expected names from {allowed}"
                + (" (alias 'bearing' = 'azimuth')" if dim == 2 else "")
            )
        i = allowed.index(name)
        if i in idx:
            raise ValueError(f"components: {name!r} is listed twice")
        idx.append(i)
    return np.asarray(idx, dtype=np.intp)
