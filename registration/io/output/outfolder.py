"""The output folder of a run, replaced whole: ``--out`` never holds a mixture of two runs.

A run writes into a folder of its own inside OUT, ``OUT/partial-<pid>-<token>``, which holds a
file ``INCOMPLETE`` saying which run it is, its checkpoint and how to resume. Only when the run
has finished are its outputs *published* (:func:`publish`): the files an earlier run wrote into
OUT (:data:`OUTPUT_NAMES`) are moved aside, then the new ones are moved in (renames within one
file system; ``summary.json`` leaves first and arrives last), and both folders are removed. During
these few renames OUT carries an ``INCOMPLETE`` file of its own listing the files being moved,
so a kill at that moment leaves OUT marked, and the next run into OUT completes the move. Files
in OUT that a run does not write are never moved or deleted.

A failed or interrupted run without a checkpoint removes its folder: OUT is unchanged, and an OUT
that the run created (with its parents) is removed again, so a failed run aimed at a new folder
leaves no empty one (:attr:`RunFolder.created`). A checkpointed run keeps its folder: the
checkpoint records the folder's name, and rerunning the same command resumes inside it. A
checkpoint written before runs had folders of their own (no name recorded) resumes in OUT
itself, which is then marked ``INCOMPLETE`` until the run ends.
Leftover folders of processes that are gone and cannot be resumed are removed by the next run.

A marker is read as untrusted input: it may name only a run folder of this module's own making
(``partial-<pid>-<hex>``, directly inside OUT, not a symbolic link) and plain file names; a
marker that names anything else is refused with a one-line :class:`OutputFolderError`, and
nothing is moved or deleted. Ctrl-C and SIGTERM are held back during the renames
(:mod:`registration.io.output.signals`), so OUT holds exactly the old outputs or exactly the new
ones when the process stops; after a SIGKILL the marker stays, and the next run completes the move.
"""

from __future__ import annotations

import fnmatch
import json
import os
import re
import secrets
import shutil
import time
from dataclasses import dataclass
from pathlib import Path

from registration.io.output.checkpoint import CheckpointError, fsync_dir, load_checkpoint
from registration.io.output.signals import deferred_signals, publication_step

__all__ = [
    "OUTPUT_NAMES",
    "MARKER",
    "OutputFolderError",
    "RunFolder",
    "prepare_out",
    "new_run_folder",
    "mark_in_place",
    "publish",
    "discard",
    "records_folder",
    "make_folders",
    "remove_empty_folders",
]

#: What a run writes into OUT (a Parquet output is a folder of parts).
OUTPUT_NAMES = frozenset(
    {
        "estimates.csv",
        "estimates.parquet",
        "positions.csv",
        "positions.parquet",
        "rejected.csv",
        "summary.json",
        "estimates.png",
        "differences.png",
        "tracks.png",
        "paired.csv",
        "paired.parquet",
        "pairing.json",
        "unpaired.csv",
    }
)
#: The file that marks a folder whose contents are not a finished run.
MARKER = "INCOMPLETE"
_PARTIAL = "partial-"
_ASIDE = ".replaced-"
#: The only folder a marker may name: one this module made (``partial-<pid>-<hex token>``).
_RUN_FOLDER = re.compile(r"partial-[0-9]+-[0-9a-f]+")


class OutputFolderError(ValueError):
    """An ``--out`` that cannot be used: a file, or a folder that cannot be created or written."""


def _is_output(name: str, names: frozenset = OUTPUT_NAMES) -> bool:
    """A name a run writes (one of ``names``, or matching one of them that holds a ``*``, such as
    ``diagnostics_*.png``: one file per sensor), or one of its temporary files (``*.tmp``,
    ``paired.*.partial``)."""
    for suffix in (".tmp", ".partial"):
        if name.endswith(suffix):
            name = name[: -len(suffix)]
    return name in names or any("*" in n and fnmatch.fnmatchcase(name, n) for n in names)


