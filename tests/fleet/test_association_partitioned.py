"""The association out of core (registration.fleet.association.partitioned): partitions with
overlaps give the labels of the association in memory, targets confirmed without an anchor keep one
name across the cuts, and ``fleet register --partition-s`` registers plots without ids."""

import json

import numpy as np
import pandas as pd
import pytest

from registration.cli import main
from registration.fleet import AssociationOptions, associate_and_register, association_scenario
from registration.fleet.association.partitioned import associate_partitioned
from registration.fleet.association.partitioned.naming import merge_labels
from registration.fleet.association.partitioned.parts import make_association_plan
from registration.fleet.association.partitioned.task import PartLabels
from registration.io import write_fleet_tables
from registration.io.fleet.memory import TablesSource


def _scenario(seed: int, ids_share: float = 0.0):
    """600 s of the association scenario (3-D and 2-D radars, clutter); the plots of a random
    share ``ids_share`` of the targets carry their id."""
    sim = association_scenario(5, duration_s=600.0, seed=seed)
    plots = dict(sim.plots)
    if ids_share:
        names = np.unique(sim.true_target[sim.true_target != ""])
        with_id = np.random.default_rng(seed).permutation(names)[: max(1, int(ids_share * names.size))]
        plots["target"] = np.where(np.isin(sim.true_target, with_id), sim.true_target, "").astype(str)
    return sim, plots


@pytest.mark.parametrize(
    ("seed", "ids_share", "partition_s"), [(11, 0.0, 200.0), (12, 0.0, 150.0), (13, 0.4, 250.0)]
)
def test_labels_equal_the_association_in_memory(seed, ids_share, partition_s):
    sim, plots = _scenario(seed, ids_share)
    sc = sim.scenario
    whole = associate_and_register(plots, sc.sensors, sc.navigation, sc.platforms, None, AssociationOptions())
    source = TablesSource(plots, sc.sensors, sc.navigation, sc.platforms)
    parts = associate_partitioned(source, AssociationOptions(), partition_s=partition_s)
    assert parts is not None and parts.plan.n_partitions >= 3
    assert parts.summary()["links_across_cuts"] > 0  # confirmed targets were carried across the cuts
    labels = np.concatenate(parts.owned)  # the source is in time order: the partitions' rows in turn
    np.testing.assert_array_equal(labels, whole.labels.astype(str))


def test_a_plots_table_whose_rows_all_carry_ids_needs_no_association():
    sim = association_scenario(3, duration_s=200.0, seed=3)
    sc = sim.scenario
    source = TablesSource(sim.labelled_plots, sc.sensors, sc.navigation, sc.platforms)
    assert associate_partitioned(source, partition_s=100.0) is None


def _part(k, time, labels):
    labels = np.asarray(labels, dtype=str)
    return PartLabels(k, np.asarray(time, float), labels, np.zeros(labels.size, bool), True, True, 0.0, ())


def test_new_targets_are_named_once_across_cuts_and_never_merge_two_anchors():
    sim = association_scenario(2, duration_s=300.0, seed=5)
    sc = sim.scenario
    plots = dict(sim.plots, target=np.where(sim.true_target == "T1", "T1", "").astype(str))
    plan = make_association_plan(
        TablesSource(plots, sc.sensors, sc.navigation, sc.platforms), partition_s=150.0, overlap_s=20.0
    )
    cut = plan.cuts[0]
    t0 = np.linspace(plan.t0, cut + 20.0, 40)  # partition 0 reads to the cut + 20 s
    t1 = np.linspace(cut - 20.0, plan.t1, 40)
    shared = np.sort(np.unique(np.concatenate([t0[t0 >= cut - 20.0], t1[t1 <= cut + 20.0]])))
    t0 = np.sort(np.unique(np.concatenate([t0[t0 < cut - 20.0], shared])))
    t1 = np.sort(np.unique(np.concatenate([shared, t1[t1 > cut + 20.0]])))
    # partition 0: a1 everywhere; partition 1 calls the same plots a1 (its own new name) -> one target
    one = merge_labels(plan, [_part(0, t0, ["a1"] * t0.size), _part(1, t1, ["a1"] * t1.size)])
    assert one.new_targets == 1 and set(np.concatenate(one.owned)) == {"a1"}
    # a new target that meets the anchor T1 across the cut takes its name
    joined = merge_labels(plan, [_part(0, t0, ["T1"] * t0.size), _part(1, t1, ["a1"] * t1.size)])
    assert set(np.concatenate(joined.owned)) == {"T1"} and joined.new_targets == 0
    # two new targets of partition 1 in different places: two names, neither an id of the data
    half = np.where(t1 < plan.t1 - 60.0, "a1", "a2")
    two = merge_labels(plan, [_part(0, t0, [""] * t0.size), _part(1, t1, half)])
    assert two.new_targets == 2 and "T1" not in set(np.concatenate(two.owned))


