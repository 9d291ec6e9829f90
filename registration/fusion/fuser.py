"""D: dissimilar-dimension fusion of a radar with a sensor that measures fewer polar components.

SPEC section 3 (seed 003). A radar at ``site_radar_loc`` measures every polar component of a
target; a second sensor at ``site_second_loc`` (another site or the same one) measures any
non-empty subset of them:

- 2-D: ``range``, ``azimuth`` (alias ``bearing``);
- 3-D: ``range``, ``azimuth``, ``elevation``.

Frame ``loc``: one local Cartesian frame shared by both sensors (in the paper's figures the
plane with +x from the radar A towards the second site B). Polar coordinates of a point seen
from a site are ``[r, az(, el)]``: range in metres, azimuth counter-clockwise from +x, elevation
above the x-y plane, radians (the generated ``polar2cartesian*`` / ``cartesian2polar*``
functions, derive/polar.py). Every transform and Jacobian is a generated function; this module
only does linear algebra on top of them.

The paper's method (:func:`fuse_paper`), steps (1)-(5) of SPEC section 3:

1. radar point ``C`` and covariance ``P = J_A diag(sigma_A^2) J_A^T``;
2. ``C`` in the second site's polar frame, each component's variance propagated from ``P``
   (eq. 7: the diagonal of ``G P G^T``, ``G = d polar_B / d p``);
3. inverse-variance fusion of each component the second sensor measures with that sensor's
   value (angles fused on the wrapped difference);
4. pseudo-measurement point ``H`` rebuilt at the second site from the fused polar values, with
   ``R = J_B diag(var_fused) J_B^T`` (eq. 9-12; like the paper, cross-covariances between the
   polar components at the second site are dropped);
5. ``X = R (P + R)^-1 X_C + P (P + R)^-1 X_H`` (eq. 13), claimed covariance
   ``P (P + R)^-1 R = (P^-1 + R^-1)^-1``.

Step 5 treats ``X_C`` and ``X_H`` as independent although ``H`` is built from the radar's own
data, so the claimed covariance is optimistic. :func:`fuse_paper` therefore also returns the
*consistent* covariance: the first-order propagation of both sensors' raw noise through all five
steps (weights held at their evaluated values), which is what the method actually delivers.

Beyond the paper, :func:`fuse_optimal` is the maximum-likelihood fuser on the raw measurements
(Gauss-Newton from the radar point) and :func:`crlb` its Cramer-Rao bound. GDOP (eq. 18) is
``sqrt(trace(cov))``: :func:`gdop` from a covariance, :func:`gdop_from_samples` from points.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration import _codegen as _loader
from registration.core.validation import as_float_array, check_finite, check_positive, check_range

__all__ = [
    "COMPONENTS",
    "FusionResult",
    "OptimalResult",
    "parse_components",
    "radar_point",
    "fuse_paper",
    "fuse_optimal",
    "crlb",
    "fisher_information",
    "gdop",
    "gdop_from_samples",
    "wrap_angle",
]

#: polar components in generated-function order, per dimension
COMPONENTS = {2: ("range", "azimuth"), 3: ("range", "azimuth", "elevation")}
_ALIASES = {"bearing": "azimuth", "r": "range", "az": "azimuth", "el": "elevation"}
_UNITS = {"range": "m", "azimuth": "rad", "elevation": "rad"}
#: a point closer than this fraction of the radar range to a site is "at the site"
_SITE_TOL = 1e-9
#: pairs processed per block: keeps the temporaries in cache (results do not depend on it)
_BLOCK = 16384


def wrap_angle(a: np.ndarray) -> np.ndarray:
    """Angles (rad) wrapped to (-pi, pi]."""
    w = np.mod(np.asarray(a, dtype=np.float64) + np.pi, 2.0 * np.pi) - np.pi
    return np.where(w == -np.pi, np.pi, w)


# --------------------------------------------------------------------------- generated transforms
def _polar2cartesian(polar: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """polar (N, d) -> p (N, d) relative to the site, J = dp/dpolar (N, d, d)."""
    d = polar.shape[-1]
    return _loader.get(f"polar2cartesian{d}")(polar)


def _cartesian2polar(p_rel: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """p relative to a site (N, d) -> polar (N, d), J = dpolar/dp (N, d, d)."""
    d = p_rel.shape[-1]
    return _loader.get(f"cartesian2polar{d}")(p_rel)


# --------------------------------------------------------------------------- input checks
def parse_components(components, dim: int) -> np.ndarray:
    """Indices (into ``COMPONENTS[dim]``) of the named components, in the order given.

    Raises ValueError for an unknown or duplicated name, an empty list, or ``elevation`` in 2-D.
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


