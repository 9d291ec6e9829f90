"""`registration import asterix|nmea`: the folder an import writes, its identity across forms of one
recording, bad input (exit 2, --out as it was), and the chain into `fleet register --tables`."""

from __future__ import annotations

import json

import pandas as pd
import pytest

from registration.cli import main

TABLES = ("plots", "navigation", "sensors", "platforms", "reference")


@pytest.fixture(scope="module")
def asterix_files(tmp_path_factory):
    pytest.importorskip("asterix")  # libasterix encodes the recording (the test extra)
    from tests.io.asterix.scenario import sites_frame, standard_recording

    folder = tmp_path_factory.mktemp("asterix")
    files = dict(standard_recording().write(folder))
    sites = folder / "sites.csv"
    sites_frame().to_csv(sites, index=False)
    return files, sites


@pytest.fixture(scope="module")
def bridge_log(tmp_path_factory):
    from tests.io.nmea.bridgelog import simulate_bridge_log

    folder = tmp_path_factory.mktemp("nmea")
    log = simulate_bridge_log()
    return log, log.write(folder / "bridge.log"), log.write_sensors(folder / "sensors.csv")


def test_raw_and_pcap_import_to_identical_folders(asterix_files, tmp_path, capsys):
    files, sites = asterix_files
    for form in ("raw", "pcap", "pcapng"):
        assert (
            main(
                ["import", "asterix", str(files[form]), "--sites", str(sites), "--out", str(tmp_path / form)]
            )
            == 0
        )
    assert "next: registration fleet register --tables" in capsys.readouterr().out
    for name in TABLES:
        raw = (tmp_path / "raw" / f"{name}.csv").read_bytes()
        assert (
            raw
            == (tmp_path / "pcap" / f"{name}.csv").read_bytes()
            == (tmp_path / "pcapng" / f"{name}.csv").read_bytes()
        )
    summary = json.loads((tmp_path / "raw" / "import_summary.json").read_text())
    assert summary  # a JSON object
    rejected = pd.read_csv(tmp_path / "pcap" / "rejected.csv")
    assert len(rejected) > 0 and {"file", "reason"} <= set(rejected.columns)


def test_parquet_format_and_a_rerun_replaces_the_other_format(asterix_files, tmp_path):
    files, sites = asterix_files
    out = tmp_path / "imp"
    assert main(["import", "asterix", str(files["raw"]), "--sites", str(sites), "--out", str(out)]) == 0
    assert (
        main(
            [
                "import",
                "asterix",
                str(files["raw"]),
                "--sites",
                str(sites),
                "--out",
                str(out),
                "--format",
                "parquet",
            ]
        )
        == 0
    )
    assert not list(out.glob("*.csv")) or {p.name for p in out.glob("*.csv")} == {"rejected.csv"}
    plots = pd.read_parquet(out / "plots.parquet")
    assert len(plots) > 0 and {"time_s", "sensor", "range_m", "bearing_deg"} <= set(plots.columns)


