"""The azimuth eccentricity and the sensor channels (``prior_eccentricity``, ``channel_of``): the
generated eccentric model against its definition, the layout's shared states, the switches and bad
input of the sensors table, the fleet files, and runs without the new columns evaluating none of
the new generated functions. The Monte Carlo is test_channels_montecarlo.py."""

from __future__ import annotations

import numpy as np
import pymap3d
import pytest

from registration import _codegen
from registration._generated import api as generated
from registration.fleet import build_problem, solve_batch
from registration.fleet.simulation.channels import atc_channel_scenario
from registration.io.fleet.reading.read import read_fleet_tables
from registration.io.fleet.write import write_fleet_tables

LAT, LON, ALT = np.radians(46.0), np.radians(6.5), 400.0
Z3, Z6 = np.zeros(3), np.zeros(6)


def _target(east, north, up):
    return np.array(pymap3d.enu2ecef(east, north, up, np.degrees(LAT), np.degrees(LON), ALT))


def _residual_ecc(p, ecc, meas, bias=Z3):
    """fleet_residual_ecc for a level, north-facing site at (LAT, LON, ALT)."""
    return generated.fleet_residual_ecc(
        p_ecef=p,
        v_ecef=Z3,
        lat=LAT,
        lon=LON,
        alt=ALT,
        heading=0.0,
        pitch=0.0,
        roll=0.0,
        nav_rate=Z6,
        att_err=Z3,
        bias=bias,
        gain=0.0,
        dt=0.0,
        pos_err=Z3,
        ecc=ecc,
        lever_deck=Z3,
        r=meas[0],
        q=meas[1],
        e=meas[2],
    )


def test_eccentricity_is_a_sin_q_plus_b_cos_q_at_the_measured_bearing():
    """A target at true bearing 50 deg: a plot reporting q with q = 50 deg + bias + a sin q + b cos q
    has a zero bearing residual; the Jacobian columns are -sin q and -cos q."""
    p = _target(30e3 * np.sin(np.radians(50.0)), 30e3 * np.cos(np.radians(50.0)), 2000.0)
    a, b, bias = np.radians(0.3), np.radians(-0.2), np.radians(0.1)
    true = generated.fleet_residual(
        p_ecef=p,
        lat=LAT,
        lon=LON,
        alt=ALT,
        heading=0.0,
        pitch=0.0,
        roll=0.0,
        att_err=Z3,
        bias=Z3,
        lever_deck=Z3,
        r=0.0,
        q=0.0,
        e=0.0,
    ).plot[0]
    q = true[1]
    for _ in range(20):
        q = true[1] + bias + a * np.sin(q) + b * np.cos(q)
    out = _residual_ecc(p, np.array([a, b]), [true[0], q, true[2]], bias=np.array([0.0, bias, 0.0]))
    assert np.abs(out.residual[0]).max() < 1e-9
    J = out.J[0]
    np.testing.assert_allclose(J[:, 14:16], [[0, 0], [-np.sin(q), -np.cos(q)], [0, 0]], atol=1e-15)
    plain = _residual_ecc(p, Z3[:2], [true[0], q, true[2]], bias=np.array([0.0, bias, 0.0]))
    assert abs(plain.residual[0][1] - (a * np.sin(q) + b * np.cos(q))) < 1e-12


def test_plot2ecef_ecc_inverts_the_residual():
    rng = np.random.default_rng(4)
    n = 200
    meas = [rng.uniform(5e3, 2e5, n), rng.uniform(-3.1, 3.1, n), rng.uniform(-0.2, 0.5, n)]
    ecc, bias = rng.uniform(-0.01, 0.01, (n, 2)), rng.uniform(-0.02, 0.02, (n, 3)) * [1e4, 1, 1]
    kw = dict(lat=LAT, lon=LON, alt=ALT, heading=0.3, pitch=0.01, roll=-0.02, att_err=Z3, bias=bias)
    kw.update(gain=1e-4, pos_err=np.array([5.0, -3.0, 2.0]), ecc=ecc, lever_deck=Z3)
    p = generated.fleet_plot2ecef_ecc(**kw, r=meas[0], q=meas[1], e=meas[2]).p_ecef
    out = generated.fleet_residual_ecc(
        p_ecef=p, v_ecef=Z3, nav_rate=Z6, dt=0.0, **kw, r=meas[0], q=meas[1], e=meas[2]
    )
    assert np.abs(out.residual[:, 0]).max() < 1e-6 and np.abs(out.residual[:, 1:]).max() < 1e-11


