"""Wave motion of a simulated ship: sinusoidal pitch and roll (rad) against time (s)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["ShipMotion"]


@dataclass(frozen=True)
class ShipMotion:
    """Sinusoidal wave motion of a ship: pitch and roll amplitudes (rad) and periods (s).

    ``pitch(t) = pitch_amplitude sin(2 pi t / pitch_period + phase)``,
    ``roll(t) = roll_amplitude sin(2 pi t / roll_period + 1.3 phase + 0.7)`` (roll out of step with pitch).
    """

    pitch_amplitude: float = np.radians(2.0)
    pitch_period: float = 8.0
    roll_amplitude: float = np.radians(5.0)
    roll_period: float = 12.0

    def __post_init__(self):
        for name in ("pitch_amplitude", "roll_amplitude"):
            v = getattr(self, name)
            if not (0 <= v < np.pi / 4):
                raise ValueError(f"{name}: {v} rad is outside [0, pi/4) (pass radians, not degrees)")
        for name in ("pitch_period", "roll_period"):
            if not getattr(self, name) > 0:
                raise ValueError(f"{name}: must be > 0 s")

    def angles(self, t: np.ndarray, phase: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
        """Pitch and roll (rad) at times ``t`` (s) for a ship with wave ``phase`` (rad)."""
        pitch = self.pitch_amplitude * np.sin(2 * np.pi * t / self.pitch_period + phase)
        roll = self.roll_amplitude * np.sin(2 * np.pi * t / self.roll_period + 1.3 * phase + 0.7)
        return pitch, roll
