"""A vertical sigma for reference positions (``sigma_up``; the file column ``sigma_up_m``).

* without it, or with ``sigma_up == sigma``, every result is the scalar-weight one, bit for bit;
* with it, the reference residual is whitened in the local frame, ``L (y - p)`` with
  ``L = diag(1/s, 1/s, 1/s_up) R_enu_ecef``: checked against an ENU rotation written out here
  (docs/reference/conventions.md), the normal equations against finite differences of the cost and a dense
  least-squares solve;
* a fleet whose reference has 3 m horizontal and 30 m vertical noise, declared so: the errors within
  3.5 sigma, the chi-square consistent, every bias's sigma below that of sigma = 30 m on all axes;
* the reference file's ``sigma_up_m`` read, written back, and refused when bad;
* the partitioned solver, the online filter and the association's gate take it too.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pandas as pd
import pytest

from registration.core.frames import ecef2geodetic
from registration.fleet import build_problem, fleet_scenario, solve_batch
from registration.fleet.association.joining.curves import anchor_curves
from registration.fleet.batch.blocks import make_blocks
from registration.fleet.batch.design import make_design
from registration.fleet.batch.initial import initial_coefficients
from registration.fleet.batch.normal import evaluate, normal_equations
from registration.fleet.batch.partitioned import solve_batch_partitioned
from registration.fleet.batch.solver import BatchOptions
from registration.fleet.data.known_targets import read_references
from registration.fleet.online.filter import OnlineOptions
from registration.fleet.online.register import register_online
from registration.io.fleet.memory import TablesSource
from registration.io.fleet.reading.read import read_fleet_tables
from registration.io.fleet.write import write_fleet_tables
from tests.fleet.test_archive import assert_same

SIGMA_H, SIGMA_UP = 3.0, 30.0
NAMES = ("plots", "navigation", "sensors", "platforms", "reference")


def _enu_rows(lat: np.ndarray, lon: np.ndarray) -> np.ndarray:
    """(N, 3, 3) R_enu_ecef written out from docs/reference/conventions.md (rows: east, north, up)."""
    sl, cl, sb, cb = np.sin(lon), np.cos(lon), np.sin(lat), np.cos(lat)
    east = np.stack([-sl, cl, np.zeros_like(sl)], axis=1)
    north = np.stack([-sb * cl, -sb * sl, cb], axis=1)
    up = np.stack([cb * cl, cb * sl, sb], axis=1)
    return np.stack([east, north, up], axis=1)


def _anisotropic_references(sc, seed: int = 11) -> dict:
    """The scenario's reference times, its target's true positions plus noise of SIGMA_H east and north
    and SIGMA_UP up, declared as sigma SIGMA_H, sigma_up SIGMA_UP."""
    t = np.asarray(sc.references["time"])
    tid = str(sc.references["target"][0])
    truth = sc.target_ecef(tid, t)
    lat, lon, _ = ecef2geodetic(truth)
    noise_enu = np.random.default_rng(seed).normal(size=(t.size, 3)) * [SIGMA_H, SIGMA_H, SIGMA_UP]
    p = truth + np.einsum("nji,nj->ni", _enu_rows(lat, lon), noise_enu)  # R_ecef_enu = R_enu_ecef^T
    return {
        "target": np.full(t.size, tid),
        "time": t,
        "x": p[:, 0],
        "y": p[:, 1],
        "z": p[:, 2],
        "sigma": np.full(t.size, SIGMA_H),
        "sigma_up": np.full(t.size, SIGMA_UP),
    }


@pytest.fixture(scope="module")
def fleet():
    sc = fleet_scenario(4, duration_s=150.0)
    return sc, _anisotropic_references(sc)


def _problem(sc, refs):
    return build_problem(sc.plots, sc.sensors, sc.navigation, sc.platforms, refs)


# (a) ---------------------------------------------------------------------------------------------
def test_sigma_up_equal_to_sigma_changes_nothing_bit_for_bit():
    sc = fleet_scenario(0, duration_s=120.0)
    base = solve_batch(sc.problem())
    for sigma_up in (
        np.array(sc.references["sigma"], dtype=float),
        np.full(sc.references["time"].size, np.nan),
    ):
        same = solve_batch(_problem(sc, {**sc.references, "sigma_up": sigma_up}))
        assert np.array_equal(same.estimate, base.estimate)
        assert np.array_equal(same.sigma, base.sigma)
        assert np.array_equal(same.covariance, base.covariance)
        assert same.chi_square.chi2 == base.chi_square.chi2 and same.chi_square.parts == base.chi_square.parts
        assert np.array_equal(same.reference_residuals, base.reference_residuals)
        assert np.array_equal(same.targets.p_ecef, base.targets.p_ecef)


# (b) ---------------------------------------------------------------------------------------------
def _tiny(fleet):
    """The first 30 s of the fleet: its design with the plots weighing nothing (the references'
    terms alone), and a point near the solution."""
    sc, refs = fleet
    keep = sc.plots["time"] < 30.0
    plots = {k: np.asarray(v)[keep] for k, v in sc.plots.items()}
    rkeep = refs["time"] < 30.0
    problem = build_problem(
        plots, sc.sensors, sc.navigation, sc.platforms, {k: v[rkeep] for k, v in refs.items()}
    )
    design = make_design(problem, make_blocks(problem, 20.0, 3))
    assert design.ref_whiten is not None and design.ref_p.shape[0] > 20
    x = solve_batch(problem).estimate
    refs_only = replace(design, weight=np.zeros_like(design.weight))
    return refs_only, x


def test_whitened_residual_is_east_north_up_over_their_sigmas(fleet):
    design, x = _tiny(fleet)
    blk = design.blocks
    coef = (
        initial_coefficients(design, x)
        + np.random.default_rng(2).normal(size=(blk.n_blocks, blk.n_coef, 3)) * 50.0
    )
    ev = evaluate(design, x, coef)
    p = np.einsum("mk,mkj->mj", blk.ref_basis, coef[blk.ref_block])
    lat, lon, _ = ecef2geodetic(design.ref_p)
    enu = np.einsum("nij,nj->ni", _enu_rows(lat, lon), design.ref_p - p)
    np.testing.assert_allclose(ev.e_ref, enu / [SIGMA_H, SIGMA_H, SIGMA_UP], rtol=1e-9, atol=1e-9)
    assert ev.cost == pytest.approx(float(np.sum(ev.e_ref**2)), rel=1e-12)  # the plots weigh nothing here


def test_whitened_normal_equations_against_finite_differences_of_the_cost(fleet):
    design, x = _tiny(fleet)
    blk = design.blocks
    rng = np.random.default_rng(3)
    coef = initial_coefficients(design, x) + rng.normal(size=(blk.n_blocks, blk.n_coef, 3)) * [
        [30.0],
        [5.0],
        [1.0],
        [0.2],
    ]
    normal = normal_equations(design, evaluate(design, x, coef))
    assert not normal.U.any() and not normal.W.any()  # references do not touch the states

    def residual(c):
        return evaluate(design, x, c).e_ref.reshape(-1)

    h = 1.0  # m: the reference residuals are linear in the coefficients, so the differences are exact
    q = 3 * blk.n_coef
    J = np.zeros((blk.ref_block.size * 3, blk.n_blocks * q))
    grad = np.zeros(blk.n_blocks * q)
    for j in range(blk.n_blocks * q):
        d = np.zeros(coef.size)
        d[j] = h
        d = d.reshape(coef.shape)
        up, down = residual(coef + d), residual(coef - d)
        J[:, j] = (up - down) / (2 * h)
        grad[j] = (np.sum(up**2) - np.sum(down**2)) / (2 * h)
    dense = J.T @ J
    for b in range(blk.n_blocks):
        sl = slice(b * q, (b + 1) * q)
        np.testing.assert_allclose(normal.V[b], dense[sl, sl], rtol=1e-6, atol=1e-9 * np.abs(dense).max())
        np.testing.assert_allclose(normal.b_c[b], -0.5 * grad[sl], rtol=1e-5, atol=1e-6 * np.abs(grad).max())
        dense[sl, sl] = 0.0
    assert np.abs(dense).max() < 1e-9  # a reference couples only its own window's coefficients


def test_whitened_step_equals_a_dense_least_squares_fit_of_the_references(fleet):
    """The windows fitted to the references alone: the Gauss-Newton step of the whitened normal
    equations against numpy's lstsq on the whitened dense system, built here from the ENU rows."""
    design, x = _tiny(fleet)
    blk = design.blocks
    start = np.zeros((blk.n_blocks, blk.n_coef, 3))
    start[:, 0] = design.ref_p.mean(axis=0)
    normal = normal_equations(design, evaluate(design, x, start))
    lat, lon, _ = ecef2geodetic(design.ref_p)
    L = _enu_rows(lat, lon) / np.array([SIGMA_H, SIGMA_H, SIGMA_UP])[:, None]
    checked = 0
    for b in np.unique(blk.ref_block):
        sel = np.flatnonzero(blk.ref_block == b)
        if sel.size < 2 * blk.n_coef or not blk.coef_mask[b].all():
            continue
        A = np.zeros((3 * sel.size, 3 * blk.n_coef))
        for r, i in enumerate(sel):
            for k in range(blk.n_coef):
                A[3 * r : 3 * r + 3, 3 * k : 3 * k + 3] = blk.ref_basis[i, k] * L[i]
        y = np.einsum("nij,nj->ni", L[sel], design.ref_p[sel]).reshape(-1)
        c_dense = np.linalg.lstsq(A, y, rcond=None)[0]
        c_step = start[b].reshape(-1) + np.linalg.solve(normal.V[b], normal.b_c[b])
        np.testing.assert_allclose(c_step, c_dense, rtol=0, atol=1e-5)
        checked += 1
    assert checked >= 2


