"""The plots of a recorded-data run: estimates.png, differences.png and tracks.png.

They are drawn from a :class:`~registration.recorded.output.plotseries.PlotSeries`, at most
:data:`PLOT_POINTS` registered rows kept while the filter streamed. A run resumed from a
checkpoint has no such series: :func:`series_from_outputs` selects the same rows from its
written outputs and input table, read again in small blocks. Before each figure the memory freed
so far is handed back to the operating system (:func:`release_free_memory`), so that drawing
(mostly matplotlib itself) does not raise the run's peak resident memory.
"""

from __future__ import annotations

import ctypes
import gc
from pathlib import Path

import numpy as np

from registration.core.frames import ecef2geodetic
from registration.core.plotting import OKABE_ITO, pyplot
from registration.online.contract import IS_ANGLE
from registration.online.plots import SHIP_COLOURS, plot_difference_series, plot_estimate_series
from registration.recorded.options import RunOptions
from registration.recorded.output.outputs import output_paths
from registration.recorded.output.plotseries import PLOT_POINTS, plot_step
from registration.recorded.reading.columns import ESTIMATE_COLUMNS, POSITION_COLUMNS
from registration.recorded.reading.formats import iter_frames

__all__ = ["write_plots", "series_from_outputs", "release_free_memory", "PLOT_POINTS", "READ_ROWS"]

#: Rows per block when outputs are read again (resumed runs): small, so the CSV parser's buffers
#: stay small (measured: +14 MiB at 5,000 rows, +55 MiB at 50,000).
READ_ROWS = 5000
_NAV_COLUMNS = ["a_lat_deg", "a_lon_deg", "b_lat_deg", "b_lon_deg"]


def release_free_memory() -> None:
    """Return freed memory to the operating system: Python's garbage, pyarrow's pool and, with
    glibc, the C heap (``malloc_trim``); a no-op where these are not available."""
    gc.collect()
    try:
        import pyarrow as pa

        pa.default_memory_pool().release_unused()
    except (ImportError, AttributeError):
        pass
    try:
        ctypes.CDLL(None).malloc_trim(0)
    except (OSError, AttributeError):
        pass


def write_plots(series: dict, status: dict, folder: Path) -> list[Path]:
    """Draw the three plots into ``folder`` from ``series`` (:meth:`PlotSeries.arrays`) and the
    observability ``status`` (state name -> status); return their paths."""
    out = Path(folder)
    release_free_memory()
    written = [
        Path(
            plot_estimate_series(
                series["time"], series["x"], series["sigma"], status, None, out / "estimates.png"
            )
        )
    ]
    release_free_memory()
    written.append(
        Path(
            plot_difference_series(
                series["time"], series["raw_diff"], series["corrected_diff"], out / "differences.png"
            )
        )
    )
    release_free_memory()
    nav = series["nav_deg"]
    tracks = {c: nav[:, i] for i, c in enumerate(_NAV_COLUMNS)}
    ok = np.ones(len(nav), dtype=bool)
    for c, v in tracks.items():
        ok &= np.isfinite(v) & (np.abs(v) <= (90 if "lat" in c else 360))
    targets = {s: _lat_lon_deg(series[f"{s}_ecef"]) for s in "ab"}
    if ok.sum() >= 2:
        written.append(_plot_tracks({k: v[ok] for k, v in tracks.items()}, targets, out / "tracks.png"))
    return written


