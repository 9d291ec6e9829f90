"""Every function the runtime may call (the list ``python -m derive`` emits), with the constants
and variant names recorded beside them in the manifest."""

from . import attitude, eccentric, fleet, geodesy, kalman, landing, polar, pseudo_measurement, tracking
from .constants import CONSTANTS

MODULES = [geodesy, attitude, pseudo_measurement, polar, kalman, landing, fleet, eccentric, tracking]

#: Variant names functions are emitted for, by kind, in derive's order (recorded in the manifest).
VARIANTS = {
    "linearization": list(kalman.LINEARIZATIONS),
    "t_variant": list(geodesy.T_VARIANTS),
    "covariance_update": list(kalman.COVARIANCE_UPDATES),
}


def all_specs() -> list:
    """Every function spec of the derive modules; ValueError on a duplicate name."""
    specs = [s for m in MODULES for s in m.specs()]
    names = [s.name for s in specs]
    dupes = {n for n in names if names.count(n) > 1}
    if dupes:
        raise ValueError(f"duplicate function names in derive/: {sorted(dupes)}")
    return specs


__all__ = ["CONSTANTS", "MODULES", "VARIANTS", "all_specs"]
