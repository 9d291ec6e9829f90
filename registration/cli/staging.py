"""Whole publication of a command's outputs: ``--out`` never holds a mixture of two runs.

A command declares the file names it writes into ``--out`` (a frozenset) and writes them inside
``with staged_outputs(out, command, names) as folder:`` into ``folder.path``, a run folder
``OUT/partial-<pid>-<token>`` of its own (see :mod:`registration.io.output.outfolder`). When the
block ends normally the earlier run's outputs in ``out`` (every one of ``names`` it left, e.g. the
PNGs of a run with plots when this one has ``--no-plots``) are replaced by the new files; when it
raises (or is interrupted), the run folder is removed and ``out`` is left exactly as it was (a new
``out``, made for the run, is removed again with its new parents).
Files in ``out`` outside ``names`` are never touched. ``folder.final(p)`` is where a file ``p`` of
the run folder ends up, the path to print; an error writing a file of the run folder names that
final path too (the run folder is gone by the time the message is read).

The consistency gate (exit code 3) of a command comes after the block: an inconsistent run is
still published, then reported.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING

from registration.cli.errors import CommandError

if TYPE_CHECKING:  # imported when a command runs: `registration --help` does not load the recorded package
    from registration.io.output.outfolder import RunFolder

__all__ = ["staged_outputs"]


@contextlib.contextmanager
def staged_outputs(
    out: Path, command: str, names: frozenset, *, folders: frozenset = frozenset()
) -> Iterator["RunFolder"]:
    """A run folder inside ``out`` for ``command`` (e.g. ``"registration fuse"``) writing ``names``:
    its files replace the earlier run's outputs in ``out`` only when the block ends normally;
    otherwise the folder is removed and ``out`` is unchanged (or gone again, if the run made it).
    Leftovers of earlier runs that are gone (``partial-*`` folders, an interrupted publication) are
    cleaned up first. A folder in ``out`` named like one of the outputs (all files) is an error
    (CommandError), never replaced; ``folders``: outputs that are folders (e.g. Parquet parts), each
    replaced whole like a file."""
    from registration.io.output.outfolder import discard, new_run_folder, prepare_out, publish

    out = Path(out)
    for name in sorted(
        set(names) - set(folders)
    ):  # a folder named like a file output is the user's: never replaced
        if (out / name).is_dir():
            raise CommandError(
                f"cannot write {out / name}: Is a directory (not an output of {command}; move it, "
                "or give another --out)"
            )
    prepare_out(out, frozenset(names) | frozenset(folders))
    folder = new_run_folder(out, None, command, frozenset(names) | frozenset(folders))
    try:
        yield folder
    except CommandError as exc:
        discard(folder)
        raise CommandError(str(exc).replace(str(folder.path), str(out)), exc.code) from exc
    except OSError as exc:
        discard(folder)
        if isinstance(exc.filename, str) and exc.filename.startswith(str(folder.path)):
            exc.filename = str(folder.final(exc.filename))
        raise
    except BaseException:
        discard(folder)
        raise
    publish(folder)
