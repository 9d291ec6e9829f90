"""The paper's fusion scenarios (SPEC section 3) and their Monte Carlo evaluation.

Frame ``loc``: radar A at the origin, +x from A towards the second site B, azimuth
counter-clockwise from +x (the convention that reproduces the paper's figures), z up in 3-D.
SI units and radians; degrees and milliradians only in :func:`describe` (table edge).

:func:`evaluate` runs ``trials`` independent measurement pairs through the paper's method
(:func:`registration.fusion.fuse_paper`) and the maximum-likelihood fuser, and returns one row
per estimator, each with an analytic GDOP (covariance formula at the noise-free measurements)
and a Monte Carlo GDOP (spread of the points), beside the paper's printed figure.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from registration.fusion import fuser as fusion
from registration.core.validation import as_float_array, check_positive

__all__ = [
    "FusionScenario",
    "FusionEvaluation",
    "ROW_NAMES",
    "paper_scenario",
    "true_position",
    "true_measurements",
    "simulate",
    "evaluate",
    "describe",
]

#: the rows of the evaluation table, in order
ROW_NAMES = ("radar", "pseudo_measurement", "paper_claimed", "paper_actual", "optimal", "crlb")

ROW_LABELS = {
    "radar": "radar alone",
    "pseudo_measurement": "pseudo-measurement H alone",
    "paper_claimed": "paper method, as claimed (eq. 13)",
    "paper_actual": "paper method, as it performs",
    "optimal": "optimal fuser (maximum likelihood)",
    "crlb": "Cramer-Rao bound",
}


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
        if d not in fusion.COMPONENTS:
            raise ValueError(f"target_polar: expected [range m, azimuth rad(, elevation rad)], got shape {tp.shape}")
        for name in ("site_radar_loc", "site_second_loc"):
            s = as_float_array(name, getattr(self, name))
            if s.shape != (d,):
                raise ValueError(f"{name}: expected ({d},) metres to match a {d}-D target, got shape {s.shape}")
        sr = as_float_array("sigma_radar", self.sigma_radar)
        if sr.shape != (d,):
            raise ValueError(f"sigma_radar: expected ({d},) standard deviations [m, rad(, rad)], got shape {sr.shape}")
        check_positive("sigma_radar", sr, "(standard deviations in m and rad)")
        idx = fusion.parse_components(self.components, d)
        ss = as_float_array("sigma_second", self.sigma_second)
        if ss.shape != (idx.size,):
            raise ValueError(
                f"sigma_second: expected one standard deviation per component {tuple(self.components)}, got shape {ss.shape}"
            )
        check_positive("sigma_second", ss, "(standard deviations in m and rad)")
        # crlb() checks the target is off both sites and validates everything once more
        fusion.crlb(true_position(self), sr, ss, self.components, self.site_second_loc, self.site_radar_loc)
        return self


def _polar_point(r: float, az: float, el: float | None = None) -> np.ndarray:
    return np.array([r, az] if el is None else [r, az, el], dtype=np.float64)


def paper_scenario(number: int) -> FusionScenario:
    """Scenario 1 (radar + remote bearing sensor) or 2 (radar + remote laser range finder), SPEC section 3."""
    if number == 1:
        return FusionScenario(
            name="scenario 1: radar + passive bearing sensor",
            site_radar_loc=np.zeros(2),
            site_second_loc=np.array([80e3, 0.0]),
            target_polar=_polar_point(100e3, np.radians(15.0)),
            sigma_radar=np.array([100.0, 7e-3]),
            components=("azimuth",),
            sigma_second=np.array([4e-3]),
            paper_gdop_m={"radar": 707.1, "paper_actual": 221.5},
            notes=(
                "paper: radar GDOP 707.1 m (= sqrt(100^2 + 700^2), the analytic value), fused 221.5 m "
                "from 1000 simulated pairs",
            ),
        ).validated()
    if number == 2:
        return FusionScenario(
            name="scenario 2: radar + laser range finder",
            site_radar_loc=np.zeros(2),
            site_second_loc=np.array([40e3, 0.0]),
            target_polar=_polar_point(80e3, np.radians(45.0)),
            sigma_radar=np.array([60.0, 5e-3]),
            components=("range",),
            sigma_second=np.array([10.0]),
            paper_gdop_m={"radar": 395.1, "paper_actual": None},
            paper_printed={"paper_actual": "?19.5"},
            notes=(
                "paper: radar GDOP 395.1 m from 1000 simulated pairs (the analytic value is "
                "sqrt(60^2 + 400^2) = 404.5 m); fused value printed as '?19.5 m' with the first "
                "digit illegible, described as 'more than 3x better'",
            ),
        ).validated()
    raise ValueError(f"scenario: expected 1 or 2 (the paper's scenarios), got {number!r}")


def true_position(sc: FusionScenario) -> np.ndarray:
    """The target position (d,) in metres, frame loc."""
    p_rel, _ = fusion._polar2cartesian(np.asarray(sc.target_polar, dtype=np.float64)[None, :])
    return p_rel[0] + np.asarray(sc.site_radar_loc, dtype=np.float64)


def true_measurements(sc: FusionScenario) -> tuple[np.ndarray, np.ndarray]:
    """Noise-free measurements: radar polar (d,) and the second sensor's components (k,)."""
    p = true_position(sc)
    pol_b, _ = fusion._cartesian2polar((p - np.asarray(sc.site_second_loc, dtype=np.float64))[None, :])
    idx = fusion.parse_components(sc.components, sc.dim)
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


