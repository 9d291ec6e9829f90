"""One PNG per sensor of the residual diagnostics (matplotlib, Agg): its residuals in display units
(range m, bearing and elevation deg) against measured azimuth (deg), range (km) and time (s), one
row per measured channel, with the bin means and their ±2σ bars (σ of a bin mean:
``scale x sigma / sqrt(n)``)."""

from __future__ import annotations

import numpy as np

from registration.core.plotting import OKABE_ITO, pyplot
from registration.fleet.diagnostics.run import Diagnostics
from registration.fleet.diagnostics.sensor import CHANNEL_NAMES, DISPLAY_UNITS

__all__ = ["diagnostics_figure"]

#: Most residuals drawn per panel (a random subset beyond; the bin means use all of them).
MAX_POINTS = 20000


def _centres(edges: list) -> np.ndarray:
    e = np.asarray(edges, dtype=float)
    return 0.5 * (e[:-1] + e[1:])


def diagnostics_figure(d: Diagnostics, sensor: str):
    """The figure of ``sensor`` (module docstring)."""
    plt = pyplot()
    p, bins = d.plots[sensor], d.sensors[sensor]
    channels = p.channels()
    columns = [
        ("by_azimuth", "edges_deg", np.degrees(np.mod(p.bearing, 2 * np.pi)), 1.0, "measured azimuth (deg)"),
        ("by_range", "edges_m", p.range / 1e3, 1e-3, "measured range (km)"),
        ("by_time", "edges_s", p.time, 1.0, "time (s)"),
    ]
    columns = [c for c in columns if c[0] in bins]
    fig, axes = plt.subplots(
        len(channels), len(columns), figsize=(4.2 * len(columns), 2.8 * len(channels)), squeeze=False
    )
    rng = np.random.default_rng(0)
    for i, c in enumerate(channels):
        y = p.e[:, c] * p.display(c)
        ok = np.flatnonzero(np.isfinite(y))
        if ok.size > MAX_POINTS:
            ok = rng.choice(ok, MAX_POINTS, replace=False)
        for j, (key, edge_key, x, k, label) in enumerate(columns):
            ax = axes[i, j]
            ax.plot(x[ok], y[ok], ".", ms=2, color="0.7", rasterized=True, label="residual")
            b = bins[key][CHANNEL_NAMES[c]]
            n = np.asarray(b["n"], dtype=float)
            mean = np.array([np.nan if v is None else v for v in b["mean"]], dtype=float)
            err = 2.0 * p.scale[c] * p.display(c) / np.sqrt(np.maximum(n, 1))
            ax.errorbar(
                _centres(bins[key][edge_key]) * k,
                mean,
                yerr=np.where(n > 0, err, np.nan),
                fmt="o",
                color=OKABE_ITO["blue"],
                capsize=3,
                label="bin mean ± 2σ",
            )
            ax.axhline(0.0, color=OKABE_ITO["black"], lw=0.8)
            lim = np.nanmax(np.abs(mean) + np.nan_to_num(err, nan=0.0)) if np.isfinite(mean).any() else 1.0
            spread = 4.0 * p.scale[c] * p.display(c)
            ax.set_ylim(-max(spread, 1.2 * lim), max(spread, 1.2 * lim))
            ax.set_xlabel(label)
            ax.set_ylabel(f"{CHANNEL_NAMES[c]} residual ({DISPLAY_UNITS[c]})")
            if i == 0 and j == 0:
                ax.legend(loc="upper right", fontsize="small")
    found = [f for f in d.findings if f.sensor == sensor]
    title = f"{sensor}: residuals (measured - fitted) and bin means ± 2σ"
    if found:
        title += "\n" + "; ".join(f"{f.test} {f.channel} z {f.z:+.1f}" for f in found[:4])
    fig.suptitle(title)
    fig.tight_layout()
    return fig
