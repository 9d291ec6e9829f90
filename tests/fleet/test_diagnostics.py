"""The residual diagnostics (registration.fleet.diagnostics) on the ATC simulator's radars
(tests/io/asterix/atc.py), written to fleet files (with the plots' kind column) and registered
without the terms that were added to the plots: an azimuth eccentricity of R2, a bearing step of
R3 at mid-time, a range offset of R1's primary-only plots. The diagnostics must name each on the
right radar, and nothing on clean runs (three seeds)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from registration.fleet import BatchOptions, solve_batch
from registration.fleet.diagnostics import diagnose
from registration.io import read_fleet_tables
from registration.io.asterix.tables.fleetfiles import site_tables
from tests.io.asterix.atc import atc_truth

DURATION_S = 300.0
#: NACp -> horizontal 95 % bound (m), as the ADS-B reference's sigma is taken (95 % / 2.4477).
_NACP_95 = {8: 92.6, 9: 30.0, 10: 10.0}
ECCENTRICITY_DEG = (0.12, 0.09)  # a sin(theta) + b cos(theta) on R2's bearings
STEP_DEG = 0.1  # on R3's bearings after mid-time
PRIMARY_RANGE_M = 60.0  # on R1's primary-only plots
GAIN_PPM = 400.0  # on R3's ranges


def _write_tables(folder, truth, plots: dict):
    """The fleet files of the simulated plots (every plot with its aircraft's id) and ADS-B."""
    tables = site_tables(truth.sites, float(np.min(plots["time_s"])))
    pd.DataFrame(
        {
            "time_s": plots["time_s"],
            "sensor": plots["radar"],
            "target": [f"AC{j}" for j in plots["aircraft"]],
            "range_m": plots["range_m"],
            "bearing_deg": plots["bearing_deg"],
            "kind": plots["kind"],
        }
    ).to_csv(folder / "plots.csv", index=False)
    a = truth.adsb
    sigma = np.array([_NACP_95[int(n)] / 2.4477 for n in a["nacp"]])
    pd.DataFrame(
        {
            "time_s": a["time_s"],
            "target": [f"AC{(int(x) - 0x400000) // 0x1234}" for x in a["address"]],
            "lat_deg": a["lat_deg"],
            "lon_deg": a["lon_deg"],
            "alt_m": a["height_m"],
            "sigma_m": sigma,
            "sigma_up_m": np.minimum(2 * sigma, 20.0),
        }
    ).to_csv(folder / "reference.csv", index=False)
    for name in ("navigation", "sensors", "platforms"):
        tables[name].to_csv(folder / f"{name}.csv", index=False)
    return read_fleet_tables(
        *(folder / f"{n}.csv" for n in ("plots", "navigation", "sensors", "platforms", "reference"))
    )


def _run(folder, seed: int, faults: bool):
    """(diagnostics, result) of a registration of the simulator's plots, its clock offsets and
    range gains taken out of the plots and out of the model (a faster solve; the range gain then is
    a diagnostic's), and with ``faults`` the terms of the module docstring added (R1's primary-only
    plots: those of the aircraft without a transponder and a fifth of the others', as when a
    transponder does not reply; a whole track's offset the track's fit would take up), and a range
    gain of R3."""
    truth = atc_truth(seed, duration_s=DURATION_S)
    plots = {k: np.array(v) for k, v in truth.plots.items()}
    for radar in np.unique(plots["radar"]):
        mine = plots["radar"] == radar
        plots["time_s"][mine] -= truth.truth[f"{radar}:time_bias"]
        plots["range_m"][mine] /= 1.0 + truth.truth[f"{radar}:range_gain"]
    truth.sites = truth.sites.drop(columns=["prior_range_gain", "prior_time_bias_s"])
    if faults:
        rng = np.random.default_rng(seed)
        plots["kind"] = plots["kind"].astype(object)
        plots["kind"][(plots["radar"] == "R1") & (rng.random(plots["kind"].size) < 0.2)] = "primary"
        theta = np.radians(plots["bearing_deg"])
        r2, r3 = plots["radar"] == "R2", plots["radar"] == "R3"
        a, b = ECCENTRICITY_DEG
        plots["bearing_deg"] = plots["bearing_deg"] + np.where(r2, a * np.sin(theta) + b * np.cos(theta), 0.0)
        mid = np.median(plots["time_s"])
        plots["bearing_deg"] = plots["bearing_deg"] + np.where(r3 & (plots["time_s"] > mid), STEP_DEG, 0.0)
        psr = (plots["radar"] == "R1") & (plots["kind"] == "primary")
        plots["range_m"] = plots["range_m"] + np.where(psr, PRIMARY_RANGE_M, 0.0)
        plots["range_m"] = plots["range_m"] * np.where(r3, 1.0 + GAIN_PPM * 1e-6, 1.0)
    tables = _write_tables(folder, truth, plots)
    problem = tables.problem()
    result = solve_batch(problem, BatchOptions(window_s=20.0))
    return diagnose(problem, result, tables.plots["kind"]), result


@pytest.fixture(scope="module")
def faulty(tmp_path_factory):
    return _run(tmp_path_factory.mktemp("faulty"), 3, faults=True)


def _found(diagnostics, test: str) -> dict:
    """Sensor -> the findings of ``test``."""
    out: dict = {}
    for f in diagnostics.findings:
        if f.test == test:
            out.setdefault(f.sensor, []).append(f)
    return out


def test_eccentricity_is_named_on_the_right_radar(faulty):
    d, _ = faulty
    found = _found(d, "eccentricity")
    assert set(found) == {"R2"}, d.finding_lines()
    amplitude = float(np.hypot(*ECCENTRICITY_DEG))
    assert found["R2"][0].size == pytest.approx(amplitude, rel=0.25)
    assert "eccentricity?" in "\n".join(d.finding_lines())


def test_bias_step_is_named_with_its_time_and_size(faulty):
    d, _ = faulty
    found = _found(d, "step")
    assert "R3" in found, d.finding_lines()
    step = next(f for f in found["R3"] if f.channel == "bearing")
    assert step.size == pytest.approx(STEP_DEG, rel=0.3)
    assert "try --bias-period-s" in step.hint


def test_psr_ssr_difference_is_named(faulty):
    d, _ = faulty
    psr = [f for f in d.findings if f.hint.startswith("PSR/SSR difference")]
    assert {(f.sensor, f.channel) for f in psr} == {("R1", "range")}, d.finding_lines()
    # part of it is taken up by the tracks of the aircraft seen by primary plots only
    assert PRIMARY_RANGE_M / 3 < psr[0].size < 1.2 * PRIMARY_RANGE_M
    assert psr[0].hint == "PSR/SSR difference: psr_channel own?"


def test_range_gain_is_named(faulty):
    d, _ = faulty
    found = _found(d, "range_gain")
    assert set(found) == {"R3"}, d.finding_lines()
    assert GAIN_PPM / 3 < found["R3"][0].size < 1.2 * GAIN_PPM  # the range bias and tracks take up part
    assert found["R3"][0].hint == "range gain?"


def test_excess_is_carried_by_the_faulty_radars(faulty):
    d, result = faulty
    share = {s: v["share"] for s, v in d.excess.items()}
    assert share["R1"] < share["R2"] and share["R1"] < share["R3"], share
    assert not result.chi_square.ok
    assert any(b["sensor"] == "R2" and b["binning"] == "azimuth" for b in d.worst_bins())
    lines = d.excess_lines()
    assert lines[0].startswith("consistency outside its band") and len(lines) > 1


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_clean_runs_have_no_finding(tmp_path, seed):
    d, _ = _run(tmp_path, seed, faults=False)
    assert d.findings == [], d.finding_lines()
    assert d.n_tests > 50 and 4.0 < d.threshold < 6.0