@dataclass(frozen=True)
class RunFolder:
    """Where a run writes (``path``) and where its outputs end up (``out``, the ``--out`` folder).
    ``path == out`` for a checkpoint of an older version resumed in place. ``created``: the
    folders this run made for ``out`` (``out`` first, then its new parents), removed again by
    :func:`discard` when they are left empty."""

    out: Path
    path: Path
    command: str = "registration register"
    names: frozenset = OUTPUT_NAMES  # what the command writes into OUT (earlier ones are replaced)
    created: tuple = ()

    @property
    def in_place(self) -> bool:
        return self.path == self.out

    def final(self, path) -> Path:
        """Where ``path`` (a file of this folder) is once the run is published."""
        path = Path(path)
        try:
            return self.out / path.relative_to(self.path)
        except ValueError:
            return path


def _pid_alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError):
        return True
    return True


def _pid_of(name: str) -> int | None:
    """The process id in ``partial-<pid>-<token>`` or ``.replaced-partial-<pid>-<token>``."""
    try:
        return int(name.removeprefix(_ASIDE).removeprefix(_PARTIAL).split("-")[0])
    except ValueError:
        return None


def _write_text(path: Path, text: str) -> None:
    with open(path, "w") as f:
        f.write(text)
        f.flush()
        os.fsync(f.fileno())


def _remove(path: Path) -> None:
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path)
    elif path.exists() or path.is_symlink():
        path.unlink()


def _marker_fields(path: Path) -> dict:
    """The ``key: value`` lines of a marker file (empty if it cannot be read)."""
    try:
        lines = path.read_text().splitlines()
    except (OSError, UnicodeDecodeError):
        return {}
    return dict(line.split(": ", 1) for line in lines if ": " in line and not line.startswith(" "))


def make_folders(out: Path) -> tuple[Path, ...]:
    """Create the folder ``out`` and its missing parents; the ones created, ``out`` first (OSError
    if impossible)."""
    missing = tuple(p for p in (out, *out.parents) if not p.exists())
    out.mkdir(parents=True, exist_ok=True)
    return missing


def remove_empty_folders(folders) -> None:
    """Remove each of ``folders`` (deepest first, as :func:`make_folders` lists them) while it is
    empty; stop at the first that is not (or is gone, or cannot be removed)."""
    for folder in folders:
        try:
            folder.rmdir()
        except OSError:
            return


def records_folder(checkpoint, name: str) -> bool:
    """Whether the checkpoint file ``checkpoint`` records the run folder ``name`` (True when it
    cannot be read: it may still be needed)."""
    if checkpoint is None or not Path(checkpoint).exists():
        return False
    try:
        return load_checkpoint(checkpoint).get("outputs", {}).get("folder") == name
    except CheckpointError:
        return True


def prepare_out(out: Path, output_names: frozenset = OUTPUT_NAMES) -> None:
    """Check that ``out`` is a folder or can be created (a new one is created by
    :func:`new_run_folder`, so a run that fails before leaves none); in an existing one, complete
    a publication that was interrupted and remove leftovers of runs that are gone and cannot be
    resumed. Raises :class:`OutputFolderError` for an unusable ``out``. ``output_names``: what
    the command writes into ``out``."""
    if out.exists() and not out.is_dir():
        raise OutputFolderError(
            f"--out {out}: is a file, not a folder; give a folder (it is created if missing)"
        )
    try:
        created = make_folders(out)
    except OSError as exc:
        raise OutputFolderError(f"--out {out}: cannot create the folder: {exc.strerror or exc}") from exc
    if created:  # a new folder: nothing to complete or clean; the run creates it again
        remove_empty_folders(created)
        return
    _complete_publication(out, output_names)
    for d in sorted(out.glob(f"{_PARTIAL}*")) + sorted(out.glob(f"{_ASIDE}*")):
        pid = _pid_of(d.name)
        if d.is_symlink() or not d.is_dir() or pid is None or _pid_alive(pid):
            continue  # a symbolic link is never followed
        if d.name.startswith(_ASIDE):
            shutil.rmtree(d, ignore_errors=True)
            continue
        ckpt = _marker_fields(d / MARKER).get("checkpoint")
        # no checkpoint line (no marker, or an empty one: the run failed as it started, a full disk
        # say): nothing can resume it
        if ckpt in (None, "none") or not records_folder(ckpt, d.name):
            shutil.rmtree(d, ignore_errors=True)


