"""Plots of an online-registration run (the paper's Fig. 2-4), written as PNG with matplotlib (Agg).

Each ``*_figure`` function returns the matplotlib figure; each ``plot_*`` writes it as a PNG.
Colours are the colour-blind-safe ones of :data:`registration.core.plotting.OKABE_ITO`.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from registration.core.plotting import OKABE_ITO, pyplot, save_figure
from registration.online.contract import IS_ANGLE, STATE_LABELS, STATE_NAMES, display_unit, to_display
from registration.online.result import RegistrationResult

#: Colours of ship A and ship B, and of the target.
SHIP_COLOURS = {"a": OKABE_ITO["blue"], "b": OKABE_ITO["orange"]}
TARGET_COLOUR = OKABE_ITO["reddish_purple"]
#: Colours of X_A - X_B before and after registration.
BEFORE, AFTER = OKABE_ITO["orange"], OKABE_ITO["blue"]


def plot_tracks(data: dict, truth: dict | None, path: Path) -> Path:
    """Ships' tracks and the target (Fig. 2a/1): longitude/latitude in degrees, as ``path`` (PNG)."""
    return save_figure(tracks_figure(data, truth), path, 110)


def tracks_figure(data: dict, truth: dict | None):
    """The figure of :func:`plot_tracks`."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 6))
    for prefix, colour in SHIP_COLOURS.items():
        lon, lat = np.degrees(data[f"{prefix}_lon"]), np.degrees(data[f"{prefix}_lat"])
        ax.plot(lon, lat, color=colour, lw=3, label=f"ship {prefix.upper()}")
        ax.plot(lon[0], lat[0], "o", color=colour)
    if truth and "target_lon" in truth:
        lon, lat = np.degrees(truth["target_lon"]), np.degrees(truth["target_lat"])
        ax.plot(lon, lat, color=TARGET_COLOUR, lw=1.5, label="target (truth)")
        ax.plot(lon[0], lat[0], "o", color=TARGET_COLOUR)
        ax.annotate("start", (lon[0], lat[0]), textcoords="offset points", xytext=(5, 5), fontsize=8)
    ax.set_xlabel("longitude (deg E)")
    ax.set_ylabel("latitude (deg N)")
    ax.set_title("Ship tracks and target (dots: start)")
    ax.set_aspect(1 / np.cos(np.radians(np.mean(np.degrees(data["a_lat"])))))
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    return fig


def plot_differences(result: RegistrationResult, path: Path) -> Path:
    """X_A - X_B per ECEF axis before and after registration (Fig. 2c and 4c)."""
    return plot_difference_series(
        result.time, result.raw_difference_ecef, result.corrected_difference_ecef, path
    )


def plot_difference_series(time: np.ndarray, raw: np.ndarray, corrected: np.ndarray, path: Path) -> Path:
    """X_A - X_B (K, 3) in m per ECEF axis, before (``raw``) and after registration, against time (K,)
    in s, as ``path`` (PNG)."""
    return save_figure(difference_figure(time, raw, corrected), path, 110)


def difference_figure(time: np.ndarray, raw: np.ndarray, corrected: np.ndarray):
    """The figure of :func:`plot_difference_series`: before in orange, after in blue (Okabe-Ito)."""
    plt = pyplot()
    fig, axes = plt.subplots(3, 1, figsize=(9, 8), sharex=True)
    for i, (ax, axis) in enumerate(zip(axes, "XYZ")):
        ax.plot(time, raw[:, i], color=BEFORE, lw=0.8, label="before")
        ax.plot(time, corrected[:, i], color=AFTER, lw=0.8, label="after")
        ax.axhline(0, color="k", lw=0.5)
        ax.set_ylabel(f"{axis}_A - {axis}_B (m)")
        ax.grid(alpha=0.3)
    axes[0].legend(loc="upper right")
    axes[0].set_title("ECEF difference of the two radars' target positions")
    axes[-1].set_xlabel("time (s)")
    fig.tight_layout()
    return fig


def plot_estimates(result: RegistrationResult, truth_state: np.ndarray | None, path: Path) -> Path:
    """Every state's estimate against time with a ±2σ band and the true value (Fig. 3), as ``path`` (PNG)."""
    sigma = np.sqrt(np.einsum("kii->ki", result.covariances))
    return plot_estimate_series(
        result.time, result.estimates, sigma, result.observability.status, truth_state, path
    )


def plot_estimate_series(
    time: np.ndarray,
    estimates: np.ndarray,
    sigma: np.ndarray,
    status: dict,
    truth_state: np.ndarray | None,
    path: Path,
) -> Path:
    """Estimates (K, 12) with a ±2 ``sigma`` (K, 12) band against time (K,) in s, SI units and radians
    (drawn in degrees or metres), as ``path`` (PNG); ``status``: state name -> observability status."""
    plt = pyplot()
    fig, axes = plt.subplots(
        6, 2, figsize=(11, 15), sharex=True, layout="constrained"
    )  # left: ship/radar A, right: B
    est = to_display(estimates)
    sig = np.where(IS_ANGLE, np.degrees(sigma), sigma)
    for i, ax in enumerate(axes.T.ravel()):
        ax.fill_between(
            time,
            est[:, i] - 2 * sig[:, i],
            est[:, i] + 2 * sig[:, i],
            color=OKABE_ITO["blue"],
            alpha=0.2,
            label="± 2σ",
        )
        ax.plot(time, est[:, i], color=OKABE_ITO["blue"], lw=1, label="estimate")
        if truth_state is not None:
            ax.axhline(to_display(truth_state)[i], color="k", ls="--", lw=1, label="truth")
        name = STATE_NAMES[i]
        flag = status.get(name, "")
        ax.set_title(
            f"{STATE_LABELS[i]} ({display_unit(i)})" + ("" if flag == "identifiable" else f"\n[{flag}]"),
            fontsize=9,
            color="k" if flag == "identifiable" else OKABE_ITO["vermillion"],
        )
        ax.grid(alpha=0.3)
        lo = np.percentile(est[:, i] - 2 * sig[:, i], 5)
        hi = np.percentile(est[:, i] + 2 * sig[:, i], 95)
        if truth_state is not None:
            t = to_display(truth_state)[i]
            lo, hi = min(lo, t), max(hi, t)
        pad = 0.1 * (hi - lo + 1e-12)
        ax.set_ylim(lo - pad, hi + pad)
    axes[0, 0].legend(fontsize=7, loc="upper right")
    for ax in axes[-1]:
        ax.set_xlabel("time (s)")
    fig.suptitle(
        "Registration error estimates with ± 2σ bands, ship A (left) and B (right)\n"
        "titles in orange: not identifiable or weak in this scenario"
    )
    return save_figure(fig, path)
