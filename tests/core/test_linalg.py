"""Batched small-matrix algebra of registration.core.linalg against numpy's own per-matrix routines."""

from __future__ import annotations

import numpy as np
import pytest

from registration.core import linalg

RNG = np.random.default_rng(11)


@pytest.mark.parametrize("d", [2, 3])
def test_products_transpose_sandwich_and_inverse_match_numpy(d):
    n = 500
    a, b = RNG.normal(size=(n, d, d)), RNG.normal(size=(n, d, d))
    v, var = RNG.normal(size=(n, d)), RNG.uniform(0.1, 2.0, size=(n, d))
    A, B = linalg.soa(a), linalg.soa(b)
    np.testing.assert_allclose(linalg.aos(linalg.mm(A, B)), a @ b, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(
        linalg.aos(linalg.mv(A, linalg.soa(v))), np.einsum("nij,nj->ni", a, v), rtol=1e-12, atol=1e-12
    )
    np.testing.assert_array_equal(linalg.aos(linalg.transpose(A)), a.transpose(0, 2, 1))
    cov = np.einsum("nik,nk,njk->nij", a, var, a)
    np.testing.assert_allclose(linalg.aos(linalg.sandwich(A, linalg.soa(var))), cov, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(linalg.aos(linalg.sym(A)), 0.5 * (a + a.transpose(0, 2, 1)), rtol=0, atol=0)
    spd = cov + 0.5 * np.eye(d)
    np.testing.assert_allclose(
        linalg.aos(linalg.inv(linalg.soa(spd))), np.linalg.inv(spd), rtol=1e-9, atol=1e-12
    )


@pytest.mark.parametrize("d", [2, 3])
def test_inverse_names_the_first_singular_matrix(d):
    m = np.stack([np.eye(d), np.eye(d), np.ones((d, d))])
    with pytest.raises(ValueError, match="singular .* at row 2"):
        linalg.inv(linalg.soa(m))
