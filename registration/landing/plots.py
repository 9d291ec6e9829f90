"""PNG plots of a landing Monte Carlo evaluation (the paper's Figs. 1-5, Wang, Liu & Gao 2017):
attitude, variance amplification ratios, RMSE by range and one run's fused polar errors. Colours are
the colour-blind-safe ones of :data:`registration.core.plotting.OKABE_ITO`; the methods also differ
by marker."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from registration.core.plotting import OKABE_ITO, pyplot, save_figure
from registration.landing.montecarlo import MonteCarloResult

__all__ = ["METHOD_LABELS", "METHOD_STYLES", "STYLE", "write_plots"]

#: how each of FUSION_METHODS is named in plots and tables
METHOD_LABELS = {
    "radar": "radar only",
    "camera": "camera angles + radar range",
    "paper": "fused (eq. 12)",
    "information": "fused, joint update",
}

#: matplotlib rc settings of these figures
STYLE = {"font.size": 11, "axes.grid": True, "grid.alpha": 0.3}


#: colour and marker of each of FUSION_METHODS in the RMSE plot
METHOD_STYLES = {
    "radar": (OKABE_ITO["vermillion"], "o"),
    "camera": (OKABE_ITO["blue"], "s"),
    "paper": (OKABE_ITO["black"], "^"),
    "information": (OKABE_ITO["bluish_green"], "v"),
}


def _save(plt, fig, path: Path) -> str:
    return save_figure(fig, path, 110).name


def _plot_attitude(plt, mc: MonteCarloResult, path: Path) -> str:
    """The paper's Fig. 1: the ship's attitude along the approach, deg."""
    fig, ax = plt.subplots(figsize=(9, 4.5), constrained_layout=True)
    for k, (name, color) in enumerate(
        (("yaw", OKABE_ITO["bluish_green"]), ("pitch", OKABE_ITO["blue"]), ("roll", OKABE_ITO["vermillion"]))
    ):
        ax.plot(mc.t, np.degrees(mc.attitude[:, k]), color=color, label=name)
    ax.set_xlabel("time since the start of the approach (s)")
    ax.set_ylabel("angle (deg)")
    ax.set_title("Ship attitude about the mean heading (known without error)")
    top = float(np.degrees(np.abs(mc.attitude).max()))
    ax.set_ylim(-1.15 * top, 1.6 * top)
    ax.legend(loc="upper center", ncol=3)
    return _save(plt, fig, path)


def _plot_variance_ratios(plt, mc: MonteCarloResult, path: Path) -> str:
    """The paper's Figs. 2-3: variance amplification ratios of both sensors against range."""
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8), constrained_layout=True)
    r = mc.ratios["radar"]
    for k, (name, color) in enumerate(
        (
            ("range", OKABE_ITO["reddish_purple"]),
            ("azimuth", OKABE_ITO["blue"]),
            ("elevation", OKABE_ITO["orange"]),
        )
    ):
        axes[0].plot(mc.range_m, r[:, k], color=color, label=name)
    axes[0].set_yscale("log")
    axes[0].set_title("Radar: variance seen from the camera / own variance")
    c = mc.ratios["camera"]
    for k, (name, color) in enumerate((("azimuth", OKABE_ITO["blue"]), ("elevation", OKABE_ITO["orange"]))):
        axes[1].plot(mc.range_m, c[:, k], color=color, label=name)
    axes[1].set_title("Camera: variance in touchdown axes / own variance")
    lo, hi = float(np.min(c)), float(np.max(c))
    pad = max(0.002, 0.2 * (hi - lo))
    axes[1].set_ylim(lo - pad, hi + pad)
    for ax in axes:
        ax.set_xlabel("range to touchdown point (m)")
        ax.set_ylabel("variance ratio")
        ax.invert_xaxis()
        ax.legend()
    return _save(plt, fig, path)