def test_a_file_that_is_no_recording_exits_2_and_leaves_out_as_it_was(asterix_files, tmp_path, capsys):
    files, sites = asterix_files
    out = tmp_path / "imp"
    assert main(["import", "asterix", str(files["raw"]), "--sites", str(sites), "--out", str(out)]) == 0
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    capsys.readouterr()
    assert main(["import", "asterix", str(sites), "--sites", str(sites), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert (
        err.startswith("registration import asterix: error:") and str(sites) in err and err.count("\n") == 1
    )
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    assert (
        main(["import", "asterix", str(tmp_path / "missing.ast"), "--sites", str(sites), "--out", str(out)])
        == 2
    )


def test_nmea_import_chains_into_fleet_register(bridge_log, tmp_path):
    log, path, sensors = bridge_log
    out = tmp_path / "imp"
    assert (
        main(["import", "nmea", str(path), "--platform", "OWN", "--sensors", str(sensors), "--out", str(out)])
        == 0
    )
    assert {f"{t}.csv" for t in TABLES} <= {p.name for p in out.iterdir()}
    platforms = pd.read_csv(out / "platforms.csv")
    assert (platforms[["prior_heading_deg", "prior_pitch_deg", "prior_roll_deg"]] == 0).all(axis=None)
    assert (
        main(
            [
                "import",
                "nmea",
                str(path),
                "--platform",
                "OWN",
                "--sensors",
                str(sensors),
                "--out",
                str(tmp_path / "free"),
                "--prior-heading-deg",
                "free",
            ]
        )
        == 0
    )
    assert pd.read_csv(tmp_path / "free" / "platforms.csv")["prior_heading_deg"].isna().all()
    reg = tmp_path / "reg"  # the ARPA's sensor-local tracks are associated to the AIS vessels
    assert main(["fleet", "register", "--tables", str(out), "--out", str(reg), "--no-plots"]) == 0
    est = pd.read_csv(reg / "estimates.csv").set_index(["object", "state"])
    truth = log.errors
    for state, scale in (("range_bias", 1.0), ("bearing_bias", 57.29577951308232), ("time_bias", 1.0)):
        row = est.loc[("RADAR", state)]
        assert abs(row["estimate"] - truth[f"RADAR:{state}"] * scale) < 3.5 * row["sigma"], state
    assoc = pd.read_csv(reg / "associations.csv", dtype={"track": str, "target": str}, keep_default_na=False)
    joined = assoc[assoc["target"] != ""]
    assert set(joined["target"]) <= set(log.track_mmsi.values())
    assert (
        joined["track"].map(log.track_mmsi) == joined["target"]
    ).all()  # every join is the track's own vessel
    without_ais = assoc[~assoc["track"].isin(log.track_mmsi)]
    assert len(without_ais) > 0 and (without_ais["target"] == "").all()
    _assert_surface_run(reg)


def _assert_surface_run(reg):
    """The vessels are surface targets (targets.csv) and AIS gives no height: the solve converges in
    a few iterations (it crept along the unmeasured heights to its 104-iteration limit when the
    AIS positions carried sea level as a measured height), no warning of unmeasured heights, and
    the chi-square no longer counts the known sea level as measured values (0.78 then; the AIS
    sigmas are bounds, so it stays a little below 1: docs/howto/import-nmea.md)."""
    summary = json.loads((reg / "summary.json").read_text())
    assert summary["converged"] and summary["iterations"] < 30
    assert not any("no measured height" in w for w in summary["warnings"])
    assert (
        summary["consistency"]["status"] != "grossly inconsistent" and summary["consistency"]["mean"] > 0.85
    )


def test_nmea_log_without_heading_exits_2(bridge_log, tmp_path, capsys):
    log, path, sensors = bridge_log
    lines = [
        ln
        for ln in path.read_text().splitlines()
        if not ln.startswith(("$PASHR", "$HEHDT", "$GPHDT", "$HETHS"))
    ]
    bad = tmp_path / "noheading.log"
    bad.write_text("\n".join(lines) + "\n")
    assert (
        main(
            [
                "import",
                "nmea",
                str(bad),
                "--platform",
                "OWN",
                "--sensors",
                str(sensors),
                "--out",
                str(tmp_path / "o"),
            ]
        )
        == 2
    )
    err = capsys.readouterr().err
    assert "heading" in err and err.count("\n") == 1
    assert not (tmp_path / "o").exists() or not any((tmp_path / "o").iterdir())


def test_nmea_chain_on_a_log_it_was_not_developed_on(tmp_path):
    """Another draw and another log: seed 7, true bearings, distances in km, a logger's unix-time
    prefix instead of tag blocks, other bias signs and sizes, 12 vessels of which 9 on AIS."""
    import dataclasses

    import numpy as np

    from tests.io.nmea.bridgelog import simulate_bridge_log
    from tests.io.nmea.truth import BridgeLogConfig

    config = dataclasses.replace(
        BridgeLogConfig(),
        seed=7,
        bearing_reference="T",
        distance_unit="K",
        reception_stamp="prefix-unix",
        n_vessels=12,
        n_ais=9,
        range_bias_m=-35.0,
        bearing_bias_rad=float(np.radians(-1.2)),
        clock_offset_s=-0.5,
    )
    log = simulate_bridge_log(config)
    path, sensors = log.write(tmp_path / "b.log"), log.write_sensors(tmp_path / "s.csv")
    out, reg = tmp_path / "imp", tmp_path / "reg"
    assert (
        main(["import", "nmea", str(path), "--platform", "OWN", "--sensors", str(sensors), "--out", str(out)])
        == 0
    )
    assert main(["fleet", "register", "--tables", str(out), "--out", str(reg), "--no-plots"]) == 0
    est = pd.read_csv(reg / "estimates.csv").set_index(["object", "state"])
    for state, scale in (("range_bias", 1.0), ("bearing_bias", 57.29577951308232), ("time_bias", 1.0)):
        row = est.loc[("RADAR", state)]
        assert abs(row["estimate"] - log.errors[f"RADAR:{state}"] * scale) < 3.5 * row["sigma"], state
    assoc = pd.read_csv(reg / "associations.csv", dtype={"track": str, "target": str}, keep_default_na=False)
    joined = assoc[assoc["target"] != ""]
    assert len(joined) > 0 and (joined["track"].map(log.track_mmsi) == joined["target"]).all()
    _assert_surface_run(reg)


def _heading_run(tmp_path, roll_deg: float, pitch_deg: float, seed: int):
    """A bridge log with a heading error of 1 deg and a bearing bias of 0.6 deg, imported with the
    heading left free (``--prior-heading-deg free``) and registered: (log, estimates by (object, state))."""
    import dataclasses

    import numpy as np

    from tests.io.nmea.bridgelog import simulate_bridge_log
    from tests.io.nmea.truth import BridgeLogConfig

    config = dataclasses.replace(
        BridgeLogConfig(),
        seed=seed,
        heading_error_rad=float(np.radians(1.0)),
        roll_amplitude_rad=float(np.radians(roll_deg)),
        pitch_amplitude_rad=float(np.radians(pitch_deg)),
    )
    log = simulate_bridge_log(config)
    path, sensors = log.write(tmp_path / "b.log"), log.write_sensors(tmp_path / "s.csv")
    out, reg = tmp_path / "imp", tmp_path / "reg"
    assert (
        main(
            [
                "import",
                "nmea",
                str(path),
                "--platform",
                "OWN",
                "--sensors",
                str(sensors),
                "--out",
                str(out),
                "--prior-heading-deg",
                "free",
            ]
        )
        == 0
    )
    assert main(["fleet", "register", "--tables", str(out), "--out", str(reg), "--no-plots"]) == 0
    return log, pd.read_csv(reg / "estimates.csv").set_index(["object", "state"])


DEG = 57.29577951308232


def test_heading_error_separated_from_the_bearing_bias_by_a_heavy_roll(tmp_path):
    """One radar on one ship: a heading error turns the picture about the vertical, a bearing bias
    about the deck's normal. A heavy roll and pitch (15 deg, 5 deg) tell them apart."""
    log, est = _heading_run(tmp_path, 15.0, 5.0, seed=2)
    for (obj, state), truth in (
        (("OWN", "heading_error"), log.errors["OWN:heading_error"]),
        (("RADAR", "bearing_bias"), log.errors["RADAR:bearing_bias"]),
    ):
        row = est.loc[(obj, state)]
        assert abs(row["estimate"] - truth * DEG) < 3.5 * row["sigma"], (state, row["estimate"], row["sigma"])
        assert row["sigma"] < 0.3 and row["status"] == "identifiable", state  # deg
    row = est.loc[("RADAR", "range_bias")]
    assert abs(row["estimate"] - log.errors["RADAR:range_bias"]) < 3.5 * row["sigma"]


def test_heading_error_weak_under_a_gentle_roll_and_the_sum_is_given(tmp_path):
    """The default motion (4 deg roll, 1.5 deg pitch) barely tells them apart: both are reported
    weak with honest sigmas (over 0.5 deg), and their sum is given as an identifiable combination."""
    log, est = _heading_run(tmp_path, 4.0, 1.5, seed=2)
    truth = {
        "heading_error": log.errors["OWN:heading_error"],
        "bearing_bias": log.errors["RADAR:bearing_bias"],
    }
    for obj, state in (("OWN", "heading_error"), ("RADAR", "bearing_bias")):
        row = est.loc[(obj, state)]
        assert row["status"] == "weak" and row["sigma"] > 0.5, state
        assert abs(row["estimate"] - truth[state] * DEG) < 3.5 * row["sigma"], state
    both = est.loc[("OWN+RADAR", "heading_error+bearing_bias")]
    assert both["status"] == "identifiable combination" and both["sigma"] < 0.01
    assert abs(both["estimate"] - sum(truth.values()) * DEG) < 3.5 * both["sigma"]


def _exits_cleanly(capsys, argv: list, path) -> int:
    """Run the command: exit 0, or 2 with one line naming ``path``; never a traceback, never 4."""
    code = main(argv)
    err = capsys.readouterr().err
    assert code in (0, 2) and "Traceback" not in err, err
    if code == 2:
        assert err.count("\n") == 1 and str(path) in err, err
    return code


@pytest.mark.parametrize("case", ["short12", "short16", "short20", "late"])
def test_pcapng_reproductions_exit_cleanly(asterix_files, tmp_path, capsys, case):
    """Issue 32: a pcapng whose last Enhanced Packet Block is 12-20 bytes long, or whose packet
    time is out of range (pcapng blocks built with struct in tests/io/asterix/repro.py)."""
    from tests.io.asterix.repro import out_of_range_time, short_last_epb

    _, sites = asterix_files
    path = tmp_path / f"{case}.pcapng"
    path.write_bytes(out_of_range_time() if case == "late" else short_last_epb(int(case[5:])))
    argv = ["import", "asterix", str(path), "--sites", str(sites), "--out", str(tmp_path / "o")]
    _exits_cleanly(capsys, argv, path)


@pytest.mark.parametrize(
    "stamp", ["0001-01-01T00:00:00Z ", "0001-01-01T00:00:00+14:00 ", "9999-12-31T23:59:59-14:00 "]
)
def test_nmea_line_stamped_in_the_year_1_never_exits_4(bridge_log, tmp_path, capsys, stamp):
    """Issue 32: an AIS line (or every line) stamped 0001-01-01: the stamp is set aside as a bad
    prefix, the import goes on (exit 0), or exit 2 naming the file when nothing is left."""
    log, path, sensors = bridge_log
    lines = path.read_text().splitlines()[:400]
    ais = next(line for line in lines if "AIVDM" in line).split("\\")[-1]
    for name, text in (("one.log", [*lines, stamp + ais]), ("all.log", [stamp + x for x in lines])):
        target = tmp_path / name
        target.write_text("\n".join(text) + "\n")
        argv = ["import", "nmea", str(target), "--platform", "OWN", "--sensors", str(sensors)]
        code = _exits_cleanly(capsys, [*argv, "--out", str(tmp_path / "o")], target)
        assert code == (0 if name == "one.log" else 2)


def test_a_directory_is_named_a_directory(asterix_files, tmp_path, capsys):
    """Issue 31 item 8: `import asterix DIR` says it is a directory, not 'no such file'."""
    _, sites = asterix_files
    argv = ["import", "asterix", str(tmp_path), "--sites", str(sites), "--out", str(tmp_path / "o")]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert f"{tmp_path}: a directory" in err and "no such file" not in err
    assert main([*argv[:2], str(tmp_path / "none.ast"), *argv[3:]]) == 2
    assert "none.ast: no such file" in capsys.readouterr().err


def test_nmea_import_of_a_binary_file(asterix_files, bridge_log, tmp_path, capsys):
    """Issue 31 item 8: an NMEA import of a binary file (an ASTERIX capture) says 'not a text NMEA log'."""
    files, _ = asterix_files
    _, _, sensors = bridge_log
    argv = ["import", "nmea", str(files["pcap"]), "--platform", "OWN", "--sensors", str(sensors)]
    assert main([*argv, "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert f"{files['pcap']}: not a text NMEA log" in err and err.count("\n") == 1


def test_a_pcap_without_asterix_exits_2_and_leaves_out_as_it_was(asterix_files, tmp_path, capsys):
    """Issue 31 item 2: a capture of other UDP traffic exits 2, and a previous good import in
    --out is kept byte for byte."""
    import numpy as np

    from tests.io.asterix.containers import pcap_bytes, udp_frame

    files, sites = asterix_files
    out = tmp_path / "out"
    assert main(["import", "asterix", str(files["raw"]), "--sites", str(sites), "--out", str(out)]) == 0
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    rng = np.random.default_rng(1)
    other = tmp_path / "other.pcap"
    other.write_bytes(pcap_bytes([udp_frame(rng.bytes(60), dport=5353) for _ in range(8)], [1.7e9] * 8))
    capsys.readouterr()
    assert main(["import", "asterix", str(other), "--sites", str(sites), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert f"{other}: not an ASTERIX recording (" in err and err.count("\n") == 1
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
