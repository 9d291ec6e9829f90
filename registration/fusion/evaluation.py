"""Monte Carlo evaluation of a fusion scenario: the table of GDOPs per estimator.

:func:`evaluate` runs ``trials`` independent measurement pairs through the paper's method and the
maximum-likelihood fuser and returns one row per estimator (:data:`ROW_NAMES`): the analytic
GDOP (covariance formula at the noise-free measurements), the Monte Carlo GDOP (spread of the
points, with its standard error) and the paper's printed figure. Metres, frame ``loc``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.fusion.gdop import gdop, gdop_from_samples
from registration.fusion.optimal import OptimalResult, crlb, fuse_optimal
from registration.fusion.paper import FusionResult, fuse_paper
from registration.fusion.scenarios import FusionScenario, describe, simulate, true_measurements, true_position

__all__ = ["ROW_NAMES", "ROW_LABELS", "FusionEvaluation", "evaluate"]

#: the rows of the evaluation table, in order
ROW_NAMES = ("radar", "pseudo_measurement", "paper_claimed", "paper_actual", "optimal", "crlb")

#: the table label of each row
ROW_LABELS = {
    "radar": "radar alone",
    "pseudo_measurement": "pseudo-measurement H alone",
    "paper_claimed": "paper method, as claimed (eq. 13)",
    "paper_actual": "paper method, as it performs",
    "optimal": "optimal fuser (maximum likelihood)",
    "crlb": "Cramer-Rao bound",
}


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
    """sqrt(mean trace) (m) of covariances (N, d, d) in m^2 and its standard error (delta method)."""
    tr = np.trace(covs, axis1=1, axis2=2)
    g = float(np.sqrt(tr.mean()))
    return g, float(tr.std(ddof=1) / np.sqrt(tr.size)) / (2.0 * g)


def _below(cov: np.ndarray, bound: np.ndarray) -> bool:
    """True when ``cov`` is smaller than ``bound`` in some
    direction (bound - cov has a positive eigenvalue)."""
    ev = np.linalg.eigvalsh(bound - cov)
    return bool(ev.max() > 1e-9 * np.trace(bound))


def _below_fraction(covs: np.ndarray, bound: np.ndarray) -> float:
    """Fraction of the covariances (N, d, d) that are below ``bound`` in some direction (as
    :func:`_below`)."""
    return float(np.mean(np.linalg.eigvalsh(bound - covs).max(axis=1) > 1e-9 * np.trace(bound)))


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
        """The row called ``name`` (one of :data:`ROW_NAMES`)."""
        return next(r for r in self.rows if r["name"] == name)

    def to_json(self) -> dict:
        """A JSON-ready summary: ``rows`` (name, analytic_gdop_m,
        monte_carlo_gdop_m, paper_gdop_m) plus context."""
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


def _fusers(sc: FusionScenario, z_a: np.ndarray, z_b: np.ndarray) -> tuple[FusionResult, OptimalResult]:
    """The paper's method and the optimal fuser on measurement pairs of ``sc``."""
    args = (sc.sigma_radar, z_b, sc.sigma_second, sc.components, sc.site_second_loc, sc.site_radar_loc)
    return fuse_paper(z_a, *args), fuse_optimal(z_a, *args)


def _rows(sc: FusionScenario, analytic_cov: dict, mc_g: dict) -> list[dict]:
    """One table row per name in :data:`ROW_NAMES`: analytic, Monte Carlo and the paper's GDOP (m)."""
    rows = []
    for name in ROW_NAMES:
        g_mc = mc_g.get(name)
        paper = sc.paper_gdop_m.get(name)
        rows.append(
            {
                "name": name,
                "analytic_gdop_m": float(gdop(analytic_cov[name])),
                "monte_carlo_gdop_m": None if g_mc is None else g_mc[0],
                "paper_gdop_m": None if paper is None else float(paper),
            }
        )
    return rows


def _warnings(
    below: bool, claimed: np.ndarray, bound: np.ndarray, opt: OptimalResult, trials: int
) -> list[str]:
    """Warnings for a claimed covariance below the CRLB and for trials the optimal fuser left unconverged."""
    g_claim, g_bound = float(gdop(claimed)), float(gdop(bound))
    warnings = []
    if below:
        warnings.append(
            f"the paper method's claimed covariance (eq. 13, GDOP {g_claim:.1f} m) is below the Cramer-Rao "
            f"bound (GDOP {g_bound:.1f} m) in some direction: it claims more accuracy than any unbiased "
            "fuser of these measurements can have, because it treats the pseudo-measurement as independent "
            "of the radar point it was built from"
        )
    if not opt.converged.all():
        warnings.append(
            f"the optimal fuser did not converge in {int((~opt.converged).sum())} of {trials} trials"
        )
    return warnings


def _details(p_true, points, analytic_cov, mc_g, opt: OptimalResult, ana: FusionResult) -> dict:
    """Extra figures for the report: GDOP about the truth, biases, the optimal fuser's own figures."""
    g_bound = float(gdop(analytic_cov["crlb"]))
    return {
        "p_true_loc_m": p_true.tolist(),
        "gdop_about_truth_m": {k: gdop_from_samples(v, p_true) for k, v in points.items()},
        "bias_m": {k: (v.mean(axis=0) - p_true).tolist() for k, v in points.items()},
        "pseudo_measurement_consistent_gdop_m": float(gdop(analytic_cov["pseudo_measurement_consistent"])),
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


def evaluate(sc: FusionScenario, trials: int = 1000, seed: int = 0) -> FusionEvaluation:
    """Monte Carlo evaluation of the paper's method, the optimal fuser and the CRLB on ``sc``.

    Analytic figures are covariance formulas evaluated at the noise-free measurements; Monte
    Carlo figures are sqrt(trace of the sample covariance) of ``trials`` estimates, except
    ``paper_claimed``, whose Monte Carlo figure is sqrt(mean trace) of the covariance the method
    reports in each trial (what it claims in use). ``crlb`` has no Monte Carlo figure.
    """
    sc = sc.validated()
    z_a, z_b = simulate(sc, trials, np.random.default_rng(seed))
    p_true = true_position(sc)
    ana, ana_opt = _fusers(sc, *true_measurements(sc))
    bound = crlb(
        p_true, sc.sigma_radar, sc.sigma_second, sc.components, sc.site_second_loc, sc.site_radar_loc
    )[0]
    mc, opt = _fusers(sc, z_a, z_b)

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
    below = _below(ana.P_claimed[0], bound)
    return FusionEvaluation(
        scenario=sc,
        trials=int(trials),
        seed=int(seed),
        rows=_rows(sc, analytic_cov, mc_g),
        monte_carlo_se_m={name: v[1] for name, v in mc_g.items()},
        analytic_cov=analytic_cov,
        points=points,
        p_true_loc=p_true,
        claimed_below_crlb=below,
        claimed_below_crlb_fraction=_below_fraction(mc.P_claimed, bound),
        details=_details(p_true, points, analytic_cov, mc_g, opt, ana),
        warnings=tuple(_warnings(below, ana.P_claimed[0], bound, opt, trials)),
    )
