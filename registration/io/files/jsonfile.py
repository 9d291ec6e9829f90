"""The one JSON writer of the commands' summaries (``summary.json``, ``import_summary.json``): a
number that JSON cannot hold (NaN, +-inf: an undetermined estimate, a failed statistic) is written
as ``null``, so a summary is always written; numpy scalars and arrays become JSON numbers and lists.
Nothing else non-standard slips through (``allow_nan=False``)."""

from __future__ import annotations

import json
import math
import os
from pathlib import Path
from typing import Any

import numpy as np

__all__ = ["json_safe", "json_text", "write_json"]


def json_safe(obj: Any) -> Any:
    """``obj`` with NaN and +-inf replaced by None, recursively through dicts, lists, tuples, numpy
    scalars and arrays (which become Python numbers and lists); other values are left as they are."""
    if isinstance(obj, dict):
        return {k: json_safe(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [json_safe(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return json_safe(obj.tolist())
    if isinstance(obj, np.generic):
        return json_safe(obj.item())
    if isinstance(obj, float) and not math.isfinite(obj):
        return None
    return obj


def json_text(obj: Any, indent: int | None = 2, default=None) -> str:
    """``obj`` as JSON text (:func:`json_safe`), ending with a newline; ``default`` as for
    :func:`json.dumps` (e.g. ``str`` for paths)."""
    return json.dumps(json_safe(obj), indent=indent, allow_nan=False, default=default) + "\n"


def write_json(path: Path, obj: Any, indent: int | None = 2, default=None, atomic: bool = False) -> None:
    """Write ``obj`` to ``path`` as :func:`json_text`; ``atomic``: through a fsync'ed temporary file
    and a rename, so ``path`` is either the old file or the whole new one."""
    text = json_text(obj, indent, default)
    if not atomic:
        Path(path).write_text(text)
        return
    tmp = Path(path).with_name(Path(path).name + ".tmp")
    with open(tmp, "w") as f:
        f.write(text)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)
