"""Stone Soup, imported once, or an ImportError that says how to install it.

Every module of :mod:`registration.interop` that needs Stone Soup imports this one first.
"""

from __future__ import annotations

__all__ = ["INSTALL_HINT", "STONESOUP_VERSION"]

INSTALL_HINT = 'pip install stonesoup (from a checkout of this package: pip install ".[stonesoup]")'

try:
    import stonesoup
except ImportError as exc:  # pragma: no cover - exercised by a test that hides the package
    raise ImportError(
        "registration.interop.stonesoup needs Stone Soup (the 'stonesoup' package, version 1.9 or "
        f"later), which is not installed: {INSTALL_HINT}"
    ) from exc

#: The installed Stone Soup version.
STONESOUP_VERSION: str = getattr(stonesoup, "__version__", "unknown")
