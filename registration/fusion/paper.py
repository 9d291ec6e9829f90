"""The paper's pseudo-measurement fusion of a radar with a sensor measuring fewer polar components.

:func:`fuse_paper` runs the paper's steps vectorised over N measurement pairs and returns every
intermediate, the covariance the method claims (eq. 13) and the consistent one (first-order
propagation of both sensors' raw noise through all steps). Positions in metres, frame ``loc``;
polar values ``[r m, az rad(, el rad)]``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.core import linalg as la
from registration.core.angles import wrap_angle
from registration.fusion.checks import (
    broadcast_rows,
    check_off_site,
    common_rows,
    in_blocks,
    pair_inputs,
    radar_inputs,
)
from registration.fusion.polar import cartesian2polar, polar2cartesian

__all__ = ["FusionResult", "radar_point", "fuse_paper"]


def radar_point(z_radar, sigma_radar, site_radar_loc=None) -> tuple[np.ndarray, np.ndarray]:
    """Step (1): radar polar measurement -> point ``p_loc`` (N, d) m and covariance ``P`` (N, d, d) m^2.

    ``z_radar`` (d,) or (N, d): [r m, az rad(, el rad)] seen from ``site_radar_loc`` (d,) m
    (default the origin). ``sigma_radar`` (d,) or (N, d): standard deviations in the same units.
    """
    z, s, site, dim = radar_inputs(z_radar, sigma_radar, site_radar_loc)
    n = common_rows(z_radar=z, sigma_radar=s)
    p_rel, J = polar2cartesian(np.ascontiguousarray(broadcast_rows(z, n)))
    return p_rel + site, la.aos(la.sandwich(la.soa(J), la.soa(broadcast_rows(s, n)) ** 2))


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


def fuse_paper(
    z_radar, sigma_radar, z_second, sigma_second, components, site_second_loc, site_radar_loc=None
) -> FusionResult:
    """The paper's dissimilar-dimension fusion, steps (1)-(5), vectorised over N pairs.

    (1) radar point C and P = J_A diag(sigma_A^2) J_A^T; (2) C seen from the second site, each
    component's variance from P (eq. 7); (3) inverse-variance fusion of the components the second
    sensor measures (angles on the wrapped difference); (4) pseudo-measurement H rebuilt at the
    second site, R = J_B diag(var_fused) J_B^T (eqs. 9-12, polar cross terms dropped as in the
    paper); (5) X = R (P + R)^-1 X_C + P (P + R)^-1 X_H (eq. 13).

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
    x = pair_inputs(z_radar, sigma_radar, z_second, sigma_second, components, site_second_loc, site_radar_loc)

    def block(rows: slice, offset: int) -> FusionResult:
        return _fuse_paper_block(
            x.z_radar[rows],
            x.sigma_radar[rows],
            x.z_second[rows],
            x.sigma_second[rows],
            x.idx,
            x.site_radar,
            x.site_second,
            offset,
        )

    return in_blocks(block, x.n, FusionResult)


def _fuse_components(polar_b, var_b_prime, z_b, var_b, idx, offset: int):
    """Step (3): weights w (k, n) of the second sensor, fused polar values and variances (d, n)."""
    w = var_b_prime[idx] / (var_b_prime[idx] + var_b)
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
        raise ValueError(
            f"z_second: the fused range at row {offset + i} is not positive ({polar_f[0, i]:.3g} m)"
        )
    return w, polar_f, var_f


def _consistent(w, idx, J_a, G, J_h, W_h, var_a, var_b):
    """First-order propagation of the raw noise through steps (1)-(5), weights held fixed.

    Returns dX/dz_radar (d, d, n), dX/dz_second (d, k, n), cov(X) and cov(H) (d, d, n).
    """
    dim, n = J_a.shape[0], J_a.shape[2]
    D = np.ones((dim, n))
    D[idx] = 1.0 - w  # d polar_f / d polar_b (diagonal)
    dH_dC = la.mm(J_h, D[:, None, :] * G)
    dH_da = la.mm(dH_dC, J_a)
    dH_db = J_h[:, idx, :] * w[None, :, :]  # J_h d polar_f / d z_second, (d, k, N)
    W_c = np.eye(dim)[:, :, None] - W_h
    dX_da = la.mm(W_c + la.mm(W_h, dH_dC), J_a)
    dX_db = la.mm(W_h, dH_db)
    P_consistent = la.sandwich(dX_da, var_a) + la.sandwich(dX_db, var_b)
    R_consistent = la.sandwich(dH_da, var_a) + la.sandwich(dH_db, var_b)
    return dX_da, dX_db, P_consistent, R_consistent


def _fuse_paper_block(z_a, s_a, z_b, s_b, idx, site_a, site_b, offset: int) -> FusionResult:
    """Steps (1)-(5) on validated (n, .) inputs; ``offset`` numbers rows in error messages."""
    z_a = np.ascontiguousarray(z_a)
    z_b = la.soa(z_b)  # (k, n)
    var_a = la.soa(s_a) ** 2  # (d, n)
    var_b = la.soa(s_b) ** 2  # (k, n)

    # (1) radar point and covariance
    p_c_rel, J_a_n = polar2cartesian(z_a)
    p_c = la.soa(p_c_rel) + site_a[:, None]  # (d, N)
    J_a = la.soa(J_a_n)
    P = la.sandwich(J_a, var_a)

    # (2) C seen from the second site; variances by the Cartesian -> polar Jacobian (eq. 7)
    polar_b_n, G_n = cartesian2polar(la.aos(p_c - site_b[:, None]))
    polar_b, G = la.soa(polar_b_n), la.soa(G_n)
    check_off_site("site_second_loc", polar_b[0], z_a[:, 0], offset)
    var_b_prime = np.sum(la.mm(G, P) * G, axis=1)  # diag(G P G^T), (d, N)

    # (3) inverse-variance fusion of the components the second sensor measures
    w, polar_f, var_f = _fuse_components(polar_b, var_b_prime, z_b, var_b, idx, offset)

    # (4) pseudo-measurement H at the second site and its covariance (paper: diagonal polar cov)
    p_h_rel, J_h_n = polar2cartesian(la.aos(polar_f))
    p_h = la.soa(p_h_rel) + site_b[:, None]
    J_h = la.soa(J_h_n)
    R = la.sandwich(J_h, var_f)

    # (5) convex combination, eq. (13)
    W_h = la.mm(P, la.inv(P + R))  # weight of H; weight of C is R (P + R)^-1 = I - W_h
    p_x = p_c + la.mv(W_h, p_h - p_c)
    P_claimed = la.sym(la.mm(W_h, R))

    dX_da, dX_db, P_consistent, R_consistent = _consistent(w, idx, J_a, G, J_h, W_h, var_a, var_b)
    return FusionResult(
        p_radar_loc=la.aos(p_c),
        P_radar=la.aos(P),
        polar_radar_at_second=polar_b_n,
        var_radar_at_second=la.aos(var_b_prime),
        polar_fused_at_second=la.aos(polar_f),
        var_fused_at_second=la.aos(var_f),
        p_pseudo_loc=la.aos(p_h),
        R_pseudo=la.aos(R),
        R_pseudo_consistent=la.aos(R_consistent),
        p_fused_loc=la.aos(p_x),
        P_claimed=la.aos(P_claimed),
        P_consistent=la.aos(P_consistent),
        dX_dz_radar=la.aos(dX_da),
        dX_dz_second=la.aos(dX_db),
    )
