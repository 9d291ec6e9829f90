"""matplotlib for the package's PNG plots: the non-interactive Agg backend, imported on first use;
the colour-blind-safe palette the figures share, and one colour and marker per label.

Colours: the Okabe-Ito palette (Okabe and Ito 2008, "Color Universal Design"), whose colours stay
apart for viewers with red-green colour blindness. Two curves that are compared in a figure
(before/after, one method against another) take colours of it that differ in lightness as well as
hue, for example ``blue`` and ``orange``, never a red against a green.
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["LABEL_COLOURS", "LABEL_MARKERS", "OKABE_ITO", "label_style", "pyplot", "save_figure"]

#: The Okabe-Ito palette by name (hex sRGB).
OKABE_ITO = {
    "black": "#000000",
    "orange": "#E69F00",
    "sky_blue": "#56B4E9",
    "bluish_green": "#009E73",
    "yellow": "#F0E442",
    "blue": "#0072B2",
    "vermillion": "#D55E00",
    "reddish_purple": "#CC79A7",
}
#: Colours cycled over the labels of a figure (yellow is too faint on white for small markers).
LABEL_COLOURS = tuple(
    OKABE_ITO[k]
    for k in ("blue", "orange", "bluish_green", "vermillion", "reddish_purple", "sky_blue", "black")
)
#: Markers cycled over the labels of a figure; 8 markers against 7 colours: 56 distinct pairs.
LABEL_MARKERS = ("o", "s", "^", "D", "v", "P", "X", "*")


def label_style(k: int) -> tuple[str, str]:
    """(colour, marker) of the ``k``-th label of a figure: colour ``k mod 7``, marker ``k mod 8``,
    so that labels 0..55 each have their own pair and neighbours differ in both."""
    return LABEL_COLOURS[k % len(LABEL_COLOURS)], LABEL_MARKERS[k % len(LABEL_MARKERS)]


def pyplot():
    """``matplotlib.pyplot`` with the Agg backend (no display needed)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def save_figure(fig, path, dpi: int = 100) -> Path:
    """Write ``fig`` as the PNG ``path`` at ``dpi`` dots per inch, close it and return the path."""
    fig.savefig(path, dpi=dpi)
    pyplot().close(fig)
    return Path(path)
