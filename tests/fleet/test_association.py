"""Association of plots without target ids across asynchronous sensors, jointly with the
registration (registration.fleet.association), on simulated data with known truth."""

import numpy as np
import pytest

from registration.fleet import (AssociationOptions, associate_and_register, association_scenario, association_scores,
                                build_problem, solve_batch)

DURATION_S = 120.0


def _run(sim, options=None):
    sc = sim.scenario
    return associate_and_register(sim.plots, sc.sensors, sc.navigation, sc.platforms, options=options)


@pytest.fixture(scope="module")
def easy():
    sim = association_scenario(5, angle_bias=np.radians(2.0), p_missed=0.0, clutter_per_scan=0.0,
                               duration_s=DURATION_S, seed=3)
    return sim, _run(sim)


def test_sensors_are_asynchronous(easy):
    sim, _ = easy
    t, s = sim.plots["time"], sim.plots["sensor"]
    for sid in np.unique(s):
        assert not np.isin(t[s == sid], t[s != sid]).any(), sid


def test_easy_case_is_associated_without_error(easy):
    sim, result = easy
    scores = association_scores(result.labels, sim.true_target)
    assert scores["error_rate"] < 0.005
    assert scores["unassociated_rate"] < 0.05
    assert result.n_targets >= 5
    assert result.converged


def test_easy_case_registers_like_the_true_ids(easy):
    sim, result = easy
    sc = sim.scenario
    base = solve_batch(build_problem(sim.labelled_plots, sc.sensors, sc.navigation, sc.platforms))
    free = base.layout.free
    assert result.batch.layout.names == base.layout.names
    diff = np.abs(result.batch.estimate - base.estimate)[free] / base.sigma[free]
    assert diff.max() < 0.5
    truth = sc.truth_vector(base.layout)
    assert np.all(np.abs(result.batch.estimate - truth)[free] < 5 * result.batch.sigma[free])


def test_clutter_and_misses():
    sim = association_scenario(5, angle_bias=np.radians(2.0), p_missed=0.1, clutter_per_scan=2.0,
                               duration_s=DURATION_S, seed=4)
    result = _run(sim)
    scores = association_scores(result.labels, sim.true_target)
    clutter = np.flatnonzero(sim.true_target == "")
    assert clutter.size > 300
    assert scores["clutter_associated"] < 0.01
    assert scores["error_rate"] < 0.01
    assert scores["unassociated_rate"] < 0.1
    assert np.isin(clutter, result.unassociated_rows).mean() > 0.99
    assert result.n_clutter >= 0.99 * clutter.size


def test_reassociation_improves_a_5_degree_case():
    """20 targets (crossing pairs), angle biases of 5 deg: the first pass, under the starting
    covariance, pairs more plots wrongly than the passes under the estimate that follow."""
    sim = association_scenario(20, crossing=True, angle_bias=np.radians(5.0), p_missed=0.1, clutter_per_scan=1.0,
                               duration_s=DURATION_S, seed=3)
    once = _run(sim, AssociationOptions(max_iterations=1))
    again = _run(sim)
    assert once.iterations == 1 and again.iterations > 1 and again.changes[0] > 0
    first = association_scores(once.labels, sim.true_target)["error_rate"]
    final = association_scores(again.labels, sim.true_target)["error_rate"]
    assert final < first
    assert final < 0.01


def test_unassociated_plots_are_reported():
    sim = association_scenario(5, angle_bias=np.radians(2.0), p_missed=0.0, clutter_per_scan=0.5,
                               duration_s=DURATION_S, seed=5)
    only_one = (sim.true_target == "T1") & (sim.plots["sensor"] != "A-3D")  # T1 left to A-3D alone
    keep = ~only_one
    sim.plots = {k: v[keep] for k, v in sim.plots.items()}
    sim.true_target = sim.true_target[keep]
    result = _run(sim)
    lone = np.flatnonzero(sim.true_target == "T1")
    assert np.all(result.labels[lone] == "")
    assert np.isin(lone, result.unassociated_rows).all()
    assert result.n_unconfirmed >= lone.size - 10
    np.testing.assert_array_equal(result.unassociated_rows, np.flatnonzero(result.labels == ""))
    assert sum(result.unassociated_by_sensor.values()) == result.unassociated_rows.size
    assert result.unassociated_by_sensor["A-3D"] >= lone.size
    assert result.n_clutter + result.n_unconfirmed == result.unassociated_rows.size
    assert np.all(result.batch.plot_target[result.unassociated_rows] == "")


def test_a_target_column_is_ignored(easy):
    sim, result = easy
    sc = sim.scenario
    plots = dict(sim.plots, target=np.full(sim.plots["time"].size, "same"))
    again = associate_and_register(plots, sc.sensors, sc.navigation, sc.platforms)
    np.testing.assert_array_equal(again.labels, result.labels)


def test_bad_input_is_refused_clearly(easy):
    sim, _ = easy
    sc = sim.scenario
    empty = {k: v[:0] for k, v in sim.plots.items()}
    with pytest.raises(ValueError, match="no plots"):
        associate_and_register(empty, sc.sensors, sc.navigation, sc.platforms)
    unknown = dict(sim.plots, sensor=sim.plots["sensor"].astype(object))
    unknown["sensor"][7] = "Z-9"
    with pytest.raises(ValueError, match=r"plots row 7: unknown sensor 'Z-9'"):
        associate_and_register(unknown, sc.sensors, sc.navigation, sc.platforms)
    one = {k: v[sim.plots["sensor"] == "B-3D"] for k, v in sim.plots.items()}
    with pytest.raises(ValueError, match="at least two sensors.*'B-3D'"):
        associate_and_register(one, sc.sensors, sc.navigation, sc.platforms)
    with pytest.raises(ValueError, match="references"):
        associate_and_register(sim.plots, sc.sensors, sc.navigation, sc.platforms, references={"target": ["T1"]})
    with pytest.raises(ValueError, match="gate_probability"):
        AssociationOptions(gate_probability=1.5)
    with pytest.raises(ValueError, match="plots: missing column 'sensor'"):
        associate_and_register({"time": sim.plots["time"]}, sc.sensors, sc.navigation, sc.platforms)
