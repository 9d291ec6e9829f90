"""Checkpoints of a streaming registration run: exact, atomic, and safe to read.

Format: one UTF-8 JSON document (no pickle: reading it executes no code) ::

    {"format": "sensor-registration-checkpoint", "version": 1,
     "payload": {...}, "sha256": "<hex digest of the canonical payload text>"}

Floats inside the payload are stored as ``float.hex`` strings (``"0x1.921fb54442d18p+1"``) in
objects ``{"__f64__": [shape], "hex": [...]}`` so a restored state is bit-for-bit the saved one.
The digest covers the canonical text of the payload (sorted keys, no spaces): a truncated file is
not valid JSON and an edited one fails the digest; both raise :class:`CheckpointError` with the
file name, never a silent restart. (The digest detects damage and hand edits, it is not a
signature: anyone who can write the file can also recompute it.)

Writing is atomic: the document goes to ``FILE.tmp``, is flushed and fsync'ed, renamed over
``FILE`` and the directory is fsync'ed, so a kill at any moment leaves either the previous or the
new checkpoint, whole.
"""

from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path

import numpy as np

__all__ = [
    "CheckpointError",
    "save_checkpoint",
    "load_checkpoint",
    "fsync_dir",
    "encode",
    "decode",
    "FORMAT",
    "VERSION",
]

FORMAT = "sensor-registration-checkpoint"
VERSION = 1


class CheckpointError(ValueError):
    """A checkpoint that cannot be used: truncated, tampered with, or written for other inputs."""


def encode(obj):
    """Numbers and arrays -> JSON-safe values with exact float encoding."""
    if isinstance(obj, np.ndarray) or isinstance(obj, (np.floating,)):
        arr = np.asarray(obj, dtype=np.float64)
        return {"__f64__": list(arr.shape), "hex": [float(v).hex() for v in arr.ravel()]}
    if isinstance(obj, float):
        return {"__f64__": [], "hex": [obj.hex()]}
    if isinstance(obj, dict):
        return {str(k): encode(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [encode(v) for v in obj]
    if isinstance(obj, (np.integer,)):
        return int(obj)
    if obj is None or isinstance(obj, (bool, int, str)):
        return obj
    raise TypeError(f"cannot store {type(obj).__name__} in a checkpoint")


def decode(obj):
    """Inverse of :func:`encode`: float arrays come back as numpy arrays (0-d as Python floats)."""
    if isinstance(obj, dict):
        if set(obj) == {"__f64__", "hex"}:
            shape = tuple(int(s) for s in obj["__f64__"])
            vals = [float.fromhex(h) for h in obj["hex"]]
            if int(np.prod(shape)) != len(vals):
                raise ValueError("array shape does not match its values")
            return vals[0] if shape == () else np.array(vals, dtype=np.float64).reshape(shape)
        return {k: decode(v) for k, v in obj.items()}
    if isinstance(obj, list):
        return [decode(v) for v in obj]
    return obj


def _canonical(payload) -> bytes:
    return json.dumps(payload, sort_keys=True, separators=(",", ":"), allow_nan=False).encode()


def save_checkpoint(path, payload: dict) -> None:
    """Write ``payload`` (numbers, strings, lists, dicts, numpy arrays) atomically to ``path``."""
    path = Path(path)
    enc = encode(payload)
    doc = {
        "format": FORMAT,
        "version": VERSION,
        "payload": enc,
        "sha256": hashlib.sha256(_canonical(enc)).hexdigest(),
    }
    data = json.dumps(doc, sort_keys=True, separators=(",", ":"), allow_nan=False).encode() + b"\n"
    tmp = path.with_name(path.name + ".tmp")
    with open(tmp, "wb") as f:
        f.write(data)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)
    fsync_dir(path.parent if str(path.parent) else Path("."))


def fsync_dir(path: Path) -> None:
    """Make the renames inside folder ``path`` durable (fsync of the folder), where the file system
    allows it."""
    try:
        fd = os.open(path, os.O_RDONLY)
        try:
            os.fsync(fd)
        finally:
            os.close(fd)
    except OSError:  # some file systems refuse fsync on a folder; the renames are still atomic
        pass


def load_checkpoint(path) -> dict:
    """Read a checkpoint written by :func:`save_checkpoint`; raise :class:`CheckpointError` if damaged."""
    path = Path(path)
    hint = "; delete it to start the run over from the beginning"
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise CheckpointError(f"checkpoint {path}: cannot be read: {exc}") from exc
    try:
        doc = json.loads(raw.decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise CheckpointError(
            f"checkpoint {path} is truncated or corrupt (not valid JSON: {exc}){hint}"
        ) from exc
    if not isinstance(doc, dict) or doc.get("format") != FORMAT:
        raise CheckpointError(f"checkpoint {path} is not a sensor-registration checkpoint{hint}")
    if doc.get("version") != VERSION:
        raise CheckpointError(
            f"checkpoint {path} has version {doc.get('version')!r}; "
            f"this program reads version {VERSION}{hint}"
        )
    payload = doc.get("payload")
    try:
        digest = hashlib.sha256(_canonical(payload)).hexdigest()
    except (TypeError, ValueError) as exc:
        raise CheckpointError(f"checkpoint {path} is corrupt ({exc}){hint}") from exc
    if not isinstance(doc.get("sha256"), str) or digest != doc["sha256"]:
        raise CheckpointError(
            f"checkpoint {path} was modified or damaged (its content does not match its sha256){hint}"
        )
    try:
        return decode(payload)
    except (TypeError, ValueError, OverflowError) as exc:
        raise CheckpointError(f"checkpoint {path} is corrupt ({exc}){hint}") from exc
