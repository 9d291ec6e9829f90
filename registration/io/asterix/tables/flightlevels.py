"""Flight levels as height measurements: the relation of pressure altitude to geometric height,
learned from the ADS-B reports that carry both, turns the Mode C / Mode S flight levels of the
plots (I048/090, I001/090) of aircraft without ADS-B into heights of the reference file.

A flight level is a pressure altitude ``Hp`` (FL x 100 ft): where the air has the ISA's pressure
at ``Hp``. The geometric height differs by hundreds of metres with the day's temperature and
sea-level pressure (:mod:`registration.core.atmosphere`: a straight line in ``Hp`` in the
troposphere, ISA + 12 K and QNH 1025 hPa put FL 350 about 560 m higher), plus the geoid undulation.
The ADS-B reports that give both the barometric flight level (I021/145) and the geometric height
above the WGS-84 ellipsoid (I021/140) measure that relation over the recording's area and time:

* :func:`learn_relation` fits ``h - Hp`` as a polynomial in ``Hp`` of degree 0 to 3 (more degrees
  as the flight levels spread: under 300 m of ``Hp`` an offset, under 3 km a line, under 6 km a
  parabola, else a cubic, which follows the change of slope at the tropopause), once again after
  setting aside the reports further than 5 sigma, and states the spread of the reports about it as
  its sigma (the ADS-B heights' own noise included: a conservative sigma);
* :func:`height_rows` makes one reference row per plot of a target that has no ADS-B reference,
  with a valid flight level (V and G 0) within the levels fitted (+- 600 m): ``alt_m`` the relation's
  height, ``sigma_up_m`` the relation's sigma and the flight level's rounding (100 ft steps, sigma
  100 ft / sqrt(12), for a target whose levels are all whole: Mode C's Gillham code; else 25 ft
  steps) together, and ``sigma_m`` inf: a height only (its latitude and longitude are the plot's
  position at that height with no registration error, for the local up).

Each row is taken as an independent measurement of the height at the plot's time; the relation's
own error is common to every row (with thousands of ADS-B reports it is small next to its sigma).

Without ADS-B reports that give both, the flight levels are converted by the ISA itself
(:func:`registration.core.atmosphere.pressure_altitude2height`) and every such height shares one
unknown offset, the registration state ``flight_levels:height_offset`` (the reference file's
``height_offset_prior_m``), estimated with the prior :func:`offset_prior_m` at the median pressure
altitude ``Hp0`` of those plots: the QNH (15 hPa x 8.3 m/hPa), the geoid (50 m) and the temperature
(15 K, so a height scale error of 15 / 288.15 = 5.2 %, times ``Hp0``) in quadrature. The offset takes
the day's shift at ``Hp0``; away from it the temperature's scale error remains, so each row's
``sigma_up_m`` adds 5.2 % of ``|Hp - Hp0|`` to its rounding.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.core.atmosphere import pressure_altitude2height
from registration.core.frames import ecef2geodetic, enu2ecef_rotation, geodetic2ecef

__all__ = [
    "FlightLevelRelation",
    "learn_relation",
    "height_rows",
    "offset_prior_m",
    "MARGIN_M",
    "OUTLIER_SIGMAS",
    "QNH_SIGMA_HPA",
    "M_PER_HPA",
    "GEOID_SIGMA_M",
    "SLOPE_SIGMA",
]

#: How far outside the fitted pressure altitudes (m) a flight level is still converted.
MARGIN_M = 600.0
#: Reports further than this many sigmas from the first fit are set aside before the second.
OUTLIER_SIGMAS = 5.0
#: Without a learned relation, the prior of the offset: the day's QNH about the standard 1013.25 hPa
#: (sigma, hPa; ICAO's extremes run from about 950 to 1050), the height of one hPa near the ground
#: (m, the ISA: 8.3 m at sea level), the geoid undulation not known (sigma, m) and the day's
#: temperature about the ISA's (sigma 15 K: the height scales by about dT / 288.15 K).
QNH_SIGMA_HPA = 15.0
M_PER_HPA = 8.3
GEOID_SIGMA_M = 50.0
SLOPE_SIGMA = 15.0 / 288.15
_FL_M = 30.48
_MEAN_EARTH_M = 6371000.0


@dataclass(frozen=True)
class FlightLevelRelation:
    """``h - Hp`` (m) as a polynomial in ``Hp`` (m): ``coef`` in increasing powers of
    ``(Hp - centre) / scale``; fitted on pressure altitudes ``lo`` to ``hi`` (m) from ``reports`` ADS-B
    reports of ``aircraft`` aircraft (``outliers`` set aside); ``sigma_m`` the spread about it."""

    coef: np.ndarray
    centre: float
    scale: float
    lo: float
    hi: float
    sigma_m: float
    reports: int
    aircraft: int
    outliers: int

    def offset(self, hp_m) -> np.ndarray:
        """(N,) ``h - Hp`` (m) at pressure altitudes ``hp_m`` (m)."""
        u = (np.asarray(hp_m, dtype=np.float64) - self.centre) / self.scale
        return np.polynomial.polynomial.polyval(u, self.coef)

    def height(self, hp_m) -> np.ndarray:
        """(N,) geometric height above the WGS-84 ellipsoid (m) at pressure altitudes ``hp_m`` (m)."""
        return np.asarray(hp_m, dtype=np.float64) + self.offset(hp_m)

    def summary(self) -> dict:
        """The relation in words and numbers: the height minus the pressure altitude at flight levels
        across the range fitted."""
        levels = np.unique(np.round(np.linspace(self.lo, self.hi, 5) / _FL_M / 10.0) * 10.0)
        return {
            "model": f"h - FL x 100 ft = polynomial of degree {self.coef.size - 1} in the pressure altitude",
            "reports": self.reports,
            "aircraft": self.aircraft,
            "outliers_set_aside": self.outliers,
            "flight_levels_fitted": [round(self.lo / _FL_M, 1), round(self.hi / _FL_M, 1)],
            "sigma_m": round(self.sigma_m, 2),
            "height_minus_pressure_altitude_m": {
                f"FL{int(fl):03d}": round(float(self.offset(fl * _FL_M)), 1) for fl in levels
            },
        }


def _degree(span_m: float) -> int:
    return 0 if span_m < 300.0 else 1 if span_m < 3000.0 else 2 if span_m < 6000.0 else 3


def _fit(hp: np.ndarray, d: np.ndarray, degree: int, centre: float, scale: float) -> tuple[np.ndarray, float]:
    u = (hp - centre) / scale
    coef = np.polynomial.polynomial.polyfit(u, d, degree)
    r = d - np.polynomial.polynomial.polyval(u, coef)
    return coef, float(np.sqrt(np.sum(r * r) / max(r.size - degree - 1, 1)))


def learn_relation(
    pressure_alt_m: np.ndarray, height_m: np.ndarray, target: np.ndarray
) -> FlightLevelRelation | None:
    """The relation (module docstring) from ADS-B reports: pressure altitude (m, NaN: no I021/145),
    geometric height (m) and target id each (R,); None with fewer than 10 reports giving both."""
    both = np.isfinite(pressure_alt_m) & np.isfinite(height_m)
    hp, h, tgt = pressure_alt_m[both], height_m[both], np.asarray(target)[both]
    if hp.size < 10:
        return None
    lo, hi = float(hp.min()), float(hp.max())
    degree = _degree(hi - lo)
    centre, scale = 0.5 * (lo + hi), max(0.5 * (hi - lo), 1.0)
    coef, sigma = _fit(hp, h - hp, degree, centre, scale)
    r = h - hp - np.polynomial.polynomial.polyval((hp - centre) / scale, coef)
    keep = np.abs(r) <= OUTLIER_SIGMAS * max(sigma, 1e-3)
    coef, sigma = _fit(hp[keep], (h - hp)[keep], degree, centre, scale)
    return FlightLevelRelation(
        coef,
        centre,
        scale,
        float(hp[keep].min()),
        float(hp[keep].max()),
        sigma,
        int(keep.sum()),
        int(np.unique(tgt[keep]).size),
        int((~keep).sum()),
    )


def _rounding_sigma(target: np.ndarray, hp: np.ndarray) -> np.ndarray:
    """(N,) the sigma (m) of each flight level's rounding: 100 ft / sqrt(12) where every level of
    its target is a whole flight level (Mode C's 100 ft steps), else 25 ft / sqrt(12)."""
    unique, inverse = np.unique(target, return_inverse=True)
    fraction = np.abs(hp / _FL_M - np.round(hp / _FL_M)) > 1e-6
    stepped = np.bincount(inverse, fraction, unique.size) > 0
    return np.where(stepped[inverse], 25.0, 100.0) * 0.3048 / np.sqrt(12.0)


def _plot_positions(site_lla: np.ndarray, range_m, bearing_deg, height_m) -> tuple[np.ndarray, np.ndarray]:
    """(lat, lon) in degrees of plots at slant range ``range_m`` and bearing ``bearing_deg`` from
    sites ``site_lla`` (N, 3: lat, lon rad, alt m) at geometric height ``height_m`` (a spherical
    Earth for the elevation: the position only gives the local up of a height)."""
    lat, lon, alt = site_lla.T
    r1, r2, r = _MEAN_EARTH_M + alt, _MEAN_EARTH_M + height_m, np.asarray(range_m, dtype=np.float64)
    sin_e = np.clip((r2 * r2 - r1 * r1 - r * r) / (2.0 * r * r1), -1.0, 1.0)
    cos_e, b = np.sqrt(1.0 - sin_e * sin_e), np.radians(bearing_deg)
    enu = r[:, None] * np.stack([cos_e * np.sin(b), cos_e * np.cos(b), sin_e], axis=1)
    p = geodetic2ecef(lat, lon, alt) + np.einsum("nij,nj->ni", enu2ecef_rotation(lat, lon), enu)
    plat, plon, _ = ecef2geodetic(p)
    return np.degrees(plat), np.degrees(plon)


def height_rows(
    plots: dict, site_lla: np.ndarray, relation: FlightLevelRelation | None, adsb_targets: set
) -> tuple[dict, dict]:
    """(reference rows, summary) of the flight levels of ``plots`` (columns ``time_s``, ``target``,
    ``range_m``, ``bearing_deg``, ``pressure_alt_m``; ``site_lla`` (N, 3) their sites' lat, lon (rad),
    alt (m)) of targets not in ``adsb_targets`` (module docstring)."""
    target = np.asarray(plots["target"]).astype(str)
    hp = np.asarray(plots["pressure_alt_m"], dtype=np.float64)
    candidate = (target != "") & np.isfinite(hp) & ~np.isin(target, list(adsb_targets))
    info: dict = {
        "plots_with_flight_level": int(np.isfinite(hp).sum()),
        "plots_of_targets_without_adsb": int(candidate.sum()),
    }
    if relation is None:
        return _offset_rows(plots, site_lla, np.flatnonzero(candidate), info)
    inside = (hp >= relation.lo - MARGIN_M) & (hp <= relation.hi + MARGIN_M)
    use = np.flatnonzero(candidate & inside)
    height = relation.height(hp[use])
    sigma_up = np.hypot(relation.sigma_m, _rounding_sigma(target[use], hp[use]))
    rows = _rows(plots, site_lla, use, height, sigma_up)
    info["relation"] = relation.summary()
    info["heights_written"] = int(use.size)
    info["targets_with_heights"] = sorted(set(target[use].tolist()))
    info["plots_outside_the_levels_fitted"] = int((candidate & ~inside).sum())
    return rows, info


def offset_prior_m(hp_ref_m: float) -> float:
    """The prior sigma (m) of the common height offset of flight levels converted by the ISA alone
    around pressure altitude ``hp_ref_m`` (m): the QNH (:data:`QNH_SIGMA_HPA` at
    :data:`M_PER_HPA`), the geoid undulation (:data:`GEOID_SIGMA_M`) and the temperature
    (:data:`SLOPE_SIGMA` of the height) together."""
    return float(np.sqrt((QNH_SIGMA_HPA * M_PER_HPA) ** 2 + GEOID_SIGMA_M**2 + (SLOPE_SIGMA * hp_ref_m) ** 2))


def _offset_rows(plots: dict, site_lla: np.ndarray, use: np.ndarray, info: dict) -> tuple[dict, dict]:
    """Without a learned relation: the ISA's heights of the flight levels, sharing one unknown offset
    (module docstring)."""
    target = np.asarray(plots["target"]).astype(str)[use]
    hp = np.asarray(plots["pressure_alt_m"], dtype=np.float64)[use]
    info["relation"] = None
    info["note"] = (
        "no ADS-B report gives both a flight level (I021/145) and a geometric height (I021/140): the "
        "flight levels are converted by the ISA, their heights sharing one unknown offset "
        "(flight_levels:height_offset) estimated with its prior"
    )
    info["heights_written"] = int(use.size)
    if not use.size:
        return {}, info
    hp_ref = float(np.median(hp))
    prior = offset_prior_m(hp_ref)
    sigma_up = np.hypot(_rounding_sigma(target, hp), SLOPE_SIGMA * np.abs(hp - hp_ref))
    rows = _rows(plots, site_lla, use, pressure_altitude2height(hp), sigma_up)
    rows["height_offset_prior_m"] = np.full(use.size, prior)
    info["height_offset"] = {
        "model": "h = the ISA's height of FL x 100 ft + one unknown offset (flight_levels:height_offset)",
        "prior_sigma_m": round(prior, 1),
        "reference_flight_level": round(hp_ref / _FL_M, 2),
        "reference_pressure_altitude_m": round(hp_ref, 3),
        "slope_sigma": round(SLOPE_SIGMA, 4),
    }
    info["targets_with_heights"] = sorted(set(target.tolist()))
    return rows, info


def _rows(
    plots: dict, site_lla: np.ndarray, use: np.ndarray, height: np.ndarray, sigma_up: np.ndarray
) -> dict:
    target = np.asarray(plots["target"]).astype(str)
    lat, lon = _plot_positions(
        site_lla[use], np.asarray(plots["range_m"])[use], np.asarray(plots["bearing_deg"])[use], height
    )
    return {
        "time_s": np.asarray(plots["time_s"], dtype=np.float64)[use],
        "target": target[use],
        "lat_deg": lat,
        "lon_deg": lon,
        "alt_m": height,
        "sigma_m": np.full(use.size, np.inf),
        "sigma_up_m": sigma_up,
    }
