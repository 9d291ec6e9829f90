"""The PNG figures of ``registration fuse`` (matplotlib, Agg): ``measurements.png``, like the
paper's Fig. 3/5 (geometry, radar points and pseudo-measurement points), and ``fused.png``, like
Fig. 4/6 (fused points of the paper's method and of the optimal fuser), all with 2σ covariance
ellipses (Mahalanobis distance 2).

Positions of the geometry in km, errors in m (x-y plane; for 3-D scenarios the x-y projection).
Each ``*_figure`` function returns the matplotlib figure; :func:`write_plots` writes both.
Colours are the colour-blind-safe ones of :data:`registration.core.plotting.OKABE_ITO`; curves
that are compared differ in line style too.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from registration.core.plotting import OKABE_ITO, pyplot, save_figure
from registration.fusion.evaluation import FusionEvaluation

__all__ = ["ellipse_points", "fused_figure", "measurements_figure", "write_plots"]

#: (covariance key, line style, colour, legend label) of the ellipses of fused.png.
FUSED_ELLIPSES = (
    ("paper_claimed", "--", OKABE_ITO["vermillion"], "2σ: paper's claimed covariance (eq. 13)"),
    ("paper_actual", "-", OKABE_ITO["black"], "2σ: paper method's consistent covariance"),
    ("crlb", ":", OKABE_ITO["blue"], "2σ: Cramér-Rao bound"),
    ("radar", "-", "0.6", "2σ: radar alone"),
)
#: Colour of the optimal fuser's points in fused.png (the paper method's are black).
OPTIMAL_COLOUR = OKABE_ITO["sky_blue"]


def ellipse_points(mean: np.ndarray, cov: np.ndarray, k: float = 2.0, n: int = 200) -> np.ndarray:
    """Points (n, 2) of the k-sigma ellipse {x : (x - mean)^T cov^-1 (x - mean) = k^2} (x-y block)."""
    c = cov[:2, :2]
    vals, vecs = np.linalg.eigh(c)
    t = np.linspace(0.0, 2.0 * np.pi, n)
    circle = np.stack([np.cos(t), np.sin(t)])
    return (mean[:2, None] + k * vecs @ (np.sqrt(np.maximum(vals, 0.0))[:, None] * circle)).T


def _projection_note(ev: FusionEvaluation) -> str:
    return " (x-y projection; GDOPs over x, y, z)" if ev.scenario.dim == 3 else ""


def _draw_geometry(ax, ev: FusionEvaluation) -> None:
    """Sites A and B, the target and the lines of sight, in km (x-y plane)."""
    sc, p_true, km = ev.scenario, ev.p_true_loc, 1e-3
    a, b = np.asarray(sc.site_radar_loc, float), np.asarray(sc.site_second_loc, float)
    ax.plot([a[0] * km, p_true[0] * km], [a[1] * km, p_true[1] * km], "k-", lw=1)
    ax.plot([b[0] * km, p_true[0] * km], [b[1] * km, p_true[1] * km], "k--", lw=1)
    ax.plot([a[0] * km, b[0] * km], [a[1] * km, b[1] * km], color="0.6", lw=1)
    ax.plot(a[0] * km, a[1] * km, "ks", ms=8)
    ax.plot(b[0] * km, b[1] * km, "k^", ms=8)
    ax.plot(p_true[0] * km, p_true[1] * km, "*", color=OKABE_ITO["vermillion"], ms=12)
    ax.annotate("A radar", (a[0] * km, a[1] * km), textcoords="offset points", xytext=(6, -14))
    ax.annotate(
        "B " + "+".join(sc.components), (b[0] * km, b[1] * km), textcoords="offset points", xytext=(6, -14)
    )
    ax.annotate(
        "target C", (p_true[0] * km, p_true[1] * km), textcoords="offset points", xytext=(0, 10), ha="center"
    )
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x (km), from A towards B" if not np.any(b[1:] - a[1:]) else "x (km)")
    ax.margins(0.15)  # room for the labels below the sites and beside the target
    ax.set_ylabel("y (km)")
    ax.set_title(f"(a) geometry{_projection_note(ev)}")
    ax.grid(alpha=0.3)


def _draw_measurement_points(ax, ev: FusionEvaluation, m: int) -> None:
    """The first ``m`` radar and pseudo-measurement points (errors in m) with 2σ ellipses; the
    legend below the axes, clear of the points."""
    p_true, zero = ev.p_true_loc, np.zeros(ev.scenario.dim)
    radar, pseudo = ev.points["radar"][:m], ev.points["pseudo_measurement"][:m]
    ax.plot(
        (radar[:, 0] - p_true[0]),
        (radar[:, 1] - p_true[1]),
        "k+",
        ms=4,
        alpha=0.6,
        label=f"radar points C (GDOP {ev.row('radar')['monte_carlo_gdop_m']:.0f} m)",
    )
    ax.plot(
        (pseudo[:, 0] - p_true[0]),
        (pseudo[:, 1] - p_true[1]),
        "x",
        color="0.55",
        ms=4,
        alpha=0.6,
        label=f"pseudo-measurements H (GDOP {ev.row('pseudo_measurement')['monte_carlo_gdop_m']:.0f} m)",
    )
    for key, style, colour, label in (
        ("radar", "-", OKABE_ITO["black"], "2σ ellipse of P (radar)"),
        ("pseudo_measurement", "-", OKABE_ITO["orange"], "2σ ellipse of R (paper's H covariance)"),
        ("pseudo_measurement_consistent", "--", OKABE_ITO["blue"], "2σ ellipse of H's actual covariance"),
    ):
        e = ellipse_points(zero, ev.analytic_cov[key])
        ax.plot(e[:, 0], e[:, 1], style, color=colour, lw=1.5, label=label)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x error (m)")
    ax.set_ylabel("y error (m)")
    ax.set_title(f"(b) {m} radar and pseudo-measurement points{_projection_note(ev)}")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=2, framealpha=0.9)


def measurements_figure(ev: FusionEvaluation, m: int):
    """measurements.png: geometry (left) and the first ``m`` radar and pseudo-measurement points (right)."""
    plt = pyplot()
    fig, (ax0, ax1) = plt.subplots(
        1, 2, figsize=(13, 6.4), gridspec_kw={"width_ratios": [1, 1.25]}, layout="constrained"
    )
    _draw_geometry(ax0, ev)
    _draw_measurement_points(ax1, ev, m)
    fig.suptitle(ev.scenario.name)
    return fig


def fused_figure(ev: FusionEvaluation, m: int):
    """fused.png: the first ``m`` fused points of both fusers (errors in m) with 2σ ellipses."""
    plt = pyplot()
    p_true, zero = ev.p_true_loc, np.zeros(ev.scenario.dim)
    paper, optimal = ev.points["paper"][:m], ev.points["optimal"][:m]
    fig, ax = plt.subplots(figsize=(11.5, 7), layout="constrained")
    ax.plot(
        paper[:, 0] - p_true[0],
        paper[:, 1] - p_true[1],
        ".",
        color="k",
        ms=3,
        alpha=0.55,
        label=f"paper method X (GDOP {ev.row('paper_actual')['monte_carlo_gdop_m']:.0f} m)",
    )
    ax.plot(
        optimal[:, 0] - p_true[0],
        optimal[:, 1] - p_true[1],
        ".",
        color=OPTIMAL_COLOUR,
        ms=2,
        alpha=0.6,
        label=f"optimal fuser (GDOP {ev.row('optimal')['monte_carlo_gdop_m']:.0f} m)",
    )
    for key, style, colour, label in FUSED_ELLIPSES:
        e = ellipse_points(zero, ev.analytic_cov[key])
        ax.plot(e[:, 0], e[:, 1], style, color=colour, lw=1.8, label=label)
    lim = 3.2 * np.sqrt(np.max(np.linalg.eigvalsh(ev.analytic_cov["paper_actual"][:2, :2])))
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_aspect("equal")
    ax.set_xlabel("x error (m)")
    ax.set_ylabel("y error (m)")
    ax.set_title(f"{ev.scenario.name}\n{m} fused points{_projection_note(ev)} (radar ellipse clipped)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=9, loc="center left", bbox_to_anchor=(1.02, 0.5), markerscale=3)
    return fig


def write_plots(ev: FusionEvaluation, out: Path, max_points: int) -> list[Path]:
    """Write measurements.png and fused.png into ``out``, at most ``max_points`` points per set."""
    m = min(max_points, ev.trials)
    return [
        save_figure(measurements_figure(ev, m), out / "measurements.png", 110),
        save_figure(fused_figure(ev, m), out / "fused.png", 110),
    ]