def _complete_publication(out: Path, output_names: frozenset = OUTPUT_NAMES) -> None:
    """Finish moving the outputs of a run whose publication into ``out`` was interrupted (its
    process is gone). Without its run folder, ``out`` stays marked unless every file arrived."""
    fields = _marker_fields(out / MARKER)
    if "publishing" not in fields:
        return
    work, names = _publication_of(out, fields)
    pid = _pid_of(work.name)
    if pid is not None and _pid_alive(pid):
        return
    if work.is_dir() or all((out / n).exists() for n in names):
        _move_in(out, work, names, output_names)


def _refuse(out: Path, what: str) -> OutputFolderError:
    return OutputFolderError(
        f"{out / MARKER}: {what}; it is not a marker this tool wrote, so nothing was moved or deleted: "
        f"check {out}, then delete {out / MARKER} to go on"
    )


def _publication_of(out: Path, fields: dict) -> tuple[Path, list[str]]:
    """The run folder and the file names an interrupted publication's marker names, checked: the
    folder must be a run folder this module makes (``partial-<pid>-<hex>``), a direct child of
    ``out`` and no symbolic link; each name a plain file name (no separator, no ``..``). Anything
    else is refused (:class:`OutputFolderError`) before a single file is moved or deleted, so a
    crafted marker cannot make a run delete or move anything outside ``out``."""
    name = fields["publishing"]
    if not _RUN_FOLDER.fullmatch(name):
        raise _refuse(out, f"names {name!r} as the folder being published, not a run folder")
    work = out / name
    if work.is_symlink():
        raise _refuse(out, f"the folder it names, {name}, is a symbolic link")
    try:
        names = json.loads(fields.get("files", "[]"))
    except json.JSONDecodeError as exc:
        raise OutputFolderError(
            f"{out / MARKER}: damaged (its file list cannot be read); the folder holds an "
            "interrupted publication: check it, then delete the marker to go on"
        ) from exc
    if not isinstance(names, list) or not all(_plain_name(n) for n in names):
        raise _refuse(out, "its file list holds something other than plain file names")
    return work, names


def _is_summary(name: str) -> bool:
    """``summary.json`` or ``import_summary.json``: the file that says a run is whole."""
    return name.endswith("summary.json")


def _plain_name(name: object) -> bool:
    """A file name with no folder part: not empty, no separator or NUL, not ``.`` or ``..``."""
    return (
        isinstance(name, str)
        and name not in ("", ".", "..")
        and not any(c in name for c in ("/", "\\", "\0"))
    )


