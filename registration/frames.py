"""Compatibility name for :mod:`registration.core.frames` (the frame transforms live there)."""

from registration.core.frames import *  # noqa: F401,F403
from registration.core.frames import __all__  # noqa: F401