@pytest.fixture(scope="module")
def scenario():
    return atc_channel_scenario(11, duration_s=100.0)


def _with(sensors: dict, **columns) -> dict:
    out = dict(sensors)
    out.update(columns)
    return {k: v for k, v in out.items() if v is not None}


def test_the_channel_shares_its_sensors_states(scenario):
    sensors = _with(
        scenario.sensors,
        prior_time_bias=np.full(4, np.inf),
        prior_position=np.full(4, 50.0),
        prior_range_gain=np.full(4, 1e-3),
    )
    layout = build_problem(scenario.plots, sensors, scenario.navigation, scenario.platforms).layout
    assert layout.width == 13
    own = [n for n in layout.names if n.startswith("R2.psr:")]
    assert own == ["R2.psr:range_bias", "R2.psr:bearing_bias", "R2.psr:elevation_bias", "R2.psr:range_gain"]
    r2, psr = 1, 3  # table order: R1, R2, R3, R2.psr
    np.testing.assert_array_equal(layout.extended_index[psr, 1:], layout.extended_index[r2, 1:])
    assert layout.extended_index[psr, 0] != layout.extended_index[r2, 0]  # its own range gain
    np.testing.assert_array_equal(layout.eccentricity_index[psr], layout.eccentricity_index[r2])
    states = layout.sensor_states(np.array([r2, psr]), np.array([0, 1, 2, 1]))
    np.testing.assert_array_equal(
        states[0, [0, 1, 2, 7, 8, 9, 10, 11, 12]], states[1, [0, 1, 2, 7, 8, 9, 10, 11, 12]]
    )
    assert (
        layout.labels[layout.index("R1:eccentricity_cos")] == "azimuth eccentricity (cos term) of sensor R1"
    )


def test_the_columns_switch_the_states(scenario):
    base = build_problem(
        scenario.plots,
        _with(scenario.sensors, prior_eccentricity=None),
        scenario.navigation,
        scenario.platforms,
    ).layout
    assert base.width == 6 and not any("eccentricity" in n for n in base.names)
    held = _with(scenario.sensors, prior_eccentricity=np.zeros(4))
    layout = build_problem(scenario.plots, held, scenario.navigation, scenario.platforms).layout
    assert layout.width == 13 and layout.prior_sigma[layout.index("R1:eccentricity_sin")] == 0.0
    one = build_problem(
        scenario.plots,
        _with(scenario.sensors, channel_of=None, prior_eccentricity=None),
        scenario.navigation,
        scenario.platforms,
    ).layout
    assert "R2.psr:range_bias" in one.names and one.width == 6  # a sensor of its own, sharing nothing


@pytest.mark.parametrize(
    "column, value, words",
    [
        ("channel_of", "R9", "sensors row 3: channel_of of sensor 'R2.psr' is 'R9'; expected the id"),
        ("channel_of", "R2.psr", "sensors row 3: channel_of of sensor 'R2.psr' is 'R2.psr'"),
        ("prior_eccentricity", -1.0, "sensors row 3: prior_eccentricity of sensor 'R2.psr' is -1.0"),
        ("prior_eccentricity", 0.5, "sensors row 3: prior_eccentricity of sensor 'R2.psr' is 0.5"),
    ],
)
def test_bad_columns_name_the_row(scenario, column, value, words):
    sensors = dict(scenario.sensors)
    sensors[column] = np.where(sensors["sensor"] == "R2.psr", value, sensors[column]).astype(
        sensors[column].dtype if column != "channel_of" else object
    )
    with pytest.raises(ValueError, match=words.replace(".", r"\.").replace("(", r"\(")):
        build_problem(scenario.plots, sensors, scenario.navigation, scenario.platforms)


