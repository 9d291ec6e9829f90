"""`registration fleet register --tables DIR`: the tables by their standard names, each overridable."""

import json
import shutil

import pandas as pd
import pytest

from registration.cli import main
from registration.io.fleet.folder import tables_in_folder


@pytest.fixture(scope="module")
def simulated(tmp_path_factory):
    out = tmp_path_factory.mktemp("fleet") / "sim"
    assert main(["fleet", "simulate", "--out", str(out), "--no-plots"]) == 0
    return out


def test_tables_folder_registers_as_the_explicit_files(simulated, tmp_path):
    assert (
        main(["fleet", "register", "--tables", str(simulated), "--out", str(tmp_path / "a"), "--no-plots"])
        == 0
    )
    got = pd.read_csv(tmp_path / "a" / "estimates.csv")
    want = pd.read_csv(simulated / "estimates.csv").drop(columns="truth")
    pd.testing.assert_frame_equal(got, want, check_exact=True)


def test_an_explicit_table_overrides_the_folder(simulated, tmp_path):
    plots = pd.read_csv(simulated / "plots.csv")
    plots.iloc[: len(plots) // 2].to_csv(tmp_path / "half.csv", index=False)
    paths = tables_in_folder(simulated, {"plots": tmp_path / "half.csv"})
    assert paths["plots"] == tmp_path / "half.csv" and paths["sensors"] == simulated / "sensors.csv"
    assert main(
        [
            "fleet",
            "register",
            "--tables",
            str(simulated),
            "--plots",
            str(tmp_path / "half.csv"),
            "--out",
            str(tmp_path / "b"),
            "--no-plots",
            "--allow-inconsistent",
        ]
    ) in (0, 3)
    used = json.loads((tmp_path / "b" / "summary.json").read_text())["inputs"]["plots_used"]
    full = json.loads((simulated / "summary.json").read_text())["inputs"]["plots_used"]
    assert used <= len(plots) // 2 < full


def test_optional_tables_may_be_missing_and_required_ones_are_named(simulated, tmp_path, capsys):
    folder = tmp_path / "tables"
    folder.mkdir()
    for name in ("plots", "navigation"):
        shutil.copy(simulated / f"{name}.csv", folder)
    assert tables_in_folder(simulated)["reference"] == simulated / "reference.csv"
    with pytest.raises(ValueError, match=r"no sensors table in the folder"):
        tables_in_folder(folder)
    assert main(["fleet", "register", "--tables", str(folder), "--out", str(tmp_path / "c")]) == 2
    assert "no sensors table" in capsys.readouterr().err
    shutil.copy(simulated / "sensors.csv", folder)
    paths = tables_in_folder(folder)
    assert paths["platforms"] is None and paths["reference"] is None
    pd.read_csv(simulated / "plots.csv").to_parquet(folder / "plots.parquet")
    with pytest.raises(ValueError, match="two formats"):
        tables_in_folder(folder)
    assert not (tmp_path / "c").exists() or not any((tmp_path / "c").iterdir())


def test_missing_folder_and_missing_tables_without_folder(tmp_path, capsys):
    assert main(["fleet", "register", "--tables", str(tmp_path / "nope"), "--out", str(tmp_path / "o")]) == 2
    assert "no such folder" in capsys.readouterr().err
    assert main(["fleet", "register", "--plots", "p.csv", "--out", str(tmp_path / "o")]) == 2
    assert "--navigation, --sensors are required" in capsys.readouterr().err
