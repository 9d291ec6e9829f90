"""The live service's state on disk (``--state DIR``): one file, ``DIR/state.npz``, written
atomically (a temporary file in DIR, flushed to disk, then renamed over the old one), so that a
crash at any moment leaves either the previous state or the new one, never half of one.

It holds the filter's checkpoint (:meth:`~registration.fleet.online.filter.FleetFilter.checkpoint`),
the recent estimates over time, and a JSON text (``meta``) with the alarms, the epochs processed, the
late plots and the data time. It is read with ``allow_pickle=False``: nothing in it is executed. A
``state.npz`` that is a symbolic link is refused. The plots of the epoch still open when the state
was written are not in it (at most one epoch, ``window_s`` of data, is lost on a restart), nor are
the residual sums (the page's residuals start again) or the duplicate check's memory.
"""

from __future__ import annotations

import json
import os
from collections import deque
from pathlib import Path

import numpy as np

from registration.live.estimator import Alarm, LiveEstimator

__all__ = ["STATE_FILE", "StateError", "load_state", "save_state"]

STATE_FILE = "state.npz"
_VERSION = 1


class StateError(ValueError):
    """A state file that cannot be used: unreadable, of another version, or of other sensors."""


def save_state(folder: Path, estimator: LiveEstimator) -> Path:
    """Write ``folder/state.npz`` atomically (module docstring); returns its path."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    arrays = {f"filter_{k}": v for k, v in estimator.filter.checkpoint().items()}
    h = estimator.history
    n = estimator.layout.n
    arrays["history_time"] = np.array([e[0] for e in h], dtype=np.float64)
    arrays["history_x"] = np.array([e[1] for e in h], dtype=np.float64).reshape(len(h), n)
    arrays["history_sigma"] = np.array([e[2] for e in h], dtype=np.float64).reshape(len(h), n)
    meta = {
        "version": _VERSION,
        "epochs": estimator.epochs,
        "late_plots": estimator.late_plots,
        "data_time_s": estimator.data_time_s,
        "alarms": [a.to_json() for a in estimator.alarms],
    }
    arrays["meta"] = np.frombuffer(json.dumps(meta).encode(), dtype=np.uint8)
    path = folder / STATE_FILE
    temp = folder / f".{STATE_FILE}.{os.getpid()}.tmp"
    try:
        with open(temp, "wb") as f:
            np.savez(f, **arrays)  # type: ignore[arg-type]  # numpy stubs: allow_pickle in **kwds
            f.flush()
            os.fsync(f.fileno())
        os.replace(temp, path)
    finally:
        temp.unlink(missing_ok=True)
    return path


def load_state(folder: Path, estimator: LiveEstimator) -> bool:
    """Restore ``estimator`` from ``folder/state.npz``; False when there is none (a first start).
    :class:`StateError` naming the file for one that cannot be used."""
    path = Path(folder) / STATE_FILE
    if path.is_symlink():
        raise StateError(
            f"{path}: a symbolic link; the state file must be a plain file written by the service"
        )
    if not path.exists():
        return False
    try:
        with np.load(path, allow_pickle=False) as z:
            arrays = {k: z[k] for k in z.files}
        meta = json.loads(arrays["meta"].tobytes().decode())
    except (OSError, ValueError, KeyError, json.JSONDecodeError) as exc:
        raise StateError(f"{path}: not a state file of this service ({exc})") from None
    if meta.get("version") != _VERSION:
        raise StateError(f"{path}: state version {meta.get('version')!r}, expected {_VERSION}")
    try:
        estimator.filter.restore(
            {k[len("filter_") :]: v for k, v in arrays.items() if k.startswith("filter_")}
        )
    except (ValueError, KeyError) as exc:
        raise StateError(f"{path}: {exc}") from None
    estimator.history = deque(
        zip(arrays["history_time"].tolist(), list(arrays["history_x"]), list(arrays["history_sigma"]))
    )
    estimator.epochs = int(meta["epochs"])
    estimator.late_plots = int(meta["late_plots"])
    estimator.data_time_s = meta["data_time_s"]
    estimator.alarms.extend(Alarm(**a) for a in meta["alarms"])
    estimator.rows_changed()
    return True
