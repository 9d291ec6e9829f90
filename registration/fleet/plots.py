"""PNG figures of a fleet registration (matplotlib, Agg): the batch estimates with their ±2σ bars
or the online estimates over time with their ±2σ bands, a map of the plots before and after
correction, and the histogram of normalised residuals.

Angles are drawn in degrees, ranges and position errors in metres, range gains in ppm, time biases
in seconds; positions as longitude/latitude in degrees. The figures draw ±2σ (two standard
deviations, about a 95 % interval) and say so in their titles and legends; the numbers (console,
files) are σ. Each ``*_figure`` function returns the matplotlib figure; each ``plot_*`` writes it.
Colours are the colour-blind-safe ones of :data:`registration.core.plotting.OKABE_ITO`.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np

from registration.core.frames import ecef2geodetic
from registration.core.plotting import OKABE_ITO, label_style, pyplot, save_figure
from registration.fleet.combinations import SUM_STATUS
from registration.fleet.corrected import corrected_plot_positions
from registration.fleet.data.layout import FILE_UNITS
from registration.fleet.data.problem import FleetProblem
from registration.fleet.result import BatchResult

__all__ = [
    "estimates_figure",
    "history_figure",
    "map_figure",
    "plot_estimates",
    "plot_history",
    "plot_map",
    "plot_residuals",
    "residuals_figure",
]

#: How a row of the estimates figure is drawn: (legend label, bar colour) per kind.
_KINDS = {
    "determined": ("identifiable or fixed, ± 2σ", OKABE_ITO["blue"]),
    "poor": ("weak or not identifiable, ± 2σ", OKABE_ITO["vermillion"]),
    "sum": ("sum the data determine, ± 2σ", OKABE_ITO["bluish_green"]),
}
_UNDETERMINED_LABEL = "undetermined (σ = ∞: no bar)"
_UNDETERMINED_STYLE = {"color": "0.88", "edgecolor": "0.35", "hatch": "///"}


def _kind(row: dict) -> str:
    if not np.isfinite(row["sigma"]):
        return "undetermined"
    if row["status"] == SUM_STATUS:
        return "sum"
    return "determined" if row["status"] in ("identifiable", "fixed") else "poor"


def _draw_rows(ax, rows: list[dict]) -> None:
    """One horizontal bar per row (display units) with its ±2σ error bar; undetermined rows hatched
    grey with an ∞ marker at the estimate and no bar; truth as black crosses."""
    y = np.arange(len(rows))
    k = np.array([FILE_UNITS[r["unit"]][3] for r in rows])
    est = np.array([r["estimate"] for r in rows]) * k
    for kind in ("determined", "poor", "sum", "undetermined"):
        on = np.array([_kind(r) == kind for r in rows])
        if not on.any():
            continue
        if kind == "undetermined":
            ax.barh(y[on], est[on], **_UNDETERMINED_STYLE)
            ax.plot(est[on], y[on], ls="none", marker="$\\infty$", ms=12, color="0.2")
            continue
        sig = np.array([r["sigma"] for r in rows])[on] * k[on]
        ax.barh(y[on], est[on], xerr=2 * sig, color=_KINDS[kind][1], alpha=0.7, capsize=3)
    if "truth" in rows[0]:
        ax.plot(np.array([r["truth"] for r in rows]) * k, y, "kx")
    ax.set_yticks(y)
    ax.set_yticklabels([r["name"] for r in rows], fontsize=8)
    ax.set_ylim(len(rows) - 0.5, -0.5)
    ax.axvline(0, color="k", lw=0.5)
    ax.grid(alpha=0.3, axis="x")


def _legend_handles(rows: list[dict]) -> list:
    from matplotlib.artist import Artist
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    kinds = {_kind(r) for r in rows}
    handles: list[Artist] = [
        Patch(color=c, alpha=0.7, label=label) for kind, (label, c) in _KINDS.items() if kind in kinds
    ]
    if "undetermined" in kinds:
        handles.append(
            Patch(
                facecolor=_UNDETERMINED_STYLE["color"],
                edgecolor=_UNDETERMINED_STYLE["edgecolor"],
                hatch=_UNDETERMINED_STYLE["hatch"],
                label=_UNDETERMINED_LABEL,
            )
        )
    if "truth" in rows[0]:
        handles.append(Line2D([], [], color="k", marker="x", ls="none", label="truth"))
    return handles


def estimates_figure(result: BatchResult, truth: dict | None = None):
    """Each state's final estimate with its ±2σ (Cramér-Rao) bar, then each sum the observability
    report names (``result.rows``), one panel per unit (angles in deg, range biases and positions in
    m, range gains in ppm, time biases in s). A state the data leave undetermined (σ = ∞) is drawn
    as a hatched grey bar with an ∞ marker and no error bar. ``truth`` {state name: value (rad, m,
    1, s)} drawn as crosses."""
    plt = pyplot()
    rows = result.rows(truth)
    unit = np.array([FILE_UNITS[r["unit"]][2] for r in rows])
    panels = [u for u in ("deg", "m", "ppm", "s") if (unit == u).any()]
    counts = [int((unit == u).sum()) for u in panels]
    fig, axes = plt.subplots(
        1,
        len(panels),
        figsize=(6 * len(panels) + 2, max(4.5, 0.3 * max(counts) + 2.5)),
        gridspec_kw={"width_ratios": counts},
        squeeze=False,
        layout="constrained",
    )
    for ax, u in zip(axes[0], panels):
        _draw_rows(ax, [r for r, on in zip(rows, unit == u) if on])
        ax.set_xlabel(u)
    handles = _legend_handles(rows)
    fig.legend(handles=handles, loc="outside lower center", ncol=min(len(handles), 3), fontsize=8)
    fig.suptitle("Batch estimates with ± 2σ bars")
    return fig


def plot_estimates(result: BatchResult, path, truth: dict | None = None) -> Path:
    """:func:`estimates_figure` as the PNG ``path``."""
    return save_figure(estimates_figure(result, truth), path)


def history_figure(result, truth: dict | None = None):
    """The online filter's estimate of every free state over time (deg, m, ppm or s) with its ±2σ
    band, one panel per state, four columns, each column with its time axis; ``truth`` {state name:
    value (rad, m, 1, s)} drawn as a dashed line."""
    plt = pyplot()
    layout, h = result.layout, result.history
    free = layout.free
    cols = 4
    rows = max(1, -(-free.size // cols))
    fig, axes = plt.subplots(
        rows, cols, figsize=(4 * cols, 2.4 * rows + 0.6), sharex=True, squeeze=False, layout="constrained"
    )
    for ax, i in zip(axes.flat, free):
        _, _, unit, k = FILE_UNITS[layout.units[i]]
        est, sig = h.estimate[:, i] * k, h.sigma[:, i] * k
        ax.fill_between(h.time, est - 2 * sig, est + 2 * sig, color=OKABE_ITO["blue"], alpha=0.25, lw=0)
        ax.plot(h.time, est, color=OKABE_ITO["blue"], lw=1)
        if truth is not None:
            ax.axhline(truth[layout.names[i]] * k, color="k", ls="--", lw=0.8)
        ax.set_title(f"{layout.names[i]} ({unit})", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(alpha=0.3)
    for ax in list(axes.flat)[free.size :]:
        ax.set_visible(False)
    for c in range(cols):
        shown = [ax for ax in axes[:, c] if ax.get_visible()]
        if shown:  # the lowest panel of each column carries the time axis, also when the last row is short
            shown[-1].xaxis.set_tick_params(labelbottom=True)
            shown[-1].set_xlabel("time (s)", fontsize=8)
    fig.get_layout_engine().set(h_pad=0.06)
    fig.suptitle("Online estimates with ± 2σ bands" + (" (dashed: truth)" if truth is not None else ""))
    return fig


def plot_history(result, path, truth: dict | None = None) -> Path:
    """:func:`history_figure` as the PNG ``path``."""
    return save_figure(history_figure(result, truth), path, 90)


def map_figure(problem: FleetProblem, result: BatchResult):
    """The plots with a range, as measured (left) and corrected by ``result.estimate`` (right), in
    longitude/latitude (deg), each target with its own colour and marker
    (:func:`registration.core.plotting.label_style`)."""
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(14, 6), sharex=True, sharey=True, layout="constrained")
    for ax, x, title in (
        (axes[0], np.zeros(problem.layout.n), "as measured"),
        (axes[1], result.estimate, "corrected by the estimates"),
    ):
        p, sel = corrected_plot_positions(problem, x)
        lat, lon, _ = ecef2geodetic(p)
        target = problem.target[sel]
        for k, tid in enumerate(problem.target_ids):
            on = target == k
            colour, marker = label_style(k)
            ax.plot(
                np.degrees(lon[on]),
                np.degrees(lat[on]),
                ls="none",
                marker=marker,
                ms=2,
                mew=0,
                color=colour,
                label=str(tid),
            )
        ax.set_title(f"plots {title}")
        ax.set_xlabel("longitude (deg E)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("latitude (deg N)")
    n = len(problem.target_ids)
    axes[1].legend(
        title="target",
        markerscale=4,
        fontsize=8,
        ncol=max(1, -(-n // 20)),
        loc="center left",
        bbox_to_anchor=(1.02, 0.5),
    )
    return fig


def plot_map(problem: FleetProblem, result: BatchResult, path) -> Path:
    """:func:`map_figure` as the PNG ``path``."""
    return save_figure(map_figure(problem, result), path)


def residuals_figure(result: BatchResult, title: str | None = None):
    """Histogram of the normalised residuals per channel (``result.residuals``), with the standard
    normal density; ``title`` (wrapped to fit) defaults to the batch chi-square check."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 5), layout="constrained")
    grid = np.linspace(-5, 5, 201)
    for k, channel in enumerate(("range", "bearing", "elevation")):
        r = result.residuals[:, k]
        r = r[np.isfinite(r)]
        if r.size:
            ax.hist(
                np.clip(r, -6, 6),
                bins=60,
                range=(-6, 6),
                density=True,
                histtype="step",
                lw=1.2,
                color=label_style(k)[0],
                label=f"{channel} ({r.size})",
            )
    ax.plot(grid, np.exp(-(grid**2) / 2) / np.sqrt(2 * np.pi), "k--", lw=1, label="N(0, 1)")
    ax.set_xlabel("normalised residual (measured - predicted) / σ, clipped to ±6")
    ax.set_ylabel("density")
    text = title if title is not None else result.chi_square.text()
    ax.set_title(textwrap.fill(text, 90), fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return fig


def plot_residuals(result: BatchResult, path, title: str | None = None) -> Path:
    """:func:`residuals_figure` as the PNG ``path``."""
    return save_figure(residuals_figure(result, title), path)
