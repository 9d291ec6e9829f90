"""Mode C / Mode S flight levels as heights: the acceptance scenario (tests/io/asterix/atc.py) with
flight levels that are pressure altitudes under ISA + 12 K and QNH 1025 hPa, encoded by
libasterix, through ``registration import asterix`` and ``fleet register --tables``. The aircraft
with ADS-B give the relation of flight level to height; the Mode S and Mode A/C aircraft without
ADS-B then have measured heights, the solver converges, and every error comes back within 3.5
sigma. Without ADS-B flight levels the heights are the ISA's, sharing one offset state: it comes
back within 3.5 sigma of the day's, and so do the errors. Seeds 21 to 24 were not used while
building either (seed 3 was)."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest

from registration.cli import main
from registration.core.atmosphere import pressure_altitude2height
from registration.fleet.batch.estimate import HEIGHT_WARNING
from registration.io.asterix.tables.flightlevels import learn_relation, offset_prior_m
from tests.io.asterix.atc import GEOID_M, atc_truth, encode_atc

DAY = (12.0, 102500.0)  # ISA + 12 K, QNH 1025 hPa
Z_LIMIT = 3.5


def _truth_offset(fl: float) -> float:
    hp = fl * 30.48
    return float(pressure_altitude2height(hp, *DAY)) + GEOID_M - hp


def _run(tmp_path, seed: int, adsb_levels: bool = True):
    truth = atc_truth(seed, 300.0, flight_levels=DAY)
    if not adsb_levels:
        del truth.adsb["fl_raw"]
    rec = encode_atc(truth.plots, truth.adsb, truth.sites, truth.date, truth.scans)
    (tmp_path / "atc.ast").write_bytes(rec.raw())
    truth.sites.to_csv(tmp_path / "SITES.csv", index=False)
    tables, out = tmp_path / "tables", tmp_path / "out"
    argv = ["import", "asterix", str(tmp_path / "atc.ast"), "--sites", str(tmp_path / "SITES.csv")]
    assert main([*argv, "--out", str(tables), "--date", truth.date.isoformat()]) == 0
    summary = json.loads((tables / "import_summary.json").read_text())
    return truth, tables, out, summary


@pytest.mark.parametrize("seed", [21, 22])
def test_flight_levels_give_heights_and_the_registration_converges(tmp_path, capsys, seed):
    truth, tables, out, summary = _run(tmp_path, seed)
    levels = summary["flight_levels"]
    relation = levels["relation"]
    assert relation["aircraft"] == 12 and relation["reports"] > 3000
    for name, offset in relation["height_minus_pressure_altitude_m"].items():
        assert abs(offset - _truth_offset(float(name[2:]))) < 5.0, (name, offset)
    assert sorted(levels["targets_with_heights"]) == sorted(
        {f"{0x400000 + 0x1234 * j:06X}" for j in (12, 13)}
        | {f"A{0o4000 + 0o11 * j:04o}" for j in (14, 15, 16)}
    )
    reference = pd.read_csv(tables / "reference.csv")
    heights = reference[np.isinf(reference["sigma_m"])]
    assert len(heights) == levels["heights_written"] > 500
    assert "by the relation learned from" in capsys.readouterr().out  # the import says what it learned
    assert main(["fleet", "register", "--tables", str(tables), "--out", str(out), "--no-plots"]) == 0
    printed = capsys.readouterr().out
    assert "converged: True" in printed
    assert HEIGHT_WARNING.split("{}")[1].strip() not in printed  # "targets have no measured height"
    est = pd.read_csv(out / "estimates.csv")
    for name, value in truth.truth.items():
        obj, state = name.split(":")
        row = est[(est["object"] == obj) & (est["state"] == state)].iloc[0]
        k = np.degrees(1.0) if row["unit"] == "deg" else 1.0
        assert abs(row["estimate"] - value * k) <= Z_LIMIT * row["sigma"], (name, row.to_dict(), value)


@pytest.mark.parametrize("seed", [23, 24])
def test_without_adsb_flight_levels_the_heights_share_an_offset_state_with_its_prior(tmp_path, capsys, seed):
    truth, tables, out, summary = _run(tmp_path, seed, adsb_levels=False)
    levels = summary["flight_levels"]
    assert levels["relation"] is None and levels["heights_written"] > 500
    offset = levels["height_offset"]
    hp0 = offset["reference_pressure_altitude_m"]
    assert offset["reference_flight_level"] == pytest.approx(hp0 / 30.48, abs=0.01)
    assert offset["prior_sigma_m"] == pytest.approx(offset_prior_m(hp0), abs=0.05)
    reference = pd.read_csv(tables / "reference.csv")
    heights = reference[np.isfinite(reference["height_offset_prior_m"])]
    assert len(heights) == levels["heights_written"] and np.isinf(heights["sigma_m"]).all()
    assert "sharing one offset state" in capsys.readouterr().out
    assert main(["fleet", "register", "--tables", str(tables), "--out", str(out), "--no-plots"]) == 0
    printed = capsys.readouterr().out
    assert "converged: True" in printed
    assert HEIGHT_WARNING.split("{}")[1].strip() not in printed
    est = pd.read_csv(out / "estimates.csv")
    row = est[(est["object"] == "flight_levels") & (est["state"] == "height_offset")].iloc[0]
    # the day's offset at hp0: ISA + 12 K, QNH 1025 hPa and the geoid, less the ISA's
    true_offset = float(pressure_altitude2height(hp0, *DAY) + GEOID_M - pressure_altitude2height(hp0))
    assert row["sigma"] < 0.2 * offset["prior_sigma_m"]  # the plots determine it, not the prior
    assert abs(row["estimate"] - true_offset) <= Z_LIMIT * row["sigma"], (row.to_dict(), true_offset)
    for name, value in truth.truth.items():
        obj, state = name.split(":")
        r = est[(est["object"] == obj) & (est["state"] == state)].iloc[0]
        k = np.degrees(1.0) if r["unit"] == "deg" else 1.0
        assert abs(r["estimate"] - value * k) <= Z_LIMIT * r["sigma"], (name, r.to_dict(), value)


def test_the_relation_follows_the_atmosphere_and_sets_outliers_aside():
    rng = np.random.default_rng(5)
    hp = rng.uniform(2000.0, 11500.0, 4000)
    h = pressure_altitude2height(hp, *DAY) + GEOID_M + rng.normal(0.0, 8.0, hp.size)
    h[:20] += 2000.0  # a wrong geometric height now and then
    rel = learn_relation(hp, h, np.repeat(np.arange(40), 100).astype(str))
    assert rel is not None and rel.outliers == 20 and rel.coef.size == 4 and rel.aircraft == 40
    grid = np.linspace(2500.0, 11000.0, 30)
    truth = pressure_altitude2height(grid, *DAY) + GEOID_M
    assert np.abs(rel.height(grid) - truth).max() < 4.0
    assert 7.5 < rel.sigma_m < 9.0
    assert learn_relation(hp[:9], h[:9], np.zeros(9).astype(str)) is None


def test_a_height_only_reference_is_read_and_both_sigmas_inf_is_an_error():
    from registration.fleet.data.known_targets import read_references

    table = {
        "target": np.array(["A", "A"]),
        "time": np.array([0.0, 1.0]),
        "lat": np.radians([45.0, 45.0]),
        "lon": np.radians([5.0, 5.0]),
        "alt": np.array([9000.0, 9010.0]),
        "sigma": np.array([np.inf, np.inf]),
        "sigma_up": np.array([20.0, 20.0]),
    }
    refs = read_references(table, ["A"])
    assert np.isinf(refs.sigma).all() and (refs.up_sigma == 20.0).all()
    table["sigma_up"] = np.array([20.0, np.inf])
    with pytest.raises(
        ValueError, match="references row 1: sigma_up inf m of target .A. must be > 0, and fin"
    ):
        read_references(table, ["A"])


def test_the_offset_terms_are_the_derivatives_of_the_cost(tmp_path):
    """The normal equations' offset terms (b_x of the offset, the blocks' coupling H: the last column of
    each block's coupling, the offset being every block's last local state) against central
    differences of the cost and of b_c in the offset, at a point off the optimum."""
    from registration.fleet.batch.blocks import make_blocks
    from registration.fleet.batch.design import make_design
    from registration.fleet.batch.normal import evaluate, normal_equations
    from registration.io.fleet.reading.read import read_fleet_tables

    truth = atc_truth(25, 60.0, flight_levels=DAY)
    del truth.adsb["fl_raw"]
    rec = encode_atc(truth.plots, truth.adsb, truth.sites, truth.date, truth.scans)
    (tmp_path / "atc.ast").write_bytes(rec.raw())
    from registration.io.asterix import import_asterix

    tables = import_asterix(tmp_path / "atc.ast", truth.sites, date=truth.date).tables
    plots = tables["plots"][tables["plots"]["target"] != ""]
    for name, frame in {**tables, "plots": plots}.items():
        frame.to_csv(tmp_path / f"{name}.csv", index=False)
    paths = [tmp_path / f"{n}.csv" for n in ("plots", "navigation", "sensors", "platforms", "reference")]
    problem = read_fleet_tables(*paths).problem()
    k = problem.layout.index("flight_levels:height_offset")
    design = make_design(problem, make_blocks(problem, 20.0, 3))
    rng = np.random.default_rng(1)
    coef0 = rng.normal(0.0, 1.0, (design.blocks.n_blocks, design.blocks.n_coef, 3))
    from registration.fleet.batch.initial import initial_coefficients

    coef = initial_coefficients(design) + coef0 * 50.0
    x = np.zeros(problem.layout.n)
    x[k] = 120.0
    normal = normal_equations(design, evaluate(design, x, coef))
    h = 1.0
    lo, hi = x.copy(), x.copy()
    lo[k] -= h
    hi[k] += h
    ev_lo, ev_hi = evaluate(design, lo, coef), evaluate(design, hi, coef)
    assert normal.b_x[k] == pytest.approx(-(ev_hi.cost - ev_lo.cost) / (4 * h), rel=1e-6)
    b_lo, b_hi = normal_equations(design, ev_lo).b_c, normal_equations(design, ev_hi).b_c
    assert np.all(design.blocks.local_state[:, -1] == k)
    H = normal.W[:, :, -1]
    assert np.abs(H).max() > 0
    np.testing.assert_allclose(H, -(b_hi - b_lo) / (2 * h), atol=1e-9 * np.abs(H).max())