# (c) ---------------------------------------------------------------------------------------------
def test_a_reference_with_3_m_horizontal_and_30_m_vertical_noise(fleet):
    sc, refs = fleet
    both = solve_batch(_problem(sc, refs))
    flat = solve_batch(
        _problem(
            sc,
            {
                **{k: v for k, v in refs.items() if k != "sigma_up"},
                "sigma": np.full(refs["time"].size, SIGMA_UP),
            },
        )
    )
    truth = sc.truth_vector(both.layout)
    free = both.layout.free
    z = (both.estimate - truth)[free] / both.sigma[free]
    assert np.all(np.isfinite(z)) and np.abs(z).max() < 3.5, np.abs(z).max()
    assert both.chi_square.ok, both.chi_square.text()
    ssq, n = both.chi_square.parts["references"]
    assert 0.6 < ssq / n < 1.3, ssq / n  # the windows absorb a share of the references' residuals
    ratio = both.sigma[free] / flat.sigma[free]
    assert np.all(ratio <= 1.0 + 1e-9), ratio
    assert ratio.min() < 0.8, ratio  # the horizontal information of the reference counts
    # the table of reference residuals: east, north, up whitened, each axis of unit spread
    spread = np.sqrt(np.mean(both.reference_residuals**2, axis=0))
    assert np.all((spread > 0.5) & (spread < 1.3)), spread


