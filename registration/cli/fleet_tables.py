"""The tables of ``fleet register`` opened once, in memory or as an archive read by parts, the same
way on both paths (:func:`registration.io.fleet.sources.open_fleet_tables`): the rows set aside
and the readers' notes printed, and ``rejected.csv`` written when no plot row is left."""

from __future__ import annotations

import argparse
from contextlib import ExitStack, contextmanager
from pathlib import Path
from typing import Iterator

from registration.cli.errors import writing
from registration.cli.staging import staged_outputs
from registration.io.fleet.archive import ParquetSource
from registration.io.fleet.folder import TABLE_NAMES
from registration.io.fleet.read import FleetTables
from registration.io.fleet.rejects import NoValidPlotsError
from registration.io.fleet.sources import open_fleet_tables

__all__ = ["REGISTER_OUTPUTS", "opened_tables", "write_rejected"]

#: What `fleet register` writes into --out (the outputs of an earlier run there are replaced whole).
REGISTER_OUTPUTS = frozenset(
    {
        "estimates.csv",
        "history.csv",
        "summary.json",
        "associations.csv",
        "rejected.csv",
        "estimates.png",
        "map.png",
        "residuals.png",
    }
)


def write_rejected(out: Path, frame) -> Path:
    """rejected.csv: the rows set aside (file, row, column, reason_code, reason)."""
    from registration.io.files.tablefile import write_frame

    path = out / "rejected.csv"
    with writing(path):
        write_frame(frame, path, "csv")
    return path


def _print_read(source: FleetTables | ParquetSource) -> None:
    """The bad rows set aside, counted per file and reason, and the readers' notes."""
    if isinstance(source, FleetTables) and source.rejected:
        frame = source.rejected_frame()
        per_file = {
            f: ", ".join(f"{n} {code}" for code, n in g.groupby("reason_code").size().items())
            for f, g in frame.groupby("file")
        }
        print(
            f"set aside {len(frame)} bad rows (in rejected.csv): "
            + "; ".join(f"{f}: {c}" for f, c in per_file.items())
        )
    for note in source.notes:  # ignored without an error, or suspicious without proof
        print(f"note: {note}")


@contextmanager
def opened_tables(
    args: argparse.Namespace, out: Path, lazy: bool = False
) -> Iterator[FleetTables | ParquetSource]:
    """The tables of ``--tables DIR`` and the table options (``--plots FILE`` ...), opened once: read
    whole, bad rows stopping the run or set aside (``--on-bad-row``), or with ``lazy`` the archive
    read by parts. With no plot row left, ``rejected.csv`` (the list of what was wrong) is the
    output written into ``out``."""
    given = {name: getattr(args, name, None) for name in TABLE_NAMES}
    with ExitStack() as stack:
        try:
            source = stack.enter_context(
                open_fleet_tables(
                    args.tables, given, on_bad_row=getattr(args, "on_bad_row", "stop"), lazy=lazy
                )
            )
        except NoValidPlotsError as exc:
            with staged_outputs(out, "registration fleet register", REGISTER_OUTPUTS) as folder:
                write_rejected(folder.path, exc.rejected_frame())
            raise
        _print_read(source)
        yield source
