"""Benchmark of the fusion: 10^6 radar + bearing pairs (paper scenario 1), library vs plain NumPy.

    python benchmarks/bench_fusion.py [--pairs 1000000] [--repeats 5] [--tiny] [--json FILE]

Prints pairs per second (median of the repeats, interleaved: common.interleave) for

- ``registration.fusion.fuse_paper``: the general method (any component subset, 2-D or 3-D) with the
  generated C transforms, returning the fused point, the claimed (eq. 13) and the consistent
  covariance and every intermediate;
- a plain-NumPy version written out by hand for this one case (2-D, bearing-only second sensor):
  the same fused point and both covariances, nothing else;
- ``registration.fusion.fuse_optimal`` (maximum likelihood, Gauss-Newton) vs a plain-NumPy
  Gauss-Newton for the same case with the same stopping rule.

The two versions' outputs are compared before timing. The hand-written formulas live here only as
the baseline; the package reaches its transforms through the generated functions only.
Figures: benchmarks/results/fusion.json.
"""

from __future__ import annotations

import argparse
import os
import sys

import numpy as np
from common import add_arguments, interleave, median, paired_ratio, summary, write

from registration import _codegen
from registration import fusion as F

SIGMA_RADAR = np.array([100.0, 7e-3])
SIGMA_B = 4e-3
SITE_B = np.array([80e3, 0.0])


def wrap(a):
    """Angles to [-pi, pi): the plain-NumPy baseline's own wrap (registration uses core.angles.wrap_angle)."""
    return np.mod(a + np.pi, 2 * np.pi) - np.pi


def plain_numpy_paper(za: np.ndarray, zb: np.ndarray):
    """Scenario-1 method by hand: radar (r, a) at the origin, bearing b at (l, 0). Returns X,
    P_claimed, P_consistent."""
    sr2, sa2, sb2 = SIGMA_RADAR[0] ** 2, SIGMA_RADAR[1] ** 2, SIGMA_B**2
    l = SITE_B[0]  # noqa: E741 (the paper's name)
    r, a = za[:, 0], za[:, 1]
    b = zb[:, 0]
    ca, sa = np.cos(a), np.sin(a)
    xc, yc = r * ca, r * sa
    # P = J diag(sr2, sa2) J^T, J = [[ca, -r sa], [sa, r ca]]
    pxx = ca * ca * sr2 + r * r * sa * sa * sa2
    pyy = sa * sa * sr2 + r * r * ca * ca * sa2
    pxy = ca * sa * (sr2 - r * r * sa2)
    dx, dy = xc - l, yc
    rb2 = dx * dx + dy * dy
    rb = np.sqrt(rb2)
    bp = np.arctan2(dy, dx)
    # gradients of b' and r_b with respect to (x, y)
    gbx, gby = -dy / rb2, dx / rb2
    grx, gry = dx / rb, dy / rb
    var_bp = gbx * gbx * pxx + 2 * gbx * gby * pxy + gby * gby * pyy  # eq. 7
    var_rb = grx * grx * pxx + 2 * grx * gry * pxy + gry * gry * pyy
    w = var_bp / (var_bp + sb2)
    bf = bp + w * wrap(b - bp)
    var_bf = var_bp * sb2 / (var_bp + sb2)
    cb, sb = np.cos(bf), np.sin(bf)
    xh, yh = l + rb * cb, rb * sb
    rxx = cb * cb * var_rb + rb2 * sb * sb * var_bf
    ryy = sb * sb * var_rb + rb2 * cb * cb * var_bf
    rxy = cb * sb * (var_rb - rb2 * var_bf)
    sxx, syy, sxy = pxx + rxx, pyy + ryy, pxy + rxy
    det = sxx * syy - sxy * sxy
    ixx, iyy, ixy = syy / det, sxx / det, -sxy / det
    # W_h = P S^-1
    wxx = pxx * ixx + pxy * ixy
    wxy = pxx * ixy + pxy * iyy
    wyx = pxy * ixx + pyy * ixy
    wyy = pxy * ixy + pyy * iyy
    ex, ey = xh - xc, yh - yc
    X = np.stack([xc + wxx * ex + wxy * ey, yc + wyx * ex + wyy * ey], axis=1)
    # claimed: W_h R
    cxx = wxx * rxx + wxy * rxy
    cxy = wxx * rxy + wxy * ryy
    cyy = wyx * rxy + wyy * ryy
    P_claimed = np.stack([np.stack([cxx, cxy], -1), np.stack([cxy, cyy], -1)], -2)
    # consistent: X = C + W_h (H(C, b) - C); dH/dC = Jh diag(1, 1 - w) G, G = [grad r_b; grad b']
    jh = np.array([[cb, -rb * sb], [sb, rb * cb]])  # (2, 2, N)
    g = np.array([[grx, gry], [(1 - w) * gbx, (1 - w) * gby]])
    dhdc = np.einsum("ikn,kjn->ijn", jh, g)
    wh = np.array([[wxx, wxy], [wyx, wyy]])
    m = np.eye(2)[:, :, None] - wh + np.einsum("ikn,kjn->ijn", wh, dhdc)
    ja = np.array([[ca, -r * sa], [sa, r * ca]])
    dxa = np.einsum("ikn,kjn->ijn", m, ja)
    dxb = np.einsum("ikn,kn->in", wh, np.array([-rb * sb * w, rb * cb * w]))
    cons = (
        np.einsum("ikn,jkn,k->ijn", dxa, dxa, np.array([sr2, sa2])) + np.einsum("in,jn->ijn", dxb, dxb) * sb2
    )
    return X, P_claimed, np.moveaxis(cons, -1, 0)


