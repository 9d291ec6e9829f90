"""Biases per period (``fleet register --bias-period-s``) on simulations they were not tuned on.

* The air-traffic simulator of the ASTERIX acceptance (tests/io/asterix/atc.py: three radars with range
  bias, range gain, azimuth bias and clock offset, ADS-B references), its plots turned into fleet
  tables directly (the plots the simulator made, without the ASTERIX round trip, which
  tests/io/asterix covers): with a 0.1 deg azimuth step of one radar at a period boundary, every state
  of every period lies within 3.5 sigma of that period's truth and changes.csv lists that step alone;
  without a step changes.csv is empty.
* A Monte Carlo over 20 seeds of the built-in fleet (:func:`registration.fleet.fleet_scenario`): the
  normalised estimation error squared of the per-period estimates in its 95 % band.
* Bad input (exit 2 naming the option), a period without plots of a sensor, the CLI end to end.
"""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest
from scipy.stats import chi2

from registration.cli import main
from registration.fleet import BatchOptions, fleet_scenario
from registration.fleet.periods import UNDETERMINED, solve_periods
from tests.io.asterix.atc import atc_truth

STEP_DEG = 0.1
Z_LIMIT = 3.5
CHANGE_HEADER = '"object","state","unit","time_s","before","after","sigma","z"'


def _atc_tables(folder, seed: int, duration_s: float, period_s: float, step_radar: str | None):
    """Fleet tables (CSV, degrees and metres) of ``atc_truth(seed)``'s plots of Mode S and Mode A/C
    aircraft, with ``STEP_DEG`` added to ``step_radar``'s azimuths from the first period boundary on;
    the sites as fixed platforms, the ADS-B reports as references. Returns (truth before, truth
    after, boundary s)."""
    atc = atc_truth(seed, duration_s=duration_s, n_aircraft=14)
    p = atc.plots
    t = np.asarray(p["time_s"], dtype=float)
    boundary = (np.floor(t.min() / period_s) + 1) * period_s
    bearing = np.asarray(p["bearing_deg"], dtype=float).copy()
    after = dict(atc.truth)
    if step_radar is not None:
        bearing[(p["radar"] == step_radar) & (t >= boundary)] += STEP_DEG
        after[f"{step_radar}:bearing_bias"] += np.radians(STEP_DEG)
    kind = np.asarray(p["kind"])
    target = np.where(
        kind == "mode_s",
        [f"{a:06X}" for a in p["address"]],
        [f"A{m:04o}" if m >= 0 else "" for m in p["mode_a"]],
    )
    keep = target != ""
    plots = pd.DataFrame(
        {
            "time_s": t,
            "sensor": p["radar"],
            "target": target,
            "range_m": p["range_m"],
            "bearing_deg": bearing % 360.0,
        }
    )[keep]
    sites = atc.sites
    navigation = pd.DataFrame(
        {
            "time_s": float(np.floor(t.min())),
            "platform": sites["sensor"],
            "lat_deg": sites["lat_deg"],
            "lon_deg": sites["lon_deg"],
            "alt_m": sites["alt_m"],
            "heading_deg": 0.0,
            "pitch_deg": 0.0,
            "roll_deg": 0.0,
        }
    )
    sensors = sites[["sensor", "sigma_range_m", "sigma_bearing_deg", "prior_range_gain", "prior_time_bias_s"]]
    sensors.insert(1, "platform", sites["sensor"])
    platforms = pd.DataFrame(
        {"platform": sites["sensor"], "prior_heading_deg": 0.0, "prior_pitch_deg": 0.0, "prior_roll_deg": 0.0}
    )
    a = atc.adsb
    sigma_h = np.select([a["nacp"] == 8, a["nacp"] == 9], [92.6, 30.0], 10.0) / 2.4477  # NACp 95 % bound
    reference = pd.DataFrame(
        {
            "time_s": a["time_s"],
            "target": [f"{x:06X}" for x in a["address"]],
            "lat_deg": a["lat_deg"],
            "lon_deg": a["lon_deg"],
            "alt_m": a["height_m"],
            "sigma_m": sigma_h,
            "sigma_up_m": np.minimum(2 * sigma_h, 20.0),
        }
    )
    for name, frame in (
        ("plots", plots),
        ("navigation", navigation),
        ("sensors", sensors),
        ("platforms", platforms),
        ("reference", reference),
    ):
        frame.to_csv(folder / f"{name}.csv", index=False)
    return atc.truth, after, float(boundary)


