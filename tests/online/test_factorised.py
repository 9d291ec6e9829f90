"""The Carlson (triangular square-root) covariance update against the Joseph form.

Tolerance, from conditioning: the Carlson step factors P- = C C^T; the factor is exact for
P- + E with ``|E_ij| <= (n+1) eps sqrt(P-_ii P-_jj)`` (Cholesky's backward error), so in the
correlation scaling D^-1 P- D^-1 = Corr(P-) the perturbation is at most ``n (n+1) eps`` in
2-norm, i.e. ``E <= n (n+1) eps / lambda_min(Corr(P-)) * P-`` in the Loewner order. The update
maps E to ``A E A^T`` (A = I - K H; the Joseph form is first-order insensitive to K), and
``A P- A^T <= P+``, so ``|dP+_ij| / sqrt(P+_ii P+_jj) <= n (n+1) eps / lambda_min(Corr(P-))``.
Each form's own rounding in the update is of the same order; a factor 4 covers both.
"""

from __future__ import annotations

import numpy as np
import pytest

from registration import _codegen
from registration.online import OnlineRegistrar, RegistrationConfig, register
from registration.online.contract import DATA_COLUMNS, N_STATE
from registration.online.filter import STEP_CARRY
from registration.online.scenario import paper_scenario

EPS = np.finfo(np.float64).eps
ILL_STEPS = 100_000  # 10^6 in benchmarks/bench_step.py --ill --steps 1000000


def _rows(n: int, seed: int = 3) -> np.ndarray:
    data = paper_scenario(seed).data
    rows = np.stack([np.asarray(data[c]) for c in DATA_COLUMNS[1:]], axis=1)
    return np.ascontiguousarray(np.tile(rows, (-(-n // len(rows)), 1))[:n])


def _inputs(cfg: RegistrationConfig, rows: np.ndarray) -> dict:
    return {
        "x": np.zeros(N_STATE),
        "P": np.diag(np.square(cfg.prior_sigma)),
        "info": np.zeros((N_STATE, N_STATE)),
        "Q": np.diag(np.square(cfg.q_sigma)),
        "row": rows,
        "sigma0": np.array(cfg.sigma0),
    }


def _tolerance(P_pred: np.ndarray) -> np.ndarray:
    """Per step: 4 n (n+1) eps / lambda_min(Corr(P-)) (module docstring)."""
    d = np.sqrt(np.einsum("kii->ki", P_pred))
    corr = P_pred / (d[:, :, None] * d[:, None, :])
    return 4 * N_STATE * (N_STATE + 1) * EPS / np.linalg.eigvalsh(corr)[:, 0]


def test_config_names_the_step():
    assert RegistrationConfig().covariance_update == "joseph"
    assert RegistrationConfig().step_name == "kalman_step_fitted_standard"
    cfg = RegistrationConfig(linearization="paper", t_variant="paper", covariance_update="carlson")
    assert cfg.step_name == "kalman_step_paper_paper_carlson"
    with pytest.raises(ValueError, match="covariance_update"):
        RegistrationConfig(covariance_update="ud")


@pytest.mark.parametrize("lin", ["paper", "relinearized", "fitted"])
def test_each_step_matches_joseph_to_the_conditioning_tolerance(lin):
    """From the same inputs at every step of a Joseph run: the same x, nu, S, nis, and P within
    the tolerance derived from the conditioning of P- (lambda_min(Corr(P-)) falls to about 1e-3 here)."""
    cfg = RegistrationConfig(linearization=lin)
    rows = _rows(600)
    joseph = _codegen.get(cfg.step_name)
    run = joseph.scan(len(rows), STEP_CARRY, _inputs(cfg, rows))
    inp = _inputs(cfg, rows)
    x = np.concatenate([inp["x"][None], run["x_new"][:-1]])
    P = np.concatenate([inp["P"][None], run["P_new"][:-1]])
    info = np.concatenate([inp["info"][None], run["info_new"][:-1]])
    args = (x, P, info, inp["Q"], rows, inp["sigma0"])
    ref = joseph(*args)
    new = _codegen.get(f"{cfg.step_name}_carlson")(*args)
    for k in (0, 2, 3, 4, 5):  # x_new, info_new, nu, S, nis: the same expressions
        np.testing.assert_allclose(new[k], ref[k], rtol=1e-12, atol=0)
    d = np.sqrt(np.einsum("kii->ki", ref[1]))
    err = np.max(np.abs(new[1] - ref[1]) / (d[:, :, None] * d[:, None, :]), axis=(1, 2))
    tol = _tolerance(P + inp["Q"])
    assert np.all(err <= tol), (
        f"worst step {np.argmax(err / tol)}: {err.max():.2e} vs tolerance {tol.min():.2e}"
    )


def test_register_and_update_run_the_carlson_step():
    data = paper_scenario(5).data
    j = register(data, RegistrationConfig())
    c = register(data, RegistrationConfig(covariance_update="carlson"))
    sd = np.sqrt(np.einsum("kii->ki", j.covariances))
    assert np.max(np.abs(c.estimates - j.estimates) / sd) < 1e-6
    reg = OnlineRegistrar(RegistrationConfig(covariance_update="carlson"))
    rows = _rows(3, seed=5)
    for r in rows:
        out = reg.update(r)
    np.linalg.cholesky(out["P"])


def test_stays_positive_definite_over_ill_conditioned_steps():
    """Priors from 1e-9 rad to 1e4 m (P- spans 26 orders of magnitude) and no process noise:
    every carried P is finite, has a Cholesky factor and a positive diagonal."""
    prior = (1e-9, 1e-9, 1e-9, 1e4, 1e-9, 1e-9) * 2
    cfg = RegistrationConfig(prior_sigma=prior, q_sigma=(0.0,) * N_STATE, covariance_update="carlson")
    out = _codegen.get(cfg.step_name).scan(
        ILL_STEPS, STEP_CARRY, _inputs(cfg, _rows(ILL_STEPS)), keep_last=("info_new",)
    )
    P = out["P_new"]
    assert np.isfinite(P).all() and np.isfinite(out["x_new"]).all()
    assert (np.einsum("kii->ki", P) > 0).all()
    np.linalg.cholesky(P)  # raises LinAlgError if any P is not positive definite


def test_a_singular_covariance_is_refused_not_propagated():
    """A P- without a Cholesky factor (here a loaded P with a zero variance, no Q) gives NaN in
    the Carlson step, so the registrar refuses the row and keeps its state; Joseph steps on."""
    row = _rows(1)[0]
    for update, refused in (("joseph", False), ("carlson", True)):
        reg = OnlineRegistrar(RegistrationConfig(covariance_update=update, q_sigma=(0.0,) * N_STATE))
        state = reg.state_dict()
        state["P"] = np.diag([0.0] + [1e-4] * (N_STATE - 1))
        reg.load_state_dict(state)
        if refused:
            with pytest.raises(RuntimeError, match="non-finite"):
                reg.update(row)
            assert reg.n_updates == 0 and reg.P[0, 0] == 0.0
        else:
            reg.update(row)
