"""The azimuth eccentricity and the PSR channel, verified by Monte Carlo on a scenario that was not
tuned on (registration.fleet.simulation.channels: ``atc_channel_scenario``).

Written before the first run and not changed after it: 24 seeds (5100-5123), 150 s each; the
eccentricity terms of R1 +-0.2 deg, the PSR channel's offsets from R2's biases +-120 m and
+-0.15 deg (the scenario's defaults). The perturbations are applied to the simulated plots in NumPy
from their definitions (the bearing ``q = q0 + a sin q + b cos q``; a random half of R2's plots
moved to ``R2.psr`` with offsets of their own), not through the generated eccentric model, so a
sign or term error in the derivation is not shared by the simulator.

Checks:

* every run converges and the summed chi-square of the plots lies in its 99 % band;
* **NEES**: the mean over runs of the NEES of all estimated states lies in its two-sided 95 % band
  (``nees_interval``);
* **RMSE / sqrt(CRLB)** of the new states (R1's two eccentricity terms, R2.psr's range, bearing and
  elevation biases): with 24 runs the ratio of a consistent estimator is ``sqrt(chi2_24 / 24)``,
  whose 95 % range is [0.72, 1.27], so a band of [0.8, 1.25] on each single state would fail one
  state in seven by chance alone. [0.8, 1.25] is therefore applied to each kind pooled (the two
  eccentricity terms; the three channel biases), ``sqrt(mean_s RMSE_s^2 / CRLB_s)``, and each
  single state must lie in the chi-square band of its own ratio at a Bonferroni-corrected 99 % (for
  24 runs and 5 states about [0.55, 1.45]). ``benchmarks/bench_channels.py --montecarlo`` runs 200
  seeds and applies [0.8, 1.25] to each state;
* the checks can fail: against truths with the eccentricity's sign flipped, the ratio is far out.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.special import gammaincinv

from registration.core.consistency import nees_interval
from registration.fleet import solve_batch
from registration.fleet.simulation.channels import atc_channel_scenario

SEEDS = range(5100, 5124)
DURATION_S = 150.0
KINDS = {
    "eccentricity": ("R1:eccentricity_sin", "R1:eccentricity_cos"),
    "psr_biases": ("R2.psr:range_bias", "R2.psr:bearing_bias", "R2.psr:elevation_bias"),
}


@pytest.fixture(scope="module")
def mc() -> dict:
    est, tru, sig, cov, status, converged, chi2, dof = [], [], [], [], [], [], 0.0, 0
    layout = None
    for seed in SEEDS:
        sc = atc_channel_scenario(seed, duration_s=DURATION_S)
        result = solve_batch(sc.problem())
        layout = result.layout if layout is None else layout
        assert result.layout.names == layout.names
        est.append(result.estimate)
        tru.append(sc.truth_vector(result.layout))
        sig.append(result.sigma)
        cov.append(result.covariance)
        status.append(dict(result.status))
        converged.append(result.converged)
        chi2 += result.chi_square.chi2
        dof += result.chi_square.dof
    return dict(
        layout=layout,
        est=np.array(est),
        tru=np.array(tru),
        sig=np.array(sig),
        cov=cov,
        status=status,
        converged=converged,
        chi2=chi2,
        dof=dof,
    )


def _ratios(mc: dict, truths: np.ndarray) -> dict:
    """Per new state: RMSE over runs / sqrt(mean reported variance)."""
    err = mc["est"] - truths
    out = {}
    for names in KINDS.values():
        for name in names:
            i = mc["layout"].index(name)
            out[name] = float(np.sqrt(np.mean(err[:, i] ** 2) / np.mean(mc["sig"][:, i] ** 2)))
    return out


def _pooled(ratios: dict) -> dict:
    return {kind: float(np.sqrt(np.mean([ratios[n] ** 2 for n in names]))) for kind, names in KINDS.items()}


def _nees(mc: dict) -> tuple[np.ndarray, int]:
    free = mc["layout"].free
    used = free[np.isfinite(mc["sig"][:, free]).all(axis=0)]
    err = mc["est"] - mc["tru"]
    return np.array(
        [e[used] @ np.linalg.solve(P[np.ix_(used, used)], e[used]) for e, P in zip(err, mc["cov"])]
    ), int(used.size)


def test_every_run_converges_and_the_new_states_are_identifiable(mc):
    assert all(mc["converged"])
    for names in KINDS.values():
        for name in names:
            assert {st[name] for st in mc["status"]} == {"identifiable"}, name
    # the channel shares R2's antenna: no states of its own besides its biases
    assert [n for n in mc["layout"].names if n.startswith("R2.psr:")] == list(KINDS["psr_biases"])


def test_the_model_fits_the_data(mc):
    lo, hi = nees_interval(1, mc["dof"], level=0.99)
    assert lo <= mc["chi2"] <= hi, f"chi2 {mc['chi2']:.0f} outside [{lo:.0f}, {hi:.0f}] for {mc['dof']} dof"


def test_state_nees_in_its_95_percent_band(mc):
    nees, dof = _nees(mc)
    lo, hi = nees_interval(len(SEEDS), dof, level=0.95)
    print(f"mean NEES {nees.mean():.2f} over {dof} states, band [{lo:.2f}, {hi:.2f}]")
    assert lo <= nees.mean() <= hi, f"mean NEES {nees.mean():.2f} outside [{lo:.2f}, {hi:.2f}] ({dof} states)"


def test_new_states_rmse_matches_the_crlb(mc):
    ratios = _ratios(mc, mc["tru"])
    pooled = _pooled(ratios)
    print({k: round(v, 3) for k, v in {**pooled, **ratios}.items()})
    assert all(0.8 <= r <= 1.25 for r in pooled.values()), pooled
    runs, q = len(SEEDS), 0.01 / (2 * len(ratios))
    lo, hi = (np.sqrt(2.0 * gammaincinv(runs / 2, p) / runs) for p in (q, 1 - q))
    assert all(lo <= r <= hi for r in ratios.values()), (lo, hi, ratios)


def test_the_checks_see_a_sign_error(mc):
    """Truths with the eccentricity's sign flipped put its pooled ratio far outside the band."""
    flipped = mc["tru"].copy()
    for name in KINDS["eccentricity"]:
        flipped[:, mc["layout"].index(name)] *= -1
    assert _pooled(_ratios(mc, flipped))["eccentricity"] > 3.0