def plain_numpy_optimal(za: np.ndarray, zb: np.ndarray, tol_m: float = 1e-6, max_iterations: int = 30):
    """Gauss-Newton by hand on (r, a, b) with 2 unknowns, from the radar point (no step halving).

    Returns the estimate (N, 2) and its covariance, the inverse information at the estimate (N, 2, 2).
    """
    w = np.array([SIGMA_RADAR[0] ** -2, SIGMA_RADAR[1] ** -2, SIGMA_B**-2])
    l = SITE_B[0]  # noqa: E741 (the paper's name)
    x = za[:, 0] * np.cos(za[:, 1])
    y = za[:, 0] * np.sin(za[:, 1])
    active = np.ones(x.size, dtype=bool)
    for _ in range(max_iterations):
        r = np.hypot(x, y)
        dx = x - l
        rb2 = dx * dx + y * y
        res = np.stack([za[:, 0] - r, wrap(za[:, 1] - np.arctan2(y, x)), wrap(zb[:, 0] - np.arctan2(y, dx))])
        H = np.array([[x / r, y / r], [-y / (r * r), x / (r * r)], [-y / rb2, dx / rb2]])  # (3, 2, N)
        A = np.einsum("kin,k,kjn->ijn", H, w, H)
        g = np.einsum("kin,k,kn->in", H, w, res)
        det = A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0]
        sx = (A[1, 1] * g[0] - A[0, 1] * g[1]) / det
        sy = (A[0, 0] * g[1] - A[1, 0] * g[0]) / det
        sx, sy = np.where(active, sx, 0.0), np.where(active, sy, 0.0)
        x, y = x + sx, y + sy
        active &= np.hypot(sx, sy) >= tol_m
        if not active.any():
            break
    r2, rb2 = x * x + y * y, (x - l) ** 2 + y * y
    r = np.sqrt(r2)
    H = np.array([[x / r, y / r], [-y / r2, x / r2], [-y / rb2, (x - l) / rb2]])
    A = np.einsum("kin,k,kjn->nij", H, w, H)
    det = A[:, 0, 0] * A[:, 1, 1] - A[:, 0, 1] ** 2
    cov = (
        np.stack([np.stack([A[:, 1, 1], -A[:, 0, 1]], -1), np.stack([-A[:, 0, 1], A[:, 0, 0]], -1)], -2)
        / det[:, None, None]
    )
    return np.stack([x, y], axis=1), cov


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pairs", type=int, default=1_000_000)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--seed", type=int, default=0)
    add_arguments(ap)
    args = ap.parse_args(argv)
    if args.tiny:
        args.pairs, args.repeats = 2000, 1
    n = args.pairs

    rng = np.random.default_rng(args.seed)
    p_true = 100e3 * np.array([np.cos(np.radians(15)), np.sin(np.radians(15))])
    za = np.array([100e3, np.radians(15)]) + rng.standard_normal((n, 2)) * SIGMA_RADAR
    zb = np.arctan2(p_true[1], p_true[0] - SITE_B[0]) + rng.standard_normal((n, 1)) * SIGMA_B

    def lib_paper():
        return F.fuse_paper(za, SIGMA_RADAR, zb, [SIGMA_B], ["azimuth"], SITE_B)

    def lib_optimal():
        return F.fuse_optimal(za, SIGMA_RADAR, zb, [SIGMA_B], ["azimuth"], SITE_B)

    # agreement first (on the full set)
    res = lib_paper()
    X, Pc, Pk = plain_numpy_paper(za, zb)
    dx = np.abs(res.p_fused_loc - X).max()
    dpc = np.abs(res.P_claimed - Pc).max() / np.abs(Pc).max()
    dpk = np.abs(res.P_consistent - Pk).max() / np.abs(Pk).max()
    opt = lib_optimal()
    p_plain, cov_plain = plain_numpy_optimal(za, zb)
    do = np.abs(opt.p_loc - p_plain).max()
    dco = np.abs(opt.P - cov_plain).max() / np.abs(cov_plain).max()
    ok = dx < 1e-6 and dpc < 1e-9 and dpk < 1e-9 and do < 1e-4 and dco < 1e-6  # GN stops at steps < 1e-6 m
    print(
        f"machine: {os.cpu_count()} CPUs, numpy {np.__version__}, generated-code backend: "
        f"{_codegen.backend()}"
    )
    print(f"{n} radar+bearing pairs (paper scenario 1), median (min) of {args.repeats} runs")
    print(
        f"agreement library vs plain NumPy: fused point {dx:.2e} m, claimed cov {dpc:.1e} rel, "
        f"consistent cov {dpk:.1e} rel, ML point {do:.1e} m, ML cov {dco:.1e} rel -> "
        f"{'OK' if ok else 'MISMATCH'}"
    )

    rows = [
        ("paper method: registration.fusion.fuse_paper", lib_paper),
        ("paper method: plain NumPy, hand-written 2-D", lambda: plain_numpy_paper(za, zb)),
        ("optimal (ML): registration.fusion.fuse_optimal", lib_optimal),
        ("optimal (ML): plain NumPy Gauss-Newton", lambda: plain_numpy_optimal(za, zb)),
    ]
    # interleaved (A B C D, D C B A, ...): load from other processes hits all alike
    times, _ = interleave(dict(rows), args.repeats, warmup=0)
    med = {label: median(v) for label, v in times.items()}
    for label, _ in rows:
        print(
            f"  {label:48s} {med[label]:7.3f} s (min {min(times[label]):.3f})  {n / med[label] / 1e6:6.2f} "
            "M pairs/s"
        )
    ratio_paper = paired_ratio(times, rows[0][0], rows[1][0])
    ratio_opt = paired_ratio(times, rows[2][0], rows[3][0])
    print(
        f"time ratio library / plain NumPy (median of per-repeat ratios): paper method {ratio_paper:.2f}, "
        f"optimal fuser {ratio_opt:.2f}"
    )
    figures = {
        "agreement": {
            "point_m": dx,
            "claimed": dpc,
            "consistent": dpk,
            "ml_point_m": do,
            "ml_cov": dco,
            "ok": ok,
        },
        "seconds": summary(times),
        "million_pairs_per_s": {label: n / med[label] / 1e6 for label in med},
        "ratio_library_over_numpy": {"paper": ratio_paper, "optimal": ratio_opt},
    }
    write("fusion", args, {"pairs": n, "repeats": args.repeats}, figures)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