def new_run_folder(
    out: Path, checkpoint, command: str = "registration register", output_names: frozenset = OUTPUT_NAMES
) -> RunFolder:
    """A new, empty run folder inside ``out`` (created if missing, with its parents) with its
    ``INCOMPLETE`` marker, for ``command`` writing ``output_names``."""
    created: tuple[Path, ...] = ()
    for _ in range(100):
        path = out / f"{_PARTIAL}{os.getpid()}-{secrets.token_hex(3)}"
        try:
            made = make_folders(out)
            created = created or made
            path.mkdir()
            break
        except (FileExistsError, FileNotFoundError):  # taken, or out removed meanwhile by a failed run: again
            continue
        except OSError as exc:
            raise OutputFolderError(
                f"--out {out}: cannot write in the folder: {exc.strerror or exc}"
            ) from exc
    else:
        raise OutputFolderError(f"--out {out}: cannot make a run folder in it")
    if checkpoint is None:
        how = (
            "checkpoint: none\nWithout --checkpoint this run cannot be resumed; once process "
            f"{os.getpid()} is gone the folder can be deleted (the next run into {out} deletes it).\n"
        )
    else:
        how = (
            f"checkpoint: {Path(checkpoint).resolve()}\nTo resume, rerun the same command (same inputs, "
            "options, --out and --checkpoint); it continues in this folder.\n"
        )
    _write_text(
        path / MARKER,
        f"This folder holds the unfinished outputs of a `{command}` run (process "
        f"{os.getpid()}, started {time.strftime('%Y-%m-%d %H:%M:%S')}). They are moved into "
        f"{out} when the run finishes; until then {out} keeps what it held before.\n" + how,
    )
    return RunFolder(out, path, command, frozenset(output_names), created)


def mark_in_place(folder: RunFolder, checkpoint) -> None:
    """Mark ``out`` itself incomplete while a checkpoint of an older version resumes in it."""
    make_folders(folder.out)
    _write_text(
        folder.out / MARKER,
        "The outputs in this folder are those of an unfinished `registration register` run.\n"
        f"checkpoint: {Path(checkpoint).resolve()}\nTo resume, rerun the same command.\n",
    )


def publish(folder: RunFolder) -> None:
    """Replace the outputs of an earlier run in ``folder.out`` by those of ``folder.path``."""
    out = folder.out
    if folder.in_place:
        (out / MARKER).unlink(missing_ok=True)
        return
    with deferred_signals():  # Ctrl-C or SIGTERM now takes effect once the outputs are whole
        _publish(folder)


def _publish(folder: RunFolder) -> None:
    out = folder.out
    fields = _marker_fields(out / MARKER)
    if fields.get("publishing") == folder.path.name:  # this very publication was interrupted: same files
        names = _publication_of(out, fields)[1]
    else:
        names = sorted(
            (p.name for p in folder.path.iterdir() if p.name != MARKER),
            key=lambda n: (_is_summary(n), n),  # the summary arrives last
        )
        _write_text(
            out / MARKER,
            f"The outputs of a `{folder.command}` run are being moved into this folder. If "
            f"this file stays, that was interrupted: the next run into {out} completes it.\n"
            f"publishing: {folder.path.name}\nfiles: {json.dumps(names)}\n",
        )
        fsync_dir(out)
    _move_in(out, folder.path, names, folder.names)


def _move_in(out: Path, work: Path, names: list[str], output_names: frozenset = OUTPUT_NAMES) -> None:
    """Move ``names`` from ``work`` into ``out``, earlier outputs aside first; safe to repeat
    after an interruption (what has already arrived stays)."""
    aside = out / (_ASIDE + work.name)
    aside.mkdir(exist_ok=True)
    new = set(names)
    old = [
        p
        for p in out.iterdir()
        if _is_output(p.name, output_names) and (p.name not in new or (work / p.name).exists())
    ]
    step = 0
    for p in sorted(old, key=lambda p: not _is_summary(p.name)):  # the summary leaves first
        _remove(aside / p.name)
        publication_step(step)
        os.rename(p, aside / p.name)
        step += 1
    for name in names:
        if (work / name).exists():
            publication_step(step)
            os.rename(work / name, out / name)
            step += 1
    fsync_dir(out)
    (out / MARKER).unlink(missing_ok=True)
    shutil.rmtree(aside, ignore_errors=True)
    shutil.rmtree(work, ignore_errors=True)


def discard(folder: RunFolder) -> None:
    """Remove a run folder that will never be published (never ``out`` itself), then ``out`` and
    its parents if this run created them and they are empty."""
    if not folder.in_place:
        shutil.rmtree(folder.path, ignore_errors=True)
        remove_empty_folders(folder.created)