# --------------------------------------------------------------------------- evaluation
def _mc_gdop(points: np.ndarray) -> tuple[float, float]:
    """Sample GDOP (m) about the sample mean and its standard error (delta method, any distribution)."""
    dev = points - points.mean(axis=0)
    q = np.sum(dev * dev, axis=1)
    n = q.size
    t = q.sum() / (n - 1)
    g = float(np.sqrt(t))
    se_t = float(q.std(ddof=1) / np.sqrt(n))
    return g, se_t / (2.0 * g)


def _mean_claim(covs: np.ndarray) -> tuple[float, float]:
    tr = np.trace(covs, axis1=1, axis2=2)
    g = float(np.sqrt(tr.mean()))
    return g, float(tr.std(ddof=1) / np.sqrt(tr.size)) / (2.0 * g)


def _below(cov: np.ndarray, bound: np.ndarray) -> bool:
    """True when ``cov`` is smaller than ``bound`` in some direction (bound - cov has a positive eigenvalue)."""
    ev = np.linalg.eigvalsh(bound - cov)
    return bool(ev.max() > 1e-9 * np.trace(bound))


@dataclass(frozen=True)
class FusionEvaluation:
    """Result of :func:`evaluate`. Positions in metres (frame loc), covariances in m^2."""

    scenario: FusionScenario
    trials: int
    seed: int
    #: one dict per row: name, analytic_gdop_m, monte_carlo_gdop_m, paper_gdop_m
    rows: list
    #: Monte Carlo standard error of each row's Monte Carlo GDOP (m)
    monte_carlo_se_m: dict
    #: analytic covariances at the noise-free measurements, by row name
    analytic_cov: dict
    #: Monte Carlo point sets (trials, d) by name: radar, pseudo_measurement, paper, optimal
    points: dict
    p_true_loc: np.ndarray
    #: the claimed (eq. 13) covariance is smaller than the CRLB in some direction
    claimed_below_crlb: bool
    #: fraction of the Monte Carlo trials in which the claimed covariance is below the CRLB
    claimed_below_crlb_fraction: float
    #: extra figures for the report (biases, self-reported covariance of the optimal fuser, ...)
    details: dict
    warnings: tuple[str, ...]

    def row(self, name: str) -> dict:
        return next(r for r in self.rows if r["name"] == name)

    def to_json(self) -> dict:
        """A JSON-ready summary (``rows`` as specified in issue 4, plus context)."""
        return {
            "scenario": describe(self.scenario),
            "trials": self.trials,
            "seed": self.seed,
            "rows": self.rows,
            "monte_carlo_se_m": self.monte_carlo_se_m,
            "claimed_below_crlb": self.claimed_below_crlb,
            "claimed_below_crlb_fraction": self.claimed_below_crlb_fraction,
            "details": self.details,
            "warnings": list(self.warnings),
            "paper_printed": dict(self.scenario.paper_printed),
            "notes": list(self.scenario.notes),
        }


