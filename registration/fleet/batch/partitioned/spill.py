"""A partition's design and latest normal equations kept on local disk between the passes of the
partitioned solver (:mod:`registration.fleet.batch.partitioned.partition_passes`,
docs/howto/register-an-archive.md):
the spill cache.

A file's name or its tag (checked before its arrays are read) is a digest of what it holds (the
partition's key; the point's states and coefficients). It is written whole under a temporary name
and renamed (after the file it replaces is removed), so a reader sees a whole file or none. A file
that is missing (another worker, another machine, removed, being replaced) or unreadable is a
miss: the pass builds the value again from the archive, exactly as without the cache, and writes
it. So the cache changes no bit of a result, and a task run again after a lost worker is still a
pure function of its arguments.

A file is one pickle (protocol 5) whose arrays are stored out of band after it, each aligned to
64 bytes, and read back with one read into one buffer: loading a partition costs one copy from the
page cache, without pickle's per-array overhead.
"""

from __future__ import annotations

import hashlib
import os
import pickle
import shutil
import struct
import tempfile
import threading

import numpy as np

__all__ = ["digest", "load", "make_folder", "remove_folder", "save"]

_MAGIC = b"RSPILL1\0"
_ALIGN = 64


def digest(*parts) -> str:
    """A file name for ``parts`` (bytes are hashed as they are, anything else by its repr)."""
    h = hashlib.sha256()
    for p in parts:
        h.update(p if isinstance(p, bytes) else repr(p).encode())
        h.update(b"\0")
    return h.hexdigest()[:40]


def save(folder: str, name: str, value, tag: str = "") -> None:
    """Write ``value`` to ``folder/name`` atomically (the folder is made if missing), labelled ``tag``
    (checked by :func:`load` before the arrays are read). A failure to write (disk full, folder
    removed) is ignored: the value is built again when it is needed."""
    buffers: list[pickle.PickleBuffer] = []
    meta = pickle.dumps(value, protocol=5, buffer_callback=buffers.append)
    raws = [b.raw() for b in buffers]
    offsets, at = [], 0
    for r in raws:
        at = -(-at // _ALIGN) * _ALIGN
        offsets.append((at, r.nbytes))
        at += r.nbytes
    table = pickle.dumps((tag, offsets), protocol=5)
    head = _MAGIC + struct.pack("<QQ", len(meta), len(table))
    start = -(-(len(head) + len(meta) + len(table)) // _ALIGN) * _ALIGN
    path = os.path.join(folder, name)
    tmp = f"{path}.{os.getpid()}.{threading.get_ident()}.tmp"
    try:
        os.makedirs(folder, exist_ok=True)
        with open(tmp, "wb") as f:
            f.write(head + meta + table)
            for (off, _), r in zip(offsets, raws):
                f.seek(start + off)
                f.write(r)
        try:  # rename onto no file: ext4 writes a file renamed over another to disk at once (auto_da_alloc)
            os.remove(path)
        except FileNotFoundError:
            pass
        os.replace(tmp, path)
    except OSError:
        try:
            os.remove(tmp)
        except OSError:
            pass


def load(folder: str, name: str, tag: str | None = None):
    """The value saved as ``folder/name``, or None when there is none, it cannot be read or its tag
    is not ``tag`` (None: any)."""
    try:
        with open(os.path.join(folder, name), "rb") as f:
            head = f.read(len(_MAGIC) + 16)
            if len(head) != len(_MAGIC) + 16 or not head.startswith(_MAGIC):
                return None
            n_meta, n_table = struct.unpack("<QQ", head[len(_MAGIC) :])
            meta, table = f.read(n_meta), f.read(n_table)
            found, offsets = pickle.loads(table)
            if tag is not None and found != tag:
                return None
            start = -(-(len(head) + n_meta + n_table) // _ALIGN) * _ALIGN
            size = max((off + n for off, n in offsets if n), default=0)
            data = np.empty(size, dtype=np.uint8)  # not zeroed, as a bytearray would be
            f.seek(start)
            if f.readinto(data.data) != size:
                return None
    except (OSError, EOFError, pickle.UnpicklingError, struct.error, ValueError, TypeError):
        return None
    view = data.data
    return pickle.loads(meta, buffers=[view[off : off + n] for off, n in offsets])


def make_folder(parent: str | None = None) -> str:
    """A new empty folder for one solve's spill files (in ``parent``, default the system's temp folder)."""
    return tempfile.mkdtemp(prefix="registration-spill-", dir=parent)


def remove_folder(folder: str) -> None:
    """Remove a spill folder and its files (nothing if it is gone)."""
    shutil.rmtree(folder, ignore_errors=True)
