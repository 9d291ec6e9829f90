"""PNG figures of a fleet registration (matplotlib, Agg): the batch estimates with their 2-sigma
bars or the online estimates over time with their 2-sigma bands, a map of the plots before and
after correction, and the histogram of normalised residuals.

Angles are drawn in degrees, ranges and position errors in metres, range gains in ppm, time biases
in seconds; positions as longitude/latitude in degrees.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from registration.core.plotting import pyplot
from registration.core.frames import ecef2geodetic
from registration.fleet.corrected import corrected_positions
from registration.fleet.layout import FILE_UNITS
from registration.fleet.problem import FleetProblem
from registration.fleet.result import BatchResult

__all__ = ["corrected_plot_positions", "plot_estimates", "plot_history", "plot_map", "plot_residuals"]


def corrected_plot_positions(problem: FleetProblem, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """ECEF positions (M, 3) m of the plots that have a range, corrected by the states ``x`` (n,)
    (rad, m, 1, s; zeros: as measured), and their indices into the problem's plots (M,). A plot
    without elevation (2-D radar) is placed in its deck plane (elevation 0 after correction); with
    a time bias the platform is taken where it was when the plot was seen."""
    layout = problem.layout
    sel = np.flatnonzero(problem.mask[:, 0])
    xs = np.append(np.asarray(x, dtype=np.float64), 0.0)  # the sink (absent state) reads 0
    state = layout.sensor_states(problem.sensor[sel], problem.sensor_platform)
    meas = problem.meas[sel].copy()
    meas[:, 2] = np.where(problem.mask[sel, 2], meas[:, 2], xs[state[:, 5]])
    nav = problem.nav[sel]
    if layout.extended and (layout.time_bias_index >= 0).any():
        nav = problem.navigation_at(problem.time[sel] - xs[state[:, 7]], sel)[0]
    p = corrected_positions(nav, state, xs, problem.sensor_lever[problem.sensor[sel]], meas)
    return p, sel


def _display(layout, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``values`` (..., n) in display units (deg, m, ppm, s) and the display unit of each state."""
    k = np.array([FILE_UNITS[u][3] for u in layout.units])
    return values * k, np.array([FILE_UNITS[u][2] for u in layout.units])


def plot_estimates(result: BatchResult, path, truth: dict | None = None) -> Path:
    """Each state's final estimate with its 2-sigma (Cramér-Rao) bar, one panel per unit (angles
    in deg, range biases and positions in m, range gains in ppm, time biases in s); ``truth``
    {state name: value (rad, m, 1, s)} drawn as crosses."""
    plt = pyplot()
    est, unit = _display(result.layout, result.estimate)
    sig, _ = _display(result.layout, result.sigma)
    names = np.array(result.layout.names)
    true = None if truth is None else _display(result.layout, np.array([truth[n] for n in names]))[0]
    panels = [u for u in ("deg", "m", "ppm", "s") if (unit == u).any()]
    counts = [int((unit == u).sum()) for u in panels]
    fig, axes = plt.subplots(1, len(panels), figsize=(6 * len(panels), max(4.0, 0.32 * max(counts) + 1.5)),
                             gridspec_kw={"width_ratios": counts}, squeeze=False)
    for ax, u in zip(axes[0], panels):
        idx = np.flatnonzero(unit == u)
        y = np.arange(idx.size)
        bar = np.where(np.isfinite(sig[idx]), 2 * sig[idx], 0.0)
        colours = ["tab:blue" if result.status[n] in ("identifiable", "fixed") else "tab:red" for n in names[idx]]
        ax.barh(y, est[idx], xerr=bar, color=colours, alpha=0.6, capsize=3, label="estimate ± 2σ")
        if true is not None:
            ax.plot(true[idx], y, "kx", label="truth")
        ax.set_yticks(y)
        ax.set_yticklabels(names[idx], fontsize=8)
        ax.invert_yaxis()
        ax.axvline(0, color="k", lw=0.5)
        ax.set_xlabel(u)
        ax.grid(alpha=0.3, axis="x")
    axes[0][0].legend(fontsize=8)
    fig.suptitle("Batch estimates with 2σ bars (red: weak or not identifiable)")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return Path(path)


def plot_history(result, path, truth: dict | None = None) -> Path:
    """The online filter's estimate of every free state over time (deg, m, ppm or s) with its 2-sigma band,
    one panel per state; ``truth`` {state name: value (rad, m)} drawn as a dashed line."""
    plt = pyplot()
    layout, h = result.layout, result.history
    free = layout.free
    cols = 4
    rows = max(1, -(-free.size // cols))
    fig, axes = plt.subplots(rows, cols, figsize=(4 * cols, 2.4 * rows), sharex=True, squeeze=False)
    for ax, i in zip(axes.flat, free):
        _, _, unit, k = FILE_UNITS[layout.units[i]]
        est, sig = h.estimate[:, i] * k, h.sigma[:, i] * k
        ax.fill_between(h.time, est - 2 * sig, est + 2 * sig, color="tab:blue", alpha=0.25, lw=0)
        ax.plot(h.time, est, color="tab:blue", lw=1)
        if truth is not None:
            ax.axhline(truth[layout.names[i]] * k, color="k", ls="--", lw=0.8)
        ax.set_title(f"{layout.names[i]} ({unit})", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(alpha=0.3)
    for ax in list(axes.flat)[free.size:]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel("time (s)", fontsize=8)
    fig.suptitle("Online estimates with 2σ bands" + (" (dashed: truth)" if truth is not None else ""))
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return Path(path)


def plot_map(problem: FleetProblem, result: BatchResult, path) -> Path:
    """The plots with a range, as measured (left) and corrected by the estimates (right), in
    longitude/latitude (deg), one colour per target."""
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(13, 6), sharex=True, sharey=True)
    for ax, x, title in ((axes[0], np.zeros(problem.layout.n), "as measured"),
                         (axes[1], result.estimate, "corrected by the estimates")):
        p, sel = corrected_plot_positions(problem, x)
        lat, lon, _ = ecef2geodetic(p)
        target = problem.target[sel]
        for k, tid in enumerate(problem.target_ids):
            on = target == k
            ax.plot(np.degrees(lon[on]), np.degrees(lat[on]), ".", ms=1.5, label=tid)
        ax.set_title(f"plots {title}")
        ax.set_xlabel("longitude (deg E)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("latitude (deg N)")
    axes[1].legend(markerscale=6, fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return Path(path)


def plot_residuals(result: BatchResult, path, title: str | None = None) -> Path:
    """Histogram of the normalised residuals per channel (``result.residuals``), with the standard
    normal density; ``title`` defaults to the batch chi-square check."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    grid = np.linspace(-5, 5, 201)
    for k, channel in enumerate(("range", "bearing", "elevation")):
        r = result.residuals[:, k]
        r = r[np.isfinite(r)]
        if r.size:
            ax.hist(np.clip(r, -6, 6), bins=60, range=(-6, 6), density=True, histtype="step", lw=1.2,
                    label=f"{channel} ({r.size})")
    ax.plot(grid, np.exp(-grid**2 / 2) / np.sqrt(2 * np.pi), "k--", lw=1, label="N(0, 1)")
    ax.set_xlabel("normalised residual (measured - predicted) / σ, clipped to ±6")
    ax.set_ylabel("density")
    ax.set_title(title if title is not None else result.chi_square.text(), fontsize=8)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return Path(path)