def test_a_chain_or_another_antenna_is_refused(scenario):
    chain = dict(scenario.sensors, channel_of=np.array(["", "R1", "", "R2"], dtype=object))
    with pytest.raises(
        ValueError, match="sensors row 3: channel_of of sensor 'R2.psr' names 'R2', itself a channel"
    ):
        build_problem(scenario.plots, chain, scenario.navigation, scenario.platforms)
    moved = dict(scenario.sensors, lever_z=np.array([10.0, 12.0, 8.0, 13.0]))
    with pytest.raises(
        ValueError, match="sensors row 3: sensor 'R2.psr' is a channel of 'R2' but its platform"
    ):
        build_problem(scenario.plots, moved, scenario.navigation, scenario.platforms)


def test_the_files_carry_the_columns(scenario, tmp_path):
    write_fleet_tables(tmp_path, scenario.plots, scenario.navigation, scenario.sensors, scenario.platforms)
    import pandas as pd

    frame = pd.read_csv(tmp_path / "sensors.csv", keep_default_na=False)
    assert frame["channel_of"].tolist() == ["", "", "", "R2"]
    assert frame["prior_eccentricity_deg"].astype(str).tolist() == ["", "0", "0", "0"]
    tables = read_fleet_tables(
        tmp_path / "plots.csv",
        tmp_path / "navigation.csv",
        tmp_path / "sensors.csv",
        tmp_path / "platforms.csv",
    )
    layout = tables.problem().layout
    reference = scenario.problem().layout
    assert layout.names == reference.names
    np.testing.assert_array_equal(layout.prior_sigma, reference.prior_sigma)
    bad = (tmp_path / "sensors.csv").read_text().replace('"R2"\n', '"R7"\n')
    (tmp_path / "sensors.csv").write_text(bad)
    with pytest.raises(ValueError, match=r"sensors\.csv: row 3, column 'channel_of': .*'R7'"):
        read_fleet_tables(
            tmp_path / "plots.csv",
            tmp_path / "navigation.csv",
            tmp_path / "sensors.csv",
            tmp_path / "platforms.csv",
        ).problem()


def test_without_the_columns_no_new_function_is_evaluated(scenario, monkeypatch):
    called = []
    original = _codegen.get

    def spy(name):
        called.append(name)
        return original(name)

    monkeypatch.setattr(_codegen, "get", spy)
    monkeypatch.setattr(generated, "get", spy)
    sensors = _with(scenario.sensors, prior_eccentricity=None, channel_of=None)
    solve_batch(
        build_problem(scenario.plots, sensors, scenario.navigation, scenario.platforms, scenario.references)
    )
    assert called and not any("_ecc" in n for n in called)
    called.clear()
    solve_batch(scenario.problem())  # no extended errors: the eccentric rows without them
    assert "fleet_rows_ecc3_4" in called and "fleet_rows_ecc_4" not in called
    called.clear()
    gains = _with(scenario.sensors, prior_range_gain=np.full(4, 1e-3))
    solve_batch(
        build_problem(scenario.plots, gains, scenario.navigation, scenario.platforms, scenario.references)
    )
    assert "fleet_rows_ecc_4" in called and "fleet_rows_ecc3_4" not in called


def test_primary_only_plots_without_ids_are_associated(scenario):
    """The channel's plots carry no target id (primary only, as imported): the association labels
    them, through the eccentric model, and the registration finds the truth."""
    from registration.fleet import associate_and_register

    plots = dict(scenario.plots)
    psr = plots["sensor"] == "R2.psr"
    plots["target"] = np.where(psr, "", plots["target"].astype(object)).astype(str)
    result = associate_and_register(
        plots, scenario.sensors, scenario.navigation, scenario.platforms, scenario.references
    )
    assert result.converged and result.problem.layout.width == 13
    labelled = result.labels[psr] != ""
    assert labelled.mean() > 0.9
    batch = result.batch
    for name in ("R1:eccentricity_sin", "R1:eccentricity_cos", "R2.psr:range_bias", "R2.psr:bearing_bias"):
        i = batch.layout.index(name)
        assert abs(batch.estimate[i] - scenario.truth_state[name]) < 4 * batch.sigma[i], name