def series_from_outputs(table_path: Path, options: RunOptions, folder: Path, registered: int) -> dict:
    """The rows a :class:`PlotSeries` of a run that registered ``registered`` rows keeps, read
    from its outputs in ``folder`` and (latitude, longitude) from the table it read."""
    paths, step = output_paths(options, folder), plot_step(registered, PLOT_POINTS)
    est = _strided(paths["estimates"], ESTIMATE_COLUMNS, step)
    pos = _strided(paths["positions"], POSITION_COLUMNS, step)
    angle = np.where(IS_ANGLE, np.pi / 180, 1.0)
    series = {
        "time": np.asarray(est["time_s"], dtype=float),
        "x": est[ESTIMATE_COLUMNS[2:-1:2]].to_numpy(dtype=float) * angle,
        "sigma": est[ESTIMATE_COLUMNS[3:-1:2]].to_numpy(dtype=float) * angle,
        "raw_diff": pos[["diff_raw_x_m", "diff_raw_y_m", "diff_raw_z_m"]].to_numpy(dtype=float),
        "corrected_diff": pos[["diff_x_m", "diff_y_m", "diff_z_m"]].to_numpy(dtype=float),
        "a_ecef": pos[["a_ecef_x_m", "a_ecef_y_m", "a_ecef_z_m"]].to_numpy(dtype=float),
        "b_ecef": pos[["b_ecef_x_m", "b_ecef_y_m", "b_ecef_z_m"]].to_numpy(dtype=float),
        "nav_deg": _rows_of(table_path, _NAV_COLUMNS, np.asarray(est["row"], dtype=np.int64)),
    }
    return series


def _rows_of(path, columns, rows: np.ndarray) -> np.ndarray:
    """(len(rows), len(columns)) numbers of the given absolute
    rows (ascending) of a table; NaN if not a number."""
    out, i = np.full((len(rows), len(columns)), np.nan), 0
    for first, frame in iter_frames(path, columns, READ_ROWS):
        j = np.searchsorted(rows, first + len(frame))
        for c, name in enumerate(columns):
            if name in frame:
                out[i:j, c] = _numeric(frame[name].iloc[rows[i:j] - first])
        i = int(j)
    return out


def _strided(path, columns, stride: int):
    """Every ``stride``-th row of a table (CSV/Parquet file or a folder of Parquet parts), streamed;
    only the kept rows are copied out of each block."""
    import pandas as pd

    files = sorted(Path(path).glob("part-*.parquet")) if Path(path).is_dir() else [Path(path)]
    pieces, pos = [], 0
    for f in files:
        for _, frame in iter_frames(f, columns, READ_ROWS):
            off = (-pos) % stride
            pieces.append(frame.iloc[off::stride].copy())  # a copy: a view would keep the whole block alive
            pos += len(frame)
    return pd.concat(pieces, ignore_index=True) if pieces else pd.DataFrame(columns=columns)


def _numeric(col) -> np.ndarray:
    import pandas as pd

    return np.asarray(pd.to_numeric(col, errors="coerce"), dtype=float)


def _lat_lon_deg(p_ecef: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """ECEF (K, 3) in m -> geodetic latitude, longitude (deg); non-finite rows give NaN."""
    lat, lon = np.full(len(p_ecef), np.nan), np.full(len(p_ecef), np.nan)
    good = np.isfinite(p_ecef).all(axis=1) & (np.einsum("ij,ij->i", p_ecef, p_ecef) >= 1e10)
    if good.any():
        la, lo, _ = ecef2geodetic(p_ecef[good])
        lat[good], lon[good] = np.degrees(la), np.degrees(lo)
    return lat, lon


def _plot_tracks(tracks: dict, targets: dict, path: Path) -> Path:
    """Ships' tracks and the target as each radar places it after registration (lon/lat, deg)."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 6))
    for s, colour in SHIP_COLOURS.items():
        lon, lat = tracks[f"{s}_lon_deg"], tracks[f"{s}_lat_deg"]
        ax.plot(lon, lat, color=colour, lw=3, label=f"ship {s.upper()}")
        ax.plot(lon[0], lat[0], "o", color=colour)
    for s, colour in (("a", OKABE_ITO["reddish_purple"]), ("b", OKABE_ITO["black"])):
        lat, lon = targets[s]
        good = np.isfinite(lat) & np.isfinite(lon)
        if good.any():
            ax.plot(
                lon[good],
                lat[good],
                ".",
                ms=2,
                color=colour,
                label=f"target, corrected plots of radar {s.upper()}",
            )
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
