"""docs/reference/cli.md is what ``python -m registration.cli.reference`` writes from the parser today:
a changed option, help text, default or exit code without the page regenerated fails here."""

from __future__ import annotations

import re
import sys

import pytest

from registration.cli import COMMANDS, build_parser, errors
from registration.cli.reference import DEFAULT_PATH, commands, exit_code_rows, main, render
from tests.docs.links import ROOT

PAGE = ROOT / DEFAULT_PATH


def test_the_cli_reference_is_current():
    page = PAGE.read_text(encoding="utf-8")
    made_by = re.search(r"by Python (\d+\.\d+)", page)
    assert made_by, "the page does not say which Python formatted it"
    here = f"{sys.version_info.major}.{sys.version_info.minor}"
    if made_by.group(1) != here:  # argparse lays out help differently from one version to the next
        pytest.skip(f"the page was formatted by Python {made_by.group(1)}, this is {here}")
    assert page == render(), "docs/reference/cli.md is stale: run `python -m registration.cli.reference`"


def test_the_exit_code_table_is_the_one_help_prints():
    rows, notes = exit_code_rows()
    codes = [
        errors.EXIT_OK,
        errors.EXIT_BAD_ROWS,
        errors.EXIT_BAD_INPUT,
        errors.EXIT_INCONSISTENT,
        errors.EXIT_NUMERICAL,
        errors.EXIT_INTERRUPTED,
        errors.EXIT_BROKEN_PIPE,
        errors.EXIT_TERMINATED,
    ]
    assert [code for code, _ in rows] == codes
    assert all(meaning for _, meaning in rows)
    assert any(errors.DEBUG_ENV in note for note in notes)
    for code, meaning in rows:  # every entry, continuation lines joined, is in --help's text
        assert " ".join(meaning.split()[:3]) in " ".join(errors.EXIT_CODES_EPILOG.split())
        assert f"| {code} | " in render()


def test_every_command_has_its_section():
    text = render()
    progs = [p.prog for p in commands(build_parser())]
    assert progs[0] == "registration"
    for name in COMMANDS:
        assert f"registration {name}" in progs
    for prog in progs:
        assert f"## `{prog}`" in text
    assert "registration fleet register" in progs and "registration import asterix" in progs


def test_the_help_does_not_depend_on_the_terminal(monkeypatch):
    monkeypatch.setenv("COLUMNS", "40")
    narrow = render()
    monkeypatch.setenv("COLUMNS", "250")
    assert render() == narrow


def test_main_writes_the_page(tmp_path, capsys):
    out = tmp_path / "cli.md"
    assert main([str(out)]) == 0
    assert out.read_text(encoding="utf-8") == render()
    assert str(out) in capsys.readouterr().out


def test_every_option_help_is_on_the_page(monkeypatch):
    """The same check on any Python: argparse's layout varies by version, an option's help does not."""
    page = " ".join(PAGE.read_text(encoding="utf-8").split())
    monkeypatch.setenv("COLUMNS", "100000")  # one line per option: its flags, 2+ spaces, its help
    missing = []
    for parser in commands(build_parser()):
        for line in parser.format_help().splitlines():
            flags_help = re.match(r"^  (-\S.*?)\s{2,}(\S.*)$", line)
            if flags_help and " ".join(flags_help.group(2).split()) not in page:
                missing.append(f"{parser.prog} {flags_help.group(1)}: {flags_help.group(2)[:60]}")
    assert not missing, (
        "docs/reference/cli.md is stale: run `python -m registration.cli.reference`\n" + "\n".join(missing)
    )
