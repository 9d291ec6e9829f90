"""The tables of ``fleet register`` opened once, in memory or as an archive read by parts, the same
way on both paths (:func:`registration.io.fleet.sources.open_fleet_tables`): the rows set aside
and the readers' notes printed; a folder that is not a finished output warned about."""

from __future__ import annotations

import argparse
from contextlib import ExitStack, contextmanager
from pathlib import Path
from typing import Iterator

from registration.cli.errors import writing
from registration.io.fleet.archive.parquet import ParquetSource
from registration.io.fleet.folder import TABLE_NAMES
from registration.io.fleet.reading.read import FleetTables
from registration.io.fleet.sources import open_fleet_tables

__all__ = ["REGISTER_OUTPUTS", "opened_tables", "warn_unfinished", "write_rejected"]

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
        "estimates_by_period.csv",
        "changes.csv",
        "bias_periods.png",
        "diagnostics_*.png",  # one per sensor
    }
)


def write_rejected(out: Path, frame) -> Path:
    """rejected.csv: the rows set aside (file, row, column, reason_code, reason)."""
    from registration.io.files.tablefile import write_frame

    path = out / "rejected.csv"
    with writing(path):
        write_frame(frame, path, "csv")
    return path


def warn_unfinished(folders: list[Path]) -> None:
    """One line on stderr per folder that carries the publication marker (``INCOMPLETE``): it is not
    a finished output (a run may be publishing into it, or was interrupted); the tables are read
    all the same."""
    import sys

    from registration.io.output.outfolder import MARKER

    for folder in dict.fromkeys(f.resolve() for f in folders):
        if (folder / MARKER).exists():
            print(
                f"warning: {folder} carries {MARKER}: it is not a finished output (a run may be "
                "publishing into it, or was interrupted); reading its tables all the same",
                file=sys.stderr,
            )


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
    read by parts. With no plot row left the run fails and ``out`` is left as it was. A folder read
    that carries the publication marker is warned about (:func:`warn_unfinished`)."""
    given = {name: getattr(args, name, None) for name in TABLE_NAMES}
    warn_unfinished(
        ([Path(args.tables)] if args.tables else []) + [Path(p).parent for p in given.values() if p]
    )
    with ExitStack() as stack:
        source = stack.enter_context(  # no plot row left: the error, --out untouched
            open_fleet_tables(args.tables, given, on_bad_row=getattr(args, "on_bad_row", "stop"), lazy=lazy)
        )
        _print_read(source)
        yield source