def _register(capsys, tables, out, *extra) -> int:
    code = main(["fleet", "register", "--tables", str(tables), "--out", str(out), "--no-plots", *extra])
    capsys.readouterr()
    return code


@pytest.fixture(scope="module")
def step_run(tmp_path_factory):
    """The ATC scenario (seed 31, 240 s) with a step of R3 at the boundary, registered with periods of
    120 s: (folder of the outputs, truth before, truth after, boundary)."""
    folder = tmp_path_factory.mktemp("step")
    before, after, boundary = _atc_tables(folder, 31, 240.0, 120.0, "R3")
    out = folder / "out"
    args = ["fleet", "register", "--tables", str(folder), "--out", str(out), "--no-plots"]
    assert main([*args, "--bias-period-s", "120"]) == 0
    return out, before, after, boundary


def test_every_state_of_every_period_is_within_3_5_sigma_of_its_truth(step_run):
    out, before, after, boundary = step_run
    rows = pd.read_csv(out / "estimates_by_period.csv")
    rows = rows[rows["status"] != "identifiable combination"]
    assert sorted(rows["period_start_s"].unique()) == [boundary - 120.0, boundary]
    k = {"deg": np.degrees(1.0), "m": 1.0, "1": 1.0, "s": 1.0}
    checked = 0
    for r in rows.itertuples():
        truth = (before if r.period_end_s <= boundary else after).get(f"{r.object}:{r.state}", 0.0)
        if not np.isfinite(r.sigma) or r.sigma == 0:
            continue
        z = (r.estimate - truth * k[r.unit]) / r.sigma
        assert abs(z) <= Z_LIMIT, (r.period_start_s, r.object, r.state, z)
        checked += 1
    assert checked >= 2 * 12  # 3 radars x 4 errors, in both periods


def test_changes_list_the_step_and_nothing_else(step_run):
    out, _, _, boundary = step_run
    changes = pd.read_csv(out / "changes.csv")
    assert len(changes) == 1, changes
    c = changes.iloc[0]
    assert (c["object"], c["state"], c["unit"], c["time_s"]) == ("R3", "bearing_bias", "deg", boundary)
    assert abs(c["after"] - c["before"] - STEP_DEG) < 4 * c["sigma"]
    summary = json.loads((out / "summary.json").read_text())["bias_periods"]
    assert summary["period_s"] == 120.0 and len(summary["periods"]) == 2
    assert summary["tests"] >= 12 and summary["threshold_z"] > 3.0
    assert [x["state"] for x in summary["changes"]] == ["bearing_bias"]
    whole = pd.read_csv(out / "estimates.csv")  # the whole run's model, as without the option
    assert "period_start_s" not in whole.columns


@pytest.mark.parametrize("seed", [32, 33])
def test_no_change_without_a_step(tmp_path, capsys, seed):
    _atc_tables(tmp_path, seed, 200.0, 100.0, None)
    assert _register(capsys, tmp_path, tmp_path / "out", "--bias-period-s", "100") == 0
    text = (tmp_path / "out" / "changes.csv").read_text().splitlines()
    assert text == [CHANGE_HEADER]


def _nees(seed: int) -> tuple[float, int]:
    """Sum over the periods of a small built-in fleet run of the NEES of the states determined
    (finite sigma, not fixed), and their number."""
    s = fleet_scenario(seed, duration_s=120.0)
    runs = solve_periods(
        s.plots,
        s.sensors,
        s.navigation,
        s.platforms,
        s.references,
        period_s=60.0,
        options=BatchOptions(window_s=20.0),
    )
    total, dof = 0.0, 0
    assert len(runs.periods) == 2
    for p in runs.periods:
        r = p.result
        names = r.layout.names
        i = np.array(
            [j for j, n in enumerate(names) if np.isfinite(r.sigma[j]) and r.status.get(n) != "fixed"]
        )
        e = r.estimate[i] - np.array([s.truth_state[names[j]] for j in i])
        total += float(e @ np.linalg.solve(r.covariance[np.ix_(i, i)], e))
        dof += i.size
    return total, dof