# (d) ---------------------------------------------------------------------------------------------
def _files(sc, refs, folder, fmt="csv"):
    write_fleet_tables(folder, sc.plots, sc.navigation, sc.sensors, sc.platforms, refs, fmt)
    return {n: folder / f"{n}.{fmt}" for n in NAMES}


def _read(paths, **kwargs):
    return read_fleet_tables(
        paths["plots"],
        paths["navigation"],
        paths["sensors"],
        paths["platforms"],
        paths["reference"],
        **kwargs,
    )


@pytest.mark.parametrize("fmt", ["csv", "parquet"])
def test_the_file_column_round_trips(fleet, tmp_path, fmt):
    sc, refs = fleet
    refs = {**refs, "sigma_up": refs["sigma_up"].copy()}
    refs["sigma_up"][::7] = np.nan  # empty cells: the same as sigma_m
    paths = _files(sc, refs, tmp_path, fmt)
    frame = pd.read_csv(paths["reference"]) if fmt == "csv" else pd.read_parquet(paths["reference"])
    assert list(frame.columns)[-2:] == ["sigma_m", "sigma_up_m"]
    tables = _read(paths)
    np.testing.assert_array_equal(tables.references["sigma_up"], refs["sigma_up"])
    got = tables.problem().references
    np.testing.assert_array_equal(
        got.sigma_up, np.where(np.isnan(refs["sigma_up"]), refs["sigma"], refs["sigma_up"])
    )
    assert np.array_equal(got.sigma_up[got.sigma_up != SIGMA_UP], got.sigma[got.sigma_up != SIGMA_UP])


