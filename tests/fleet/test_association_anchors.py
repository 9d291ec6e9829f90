"""Anchors: reference targets (AIS, ADS-B) and target ids given for some rows, with plots and
sensor tracks that carry none, on draws the association was not tuned on (seeds written down before
any run).

* one ship, one 2-D ARPA radar with track numbers, AIS for 11 of 14 vessels (a bridge log);
* the same with a track number reused for another vessel after a gap;
* three shore 2-D radars with range bias, gain, bearing bias and clock offset; Mode S addresses,
  Mode A codes and no ids at all; ADS-B for most Mode S aircraft (an ATC recording);
* a rolling fleet whose plots carry no ids at all, with one aircraft's ADS-B: the reference id
  carries over to its plots.

Criteria as in test_association_robust.py: identifiable states and sums within 3.5 sigma of the truth,
sigma within 1.3 times that of the registration with true ids, chi-square within its 99.9 % band, no
wrong joins.
"""

import numpy as np
import pytest

from registration.fleet import associate_and_register, build_problem, solve_batch
from registration.fleet.association.simulated.fleets import (
    atc_fleet,
    registration_scores,
    rolling_fleet,
    vessel_fleet,
)


def _wrong(labels, truth) -> int:
    return int(np.count_nonzero((labels != "") & (labels != truth)))


@pytest.fixture(scope="module")
def bridge_log():
    sim, refs = vessel_fleet(31, duration_s=600.0)
    sc = sim.scenario
    result = associate_and_register(sim.plots, sc.sensors, sc.navigation, sc.platforms, refs)
    ais = np.isin(sim.true_target, np.unique(refs["target"]))
    plots = {k: v[ais] for k, v in sim.plots.items() if k != "track"}
    plots["target"] = sim.true_target[ais]
    base = solve_batch(build_problem(plots, sc.sensors, sc.navigation, sc.platforms, refs))
    return sim, refs, result, base


def test_single_2d_radar_tracks_join_the_ais_vessels(bridge_log):
    sim, refs, result, _ = bridge_log
    ais = np.isin(sim.true_target, np.unique(refs["target"]))
    assert _wrong(result.labels, sim.true_target) == 0
    assert not (result.labels[~ais] != "").any()  # the vessels without AIS stay unassociated
    assert np.mean(result.labels[ais] != "") > 0.95
    assert result.n_targets == 11
    assert set(result.reasons[~ais]) <= {"no_match", "no_anchor"}


def test_single_2d_radar_registers_like_the_true_ids(bridge_log):
    sim, _, result, base = bridge_log
    scores = registration_scores(result.batch, base, sim.scenario.truth_state)
    assert scores["vs_truth"] < 3.5 and scores["sigma_ratio"] < 1.3 and scores["chi2_ok"], scores
    for name in ("ARPA:range_bias", "ARPA:time_bias"):
        assert result.batch.status[name] == "identifiable"
    truth = sim.scenario.truth_state
    value, sigma = result.batch.combination({"A:heading_error": 1, "ARPA:bearing_bias": 1})
    assert abs(value - truth["A:heading_error"] - truth["ARPA:bearing_bias"]) < 3.5 * sigma


def test_a_track_number_reused_after_a_gap_is_split_with_a_note():
    sim, refs = vessel_fleet(32, duration_s=400.0)
    sc = sim.scenario
    plots = dict(sim.plots)
    truth, t = sim.true_target, plots["time"]
    first, second = "V2", "V5"  # V2's number goes to V5 once V2's track ends; both report AIS
    number = plots["track"][truth == first][0]
    keep = ~(((truth == first) & (t > 180.0)) | ((truth == second) & (t < 260.0)))
    plots = {k: v[keep] for k, v in plots.items()}
    truth = truth[keep]
    plots["track"] = np.where(truth == second, number, plots["track"])
    result = associate_and_register(plots, sc.sensors, sc.navigation, sc.platforms, refs)
    assert _wrong(result.labels, truth) == 0
    for v in (first, second):
        assert np.mean(result.labels[truth == v] == v) > 0.9
    assert any(f"track {number}:" in n and first in n and second in n for n in result.notes), result.notes


@pytest.fixture(scope="module")
def atc():
    sim, refs = atc_fleet(33)
    sc = sim.scenario
    result = associate_and_register(sim.plots, sc.sensors, sc.navigation, sc.platforms, refs)
    real = sim.true_target != ""
    plots = {k: v[real] for k, v in sim.plots.items()}
    plots["target"] = sim.true_target[real]
    base = solve_batch(build_problem(plots, sc.sensors, sc.navigation, sc.platforms, refs))
    return sim, refs, result, base


def test_2d_radars_with_mode_s_mode_a_and_primary_plots(atc):
    sim, refs, result, _ = atc
    given = sim.plots["target"] != ""
    assert np.all(result.labels[given] == sim.plots["target"][given])  # ids given are kept
    assert result.given[given].all() and not result.given[~given].any()
    assert _wrong(result.labels, sim.true_target) == 0
    ided = np.isin(sim.true_target, np.unique(sim.plots["target"][given]))
    assert np.mean(result.labels[~given & ided] != "") > 0.6  # primary plots of aircraft with ids join them
    never = ~ided & (sim.true_target != "")  # aircraft with no id at all: only 2-D radars see them
    assert not (result.labels[never] != "").any()
    assert set(result.reasons[never]) <= {"no_match", "no_anchor", "clutter", "short_track", "ambiguous"}


def test_2d_radars_register_like_the_true_ids(atc):
    sim, _, result, base = atc
    scores = registration_scores(result.batch, base, sim.scenario.truth_state)
    assert scores["vs_truth"] < 3.5 and scores["sigma_ratio"] < 1.3 and scores["chi2_ok"], scores


def test_reference_id_carries_over_to_plots_without_ids():
    from registration.fleet.association.simulated.fleets import reference_table

    sim = rolling_fleet(34, duration_s=300.0, clutter_share=0.05)
    sc = sim.scenario
    refs = reference_table(
        sc, ["T2"], np.random.default_rng(34), period_s=1.0, sigma_m=20.0, duration_s=300.0
    )
    refs["target"] = np.full(refs["target"].size, "ADSB-4CA2B1")
    result = associate_and_register(sim.plots, sc.sensors, sc.navigation, sc.platforms, refs)
    mine = sim.true_target == "T2"
    assert np.mean(result.labels[mine] == "ADSB-4CA2B1") > 0.95
    assert not np.any((result.labels == "ADSB-4CA2B1") & ~mine)
    assert result.batch.references_given > 0 and result.batch.reference_target.size > 0
