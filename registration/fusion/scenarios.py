"""Fusion scenarios: the paper's two (radar + remote bearing sensor, radar + remote laser range
finder), their noise-free and simulated measurements, and a description for reports.

Frame ``loc``: radar A at the origin, +x from A towards the second site B, azimuth
counter-clockwise from +x (the convention that reproduces the paper's figures), z up in 3-D.
SI units and radians; degrees and milliradians only in :func:`describe` (table edge).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from registration.core.validation import as_float_array, check_positive
from registration.fusion.optimal import crlb
from registration.fusion.polar import COMPONENTS, cartesian2polar, parse_components, polar2cartesian

__all__ = ["FusionScenario", "paper_scenario", "true_position", "true_measurements", "simulate", "describe"]


@dataclass(frozen=True)
class FusionScenario:
    """A radar at ``site_radar_loc`` and a second sensor at ``site_second_loc`` seeing one target.

    ``target_polar``: the target in the radar's polar frame, [r m, az rad(, el rad)] (d = 2 or 3).
    ``sigma_radar`` (d,): radar standard deviations [m, rad(, rad)]. ``components`` and
    ``sigma_second`` (k,): what the second sensor measures and how well (m or rad).
    ``paper_gdop_m``: the paper's printed GDOP per row name (None where it prints none).
    """

    name: str
    site_radar_loc: np.ndarray
    site_second_loc: np.ndarray
    target_polar: np.ndarray
    sigma_radar: np.ndarray
    components: tuple[str, ...]
    sigma_second: np.ndarray
    paper_gdop_m: dict = field(default_factory=dict)
    #: the paper's figures as printed, where a number cannot be read (row name -> text)
    paper_printed: dict = field(default_factory=dict)
    notes: tuple[str, ...] = ()

    @property
    def dim(self) -> int:
        """2 or 3: the number of polar components of the target."""
        return int(self.target_polar.shape[0])

    def with_changes(self, **changes) -> "FusionScenario":
        """A copy with fields replaced and validated; the paper's figures no longer apply."""
        sc = replace(self, **changes)
        if changes:
            sc = replace(sc, name=f"custom (from {self.name})", paper_gdop_m={}, paper_printed={}, notes=())
        return sc.validated()

    def validated(self) -> "FusionScenario":
        """Check shapes, signs and that the target is at neither site; return self."""
        tp = as_float_array("target_polar", self.target_polar)
        d = tp.shape[0] if tp.ndim == 1 else -1
        if d not in COMPONENTS:
            raise ValueError(
                f"target_polar: expected [range m, azimuth rad(, elevation rad)], got shape {tp.shape}"
            )
        for name in ("site_radar_loc", "site_second_loc"):
            s = as_float_array(name, getattr(self, name))
            if s.shape != (d,):
                raise ValueError(
                    f"{name}: expected ({d},) metres to match a {d}-D target, got shape {s.shape}"
                )
        sr = as_float_array("sigma_radar", self.sigma_radar)
        if sr.shape != (d,):
            raise ValueError(
                f"sigma_radar: expected ({d},) standard deviations [m, rad(, rad)], got shape {sr.shape}"
            )
        check_positive("sigma_radar", sr, "(standard deviations in m and rad)")
        idx = parse_components(self.components, d)
        ss = as_float_array("sigma_second", self.sigma_second)
        if ss.shape != (idx.size,):
            raise ValueError(
                f"sigma_second: expected one standard deviation per component {tuple(self.components)}, got "
                f"shape {ss.shape}"
            )
        check_positive("sigma_second", ss, "(standard deviations in m and rad)")
        # crlb() checks the target is off both sites and validates everything once more
        crlb(true_position(self), sr, ss, self.components, self.site_second_loc, self.site_radar_loc)
        return self


@dataclass(frozen=True)
class _PaperSetup:
    """One of the paper's scenarios: radar at the origin, second site at (baseline, 0)."""

    name: str
    baseline_m: float
    target_range_m: float
    target_azimuth_deg: float
    sigma_radar: tuple[float, float]
    component: str
    sigma_second: float
    paper_gdop_m: dict
    paper_printed: dict
    note: str


