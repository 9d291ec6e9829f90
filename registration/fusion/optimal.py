"""The optimal fuser of a radar and a sensor measuring fewer polar components, and its bound.

:func:`fuse_optimal` is the maximum-likelihood position from both sensors' raw polar
measurements (Gauss-Newton from the radar point); :func:`fisher_information` and :func:`crlb`
give the information and the Cramer-Rao bound about a position. Positions in metres, frame
``loc``; covariances in m^2.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.core import linalg as la
from registration.core.angles import wrap_angle
from registration.core.validation import check_finite
from registration.fusion.checks import (
    SITE_TOL,
    broadcast_rows,
    check_off_site,
    common_rows,
    in_blocks,
    pair_inputs,
    point_rows,
    radar_site,
    sigma_rows,
    site_position,
)
from registration.fusion.polar import COMPONENTS, cartesian2polar, parse_components, polar2cartesian

__all__ = ["OptimalResult", "fisher_information", "crlb", "fuse_optimal"]


def _model(p_loc: np.ndarray, site_a: np.ndarray, site_b: np.ndarray, idx: np.ndarray):
    """Predicted measurements [radar polar (d), second (k)] as (d+k, N) and their Jacobian d/dp (d+k, d, N).

    ``p_loc`` (d, N) metres; sites (d,).
    """
    pol_a, G_a = cartesian2polar(la.aos(p_loc - site_a[:, None]))
    pol_b, G_b = cartesian2polar(la.aos(p_loc - site_b[:, None]))
    h = np.concatenate([la.soa(pol_a), la.soa(pol_b[:, idx])], axis=0)
    H = np.concatenate([la.soa(G_a), la.soa(G_b[:, idx, :])], axis=0)
    return h, H


def _information(H: np.ndarray, inv_var: np.ndarray) -> np.ndarray:
    """H^T diag(inv_var) H: H (m, d, N), inv_var (m, N) -> (d, d, N)."""
    return la.sym(la.mm(la.transpose(H) * inv_var[None, :, :], H))


def _residual(z: np.ndarray, h: np.ndarray, angle_rows: np.ndarray) -> np.ndarray:
    """z - h (m, N), angle rows wrapped to (-pi, pi]."""
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


def fisher_information(
    p_loc, sigma_radar, sigma_second, components, site_second_loc, site_radar_loc=None
) -> np.ndarray:
    """Fisher information (N, d, d) in 1/m^2 of the raw
    measurements about the position ``p_loc`` (d,) or (N, d) m."""
    p, dim = point_rows("p_loc", p_loc, "in metres with d = 2 or 3")
    check_finite("p_loc", p, "m")
    s_a = sigma_rows("sigma_radar", sigma_radar, dim, COMPONENTS[dim])
    site_a = radar_site(site_radar_loc, dim)
    site_b = site_position("site_second_loc", site_second_loc, dim)
    idx = parse_components(components, dim)
    s_b = sigma_rows("sigma_second", sigma_second, idx.size, tuple(COMPONENTS[dim][i] for i in idx))
    n = common_rows(p_loc=p, sigma_radar=s_a, sigma_second=s_b)
    p = la.soa(broadcast_rows(p, n))
    scale = np.linalg.norm(p - site_a[:, None], axis=0)
    check_off_site("site_radar_loc", scale, scale)
    check_off_site("site_second_loc", np.linalg.norm(p - site_b[:, None], axis=0), scale)
    _, H = _model(p, site_a, site_b, idx)
    inv_var = la.soa(np.concatenate([broadcast_rows(s_a, n), broadcast_rows(s_b, n)], axis=1)) ** -2
    return la.aos(_information(H, inv_var))


def crlb(p_loc, sigma_radar, sigma_second, components, site_second_loc, site_radar_loc=None) -> np.ndarray:
    """Cramer-Rao bound (N, d, d) in m^2 on the position of a target at ``p_loc`` (d,) or (N, d) m.

    The inverse Fisher information of the radar's polar measurement and the second sensor's
    components, all with independent Gaussian noise: no unbiased fuser of these raw measurements
    can have a smaller covariance.
    """
    info = la.soa(
        fisher_information(p_loc, sigma_radar, sigma_second, components, site_second_loc, site_radar_loc)
    )
    return la.aos(la.sym(la.inv(info)))


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
    (-pi, pi]); a step that raises the cost is halved (up to 20 times); a pair stops when its step
    is below ``tol_m`` metres. Same inputs as :func:`~registration.fusion.fuse_paper`. Its
    covariance is the inverse Fisher information at the estimate, which tends to :func:`crlb` as
    the noise shrinks.
    """
    if not (isinstance(max_iterations, (int, np.integer)) and max_iterations >= 1):
        raise ValueError(f"max_iterations: expected a positive integer, got {max_iterations!r}")
    if not (np.isfinite(tol_m) and tol_m > 0):
        raise ValueError(f"tol_m: expected a positive step tolerance in metres, got {tol_m!r}")
    x = pair_inputs(z_radar, sigma_radar, z_second, sigma_second, components, site_second_loc, site_radar_loc)
    z_all = np.concatenate([x.z_radar, x.z_second], axis=1)  # (N, d+k)
    s_all = np.concatenate([x.sigma_radar, x.sigma_second], axis=1)

    def block(rows: slice, offset: int) -> OptimalResult:
        return _fuse_optimal_block(
            z_all[rows], s_all[rows], x.idx, x.site_radar, x.site_second, max_iterations, tol_m, offset
        )

    return in_blocks(block, x.n, OptimalResult)