def _polar_checks(name: str, z: np.ndarray, names: tuple[str, ...]) -> None:
    for j, comp in enumerate(names):
        col = z[..., j]
        field = f"{name}[..., {j}] ({comp})"
        if comp == "range":
            check_positive(field, col, "m")
        elif comp == "azimuth":
            check_range(field, col, -2 * np.pi, 2 * np.pi, "rad (azimuth, counter-clockwise from +x)", angle=True)
        else:
            check_range(field, col, -np.pi / 2, np.pi / 2, "rad (elevation above the x-y plane)", angle=True)


def _as_rows(name: str, value, width: int, what: str) -> np.ndarray:
    """A (width,) or (N, width) float array as (N, width)."""
    a = as_float_array(name, value)
    if a.ndim == 1 and a.shape[0] == width:
        return a[None, :]
    if a.ndim == 2 and a.shape[1] == width:
        return a
    raise ValueError(f"{name}: expected shape ({width},) or (N, {width}) [{what}], got {a.shape}")


def _sigmas(name: str, value, width: int, names: tuple[str, ...]) -> np.ndarray:
    units = ", ".join(f"{n} {_UNITS[n]}" for n in names)
    s = _as_rows(name, value, width, f"standard deviations: {units}")
    check_positive(name, s, f"(standard deviations: {units})")
    return s


def _site(name: str, value, dim: int) -> np.ndarray:
    s = as_float_array(name, value)
    if s.shape != (dim,):
        raise ValueError(f"{name}: expected a position of shape ({dim},) in metres (frame loc), got {s.shape}")
    check_finite(name, s, "m")
    return s


def _radar_inputs(z_radar, sigma_radar, site_radar_loc):
    """Checked radar plot rows (N, d), sigmas, site (default origin) and the dimension d."""
    z = as_float_array("z_radar", z_radar)
    dim = z.shape[-1] if z.ndim in (1, 2) else -1
    if dim not in COMPONENTS:
        raise ValueError(f"z_radar: expected shape (d,) or (N, d) with d = 2 or 3 (range m, azimuth rad[, elevation rad]), got {z.shape}")
    z = _as_rows("z_radar", z, dim, "range m, azimuth rad[, elevation rad]")
    _polar_checks("z_radar", z, COMPONENTS[dim])
    s = _sigmas("sigma_radar", sigma_radar, dim, COMPONENTS[dim])
    site = _site("site_radar_loc", np.zeros(dim) if site_radar_loc is None else site_radar_loc, dim)
    return z, s, site, dim


def _common_n(**arrays: np.ndarray) -> int:
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


def _bcast(a: np.ndarray, n: int) -> np.ndarray:
    return np.broadcast_to(a, (n,) + a.shape[1:]) if a.shape[0] != n else a


def _check_off_site(name: str, range_m: np.ndarray, scale_m: np.ndarray, offset: int = 0) -> None:
    bad = range_m <= _SITE_TOL * np.maximum(scale_m, 1.0)
    if bad.any():
        i = int(np.argwhere(bad)[0][0])
        raise ValueError(
            f"{name}: the target at row {offset + i} is at the sensor's site (distance {range_m[i]:.3g} m); "
            "bearings from a site to itself are undefined"
        )


