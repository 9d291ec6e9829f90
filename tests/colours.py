"""Whether two plot colours stay apart for viewers with red-green colour blindness.

Each colour is passed through the protanopia and deuteranopia simulations of Machado, Oliveira and
Fernandes (2009, severity 1.0, linear RGB) and compared in CIELAB (CIE76 colour difference). Two
colours are told apart when they differ by at least ``MIN_DELTA_E`` for normal vision and under
both simulations. tab:red against tab:green, which the figures used, differs by 120 for normal
vision but by only 7 for a deuteranope; Okabe-Ito orange against blue differs by 110 or more in
all three.
"""

from __future__ import annotations

import numpy as np
from matplotlib.colors import to_rgb

__all__ = ["MIN_DELTA_E", "chromatic", "colours_told_apart", "delta_e", "figure_colours_told_apart"]

MIN_DELTA_E = 20.0

_SIMULATIONS = {
    "normal": np.eye(3),
    "protanopia": np.array(
        [[0.152286, 1.052583, -0.204868], [0.114503, 0.786281, 0.099216], [-0.003882, -0.048116, 1.051998]]
    ),
    "deuteranopia": np.array(
        [[0.367322, 0.860646, -0.227968], [0.280085, 0.672501, 0.047413], [-0.011820, 0.042940, 0.968881]]
    ),
}
_XYZ = np.array([[0.4124, 0.3576, 0.1805], [0.2126, 0.7152, 0.0722], [0.0193, 0.1192, 0.9505]])
_WHITE = _XYZ @ np.ones(3)


def _linear(c: np.ndarray) -> np.ndarray:
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def _lab(linear_rgb: np.ndarray) -> np.ndarray:
    t = (_XYZ @ np.clip(linear_rgb, 0, 1)) / _WHITE
    f = np.where(t > (6 / 29) ** 3, np.cbrt(t), t / (3 * (6 / 29) ** 2) + 4 / 29)
    return np.array([116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2])])


def delta_e(a, b, vision: str = "normal") -> float:
    """CIE76 difference of matplotlib colours ``a`` and ``b`` as seen with ``vision``."""
    m = _SIMULATIONS[vision]
    la, lb = (_lab(m @ _linear(np.array(to_rgb(c)))) for c in (a, b))
    return float(np.linalg.norm(la - lb))


def colours_told_apart(a, b) -> bool:
    """True when ``a`` and ``b`` differ by at least MIN_DELTA_E for every vision simulated."""
    return all(delta_e(a, b, v) >= MIN_DELTA_E for v in _SIMULATIONS)


def chromatic(colour) -> bool:
    """True for a colour with a hue (not black, white or a grey)."""
    r, g, b = to_rgb(colour)
    return max(r, g, b) - min(r, g, b) > 0.15


def figure_colours_told_apart(fig) -> list[tuple[str, str]]:
    """The pairs of labelled, chromatic line colours of any axes of ``fig`` that a viewer with
    red-green colour blindness could confuse ([] when all are told apart)."""
    bad = []
    for ax in fig.axes:
        colours = {
            line.get_label(): line.get_color()
            for line in ax.get_lines()
            if not line.get_label().startswith("_") and chromatic(line.get_color())
        }
        names = sorted(colours)
        bad += [
            (a, b)
            for i, a in enumerate(names)
            for b in names[i + 1 :]
            if to_rgb(colours[a]) != to_rgb(colours[b]) and not colours_told_apart(colours[a], colours[b])
        ]
    return bad