def test_a_partition_without_anchors_keeps_its_ids_and_says_why():
    sim = association_scenario(3, duration_s=300.0, seed=7)
    sc = sim.scenario
    one = np.asarray(sim.plots["sensor"]) == np.asarray(sc.sensors["sensor"])[0]
    plots = {k: np.asarray(v)[one] for k, v in sim.plots.items()}  # one sensor, no ids, no references
    plots["target"] = np.full(one.sum(), "", dtype=object).astype(str)
    plots["target"][:5] = "X"
    result = associate_partitioned(
        TablesSource(plots, sc.sensors, sc.navigation, sc.platforms), partition_s=150.0
    )
    assert result is not None and not any(p.associated for p in result.parts)
    assert result.notes and "stay without one" in result.notes[0]
    assert set(np.concatenate(result.owned)) == {"", "X"}


@pytest.mark.parametrize("fmt", ["parquet", "csv"])
def test_register_by_partitions_equals_the_run_in_memory(tmp_path, fmt, capsys):
    sim, plots = _scenario(21, 0.3)
    sc = sim.scenario
    folder = tmp_path / "tables"
    folder.mkdir()
    write_fleet_tables(folder, plots, sc.navigation, sc.sensors, sc.platforms, None, fmt=fmt)
    run = ["fleet", "register", "--tables", str(folder), "--no-plots", "--out"]
    assert main([*run, str(tmp_path / "memory")]) == 0
    assert main([*run, str(tmp_path / "parts"), "--partition-s", "200"]) == 0
    assert "association:" in capsys.readouterr().out
    a = pd.read_csv(tmp_path / "memory" / "estimates.csv")
    b = pd.read_csv(tmp_path / "parts" / "estimates.csv")
    both = a.merge(b, on=["object", "state"], suffixes=("_m", "_p"))
    both = both[both["sigma_m"] > 0]
    assert len(both) == len(a[a["sigma"] > 0]) > 10
    assert np.max(np.abs(both["estimate_m"] - both["estimate_p"]) / both["sigma_m"]) < 0.01
    np.testing.assert_allclose(both["sigma_p"], both["sigma_m"], rtol=1e-5)
    summary = json.loads((tmp_path / "parts" / "summary.json").read_text())
    memory = json.loads((tmp_path / "memory" / "summary.json").read_text())
    assert summary["association"]["partitions"] == 3
    assert summary["association"]["plots_without_id"] == int((plots["target"] == "").sum())
    assert summary["chi_square"]["dof"] == memory["chi_square"]["dof"]
    by_time = ["time_s", "sensor"]
    labelled = pd.read_parquet(tmp_path / "parts" / "labelled_plots").sort_values(by_time, kind="stable")
    memory_csv = tmp_path / "memory" / "associations.csv"
    found = pd.read_csv(memory_csv, dtype={"target": str}, keep_default_na=False)
    found = found[found["target"] != ""].sort_values(by_time, kind="stable")
    assert len(labelled) == len(found) and "track" not in labelled.columns
    np.testing.assert_array_equal(labelled["target"].to_numpy(), found["target"].to_numpy())
    np.testing.assert_array_equal(labelled["time_s"].to_numpy(), found["time_s"].to_numpy())


def test_dask_workers_give_the_same_labels():
    pytest.importorskip("distributed")
    from registration.core.parallel import dask_client

    sim, plots = _scenario(31, 0.2)
    sc = sim.scenario
    source = TablesSource(plots, sc.sensors, sc.navigation, sc.platforms)
    here = associate_partitioned(source, partition_s=200.0)
    with dask_client(None, 2) as client:
        there = associate_partitioned(source, partition_s=200.0, client=client)
    assert here is not None and there is not None
    for a, b in zip(here.owned, there.owned, strict=True):
        np.testing.assert_array_equal(a, b)


