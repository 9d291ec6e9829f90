"""The figure of a per-period registration (matplotlib, Agg): each state's estimate per period with its
±σ bar (one standard deviation), one panel per state group (heading errors, range biases, bearing
biases, ...), one colour and marker per sensor or platform; a boundary where a change was declared
dashed in the panel of the state that changed. Angles in degrees, ranges and positions in
metres, range gains in ppm, time biases in seconds."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from registration.core.plotting import label_style, pyplot, save_figure
from registration.fleet.data.layout import FILE_UNITS
from registration.fleet.periods.solve import BiasPeriods

__all__ = ["bias_periods_figure", "plot_bias_periods"]


def _groups(bias_periods: BiasPeriods) -> dict[str, list[int]]:
    """State group (quantity) -> the free states of it, in layout order."""
    layout = bias_periods.periods[0].result.layout
    groups: dict[str, list[int]] = {}
    for i in layout.free:
        groups.setdefault(layout.quantities[i], []).append(int(i))
    return groups


def bias_periods_figure(bias_periods: BiasPeriods, truth: dict | None = None):
    """The module docstring's figure; ``truth`` {state name: value (rad, m, 1, s)}, constant over the
    run, drawn as a dotted line per state."""
    plt = pyplot()
    periods = bias_periods.periods
    layout = periods[0].result.layout
    groups = _groups(bias_periods)
    cols = min(3, max(1, len(groups)))
    rows = -(-len(groups) // cols)
    fig, axes = plt.subplots(
        rows, cols, figsize=(5 * cols, 2.8 * rows + 0.8), squeeze=False, layout="constrained"
    )
    mid = np.array([(p.start_s + p.end_s) / 2 for p in periods])
    half = np.array([(p.end_s - p.start_s) / 2 for p in periods])
    changes = bias_periods.changes
    found = changes.found
    for ax, (group, states) in zip(axes.flat, groups.items()):
        _, _, unit, k = FILE_UNITS[layout.units[states[0]]]
        offsets = (np.arange(len(states)) - (len(states) - 1) / 2) * 0.6 * half.min() / max(len(states), 1)
        for j, (i, dx) in enumerate(zip(states, offsets)):
            est = np.array([p.result.estimate[i] for p in periods]) * k
            sig = np.array([p.result.sigma[i] for p in periods]) * k
            shown = np.isfinite(sig)
            colour, marker = label_style(j)
            ax.errorbar(
                (mid + dx)[shown],
                est[shown],
                yerr=sig[shown],
                color=colour,
                marker=marker,
                ms=4,
                ls="none",
                capsize=2,
                label=layout.objects[i],
            )
            if truth is not None and layout.names[i] in truth:
                ax.axhline(truth[layout.names[i]] * k, color=colour, ls=":", lw=0.8)
        for p in periods[1:]:
            ax.axvline(p.start_s, color="0.8", lw=0.6)
        for t in np.unique(changes.time_s[found[np.isin(changes.state[found], states)]]):
            ax.axvline(t, color="k", ls="--", lw=0.8)  # a change of a state of this panel
        ax.set_xlim(periods[0].start_s, periods[-1].end_s)
        ax.set_title(f"{group} ({unit})", fontsize=9)
        ax.set_xlabel("time (s)", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="best")
    for ax in list(axes.flat)[len(groups) :]:
        ax.set_visible(False)
    fig.suptitle(
        f"Estimates per period of {bias_periods.period_s:g} s with ± 1σ bars"
        + (" (dashed: a change found)" if found.size else "")
    )
    return fig


def plot_bias_periods(bias_periods: BiasPeriods, path, truth: dict | None = None) -> Path:
    """:func:`bias_periods_figure` as the PNG ``path``."""
    return save_figure(bias_periods_figure(bias_periods, truth), path, 90)