def test_nees_of_the_per_period_estimates_over_20_seeds_is_in_its_95_percent_band():
    parts = [_nees(seed) for seed in range(100, 120)]
    total, dof = sum(p[0] for p in parts), sum(p[1] for p in parts)
    lo, hi = chi2.ppf([0.025, 0.975], dof)
    assert lo <= total <= hi, (total / dof, lo / dof, hi / dof)


def test_a_period_without_plots_of_a_sensor_leaves_its_states_undetermined():
    s = fleet_scenario(4, duration_s=120.0)
    gone = (s.plots["sensor"] == "C-2D") & (s.plots["time"] >= 60.0)
    plots = {k: v[~gone] for k, v in s.plots.items()}
    runs = solve_periods(plots, s.sensors, s.navigation, s.platforms, s.references, period_s=60.0)
    first, second = (p.result for p in runs.periods)
    assert first.status["C-2D:range_bias"] == "identifiable"
    assert second.status["C-2D:range_bias"] == UNDETERMINED
    assert second.status["C-2D:bearing_bias"] == UNDETERMINED
    assert not np.isfinite(second.sigma_of("C-2D:range_bias"))
    tested = {runs.periods[0].result.layout.names[i] for i in runs.changes.state}
    assert "C-2D:range_bias" not in tested and "C-3D:range_bias" in tested


def test_a_period_without_plots_is_left_out_with_a_note():
    s = fleet_scenario(5, duration_s=180.0)
    gone = (s.plots["time"] >= 60.0) & (s.plots["time"] < 120.0)
    plots = {k: v[~gone] for k, v in s.plots.items()}
    runs = solve_periods(plots, s.sensors, s.navigation, s.platforms, s.references, period_s=60.0)
    assert [p.start_s for p in runs.periods] == [0.0, 120.0]
    assert runs.notes() == ["period [60, 120) s left out: no plots"]


@pytest.fixture(scope="module")
def fleet_tables(tmp_path_factory):
    folder = tmp_path_factory.mktemp("fleet")
    assert main(["fleet", "simulate", "--out", str(folder), "--duration-s", "120", "--no-plots"]) == 0
    return folder


@pytest.mark.parametrize(
    "extra",
    [
        ["--bias-period-s", "30"],  # shorter than two windows of 20 s
        ["--bias-period-s", "0"],
        ["--bias-period-s", "nan"],
        ["--bias-period-s", "60", "--window-s", "40"],
        ["--bias-period-s", "60", "--method", "online"],
    ],
)
def test_bad_periods_exit_2_naming_the_option(fleet_tables, tmp_path, capsys, extra):
    code = main(["fleet", "register", "--tables", str(fleet_tables), "--out", str(tmp_path / "out"), *extra])
    err = capsys.readouterr().err
    assert code == 2
    assert "--bias-period-s" in err
    assert not (tmp_path / "out" / "estimates.csv").exists()


def test_the_cli_end_to_end(fleet_tables, tmp_path, capsys):
    out = tmp_path / "out"
    args = ["fleet", "register", "--tables", str(fleet_tables), "--out", str(out)]
    code = main([*args, "--bias-period-s", "60"])
    printed = capsys.readouterr().out
    assert code == 0
    names = ("estimates.csv", "estimates_by_period.csv", "changes.csv", "summary.json", "bias_periods.png")
    for name in names:
        assert (out / name).is_file(), name
    assert (out / "changes.csv").read_text().splitlines()[0] == CHANGE_HEADER
    by_period = pd.read_csv(out / "estimates_by_period.csv")
    assert list(by_period.columns) == [
        "period_start_s",
        "period_end_s",
        "object",
        "state",
        "unit",
        "estimate",
        "sigma",
        "status",
    ]
    assert sorted(by_period["period_start_s"].unique()) == [0.0, 60.0]
    assert "Biases per period of 60 s: 2 periods" in printed
    summary = json.loads((out / "summary.json").read_text())
    assert summary["bias_periods"]["period_s"] == 60.0