_PAPER = {
    1: _PaperSetup(
        name="scenario 1: radar + passive bearing sensor",
        baseline_m=80e3,
        target_range_m=100e3,
        target_azimuth_deg=15.0,
        sigma_radar=(100.0, 7e-3),
        component="azimuth",
        sigma_second=4e-3,
        paper_gdop_m={"radar": 707.1, "paper_actual": 221.5},
        paper_printed={},
        note="paper: radar GDOP 707.1 m (= sqrt(100^2 + 700^2), the analytic value), fused 221.5 m "
        "from 1000 simulated pairs",
    ),
    2: _PaperSetup(
        name="scenario 2: radar + laser range finder",
        baseline_m=40e3,
        target_range_m=80e3,
        target_azimuth_deg=45.0,
        sigma_radar=(60.0, 5e-3),
        component="range",
        sigma_second=10.0,
        paper_gdop_m={"radar": 395.1, "paper_actual": None},
        paper_printed={"paper_actual": "?19.5"},
        note="paper: radar GDOP 395.1 m from 1000 simulated pairs (the analytic value is "
        "sqrt(60^2 + 400^2) = 404.5 m); fused value printed as '?19.5 m' with the first "
        "digit illegible, described as 'more than 3x better'",
    ),
}


def paper_scenario(number: int) -> FusionScenario:
    """Scenario 1 (radar + remote bearing sensor) or 2 (radar + remote laser range finder) of the paper.

    ``paper_gdop_m`` holds the paper's printed GDOPs (m), None where the figure is illegible;
    ``paper_printed`` holds such a figure as printed.
    """
    if number not in (1, 2):
        raise ValueError(f"scenario: expected 1 or 2 (the paper's scenarios), got {number!r}")
    p = _PAPER[number]
    return FusionScenario(
        name=p.name,
        site_radar_loc=np.zeros(2),
        site_second_loc=np.array([p.baseline_m, 0.0]),
        target_polar=np.array([p.target_range_m, np.radians(p.target_azimuth_deg)], dtype=np.float64),
        sigma_radar=np.array(p.sigma_radar),
        components=(p.component,),
        sigma_second=np.array([p.sigma_second]),
        paper_gdop_m=dict(p.paper_gdop_m),
        paper_printed=dict(p.paper_printed),
        notes=(p.note,),
    ).validated()


def true_position(sc: FusionScenario) -> np.ndarray:
    """The target position (d,) in metres, frame loc."""
    p_rel, _ = polar2cartesian(np.asarray(sc.target_polar, dtype=np.float64)[None, :])
    return p_rel[0] + np.asarray(sc.site_radar_loc, dtype=np.float64)


def true_measurements(sc: FusionScenario) -> tuple[np.ndarray, np.ndarray]:
    """Noise-free measurements: radar polar (d,) and the second sensor's components (k,)."""
    p = true_position(sc)
    pol_b, _ = cartesian2polar((p - np.asarray(sc.site_second_loc, dtype=np.float64))[None, :])
    idx = parse_components(sc.components, sc.dim)
    return np.asarray(sc.target_polar, dtype=np.float64).copy(), pol_b[0, idx]


def simulate(sc: FusionScenario, trials: int, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """``trials`` independent noisy pairs: radar (trials, d) and second sensor (trials, k).

    Gaussian noise with the scenario's standard deviations, independent across components and
    sensors, no bias (the paper's simulation).
    """
    if not (isinstance(trials, (int, np.integer)) and trials >= 2):
        raise ValueError(f"trials: expected an integer >= 2, got {trials!r}")
    z_a, z_b = true_measurements(sc)
    noise_a = rng.standard_normal((trials, z_a.size)) * sc.sigma_radar
    noise_b = rng.standard_normal((trials, z_b.size)) * sc.sigma_second
    return z_a + noise_a, z_b + noise_b


def describe(sc: FusionScenario) -> dict:
    """The scenario's parameters for people: metres, degrees (``_deg``) and milliradians (``_mrad``)."""
    idx = parse_components(sc.components, sc.dim)
    names = [COMPONENTS[sc.dim][i] for i in idx]
    out = {
        "name": sc.name,
        "dim": sc.dim,
        "site_radar_m": np.asarray(sc.site_radar_loc, dtype=float).tolist(),
        "site_second_m": np.asarray(sc.site_second_loc, dtype=float).tolist(),
        "target_range_m": float(sc.target_polar[0]),
        "target_azimuth_deg": float(np.degrees(sc.target_polar[1])),
        "sigma_radar": {"range_m": float(sc.sigma_radar[0]), "azimuth_mrad": float(sc.sigma_radar[1] * 1e3)},
        "sigma_second": {},
    }
    if sc.dim == 3:
        out["target_elevation_deg"] = float(np.degrees(sc.target_polar[2]))
        out["sigma_radar"]["elevation_mrad"] = float(sc.sigma_radar[2] * 1e3)
    for name, s in zip(names, np.asarray(sc.sigma_second, dtype=float)):
        out["sigma_second"][f"{name}_m" if name == "range" else f"{name}_mrad"] = float(
            s if name == "range" else s * 1e3
        )
    return out
