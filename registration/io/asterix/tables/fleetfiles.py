"""The fleet files that come from SITES (degrees and metres, the columns of docs/reference/fleet-files.md):
each
site a fixed platform named after its sensor, level and north-aligned (heading, pitch, roll 0),
its attitude held fixed unless SITES gives attitude priors.

* ``navigation``: ``time_s``, ``platform``, ``lat_deg``, ``lon_deg``, ``alt_m``, ``heading_deg``,
  ``pitch_deg``, ``roll_deg``: one row per site (a fixed site), at any time of the span;
* ``sensors``: ``sensor``, ``platform``, ``sigma_range_m``, ``sigma_bearing_deg`` (no elevation
  channel) and the prior columns SITES gives (:data:`~registration.io.asterix.tables.sites.SENSOR_PRIORS`);
  a site with ``psr_channel`` ``own`` adds the row of its channel ``<sensor>.psr`` (same platform,
  noise and priors; ``channel_of`` the site's sensor; the column only when some site has a channel);
* ``platforms``: ``platform``, ``prior_heading_deg``, ``prior_pitch_deg``, ``prior_roll_deg``
  (SITES' values, an empty cell meaning no prior as in the fleet files; without the column 0:
  held fixed).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from registration.io.asterix.tables.sites import PLATFORM_PRIORS, PSR_SUFFIX, SENSOR_PRIORS

__all__ = ["PLOT_COLUMNS", "REFERENCE_COLUMNS", "site_tables"]

#: Columns of the plots file written (no elevation_deg: not measured).
PLOT_COLUMNS = ("time_s", "sensor", "target", "range_m", "bearing_deg")
#: Columns of the reference file.
REFERENCE_COLUMNS = ("time_s", "target", "lat_deg", "lon_deg", "alt_m", "sigma_m", "sigma_up_m")


def site_tables(sites: pd.DataFrame, time_s: float) -> dict:
    """``navigation``, ``sensors`` and ``platforms`` DataFrames of the checked SITES table
    (:func:`~registration.io.asterix.tables.sites.check_sites`); ``time_s`` the navigation rows' time."""
    import pandas as pd

    n = len(sites)
    name = sites["sensor"].astype(str).to_numpy()
    navigation = pd.DataFrame(
        {
            "time_s": np.full(n, float(time_s)),
            "platform": name,
            "lat_deg": sites["lat_deg"].to_numpy(float),
            "lon_deg": sites["lon_deg"].to_numpy(float),
            "alt_m": sites["alt_m"].to_numpy(float),
            "heading_deg": np.zeros(n),
            "pitch_deg": np.zeros(n),
            "roll_deg": np.zeros(n),
        }
    )
    sensors = pd.DataFrame(
        {
            "sensor": name,
            "platform": name,
            "sigma_range_m": sites["sigma_range_m"].to_numpy(float),
            "sigma_bearing_deg": sites["sigma_bearing_deg"].to_numpy(float),
        }
    )
    for column in SENSOR_PRIORS:
        if column in sites:
            sensors[column] = sites[column].to_numpy(float)
    own = (
        sites["psr_channel"].astype(str).to_numpy() == "own" if "psr_channel" in sites else np.zeros(n, bool)
    )
    if own.any():
        channels = sensors[own].copy()
        channels["sensor"] = channels["sensor"] + PSR_SUFFIX
        channels["channel_of"] = name[own]
        sensors["channel_of"] = ""
        sensors = pd.concat([sensors, channels], ignore_index=True)
    platforms = pd.DataFrame({"platform": name})
    for column in PLATFORM_PRIORS:
        platforms[column] = sites[column].to_numpy(float) if column in sites else np.zeros(n)
    return {"navigation": navigation, "sensors": sensors, "platforms": platforms}