# --------------------------------------------------------------------------- small linear algebra
# Internally, stacks of tiny matrices (d <= 3) are held "structure of arrays": a matrix stack is
# (rows, cols, N) and a vector stack (rows, N), so every entry is one contiguous array of N values
# and each product is a handful of whole-array operations (much faster than (N, d, d) @ in numpy).
def _soa(m: np.ndarray) -> np.ndarray:
    """(N, ...) -> (..., N), contiguous."""
    return np.ascontiguousarray(np.moveaxis(m, 0, -1))


def _aos(m: np.ndarray) -> np.ndarray:
    """(..., N) -> (N, ...), contiguous."""
    return np.ascontiguousarray(np.moveaxis(m, -1, 0))


def _mm(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """(i, k, N) x (k, j, N) -> (i, j, N)."""
    out = a[:, 0, None, :] * b[None, 0, :, :]
    for k in range(1, a.shape[1]):
        out += a[:, k, None, :] * b[None, k, :, :]
    return out


def _mv(a: np.ndarray, v: np.ndarray) -> np.ndarray:
    """(i, k, N) x (k, N) -> (i, N)."""
    out = a[:, 0, :] * v[0]
    for k in range(1, a.shape[1]):
        out += a[:, k, :] * v[k]
    return out


def _t(a: np.ndarray) -> np.ndarray:
    return a.transpose(1, 0, 2)


def _sym(m: np.ndarray) -> np.ndarray:
    return 0.5 * (m + _t(m))


def _sandwich(a: np.ndarray, diag: np.ndarray) -> np.ndarray:
    """a diag(diag) a^T: a (i, k, N), diag (k, N) -> symmetric (i, i, N)."""
    return _sym(_mm(a * diag[None, :, :], _t(a)))


def _inv(m: np.ndarray) -> np.ndarray:
    """Inverse of a (d, d, N) stack, d = 2 or 3, by the adjugate.

    Raises ValueError when a matrix is singular to working precision (a degenerate geometry).
    """
    d = m.shape[0]
    out = np.empty_like(m)
    if d == 2:
        a, b, c, e = m[0, 0], m[0, 1], m[1, 0], m[1, 1]
        det = a * e - b * c
        scale = np.abs(a * e) + np.abs(b * c)
        out[0, 0], out[0, 1], out[1, 0], out[1, 1] = e, -b, -c, a
    else:
        r0, r1, r2 = m[0], m[1], m[2]
        out[:, 0] = np.cross(r1, r2, axis=0)
        out[:, 1] = np.cross(r2, r0, axis=0)
        out[:, 2] = np.cross(r0, r1, axis=0)
        det = np.sum(r0 * out[:, 0], axis=0)
        scale = np.sqrt(np.sum(r0 * r0, axis=0) * np.sum(r1 * r1, axis=0) * np.sum(r2 * r2, axis=0))  # Hadamard
    bad = ~(np.abs(det) > 1e-13 * scale)
    if bad.any():
        i = int(np.argwhere(bad)[0][0])
        raise ValueError(f"singular {d}x{d} covariance or information matrix at row {i}: degenerate geometry")
    out /= det
    return out


def gdop(cov) -> np.ndarray:
    """GDOP (eq. 18) = sqrt(trace(cov)) in metres for a covariance (d, d) or a stack (..., d, d) in m^2."""
    c = as_float_array("cov", cov)
    if c.ndim < 2 or c.shape[-1] != c.shape[-2]:
        raise ValueError(f"cov: expected a square covariance (..., d, d) in m^2, got shape {c.shape}")
    return np.sqrt(np.trace(c, axis1=-2, axis2=-1))


def gdop_from_samples(p, truth=None) -> float:
    """GDOP (m) of sample points ``p`` (N, d) in metres.

    Without ``truth``: sqrt(trace of the sample covariance about the sample mean), the definition
    of eq. (18). With ``truth`` (d,): the root-mean-square distance to it (includes any bias).
    """
    x = as_float_array("p", p)
    if x.ndim != 2 or x.shape[0] < 2:
        raise ValueError(f"p: expected at least 2 sample points of shape (N, d) in metres, got {x.shape}")
    if truth is None:
        dev = x - x.mean(axis=0)
        return float(np.sqrt(np.sum(dev * dev) / (x.shape[0] - 1)))
    t = as_float_array("truth", truth)
    if t.shape != (x.shape[1],):
        raise ValueError(f"truth: expected shape ({x.shape[1]},) in metres, got {t.shape}")
    dev = x - t
    return float(np.sqrt(np.sum(dev * dev) / x.shape[0]))


# --------------------------------------------------------------------------- step (1)
def radar_point(z_radar, sigma_radar, site_radar_loc=None) -> tuple[np.ndarray, np.ndarray]:
    """Step (1): radar polar measurement -> point ``p_loc`` (N, d) m and covariance ``P`` (N, d, d) m^2.

    ``z_radar`` (d,) or (N, d): [r m, az rad(, el rad)] seen from ``site_radar_loc`` (d,) m
    (default the origin). ``sigma_radar`` (d,) or (N, d): standard deviations in the same units.
    """
    z, s, site, dim = _radar_inputs(z_radar, sigma_radar, site_radar_loc)
    n = _common_n(z_radar=z, sigma_radar=s)
    p_rel, J = _polar2cartesian(np.ascontiguousarray(_bcast(z, n)))
    return p_rel + site, _aos(_sandwich(_soa(J), _soa(_bcast(s, n)) ** 2))


# --------------------------------------------------------------------------- the paper's method
@dataclass(frozen=True)
class FusionResult:
    """Output of :func:`fuse_paper`; every array has a leading axis of N measurement pairs.

    Positions in metres in frame ``loc``; covariances in m^2; polar values [r m, az rad(, el rad)]
    seen from the second site.
    """

    #: step (1): radar point C (N, d) and its covariance P (N, d, d)
    p_radar_loc: np.ndarray
    P_radar: np.ndarray
    #: step (2): C in the second site's polar frame (N, d) and each component's variance (eq. 7)
    polar_radar_at_second: np.ndarray
    var_radar_at_second: np.ndarray
    #: step (3): fused polar values at the second site and their variances
    polar_fused_at_second: np.ndarray
    var_fused_at_second: np.ndarray
    #: step (4): pseudo-measurement H and the paper's covariance R (cross terms dropped)
    p_pseudo_loc: np.ndarray
    R_pseudo: np.ndarray
    #: first-order covariance of H from both sensors' raw noise (what H really scatters with)
    R_pseudo_consistent: np.ndarray
    #: step (5): fused point X (eq. 13), the method's own covariance, and the consistent one
    p_fused_loc: np.ndarray
    P_claimed: np.ndarray
    P_consistent: np.ndarray
    #: d X / d z_radar (N, d, d) and d X / d z_second (N, d, k): the first-order sensitivities
    dX_dz_radar: np.ndarray
    dX_dz_second: np.ndarray


def _second_inputs(z_second, sigma_second, components, dim: int):
    idx = parse_components(components, dim)
    k = idx.size
    names = tuple(COMPONENTS[dim][i] for i in idx)
    z2 = _as_rows("z_second", z_second, k, ", ".join(f"{n} {_UNITS[n]}" for n in names))
    _polar_checks("z_second", z2, names)
    s2 = _sigmas("sigma_second", sigma_second, k, names)
    return idx, z2, s2


def fuse_paper(
    z_radar,
    sigma_radar,
    z_second,
    sigma_second,
    components,
    site_second_loc,
    site_radar_loc=None,
) -> FusionResult:
    """The paper's dissimilar-dimension fusion, steps (1)-(5), vectorised over N pairs.

    Parameters
    ----------
    z_radar : (d,) or (N, d)
        Radar polar measurement [r m, az rad(, el rad)] from ``site_radar_loc``; d = 2 or 3.
    sigma_radar : (d,) or (N, d)
        Radar standard deviations [m, rad(, rad)].
    z_second : (k,) or (N, k)
        The second sensor's measurement of ``components`` (in that order) from ``site_second_loc``.
    sigma_second : (k,) or (N, k)
        Its standard deviations, same order and units.
    components : sequence of str
        Names of the components the second sensor measures (``range``, ``azimuth``/``bearing``,
        ``elevation`` in 3-D), any non-empty subset in any order.
    site_second_loc, site_radar_loc : (d,)
        Site positions in metres, frame ``loc`` (radar default: the origin). Equal sites are the
        same-platform case: then the transformed variances equal the radar's own.
    """
    z_a, s_a, site_a, dim = _radar_inputs(z_radar, sigma_radar, site_radar_loc)
    site_b = _site("site_second_loc", site_second_loc, dim)
    idx, z_b, s_b = _second_inputs(z_second, sigma_second, components, dim)
    n = _common_n(z_radar=z_a, sigma_radar=s_a, z_second=z_b, sigma_second=s_b)
    z_a, s_a, z_b, s_b = (_bcast(a, n) for a in (z_a, s_a, z_b, s_b))
    blocks = [
        _fuse_paper_block(z_a[i:i + _BLOCK], s_a[i:i + _BLOCK], z_b[i:i + _BLOCK], s_b[i:i + _BLOCK], idx, site_a, site_b, i)
        for i in range(0, n, _BLOCK)
    ]
    if len(blocks) == 1:
        return blocks[0]
    return FusionResult(**{f: np.concatenate([getattr(b, f) for b in blocks]) for f in FusionResult.__dataclass_fields__})


def _fuse_paper_block(z_a, s_a, z_b, s_b, idx, site_a, site_b, offset: int) -> FusionResult:
    """Steps (1)-(5) on validated (n, .) inputs; ``offset`` numbers rows in error messages."""
    n, dim = z_a.shape
    z_a = np.ascontiguousarray(z_a)
    z_b = _soa(z_b)  # (k, n)
    var_a = _soa(s_a) ** 2  # (d, n)
    var_b = _soa(s_b) ** 2  # (k, n)

    # (1) radar point and covariance
    p_c_rel, J_a_n = _polar2cartesian(z_a)
    p_c = _soa(p_c_rel) + site_a[:, None]  # (d, N)
    J_a = _soa(J_a_n)
    P = _sandwich(J_a, var_a)

    # (2) C seen from the second site; variances by the Cartesian -> polar Jacobian (eq. 7)
    polar_b_n, G_n = _cartesian2polar(_aos(p_c - site_b[:, None]))
    polar_b, G = _soa(polar_b_n), _soa(G_n)
    _check_off_site("site_second_loc", polar_b[0], z_a[:, 0], offset)
    var_b_prime = np.sum(_mm(G, P) * G, axis=1)  # diag(G P G^T), (d, N)

    # (3) inverse-variance fusion of the components the second sensor measures
    w = var_b_prime[idx] / (var_b_prime[idx] + var_b)  # weight of the second sensor, (k, N)
    innov = z_b - polar_b[idx]
    angles = idx != 0
    innov[angles] = wrap_angle(innov[angles])  # angles fused on the wrapped difference
    polar_f = polar_b.copy()
    polar_f[idx] += w * innov
    polar_f[1] = wrap_angle(polar_f[1])  # azimuth back to (-pi, pi]
    var_f = var_b_prime.copy()
    var_f[idx] = var_b_prime[idx] * var_b / (var_b_prime[idx] + var_b)
    if (polar_f[0] <= 0).any():
        i = int(np.argwhere(polar_f[0] <= 0)[0][0])
        raise ValueError(f"z_second: the fused range at row {offset + i} is not positive ({polar_f[0, i]:.3g} m)")

    # (4) pseudo-measurement H at the second site and its covariance (paper: diagonal polar cov)
    p_h_rel, J_h_n = _polar2cartesian(_aos(polar_f))
    p_h = _soa(p_h_rel) + site_b[:, None]
    J_h = _soa(J_h_n)
    R = _sandwich(J_h, var_f)

    # (5) convex combination, eq. (13)
    W_h = _mm(P, _inv(P + R))  # weight of H; weight of C is R (P + R)^-1 = I - W_h
    p_x = p_c + _mv(W_h, p_h - p_c)
    P_claimed = _sym(_mm(W_h, R))

    # consistent covariance: first-order propagation of the raw noise, weights held fixed
    D = np.ones((dim, n))
    D[idx] = 1.0 - w  # d polar_f / d polar_b (diagonal)
    dH_dC = _mm(J_h, D[:, None, :] * G)
    dH_da = _mm(dH_dC, J_a)
    dH_db = J_h[:, idx, :] * w[None, :, :]  # J_h d polar_f / d z_second, (d, k, N)
    W_c = np.eye(dim)[:, :, None] - W_h
    dX_da = _mm(W_c + _mm(W_h, dH_dC), J_a)
    dX_db = _mm(W_h, dH_db)
    P_consistent = _sandwich(dX_da, var_a) + _sandwich(dX_db, var_b)
    R_consistent = _sandwich(dH_da, var_a) + _sandwich(dH_db, var_b)

    return FusionResult(
        p_radar_loc=_aos(p_c),
        P_radar=_aos(P),
        polar_radar_at_second=polar_b_n,
        var_radar_at_second=_aos(var_b_prime),
        polar_fused_at_second=_aos(polar_f),
        var_fused_at_second=_aos(var_f),
        p_pseudo_loc=_aos(p_h),
        R_pseudo=_aos(R),
        R_pseudo_consistent=_aos(R_consistent),
        p_fused_loc=_aos(p_x),
        P_claimed=_aos(P_claimed),
        P_consistent=_aos(P_consistent),
        dX_dz_radar=_aos(dX_da),
        dX_dz_second=_aos(dX_db),
    )


# --------------------------------------------------------------------------- optimal fuser and CRLB
def _model(p_loc: np.ndarray, site_a: np.ndarray, site_b: np.ndarray, idx: np.ndarray):
    """Predicted measurements [radar polar (d), second (k)] as (d+k, N) and their Jacobian d/dp (d+k, d, N).

    ``p_loc`` (d, N) metres; sites (d,).
    """
    pol_a, G_a = _cartesian2polar(_aos(p_loc - site_a[:, None]))
    pol_b, G_b = _cartesian2polar(_aos(p_loc - site_b[:, None]))
    h = np.concatenate([_soa(pol_a), _soa(pol_b[:, idx])], axis=0)
    H = np.concatenate([_soa(G_a), _soa(G_b[:, idx, :])], axis=0)
    return h, H


def _information(H: np.ndarray, inv_var: np.ndarray) -> np.ndarray:
    """H^T diag(inv_var) H: H (m, d, N), inv_var (m, N) -> (d, d, N)."""
    return _sym(_mm(_t(H) * inv_var[None, :, :], H))


def _residual(z: np.ndarray, h: np.ndarray, angle_rows: np.ndarray) -> np.ndarray:
    r = z - h
    r[angle_rows] = wrap_angle(r[angle_rows])
    return r


@dataclass(frozen=True)
class OptimalResult:
    """Output of :func:`fuse_optimal` (leading axis N)."""

    #: maximum-likelihood position (N, d), metres, frame loc
    p_loc: np.ndarray
    #: inverse Fisher information at the estimate (N, d, d), m^2: the fuser's own covariance
    P: np.ndarray
    #: Gauss-Newton iterations used per pair, and whether the step fell below ``tol_m``
    iterations: np.ndarray
    converged: np.ndarray


def fisher_information(p_loc, sigma_radar, sigma_second, components, site_second_loc, site_radar_loc=None) -> np.ndarray:
    """Fisher information (N, d, d) in 1/m^2 of the raw measurements about the position ``p_loc`` (d,) or (N, d) m."""
    p = as_float_array("p_loc", p_loc)
    dim = p.shape[-1] if p.ndim in (1, 2) else -1
    if dim not in COMPONENTS:
        raise ValueError(f"p_loc: expected shape (d,) or (N, d) in metres with d = 2 or 3, got {p.shape}")
    p = _as_rows("p_loc", p, dim, "m")
    check_finite("p_loc", p, "m")
    s_a = _sigmas("sigma_radar", sigma_radar, dim, COMPONENTS[dim])
    site_a = _site("site_radar_loc", np.zeros(dim) if site_radar_loc is None else site_radar_loc, dim)
    site_b = _site("site_second_loc", site_second_loc, dim)
    idx = parse_components(components, dim)
    s_b = _sigmas("sigma_second", sigma_second, idx.size, tuple(COMPONENTS[dim][i] for i in idx))
    n = _common_n(p_loc=p, sigma_radar=s_a, sigma_second=s_b)
    p = _soa(_bcast(p, n))
    scale = np.linalg.norm(p - site_a[:, None], axis=0)
    _check_off_site("site_radar_loc", scale, scale)
    _check_off_site("site_second_loc", np.linalg.norm(p - site_b[:, None], axis=0), scale)
    _, H = _model(p, site_a, site_b, idx)
    inv_var = _soa(np.concatenate([_bcast(s_a, n), _bcast(s_b, n)], axis=1)) ** -2
    return _aos(_information(H, inv_var))


def crlb(p_loc, sigma_radar, sigma_second, components, site_second_loc, site_radar_loc=None) -> np.ndarray:
    """Cramer-Rao bound (N, d, d) in m^2 on the position of a target at ``p_loc`` (d,) or (N, d) m.

    The inverse Fisher information of the radar's polar measurement and the second sensor's
    components, all with independent Gaussian noise: no unbiased fuser of these raw measurements
    can have a smaller covariance.
    """
    info = _soa(fisher_information(p_loc, sigma_radar, sigma_second, components, site_second_loc, site_radar_loc))
    return _aos(_sym(_inv(info)))


def fuse_optimal(
    z_radar,
    sigma_radar,
    z_second,
    sigma_second,
    components,
    site_second_loc,
    site_radar_loc=None,
    *,
    max_iterations: int = 30,
    tol_m: float = 1e-6,
) -> OptimalResult:
    """Maximum-likelihood fusion of the raw measurements by Gauss-Newton from the radar point.

    Minimises sum ((z - h(p)) / sigma)^2 over both sensors' components (angle residuals wrapped to
    (-pi, pi]); a step that raises the cost is halved (up to 20 times). Same inputs as
    :func:`fuse_paper`. Its covariance is the inverse Fisher information at the estimate, which
    tends to :func:`crlb` as the noise shrinks.
    """
    if not (isinstance(max_iterations, (int, np.integer)) and max_iterations >= 1):
        raise ValueError(f"max_iterations: expected a positive integer, got {max_iterations!r}")
    if not (np.isfinite(tol_m) and tol_m > 0):
        raise ValueError(f"tol_m: expected a positive step tolerance in metres, got {tol_m!r}")
    z_a = as_float_array("z_radar", z_radar)
    dim = z_a.shape[-1] if z_a.ndim in (1, 2) else -1
    if dim not in COMPONENTS:
        raise ValueError(f"z_radar: expected shape (d,) or (N, d) with d = 2 or 3 (range m, azimuth rad[, elevation rad]), got {z_a.shape}")
    z_a = _as_rows("z_radar", z_a, dim, "range m, azimuth rad[, elevation rad]")
    site_a = _site("site_radar_loc", np.zeros(dim) if site_radar_loc is None else site_radar_loc, dim)
    site_b = _site("site_second_loc", site_second_loc, dim)
    idx, z_b, s_b = _second_inputs(z_second, sigma_second, components, dim)
    s_a = _sigmas("sigma_radar", sigma_radar, dim, COMPONENTS[dim])
    _polar_checks("z_radar", z_a, COMPONENTS[dim])
    n = _common_n(z_radar=z_a, sigma_radar=s_a, z_second=z_b, sigma_second=s_b)
    z_all = np.concatenate([_bcast(z_a, n), _bcast(z_b, n)], axis=1)  # (N, d+k)
    s_all = np.concatenate([_bcast(s_a, n), _bcast(s_b, n)], axis=1)
    blocks = [
        _fuse_optimal_block(z_all[i:i + _BLOCK], s_all[i:i + _BLOCK], idx, site_a, site_b, max_iterations, tol_m, i)
        for i in range(0, n, _BLOCK)
    ]
    if len(blocks) == 1:
        return blocks[0]
    return OptimalResult(**{f: np.concatenate([getattr(b, f) for b in blocks]) for f in OptimalResult.__dataclass_fields__})


def _fuse_optimal_block(z_all, s_all, idx, site_a, site_b, max_iterations: int, tol_m: float, offset: int) -> OptimalResult:
    """Gauss-Newton on validated (n, d+k) measurements and sigmas; ``offset`` numbers rows in errors."""
    n, dim = z_all.shape[0], site_a.size
    z = _soa(z_all)  # (d+k, n)
    inv_var = _soa(s_all) ** -2
    angle_rows = np.flatnonzero(np.concatenate([np.arange(dim), idx]) != 0)

    p_rel, _ = _polar2cartesian(np.ascontiguousarray(z_all[:, :dim]))
    p = _soa(p_rel) + site_a[:, None]  # start at the radar point, (d, N)
    scale = np.maximum(z[0], 1.0)
    iterations = np.zeros(n, dtype=np.int64)
    converged = np.zeros(n, dtype=bool)

    def evaluate(points, rows):
        """Residuals (m, n'), Jacobians (m, d, n') and costs (n') at points (d, n') for block rows."""
        for name, site in (("site_second_loc", site_b), ("site_radar_loc", site_a)):
            near = np.sqrt(np.sum((points - site[:, None]) ** 2, axis=0)) <= _SITE_TOL * scale[rows]
            if near.any():
                i = offset + int(rows[np.argmax(near)])
                raise ValueError(f"{name}: the Gauss-Newton iterate for row {i} reached the sensor's site; degenerate geometry")
        h, H = _model(points, site_a, site_b, idx)
        r = _residual(z[:, rows], h, angle_rows)
        return r, H, np.sum(r * r * inv_var[:, rows], axis=0)

    active = np.arange(n)
    r, H, cost = evaluate(p, active)  # at the current iterate, for the active rows
    for _ in range(max_iterations):
        if active.size == 0:
            break
        iv = inv_var[:, active]
        HtW = _t(H) * iv[None, :, :]  # (d, m, n')
        step = _mv(_inv(_mm(HtW, H)), _mv(HtW, r))
        p_new = p[:, active] + step
        r_new, H_new, cost_new = evaluate(p_new, active)
        # backtracking: halve the step where the cost went up (the evaluation is reused next iteration)
        for _halve in range(20):
            big = np.sum(step * step, axis=0) >= tol_m * tol_m  # below tol_m rounding decides, not the model
            worse = np.flatnonzero((cost_new > cost * (1 + 1e-9) + 1e-300) & big)
            if worse.size == 0:
                break
            step[:, worse] *= 0.5
            p_new[:, worse] = p[:, active[worse]] + step[:, worse]
            r_w, H_w, c_w = evaluate(p_new[:, worse], active[worse])
            r_new[:, worse], H_new[:, :, worse], cost_new[worse] = r_w, H_w, c_w
        p[:, active] = p_new
        iterations[active] += 1
        keep = np.sqrt(np.sum(step * step, axis=0)) >= tol_m
        converged[active[~keep]] = True
        active = active[keep]
        r, H, cost = r_new[:, keep], H_new[:, :, keep], cost_new[keep]

    _, H = _model(p, site_a, site_b, idx)
    P = _inv(_information(H, inv_var))
    return OptimalResult(p_loc=_aos(p), P=_aos(_sym(P)), iterations=iterations, converged=converged)
