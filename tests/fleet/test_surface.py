"""Surface targets: targets that move on a surface of known height (ships on the sea; the targets
table's ``surface_alt``, ``sigma_surface``), and references without a height (``sigma_up`` inf).

* the table is read and refused row by row;
* each surface window gets one height constraint per used coefficient, at its Gauss-Legendre
  nodes; the residual is ``(alt_surface - h(p)) / sigma`` with h the geodetic height, checked
  against pymap3d, and the normal equations against central differences of the cost;
* a reference without a height counts 2 values, a surface constraint 1;
* on a bridge log (ARPA range and bearing only, AIS without heights): with the surface the solve
  converges in a few iterations and recovers the radar's errors; without it the run warns that
  the heights are not measured;
* the partitioned archive solver takes the surface too (tables in memory, and a Parquet folder
  through the command): the same estimate as solve_batch.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from registration.fleet import build_problem, solve_batch
from registration.fleet.batch.blocks import make_blocks
from registration.fleet.batch.design import make_design
from registration.fleet.batch.estimate import HEIGHT_WARNING
from registration.fleet.batch.initial import initial_coefficients
from registration.fleet.batch.normal import evaluate, normal_equations, positions
from registration.fleet.data.known_targets import read_surface
from registration.io import read_fleet_tables
from registration.io.nmea import import_nmea
from tests.io.nmea.bridgelog import PLATFORM, simulate_bridge_log


@pytest.fixture(scope="module")
def bridge(tmp_path_factory):
    """A bridge log imported (heading held) and read back as fleet tables, with its targets file."""
    folder = tmp_path_factory.mktemp("surface")
    log = simulate_bridge_log()
    result = import_nmea(
        log.write(folder / "bridge.log"),
        PLATFORM,
        log.sensors,
        platform_priors={"prior_heading_deg": 0.0, "prior_pitch_deg": 0.0, "prior_roll_deg": 0.0},
    )
    written = result.write(folder)
    return log, written


def _labelled(log, written, targets=True):
    """The tables with the simulation's track -> MMSI labels as target ids (the association's answer)."""
    tables = read_fleet_tables(
        written["plots"],
        written["navigation"],
        written["sensors"],
        written["platforms"],
        written["reference"],
        targets=written["targets"] if targets else None,
    )
    plots = dict(tables.plots)
    plots["target"] = np.array([log.track_mmsi.get(str(t), f"T{t}") for t in plots.pop("track")])
    return replace(tables, plots=plots)


# the table -----------------------------------------------------------------------------------------
def test_the_targets_table_is_read_and_refused_row_by_row():
    table = {
        "target": ["A", "B", "C"],
        "surface_alt": [42.0, np.nan, 40.0],
        "sigma_surface": [5.0, np.nan, 2.0],
    }
    surface = read_surface(table)
    alt, sigma = surface.of(["C", "X", "A", "B"])
    np.testing.assert_array_equal(alt, [40.0, np.nan, 42.0, np.nan])
    np.testing.assert_array_equal(sigma, [2.0, np.nan, 5.0, np.nan])
    assert read_surface(None) is None and read_surface({"target": ["A"], "name": ["x"]}) is None
    for bad, words in (
        (dict(table, target=["A", "B", "A"]), "targets row 2: target 'A' is listed again (first in row 0)"),
        (dict(table, sigma_surface=[5.0, np.nan, 0.0]), "targets row 2: target 'C': sigma_surface 0.0 m"),
        (dict(table, sigma_surface=[np.nan, np.nan, 2.0]), "targets row 0: target 'A': sigma_surface nan m"),
        (dict(table, surface_alt=[42.0, np.nan, 2e4]), "targets row 2: target 'C': surface_alt 20000.0 m"),
    ):
        with pytest.raises(ValueError) as err:
            read_surface(bad)
        assert words in str(err.value)


def test_the_targets_file_is_refused_naming_file_row_and_unit(bridge, tmp_path):
    import pandas as pd

    log, written = bridge
    frame = pd.read_csv(written["targets"], dtype={"target": str})
    frame.loc[3, "sigma_surface_m"] = -1.0
    bad = tmp_path / "targets.csv"
    frame.to_csv(bad, index=False)
    with pytest.raises(ValueError) as err:
        read_fleet_tables(
            written["plots"],
            written["navigation"],
            written["sensors"],
            written["platforms"],
            written["reference"],
            targets=bad,
        )
    assert all(w in str(err.value) for w in ("targets.csv", "row 3", "sigma_surface_m", "m"))


# the model -----------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def small(bridge):
    """The first 60 s of the labelled bridge log: its problem and design."""
    log, written = bridge
    tables = _labelled(log, written)
    t0 = tables.plots["time"].min()
    keep = tables.plots["time"] < t0 + 60.0
    plots = {k: np.asarray(v)[keep] for k, v in tables.plots.items()}
    rkeep = tables.references["time"] < t0 + 60.0
    refs = {k: np.asarray(v)[rkeep] for k, v in tables.references.items()}
    problem = build_problem(plots, tables.sensors, tables.navigation, tables.platforms, refs, tables.targets)
    design = make_design(problem, make_blocks(problem, 20.0, 3))
    return problem, design


def test_one_constraint_per_used_coefficient_at_the_gauss_legendre_nodes(small):
    problem, design = small
    blk, surf = design.blocks, design.surface
    assert surf is not None
    on_surface = np.isfinite(problem.surface_of_targets()[0])[blk.block_target]
    per_block = np.bincount(surf.block, minlength=blk.n_blocks)
    np.testing.assert_array_equal(per_block, np.where(on_surface, blk.coef_mask.sum(axis=1), 0))
    for b in np.flatnonzero(on_surface):
        k = int(blk.coef_mask[b].sum())
        tau = np.polynomial.legendre.leggauss(k)[0]
        expected = blk.basis_at(np.full(k, b), blk.block_centre[b] + tau * blk.block_half[b])
        np.testing.assert_allclose(surf.basis[surf.block == b], expected, rtol=0, atol=1e-15)


def test_the_height_residual_against_pymap3d(small):
    pymap3d = pytest.importorskip("pymap3d")
    problem, design = small
    x = np.zeros(problem.layout.n)
    coef = initial_coefficients(design, x)
    coef[:, 0] += np.random.default_rng(1).normal(size=(coef.shape[0], 3)) * 40.0  # off the surface
    ev = evaluate(design, x, coef)
    surf = design.surface
    p = positions(surf.basis, surf.block, coef)
    _, _, h = pymap3d.ecef2geodetic(p[:, 0], p[:, 1], p[:, 2])
    np.testing.assert_allclose(ev.e_surface, (surf.alt - h) * surf.weight, rtol=0, atol=1e-6)
    assert ev.e_surface.std() > 0.5  # the test moved the windows off the surface


def test_surface_normal_equations_against_central_differences_of_the_cost(small):
    problem, design = small
    alone = replace(
        design,
        weight=np.zeros_like(design.weight),
        ref_weight=np.zeros_like(design.ref_weight),
        ref_whiten=None if design.ref_whiten is None else np.zeros_like(design.ref_whiten),
    )
    x = np.zeros(problem.layout.n)
    rng = np.random.default_rng(3)
    coef = (
        initial_coefficients(design, x)
        + rng.normal(size=(design.blocks.n_blocks, design.blocks.n_coef, 3)) * 30.0
    )
    normal = normal_equations(alone, evaluate(alone, x, coef))
    blk = design.blocks
    q = 3 * blk.n_coef
    for b in np.unique(design.surface.block)[:4]:
        grad = np.zeros(q)
        sel = design.surface.block == b
        J = np.zeros((int(sel.sum()), q))
        for j in range(q):
            d = np.zeros(coef.shape)
            d[b] = np.eye(q)[j].reshape(blk.n_coef, 3) * 1.0  # m: heights are smooth at the metre scale
            up, down = evaluate(alone, x, coef + d), evaluate(alone, x, coef - d)
            grad[j] = (up.cost - down.cost) / 2.0
            J[:, j] = (up.e_surface[sel] - down.e_surface[sel]) / 2.0
        np.testing.assert_allclose(normal.b_c[b], -0.5 * grad, rtol=1e-5, atol=1e-9 * np.abs(grad).max())
        # Gauss-Newton: V is J^T J of the whitened height residuals (their own second derivative left out)
        np.testing.assert_allclose(normal.V[b], J.T @ J, rtol=1e-6, atol=1e-9 * np.abs(J.T @ J).max())


def test_values_counted_two_per_reference_without_height_and_one_per_constraint(small):
    from registration.fleet.batch.residuals import chi_square_parts

    problem, design = small
    x = np.zeros(problem.layout.n)
    ev = evaluate(design, x, initial_coefficients(design, x))
    parts = chi_square_parts(design, ev)
    assert np.isinf(problem.references.sigma_up).all()
    assert parts["references"][1] == 2 * design.ref_p.shape[0]
    assert parts["surface"][1] == design.surface.size
    assert ev.cost == pytest.approx(sum(v for v, _ in parts.values()), rel=1e-12)


# the bridge log ------------------------------------------------------------------------------------
def test_with_the_surface_the_radar_errors_come_back_and_without_it_a_warning(bridge):
    log, written = bridge
    c = log.config
    with_surface = solve_batch(_labelled(log, written).problem())
    assert with_surface.converged and with_surface.iterations < 30
    for state, truth in (
        ("RADAR:range_bias", c.range_bias_m),
        ("RADAR:bearing_bias", c.bearing_bias_rad),
        ("RADAR:time_bias", c.clock_offset_s),
    ):
        assert abs(with_surface.value(state) - truth) < 3.5 * with_surface.sigma_of(state), state
    parts = with_surface.chi_square.parts
    assert parts["surface"][0] < 0.01 * parts["surface"][1]  # the heights follow the sea; no measured value
    assert not any("no measured height" in w for w in with_surface.warnings)
    without = solve_batch(_labelled(log, written, targets=False).problem())
    text = [w for w in without.warnings if "no measured height" in w]
    assert len(text) == 1 and "surface_alt_m" in text[0]
    assert text[0].startswith(HEIGHT_WARNING.split("{}")[0])


# the archive path ----------------------------------------------------------------------------------
def test_the_partitioned_solver_takes_the_surface(bridge):
    from registration.fleet.batch.partitioned import solve_batch_partitioned
    from registration.io.fleet.memory import TablesSource
    from tests.fleet.test_archive import assert_same

    log, written = bridge
    tables = _labelled(log, written)
    batch = solve_batch(tables.problem())
    source = TablesSource(
        tables.plots,
        tables.sensors,
        tables.navigation,
        tables.platforms,
        tables.references,
        targets=tables.targets,
    )
    for partitions in (1, 3):
        part = solve_batch_partitioned(source, partitions=partitions)
        assert_same(part, batch)
        assert part.chi_square.parts["surface"][1] == batch.chi_square.parts["surface"][1]
        assert [(r["name"], r["status"]) for r in part.rows()] == [
            (r["name"], r["status"]) for r in batch.rows()
        ]


def test_an_archive_folder_with_a_targets_file_registers_with_the_surface(bridge, tmp_path):
    import pandas as pd

    from registration.cli import main

    log, written = bridge
    tables = _labelled(log, written)
    folder = tmp_path / "archive"
    folder.mkdir()
    for name in ("navigation", "sensors", "platforms", "reference", "targets"):
        frame = pd.read_csv(written[name], dtype={"target": str, "sensor": str, "platform": str, "name": str})
        frame.to_parquet(folder / f"{name}.parquet", index=False)
    plots = pd.read_csv(written["plots"], dtype={"track": str, "sensor": str})
    plots["target"] = [log.track_mmsi.get(t, f"T{t}") for t in plots.pop("track")]
    plots.to_parquet(folder / "plots.parquet", index=False)
    out = tmp_path / "out"
    assert (
        main(
            [
                "fleet",
                "register",
                "--tables",
                str(folder),
                "--partition-s",
                "200",
                "--out",
                str(out),
                "--no-plots",
            ]
        )
        == 0
    )
    est = pd.read_csv(out / "estimates.csv").set_index(["object", "state"])
    batch = solve_batch(tables.problem())
    for name in ("range_bias", "time_bias"):  # m, s: file units are SI here
        assert est.loc[("RADAR", name), "estimate"] == pytest.approx(batch.value(f"RADAR:{name}"), rel=1e-9)
    summary = __import__("json").loads((out / "summary.json").read_text())
    assert "surface" in summary["chi_square"]["parts"]
