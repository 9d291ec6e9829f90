"""The fleet files' schemas are defined once (registration.io.fleet.schema): the reader's columns,
the `fleet register` help and docs/reference/fleet-tables.md all come from it, and the page fails
this test when it is stale (regenerate it: python -m registration.io.fleet >
docs/reference/fleet-tables.md)."""

from __future__ import annotations

import argparse
from pathlib import Path

from registration.cli import build_parser
from registration.io.fleet.reading.cells import FILE_COLUMNS
from registration.io.fleet.schema import FLEET_FILES
from registration.io.fleet.schemadoc import option_help, schema_markdown

PAGE = Path(__file__).resolve().parents[2] / "docs" / "reference" / "fleet-tables.md"


def test_the_reference_page_is_the_schema():
    assert PAGE.read_text(encoding="utf-8") == schema_markdown(), (
        "docs/reference/fleet-tables.md is stale: regenerate it with "
        "python -m registration.io.fleet > docs/reference/fleet-tables.md"
    )


def test_the_reader_checks_the_schemas_columns():
    assert list(FILE_COLUMNS) == list(FLEET_FILES)
    for name, table in FLEET_FILES.items():
        assert FILE_COLUMNS[name] == tuple(
            (c.file, c.column, c.unit, c.required, c.limits) for c in table.columns
        )
        assert all(c.text for c in table.columns)


def _register_parser() -> argparse.ArgumentParser:
    sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    fleet = sub.choices["fleet"]
    return next(a for a in fleet._actions if isinstance(a, argparse._SubParsersAction)).choices["register"]


def test_each_table_options_help_is_its_schema():
    helps = {a.dest: a.help for a in _register_parser()._actions}
    for name, table in FLEET_FILES.items():
        assert helps[name] == option_help(name)
        assert all(c.file in helps[name] for c in table.columns)