def test_a_memory_limit_partitions_plots_without_ids_by_their_association(tmp_path, monkeypatch, capsys):
    """The association's memory per plot made large: tables without ids that the limit cannot hold
    in memory are associated and registered by partitions the run chooses for the association."""
    from registration.fleet.batch.partitioned import sizing

    sim, plots = _scenario(41, 0.2)
    sc = sim.scenario
    folder = tmp_path / "tables"
    folder.mkdir()
    write_fleet_tables(folder, plots, sc.navigation, sc.sensors, sc.platforms, None, fmt="parquet")
    n = plots["time"].size
    monkeypatch.setattr(sizing, "ASSOCIATION_PER_PLOT", 3 * (1 << 29) // n)  # the whole: 1.5 GiB
    out = tmp_path / "auto"
    run = ["fleet", "register", "--tables", str(folder), "--no-plots", "--memory-limit", "1.5GiB"]
    assert main([*run, "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "registering the archive by partitions" in text and "association:" in text
    summary = json.loads((out / "summary.json").read_text())
    chosen = summary["partition_s"]
    # the chosen partitions and their overlaps fit the association's limit; twice as long would not
    per_s = n / (plots["time"].max() - plots["time"].min())
    assert sizing.association_bytes(int(per_s * (chosen + 240.0) * 0.8)) <= 3 << 29
    assert summary["association"]["partitions"] == summary["partitions"] > 1
    assert summary["association"]["plots_labelled"] > 0.7 * n


def test_partitions_leave_the_final_registration_to_the_partitioned_solver(monkeypatch):
    """A partition's association stops at its labels: the full registration of its accepted plots
    (the longest solve of a partition of an imported day) would be done again by the partitioned
    solver. In memory the association still ends with it."""
    import registration.fleet.association.associate as associate_module
    from registration.fleet.association.solves import INTERMEDIATE_ITERATIONS

    seen = []
    solve = associate_module.solve_batch

    def watched(problem, options=None, x0=None, **kwargs):
        seen.append(options.max_iterations)
        return solve(problem, options, x0, **kwargs)

    monkeypatch.setattr(associate_module, "solve_batch", watched)
    sim, plots = _scenario(11)
    sc = sim.scenario
    whole = associate_and_register(plots, sc.sensors, sc.navigation, sc.platforms, None, AssociationOptions())
    assert whole.batch is not None and seen[-1] > INTERMEDIATE_ITERATIONS  # the full solve
    seen.clear()
    source = TablesSource(plots, sc.sensors, sc.navigation, sc.platforms)
    parts = associate_partitioned(source, AssociationOptions(), partition_s=200.0)
    assert parts is not None and seen and max(seen) <= INTERMEDIATE_ITERATIONS


def test_the_association_partitions_are_at_most_their_longest_length(tmp_path, monkeypatch):
    """Registration partitions longer than MAX_ASSOCIATION_PARTITION_S are associated in shorter
    ones (an association's time grows faster than its length); the labels stay those of memory."""
    from registration.fleet.association.partitioned import parts

    sim, plots = _scenario(12)
    sc = sim.scenario
    folder = tmp_path / "tables"
    folder.mkdir()
    write_fleet_tables(folder, plots, sc.navigation, sc.sensors, sc.platforms, None, fmt="parquet")
    monkeypatch.setattr(parts, "MAX_ASSOCIATION_PARTITION_S", 150.0)
    out = tmp_path / "parts"
    run = ["fleet", "register", "--tables", str(folder), "--no-plots", "--partition-s", "300"]
    assert main([*run, "--out", str(out)]) == 0
    summary = json.loads((out / "summary.json").read_text())
    assert summary["partitions"] == 2 and summary["partition_s"] == 300.0
    assert summary["association"]["partition_s"] == 150.0 and summary["association"]["partitions"] == 4
    whole = associate_and_register(plots, sc.sensors, sc.navigation, sc.platforms, None, AssociationOptions())
    labelled = pd.read_parquet(out / "labelled_plots").sort_values(["time_s", "sensor"], kind="stable")
    keep = whole.labels != ""
    memory = pd.DataFrame(
        {"time_s": np.asarray(plots["time"])[keep], "sensor": np.asarray(plots["sensor"])[keep]}
    ).assign(target=whole.labels[keep].astype(str))
    memory = memory.sort_values(["time_s", "sensor"], kind="stable")
    assert len(labelled) == len(memory) > 0
    np.testing.assert_array_equal(labelled["target"].to_numpy(), memory["target"].to_numpy())
