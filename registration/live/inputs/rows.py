"""Tables as dicts of equal-length column arrays (the stream inputs' plots, navigation and
references): :func:`concat_rows` puts the rows of several in one."""

from __future__ import annotations

import numpy as np

__all__ = ["concat_rows"]


def concat_rows(tables: list[dict | None]) -> dict | None:
    """The rows of ``tables`` in one table (None and tables without rows left out; None when no
    row is left). A column some tables lack is filled with NaN there, or '' for text."""
    kept: list[dict] = [t for t in tables if t is not None and t["time"].size]
    if not kept:
        return None
    keys = list(dict.fromkeys(k for t in kept for k in t))
    out = {}
    for k in keys:
        text = any(t[k].dtype.kind in "US" for t in kept if k in t)
        fill = "" if text else np.nan
        out[k] = np.concatenate([t[k] if k in t else np.full(t["time"].size, fill) for t in kept])
    return out
