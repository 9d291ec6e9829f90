"""What the CAT034 service messages tell about each radar: the antenna scan period and a check of
the plots' time stamps against the antenna position.

* Scan period: the median interval between consecutive north markers (I034/000 = 1, times
  I034/030), each interval divided by the number of turns it spans (a missed marker doubles one);
  beside it the median antenna rotation period the radar states in I034/041, when it does.
* Clock check: the north markers (azimuth 0) and sector crossings (I034/020, the azimuth of the
  sector's start) trace the antenna's azimuth against time, a turn each scan. A plot at azimuth
  theta (I048/040) should carry the time the antenna pointed at theta: between the sector
  messages around it. The check reports the median of (plot time - time the antenna pointed at
  the plot's azimuth, linearly between the messages) and how many plots lie outside their sector.
  Both clocks are the radar's own: a clock offset common to its CAT034 and CAT048 time stamps
  does not show here (it does show against the capture times, :mod:`registration.io.asterix.tables.summary`),
  an azimuth bias shows as bias / 360 x period.
"""

from __future__ import annotations

import numpy as np

__all__ = ["scan_period", "antenna_track", "clock_check"]


def scan_period(north_times: np.ndarray) -> dict:
    """``north_markers`` (count) and ``scan_period_s`` (median, None with fewer than two markers)
    from the north marker times (s)."""
    t = np.sort(np.asarray(north_times, dtype=float))
    out: dict[str, int | float | None] = {"north_markers": int(t.size), "scan_period_s": None}
    d = np.diff(t)
    d = d[d > 0]
    if d.size == 0:
        return out
    turns = np.maximum(np.round(d / np.median(d)), 1.0)
    out["scan_period_s"] = float(np.median(d / turns))
    return out


def antenna_track(
    times: np.ndarray, azimuth_deg: np.ndarray, period_s: float | None
) -> tuple[np.ndarray, np.ndarray]:
    """(times, unwrapped azimuth in degrees, increasing) of the antenna from its service messages
    (north markers at 0 deg, sector crossings at their azimuth). Messages at one time count once;
    the turns between messages come from the scan period when known (a gap of missed messages),
    else a message at or below the previous azimuth starts a new turn."""
    order = np.argsort(times, kind="stable")
    t, az = np.asarray(times, dtype=float)[order], np.mod(np.asarray(azimuth_deg, dtype=float)[order], 360.0)
    keep = np.concatenate([[True], np.diff(t) > 0]) if t.size else np.zeros(0, dtype=bool)
    t, az = t[keep], az[keep]
    if t.size < 2:
        return t, az
    step = np.mod(np.diff(az), 360.0)
    if period_s:
        step += 360.0 * np.maximum(np.round((np.diff(t) / period_s * 360.0 - step) / 360.0), 0.0)
    else:
        step[step == 0] = 360.0
    angle = az[0] + np.concatenate([[0.0], np.cumsum(step)])
    good = np.concatenate([[True], step > 0])
    return t[good], angle[good]


def clock_check(
    track_t: np.ndarray, track_deg: np.ndarray, plot_t: np.ndarray, plot_bearing_deg: np.ndarray
) -> dict:
    """The clock check of one radar's plots (times s, azimuths deg) against its antenna track
    (:func:`antenna_track`): ``plots_checked`` (plots within the track's time span),
    ``median_offset_s`` (plot time - time the antenna pointed at the plot's azimuth),
    ``plots_outside_their_sector`` (time stamped before the sector message that opens their sector
    or after the one that closes it)."""
    out: dict[str, int | float | None] = {
        "plots_checked": 0,
        "median_offset_s": None,
        "plots_outside_their_sector": 0,
    }
    if track_t.size < 2:
        return out
    inside = (plot_t >= track_t[0]) & (plot_t <= track_t[-1])
    t, theta = plot_t[inside], np.asarray(plot_bearing_deg, dtype=float)[inside]
    antenna = np.interp(t, track_t, track_deg)
    unwrapped = theta + 360.0 * np.round((antenna - theta) / 360.0)
    ok = (unwrapped >= track_deg[0]) & (unwrapped <= track_deg[-1])
    t, unwrapped = t[ok], unwrapped[ok]
    if t.size == 0:
        return out
    offset = t - np.interp(unwrapped, track_deg, track_t)
    k = np.clip(np.searchsorted(track_deg, unwrapped, side="right"), 1, track_t.size - 1)
    outside = (t < track_t[k - 1]) | (t > track_t[k])
    out.update(
        plots_checked=int(t.size),
        median_offset_s=float(np.median(offset)),
        plots_outside_their_sector=int(outside.sum()),
    )
    return out
