"""The consistency gate: mean normalised innovations against their chi-square band."""

from __future__ import annotations

import numpy as np
import pytest

from registration.core.consistency import GROSS_FACTOR, check_consistency
from registration.online import RegistrationConfig, register
from registration.online.scenario import paper_scenario


def test_chi_square_draws_pass_and_scaled_draws_fail():
    rng = np.random.default_rng(5)
    good = check_consistency(rng.chisquare(3, size=2000), 3)
    assert good.status == "consistent" and good.ok
    assert check_consistency(rng.chisquare(3, size=2000) * 1.5, 3).status == "outside band"
    bad = check_consistency(rng.chisquare(3, size=2000) * (GROSS_FACTOR + 1), 3)
    assert bad.status == "grossly inconsistent" and not bad.ok
    assert "Likely causes" in bad.message() and "radians" in bad.message()
    assert not check_consistency([1.0, np.nan], 3).ok
    with pytest.raises(ValueError, match="no samples"):
        check_consistency([], 3)


def test_a_sigma_in_the_wrong_unit_fails_the_gate_and_the_right_one_passes():
    scenario = paper_scenario(n_steps=200)
    right = register(scenario.data, RegistrationConfig(sigma0=tuple(scenario.sigma0)))
    assert right.consistency.ok and right.consistency.status == "consistent"
    # 0.5 deg of noise, told 0.5 mrad... as a user who typed radians into a degree option would
    wrong_sigma = tuple(
        v if i % 3 == 0 else np.radians(np.radians(0.5)) * 10 for i, v in enumerate(scenario.sigma0)
    )
    wrong = register(scenario.data, RegistrationConfig(sigma0=wrong_sigma))
    assert not wrong.consistency.ok, wrong.consistency.message()
    assert wrong.consistency.to_json()["status"] == "grossly inconsistent"


def test_a_streamed_mean_is_judged_against_the_chi_square_quantiles():
    """from_mean (streaming runs keep only a sum and a count): the band is the chi-square quantiles
    of the mean of n values (scipy.stats, an independent route), and the status follows it."""
    from scipy.stats import chi2

    from registration.core.consistency import ConsistencyReport

    n, dof = 500, 3
    lo, hi = chi2.ppf(0.025, n * dof) / n, chi2.ppf(0.975, n * dof) / n
    inside = ConsistencyReport.from_mean(3.0, n, dof)
    assert inside.interval == pytest.approx((lo, hi), rel=1e-12) and inside.status == "consistent"
    assert ConsistencyReport.from_mean(hi * 1.01, n, dof).status == "outside band"
    assert ConsistencyReport.from_mean(lo * 0.99, n, dof).status == "outside band"
    assert not ConsistencyReport.from_mean(dof * GROSS_FACTOR * 1.01, n, dof).ok
    with pytest.raises(ValueError, match="no samples"):
        ConsistencyReport.from_mean(3.0, 0, dof)
