"""Every function the runtime may call: the list ``python -m derive`` emits."""

from . import attitude, geodesy, kalman, landing, polar, pseudo_measurement
from .constants import CONSTANTS

MODULES = [geodesy, attitude, pseudo_measurement, polar, kalman, landing]


def all_specs() -> list:
    specs = [s for m in MODULES for s in m.specs()]
    names = [s.name for s in specs]
    dupes = {n for n in names if names.count(n) > 1}
    if dupes:
        raise ValueError(f"duplicate function names in derive/: {sorted(dupes)}")
    return specs


__all__ = ["all_specs", "CONSTANTS"]