def _fuse_optimal_block(
    z_all, s_all, idx, site_a, site_b, max_iterations: int, tol_m: float, offset: int
) -> OptimalResult:
    """Gauss-Newton on validated (n, d+k) measurements and sigmas; ``offset`` numbers rows in errors."""
    n, dim = z_all.shape[0], site_a.size
    z = la.soa(z_all)  # (d+k, n)
    inv_var = la.soa(s_all) ** -2
    angle_rows = np.flatnonzero(np.concatenate([np.arange(dim), idx]) != 0)

    p_rel, _ = polar2cartesian(np.ascontiguousarray(z_all[:, :dim]))
    p = la.soa(p_rel) + site_a[:, None]  # start at the radar point, (d, N)
    scale = np.maximum(z[0], 1.0)
    iterations = np.zeros(n, dtype=np.int64)
    converged = np.zeros(n, dtype=bool)

    def evaluate(points, rows):
        """Residuals (m, n'), Jacobians (m, d, n') and costs (n') at points (d, n') for block rows."""
        for name, site in (("site_second_loc", site_b), ("site_radar_loc", site_a)):
            near = np.sqrt(np.sum((points - site[:, None]) ** 2, axis=0)) <= SITE_TOL * scale[rows]
            if near.any():
                i = offset + int(rows[np.argmax(near)])
                raise ValueError(
                    f"{name}: the Gauss-Newton iterate for row {i} reached the sensor's site; degenerate "
                    "geometry"
                )
        h, H = _model(points, site_a, site_b, idx)
        r = _residual(z[:, rows], h, angle_rows)
        return r, H, np.sum(r * r * inv_var[:, rows], axis=0)

    active = np.arange(n)
    r, H, cost = evaluate(p, active)  # at the current iterate, for the active rows
    for _ in range(max_iterations):
        if active.size == 0:
            break
        iv = inv_var[:, active]
        HtW = la.transpose(H) * iv[None, :, :]  # (d, m, n')
        step = la.mv(la.inv(la.mm(HtW, H)), la.mv(HtW, r))
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
    P = la.inv(_information(H, inv_var))
    return OptimalResult(p_loc=la.aos(p), P=la.aos(la.sym(P)), iterations=iterations, converged=converged)