def evaluate(sc: FusionScenario, trials: int = 1000, seed: int = 0) -> FusionEvaluation:
    """Monte Carlo evaluation of the paper's method, the optimal fuser and the CRLB on ``sc``.

    Analytic figures are covariance formulas evaluated at the noise-free measurements; Monte
    Carlo figures are sqrt(trace of the sample covariance) of ``trials`` estimates, except
    ``paper_claimed``, whose Monte Carlo figure is sqrt(mean trace) of the covariance the method
    reports in each trial (what it claims in use). ``crlb`` has no Monte Carlo figure.
    """
    sc = sc.validated()
    rng = np.random.default_rng(seed)
    z_a, z_b = simulate(sc, trials, rng)
    args = (sc.sigma_radar, sc.sigma_second, sc.components, sc.site_second_loc, sc.site_radar_loc)
    z_a0, z_b0 = true_measurements(sc)
    p_true = true_position(sc)

    ana = fusion.fuse_paper(z_a0, sc.sigma_radar, z_b0, *args[1:])
    ana_opt = fusion.fuse_optimal(z_a0, sc.sigma_radar, z_b0, *args[1:])
    bound = fusion.crlb(p_true, *args)[0]
    mc = fusion.fuse_paper(z_a, sc.sigma_radar, z_b, *args[1:])
    opt = fusion.fuse_optimal(z_a, sc.sigma_radar, z_b, *args[1:])

    analytic_cov = {
        "radar": ana.P_radar[0],
        "pseudo_measurement": ana.R_pseudo[0],
        "pseudo_measurement_consistent": ana.R_pseudo_consistent[0],
        "paper_claimed": ana.P_claimed[0],
        "paper_actual": ana.P_consistent[0],
        "optimal": ana_opt.P[0],
        "crlb": bound,
    }
    points = {
        "radar": mc.p_radar_loc,
        "pseudo_measurement": mc.p_pseudo_loc,
        "paper": mc.p_fused_loc,
        "optimal": opt.p_loc,
    }
    mc_g = {
        "radar": _mc_gdop(mc.p_radar_loc),
        "pseudo_measurement": _mc_gdop(mc.p_pseudo_loc),
        "paper_claimed": _mean_claim(mc.P_claimed),
        "paper_actual": _mc_gdop(mc.p_fused_loc),
        "optimal": _mc_gdop(opt.p_loc),
    }
    rows = []
    for name in ROW_NAMES:
        g_mc = mc_g.get(name)
        paper = sc.paper_gdop_m.get(name)
        rows.append(
            {
                "name": name,
                "analytic_gdop_m": float(fusion.gdop(analytic_cov[name])),
                "monte_carlo_gdop_m": None if g_mc is None else g_mc[0],
                "paper_gdop_m": None if paper is None else float(paper),
            }
        )
    se = {name: v[1] for name, v in mc_g.items()}

    below = _below(ana.P_claimed[0], bound)
    below_frac = float(np.mean(np.linalg.eigvalsh(bound - mc.P_claimed).max(axis=1) > 1e-9 * np.trace(bound)))
    g_claim, g_bound = float(fusion.gdop(ana.P_claimed[0])), float(fusion.gdop(bound))
    warnings = []
    if below:
        warnings.append(
            f"the paper method's claimed covariance (eq. 13, GDOP {g_claim:.1f} m) is below the Cramer-Rao bound "
            f"(GDOP {g_bound:.1f} m) in some direction: it claims more accuracy than any unbiased fuser of these "
            "measurements can have, because it treats the pseudo-measurement as independent of the radar point it "
            "was built from"
        )
    if not opt.converged.all():
        warnings.append(f"the optimal fuser did not converge in {int((~opt.converged).sum())} of {trials} trials")

    def bias(pts):
        return (pts.mean(axis=0) - p_true).tolist()

    details = {
        "p_true_loc_m": p_true.tolist(),
        "gdop_about_truth_m": {k: fusion.gdop_from_samples(v, p_true) for k, v in points.items()},
        "bias_m": {k: bias(v) for k, v in points.items()},
        "pseudo_measurement_consistent_gdop_m": float(fusion.gdop(analytic_cov["pseudo_measurement_consistent"])),
        "optimal_self_reported_gdop_m": _mean_claim(opt.P)[0],
        "optimal_iterations_max": int(opt.iterations.max()),
        "optimal_converged_fraction": float(opt.converged.mean()),
        "radar_at_second_site": {
            "polar": ana.polar_radar_at_second[0].tolist(),
            "sigma": np.sqrt(ana.var_radar_at_second[0]).tolist(),
        },
        "efficiency_paper_vs_crlb": g_bound / mc_g["paper_actual"][0],
        "improvement_over_radar": {
            "paper_actual": mc_g["radar"][0] / mc_g["paper_actual"][0],
            "optimal": mc_g["radar"][0] / mc_g["optimal"][0],
        },
    }
    return FusionEvaluation(
        scenario=sc,
        trials=int(trials),
        seed=int(seed),
        rows=rows,
        monte_carlo_se_m=se,
        analytic_cov=analytic_cov,
        points=points,
        p_true_loc=p_true,
        claimed_below_crlb=below,
        claimed_below_crlb_fraction=below_frac,
        details=details,
        warnings=tuple(warnings),
    )


def describe(sc: FusionScenario) -> dict:
    """The scenario's parameters for people: metres, degrees (``_deg``) and milliradians (``_mrad``)."""
    idx = fusion.parse_components(sc.components, sc.dim)
    names = [fusion.COMPONENTS[sc.dim][i] for i in idx]
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
        out["sigma_second"][f"{name}_m" if name == "range" else f"{name}_mrad"] = float(s if name == "range" else s * 1e3)
    return out