@pytest.mark.parametrize(
    "value, code, words",
    [
        ("0", "out_of_range", ["0 m is outside (0, inf] m"]),
        ("-2", "out_of_range", ["-2 m is outside (0, inf] m"]),
        ("-inf", "non_finite", ["-inf m is outside"]),
        ("high", "non_numeric", ["'high' is not a number (m)"]),
    ],
)
def test_bad_sigma_up_cells_name_file_row_column_and_unit(fleet, tmp_path, value, code, words):
    sc, refs = fleet
    paths = _files(sc, refs, tmp_path)
    frame = pd.read_csv(paths["reference"], dtype={"target": str})
    frame["sigma_up_m"] = frame["sigma_up_m"].astype(object)
    frame.loc[5, "sigma_up_m"] = value
    frame.to_csv(paths["reference"], index=False)
    with pytest.raises(ValueError) as err:
        _read(paths)
    text = str(err.value)
    for word in ["reference.csv", "row 5", "'sigma_up_m'", *words]:
        assert word in text, (word, text)
    skipped = _read(paths, on_bad_row="skip")
    assert [(r.row, r.column, r.code) for r in skipped.rejected] == [(5, "sigma_up_m", code)]
    assert skipped.references["time"].size == refs["time"].size - 1


def test_the_table_refuses_a_bad_sigma_up_naming_the_row():
    refs = {
        "target": ["T1", "T1"],
        "time": [0.0, 1.0],
        "x": [6.4e6, 6.4e6],
        "y": [0.0, 0.0],
        "z": [0.0, 0.0],
        "sigma": [3.0, 3.0],
        "sigma_up": [30.0, -1.0],
    }
    with pytest.raises(ValueError, match=r"references row 1: sigma_up -1.0 m of target 'T1' must be > 0"):
        read_references(refs, ["T1"])
    ok = read_references({**refs, "sigma_up": [np.nan, 7.0]}, ["T1"])
    np.testing.assert_array_equal(ok.sigma_up, [3.0, 7.0])
    np.testing.assert_array_equal(ok.subset(np.array([1])).sigma_up, [7.0])
    np.testing.assert_array_equal(ok.subset(np.array([True, False])).sigma_up, [3.0])


# (e) and the other users -------------------------------------------------------------------------
def test_partitioned_solver_equals_solve_batch_with_sigma_up(fleet):
    sc, refs = fleet
    batch = solve_batch(_problem(sc, refs))
    source = TablesSource(sc.plots, sc.sensors, sc.navigation, sc.platforms, refs)
    for partitions in (1, 3):
        assert_same(solve_batch_partitioned(source, partitions=partitions), batch)


def test_the_online_filter_takes_sigma_up(fleet):
    sc, refs = fleet
    flat = {
        **{k: v for k, v in refs.items() if k != "sigma_up"},
        "sigma": np.full(refs["time"].size, SIGMA_UP),
    }
    options = OnlineOptions()
    both = register_online(
        sc.plots, sc.sensors, sc.navigation, sc.platforms, refs, options=options, residuals=False
    )
    wide = register_online(
        sc.plots, sc.sensors, sc.navigation, sc.platforms, flat, options=options, residuals=False
    )
    free = both.layout.free
    truth = sc.truth_vector(both.layout)
    assert np.abs((both.estimate - truth)[free] / both.sigma[free]).max() < 3.5
    assert (
        np.all(both.sigma[free] <= wide.sigma[free] * (1 + 1e-6))
        and (both.sigma[free] < 0.8 * wide.sigma[free]).any()
    )


def test_the_association_gate_takes_the_larger_sigma(fleet):
    sc, refs = fleet
    r = read_references(
        {**refs, "sigma_up": np.where(np.arange(refs["time"].size) % 2, 1.0, SIGMA_UP)},
        [str(refs["target"][0])],
    )
    curves = anchor_curves(None, np.zeros(0), r, BatchOptions(), gap_s=10.0, accel_sigma=1.0)
    np.testing.assert_array_equal(np.sort(curves.ref_sigma), np.sort(np.maximum(r.sigma, r.sigma_up)))
