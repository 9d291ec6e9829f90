"""``fleet register --cat063 FILE``: the run's estimates as EUROCONTROL ASTERIX CAT063 sensor status
messages, one record per radar, with the encoder of the live service
(:func:`registration.io.asterix.encode.cat063.estimates_cat063`). The radars' SAC/SIC come from
the ``import_summary.json`` that ``registration import asterix`` wrote beside the tables."""

from __future__ import annotations

import argparse
import json
import os
from pathlib import Path

import numpy as np

__all__ = ["cat063_sources", "write_cat063"]

SUMMARY = "import_summary.json"


def cat063_sources(args: argparse.Namespace) -> dict[str, tuple[int, int]] | None:
    """Sensor -> (SAC, SIC) from the tables folder's import summary (None without ``--cat063``);
    ValueError naming ``--cat063`` when there is none."""
    if getattr(args, "cat063", None) is None:
        return None
    folder = getattr(args, "tables", None)
    path = Path(folder) / SUMMARY if folder is not None else None
    if path is None or not path.is_file():
        raise ValueError(
            f"--cat063: the radars' SAC/SIC come from {SUMMARY}, which 'registration import asterix' "
            "writes beside the tables; give --tables DIR of such an import"
        )
    try:
        sensors = json.loads(path.read_text(encoding="utf-8"))["sensors"]
        return {str(k): (int(v["sac"]), int(v["sic"])) for k, v in sensors.items()}
    except (ValueError, KeyError, TypeError, AttributeError) as exc:
        raise ValueError(f"--cat063: {path}: no sensors with their sac and sic ({exc})") from None


def write_cat063(
    path: Path, result, sources: dict[str, tuple[int, int]], time_s: float, service: tuple[int, int]
) -> Path:
    """Write the CAT063 message of ``result``'s estimates at ``time_s`` (s on the tables' time axis,
    counted from a midnight UTC) atomically to ``path``."""
    from registration.io.asterix.encode.cat063 import estimates_cat063

    layout = result.layout
    estimates: dict[str, dict[str, float]] = {}
    for i in np.asarray(layout.free):
        if np.isfinite(result.sigma[i]):
            estimates.setdefault(layout.objects[i], {})[layout.quantities[i]] = float(result.estimate[i])
    data = estimates_cat063(estimates, sources, float(time_s) % 86400.0, service)
    path = Path(path)
    temp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        temp.write_bytes(data)
        os.replace(temp, path)
    finally:
        temp.unlink(missing_ok=True)
    return path
