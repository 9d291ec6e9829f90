"""PNG figures of a fleet registration (matplotlib, Agg): the batch estimates with their 2-sigma
bars or the online estimates over time with their 2-sigma bands, a map of the plots before and
after correction, and the histogram of normalised residuals.

Angles are drawn in degrees and ranges in metres; positions as longitude/latitude in degrees.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from registration import _codegen
from registration.core.plotting import pyplot
from registration.core.frames import ecef2geodetic
from registration.fleet.problem import FleetProblem
from registration.fleet.result import BatchResult

__all__ = ["corrected_plot_positions", "plot_estimates", "plot_history", "plot_map", "plot_residuals"]


def corrected_plot_positions(problem: FleetProblem, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """ECEF positions (M, 3) m of the plots that have a range, corrected by the states ``x`` (n,)
    (rad, m; zeros: as measured), and their indices into the problem's plots (M,). A plot without
    elevation (2-D radar) is placed in its deck plane (elevation 0 after correction)."""
    layout = problem.layout
    sel = np.flatnonzero(problem.mask[:, 0])
    xs = np.append(np.asarray(x, dtype=np.float64), 0.0)  # index -1 (absent channel) reads 0
    att = xs[layout.att_index[problem.platform[sel]]]
    bias = xs[layout.bias_index[problem.sensor[sel]]]
    meas = problem.meas[sel]
    e = np.where(problem.mask[sel, 2], meas[:, 2], bias[:, 2])
    nav = problem.nav[sel]
    p = _codegen.get("fleet_plot2ecef")(*nav.T, att, bias, problem.sensor_lever[problem.sensor[sel]],
                                        meas[:, 0], meas[:, 1], e)[0]
    return np.asarray(p).reshape(-1, 3), sel


def _display(result: BatchResult) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Estimates and sigmas in degrees or metres, and which states are angles."""
    angle = np.array([u == "rad" for u in result.layout.units])
    k = np.where(angle, np.degrees(1.0), 1.0)
    return result.estimate * k, result.sigma * k, angle


def plot_estimates(result: BatchResult, path, truth: dict | None = None) -> Path:
    """Each state's final estimate with its 2-sigma (Cramér-Rao) bar; angles (deg) on the left
    panel, range biases (m) on the right; ``truth`` {state name: value (rad, m)} drawn as crosses."""
    plt = pyplot()
    est, sig, angle = _display(result)
    names = np.array(result.layout.names)
    fig, axes = plt.subplots(1, 2, figsize=(12, max(4.0, 0.32 * angle.sum() + 1.5)),
                             gridspec_kw={"width_ratios": [max(int(angle.sum()), 1), max(int((~angle).sum()), 1)]})
    for ax, sel, unit in ((axes[0], angle, "deg"), (axes[1], ~angle, "m")):
        idx = np.flatnonzero(sel)
        y = np.arange(idx.size)
        bar = np.where(np.isfinite(sig[idx]), 2 * sig[idx], 0.0)
        colours = ["tab:blue" if result.status[n] in ("identifiable", "fixed") else "tab:red" for n in names[idx]]
        ax.barh(y, est[idx], xerr=bar, color=colours, alpha=0.6, capsize=3, label="estimate ± 2σ")
        if truth is not None:
            k = np.degrees(1.0) if unit == "deg" else 1.0
            ax.plot([truth[n] * k for n in names[idx]], y, "kx", label="truth")
        ax.set_yticks(y)
        ax.set_yticklabels(names[idx], fontsize=8)
        ax.invert_yaxis()
        ax.axvline(0, color="k", lw=0.5)
        ax.set_xlabel(unit)
        ax.grid(alpha=0.3, axis="x")
    axes[0].legend(fontsize=8)
    fig.suptitle("Batch estimates with 2σ bars (red: weak or not identifiable)")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return Path(path)


def plot_history(result, path, truth: dict | None = None) -> Path:
    """The online filter's estimate of every free state over time (deg or m) with its 2-sigma band,
    one panel per state; ``truth`` {state name: value (rad, m)} drawn as a dashed line."""
    plt = pyplot()
    layout, h = result.layout, result.history
    free = layout.free
    cols = 4
    rows = max(1, -(-free.size // cols))
    fig, axes = plt.subplots(rows, cols, figsize=(4 * cols, 2.4 * rows), sharex=True, squeeze=False)
    for ax, i in zip(axes.flat, free):
        k = np.degrees(1.0) if layout.units[i] == "rad" else 1.0
        est, sig = h.estimate[:, i] * k, h.sigma[:, i] * k
        ax.fill_between(h.time, est - 2 * sig, est + 2 * sig, color="tab:blue", alpha=0.25, lw=0)
        ax.plot(h.time, est, color="tab:blue", lw=1)
        if truth is not None:
            ax.axhline(truth[layout.names[i]] * k, color="k", ls="--", lw=0.8)
        ax.set_title(f"{layout.names[i]} ({'deg' if k != 1.0 else 'm'})", fontsize=8)
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