def _plot_rmse(plt, mc: MonteCarloResult, fine: MonteCarloResult, path: Path) -> str:
    """The paper's Fig. 4: RMSE of the methods against range, and eq. 12 relative to camera + radar range."""
    fig, (ax, ax2) = plt.subplots(
        2, 1, figsize=(9, 7.5), sharex=True, constrained_layout=True, gridspec_kw={"height_ratios": [3, 2]}
    )
    centres = 0.5 * (fine.bin_edges_m[:-1] + fine.bin_edges_m[1:])
    base = fine.rmse("camera")
    for m in fine.methods:
        col, mk = METHOD_STYLES[m]
        ax.plot(
            centres,
            fine.rmse(m),
            color=col,
            marker=mk,
            ms=4,
            label=METHOD_LABELS[m],
            lw=1.5 if m != "paper" else 2,
        )
        if m == "paper":
            ax2.plot(
                centres, 100 * (fine.rmse(m) / base - 1), color=col, marker=mk, ms=4, label=METHOD_LABELS[m]
            )
    ax.set_ylabel("3-D position RMSE (m)")
    ax.set_ylim(bottom=0)
    ax.set_title(
        f"Positioning RMSE along the approach ({mc.runs} runs, {fine.bin_edges_m[1] - fine.bin_edges_m[0]:g} "
        "m bins)"
    )
    ax.legend()
    ax2.set_ylabel("fused (eq. 12) RMSE vs\ncamera + radar range (%)")
    ax2.axhline(0, color=METHOD_STYLES["camera"][0], lw=1)
    ax2.set_title(
        "the eq. 12 gain is small: the 3-D error is dominated by the radar range, which both share",
        fontsize=10,
    )
    ax2.set_xlabel("range to touchdown point (m)")
    ax2.invert_xaxis()
    return _save(plt, fig, path)


def _plot_fused_polar(plt, mc: MonteCarloResult, path: Path) -> str:
    """The paper's Fig. 5: one run's fused error in polar coordinates about the camera, with the
    predicted 3-sigma band."""
    ex = mc.example["paper"]
    fig, axes = plt.subplots(3, 1, figsize=(10, 8.5), sharex=True, constrained_layout=True)
    scale = (1.0, 1e3, 1e3)
    units = ("range error (m)", "azimuth error (mrad)", "elevation error (mrad)")
    for k, ax in enumerate(axes):
        if "camera" in mc.example:
            ax.plot(
                mc.range_m,
                mc.example["camera"]["polar_error"][:, k] * scale[k],
                color=OKABE_ITO["blue"],
                lw=0.7,
                alpha=0.45,
                label="camera angles + radar range",
            )
        ax.plot(mc.range_m, ex["polar_error"][:, k] * scale[k], color="black", lw=0.8, label="fused (eq. 12)")
        s3 = 3 * ex["polar_sigma"][:, k] * scale[k]
        ax.fill_between(
            mc.range_m, -s3, s3, color=OKABE_ITO["orange"], alpha=0.25, label="fused ± 3σ (predicted)"
        )
        ax.set_ylabel(units[k])
        ymax = float(np.nanmax(s3) if k == 0 else np.nanpercentile(s3, 99)) * 1.3
        ax.set_ylim(-ymax, ymax)
    fig.legend(*axes[0].get_legend_handles_labels(), loc="outside lower center", ncol=3, fontsize=9)
    axes[-1].set_xlabel("range to touchdown point (m)")
    axes[-1].invert_xaxis()
    axes[0].set_title("Fused estimate in polar coordinates about the camera (touchdown axes), one run")
    return _save(plt, fig, path)


def write_plots(out: Path, mc: MonteCarloResult, fine: MonteCarloResult) -> list[str]:
    """Write attitude.png, variance_ratios.png, rmse.png (from the finely binned ``fine``) and
    fused_polar.png into ``out``; return their file names."""
    plt = pyplot()
    with plt.rc_context(STYLE):
        return [
            _plot_attitude(plt, mc, out / "attitude.png"),
            _plot_variance_ratios(plt, mc, out / "variance_ratios.png"),
            _plot_rmse(plt, mc, fine, out / "rmse.png"),
            _plot_fused_polar(plt, mc, out / "fused_polar.png"),
        ]
