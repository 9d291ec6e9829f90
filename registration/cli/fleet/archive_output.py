"""What ``registration fleet register --partition-s`` writes besides its estimates
(docs/howto/register-an-archive.md,
"Outputs of an archive run"): ``residuals.csv`` and the residual part of ``summary.json`` from the
residual sums of :func:`registration.fleet.batch.outputs.archive_outputs`, and the PNG figures:
``residuals.png`` (the histogram of every whitened residual per channel, from exact counts),
``residuals_time.png`` (the sampled plots' residuals over time, one panel per sensor) and
``map.png`` (the sampled plots as measured and as corrected)."""

from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np

from registration.cli.errors import writing

__all__ = ["PNG_OUTPUTS", "residual_lines", "residual_summary", "write_figures"]

#: The figures of an archive run.
PNG_OUTPUTS = ("residuals.png", "residuals_time.png", "map.png")


def _number(v) -> str:
    return repr(float(v)) if np.isfinite(v) else ""


def residual_lines(outputs) -> list[str]:
    """residuals.csv: per sensor and channel with values, the count, mean, RMS and sum of squares of
    the whitened residuals (measured - predicted) / sigma (dimensionless)."""
    from registration.fleet.batch.outputs import CHANNELS

    lines = ["sensor,channel,count,mean,rms,sum_of_squares"]
    for i, sensor in enumerate(outputs.sensor_ids):
        for c, channel in enumerate(CHANNELS):
            if outputs.count[i, c]:
                lines.append(
                    f"{sensor},{channel},{int(outputs.count[i, c])},{_number(outputs.mean[i, c])},"
                    f"{_number(outputs.rms[i, c])},{_number(outputs.squares[i, c])}"
                )
    return lines


def _mean_squares(table: dict) -> dict:
    return {str(k): {"mean_square": ss / n if n else None, "values": int(n)} for k, (ss, n) in table.items()}


def residual_summary(outputs) -> dict:
    """The residual part of summary.json, named as the in-memory run names it."""
    from registration.fleet.batch.outputs import CHANNELS

    by_sensor = {}
    for i, sensor in enumerate(outputs.sensor_ids):
        n = int(outputs.count[i].sum())
        if n:
            by_sensor[str(sensor)] = {"mean_square": float(outputs.squares[i].sum() / n), "values": n}
    ref_ss, ref_n = outputs.parts["references"]
    return {
        "residuals_by_sensor": by_sensor,
        "residuals_by_channel": {
            ch: {
                "values": int(outputs.count[:, c].sum()),
                "mean_square": (
                    float(outputs.squares[:, c].sum() / outputs.count[:, c].sum())
                    if outputs.count[:, c].sum()
                    else None
                ),
            }
            for c, ch in enumerate(CHANNELS)
        },
        "residuals_by_target": _mean_squares(outputs.by_target),
        "residuals_of_references": {
            "positions_used": int(ref_n // 3),
            "values": int(ref_n),
            "mean_square": ref_ss / ref_n if ref_n else None,
            "by_target": _mean_squares(outputs.by_reference),
        },
    }


def _histogram_figure(outputs, title: str):
    from registration.core.plotting import label_style, pyplot
    from registration.fleet.batch.outputs import CHANNELS, HIST_BINS, HIST_LIMIT

    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 5), layout="constrained")
    edges = np.linspace(-HIST_LIMIT, HIST_LIMIT, HIST_BINS + 1)
    for c, channel in enumerate(CHANNELS):
        n = int(outputs.hist[c].sum())
        if n:
            ax.stairs(
                outputs.hist[c] / (n * np.diff(edges)),
                edges,
                lw=1.2,
                color=label_style(c)[0],
                label=f"{channel} ({n})",
            )
    grid = np.linspace(-5, 5, 201)
    ax.plot(grid, np.exp(-(grid**2) / 2) / np.sqrt(2 * np.pi), "k--", lw=1, label="N(0, 1)")
    ax.set_xlabel(f"normalised residual (measured - predicted) / σ, clipped to ±{HIST_LIMIT:g}")
    ax.set_ylabel("density")
    ax.set_title(textwrap.fill(title, 90), fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return fig


def _time_figure(outputs):
    from registration.core.plotting import label_style, pyplot
    from registration.fleet.batch.outputs import CHANNELS

    plt = pyplot()
    s = outputs.sample
    sensors = [i for i in range(len(outputs.sensor_ids)) if np.any(s["sensor"] == i)]
    fig, axes = plt.subplots(
        max(1, len(sensors)),
        1,
        figsize=(10, 1.8 * max(1, len(sensors)) + 1),
        sharex=True,
        squeeze=False,
        layout="constrained",
    )
    for ax, i in zip(axes[:, 0], sensors):
        on = s["sensor"] == i
        for c, channel in enumerate(CHANNELS):
            r = s["residual"][on, c]
            if np.isfinite(r).any():
                ax.plot(
                    s["time"][on],
                    np.clip(r, -6, 6),
                    ls="none",
                    marker=".",
                    ms=2,
                    color=label_style(c)[0],
                    label=channel,
                )
        ax.set_ylabel(f"{outputs.sensor_ids[i]}", fontsize=8)
        ax.set_ylim(-6.3, 6.3)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper right", markerscale=4)
    axes[-1, 0].set_xlabel("time (s, reported)")
    fig.suptitle(
        f"Normalised residuals (measured - predicted) / σ, clipped to ±6: {s['time'].size} plots "
        f"(1 in {outputs.sample_every} of each partition)",
        fontsize=9,
    )
    return fig


def _map_figure(outputs, target_ids: tuple):
    from registration.core.plotting import label_style, pyplot

    plt = pyplot()
    s = outputs.sample
    fig, axes = plt.subplots(1, 2, figsize=(14, 6), sharex=True, sharey=True, layout="constrained")
    for ax, name, title in (
        (axes[0], "measured", "as measured"),
        (axes[1], "corrected", "corrected by the estimates"),
    ):
        lat, lon = np.degrees(s[f"{name}_lat"]), np.degrees(s[f"{name}_lon"])
        for k in np.unique(s["target"]):
            on = (s["target"] == k) & np.isfinite(lat)
            colour, marker = label_style(int(k))
            ax.plot(
                lon[on],
                lat[on],
                ls="none",
                marker=marker,
                ms=2,
                mew=0,
                color=colour,
                label=str(target_ids[k]),
            )
        ax.set_title(f"sampled plots {title} ({int(np.isfinite(lat).sum())})")
        ax.set_xlabel("longitude (deg E)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("latitude (deg N)")
    n = np.unique(s["target"]).size
    axes[1].legend(
        title="target",
        markerscale=4,
        fontsize=8,
        ncol=max(1, -(-n // 20)),
        loc="center left",
        bbox_to_anchor=(1.02, 0.5),
    )
    return fig


def write_figures(folder: Path, outputs, result) -> list[Path]:
    """The PNG figures (module docstring) in ``folder``."""
    from registration.core.plotting import save_figure

    draws = {
        "residuals.png": lambda: _histogram_figure(outputs, result.chi_square.text()),
        "residuals_time.png": lambda: _time_figure(outputs),
        "map.png": lambda: _map_figure(outputs, result.plan.target_ids),
    }
    written = []
    for name in PNG_OUTPUTS:
        with writing(folder / name):
            written.append(save_figure(draws[name](), folder / name))
    return written
