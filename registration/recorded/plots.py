"""The plots of a recorded-data run: estimates.png, differences.png and tracks.png.

They are drawn from the written outputs and the input table, read with a stride so that at most
about ``PLOT_POINTS`` points are held, whatever the length of the run.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from registration import _codegen
from registration.core.plotting import pyplot
from registration.online.contract import IS_ANGLE
from registration.online.plots import plot_difference_series, plot_estimate_series
from registration.recorded.columns import ESTIMATE_COLUMNS, POSITION_COLUMNS
from registration.recorded.formats import iter_frames
from registration.recorded.options import RunOptions
from registration.recorded.outputs import output_paths

__all__ = ["write_plots", "PLOT_POINTS"]

PLOT_POINTS = 4000
_NAV_COLUMNS = ["a_lat_deg", "a_lon_deg", "b_lat_deg", "b_lon_deg"]


def write_plots(table_path: Path, options: RunOptions, summary: dict) -> list[str]:
    """Draw the three plots of the run that ``summary`` describes into ``options.out``; return their paths."""
    out, paths = options.out, output_paths(options)
    stride = max(1, -(-max(int(summary["rows"]["accepted"]), 1) // PLOT_POINTS))
    est = _strided(paths["estimates"], ESTIMATE_COLUMNS, stride)
    pos = _strided(paths["positions"], POSITION_COLUMNS, stride)
    x = np.stack([np.radians(est[c]) if IS_ANGLE[i] else est[c] for i, c in enumerate(ESTIMATE_COLUMNS[2:-1:2])], axis=1)
    s = np.stack([np.radians(est[c]) if IS_ANGLE[i] else est[c] for i, c in enumerate(ESTIMATE_COLUMNS[3:-1:2])], axis=1)
    written = [str(plot_estimate_series(np.asarray(est["time_s"]), x, s, summary["observability"]["status"], None, out / "estimates.png"))]
    raw = pos[["diff_raw_x_m", "diff_raw_y_m", "diff_raw_z_m"]].to_numpy()
    corrected = pos[["diff_x_m", "diff_y_m", "diff_z_m"]].to_numpy()
    written.append(str(plot_difference_series(np.asarray(pos["time_s"]), raw, corrected, out / "differences.png")))
    nav = _strided(table_path, _NAV_COLUMNS, max(1, -(-summary["rows"]["read"] // PLOT_POINTS)))
    tracks = {c: _numeric(nav[c]) if c in nav else np.empty(0) for c in _NAV_COLUMNS}
    ok = np.ones(len(tracks["a_lat_deg"]), dtype=bool)
    for c, v in tracks.items():
        ok &= np.isfinite(v) & (np.abs(v) <= (90 if "lat" in c else 360))
    targets = {s: _approx_lat_lon_deg(pos[[f"{s}_ecef_x_m", f"{s}_ecef_y_m", f"{s}_ecef_z_m"]].to_numpy()) for s in "ab"}
    if ok.sum() >= 2:
        written.append(str(_plot_tracks({k: v[ok] for k, v in tracks.items()}, targets, out / "tracks.png")))
    return written


def _strided(path, columns, stride: int):
    """Every ``stride``-th row of a table (CSV/Parquet file or a folder of Parquet parts), streamed."""
    import pandas as pd

    files = sorted(Path(path).glob("part-*.parquet")) if Path(path).is_dir() else [Path(path)]
    pieces, pos = [], 0
    for f in files:
        for _, frame in iter_frames(f, columns, 50_000):
            off = (-pos) % stride
            pieces.append(frame.iloc[off::stride])
            pos += len(frame)
    return pd.concat(pieces, ignore_index=True) if pieces else pd.DataFrame(columns=columns)


def _numeric(col) -> np.ndarray:
    import pandas as pd

    return np.asarray(pd.to_numeric(col, errors="coerce"), dtype=float)


def _approx_lat_lon_deg(p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """ECEF (K, 3) in m -> geodetic latitude, longitude (deg) by Bowring's formula, with the WGS-84
    constants of the generated code: metre-level, for the track plot only."""
    wgs = _codegen.wgs84()
    a, b, e2 = wgs["wgs84_a_m"], wgs["wgs84_b_m"], wgs["wgs84_e2"]
    ep2 = (a * a - b * b) / (b * b)
    x, y, z = p[:, 0], p[:, 1], p[:, 2]
    rho = np.hypot(x, y)
    th = np.arctan2(z * a, rho * b)
    lat = np.arctan2(z + ep2 * b * np.sin(th) ** 3, rho - e2 * a * np.cos(th) ** 3)
    return np.degrees(lat), np.degrees(np.arctan2(y, x))


def _plot_tracks(tracks: dict, targets: dict, path: Path) -> Path:
    """Ships' tracks and the target as each radar places it after registration (lon/lat, deg)."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 6))
    for s, colour in (("a", "tab:blue"), ("b", "tab:orange")):
        lon, lat = tracks[f"{s}_lon_deg"], tracks[f"{s}_lat_deg"]
        ax.plot(lon, lat, color=colour, lw=3, label=f"ship {s.upper()}")
        ax.plot(lon[0], lat[0], "o", color=colour)
    for s, colour in (("a", "tab:red"), ("b", "tab:purple")):
        lat, lon = targets[s]
        good = np.isfinite(lat) & np.isfinite(lon)
        if good.any():
            ax.plot(lon[good], lat[good], ".", ms=2, color=colour, label=f"target, corrected plots of radar {s.upper()}")
    ax.set_xlabel("longitude (deg E)")
    ax.set_ylabel("latitude (deg N)")
    ax.set_title("Ship tracks and the target (dots on tracks: start)")
    ax.set_aspect(1 / max(np.cos(np.radians(np.nanmean(tracks["a_lat_deg"]))), 0.05))
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
