"""Which input file of the asynchronous form gives which radar's plots and which ship's navigation.

:func:`plan_sources` reads the column names of two plot files (radar A then B; a ``a_``/``b_``
prefix on the plot columns overrides the order) and of the navigation files, and returns one
:class:`Source` per file with its row layout and clock offset (s). Ambiguity is refused: both
plot files of one radar, a ship without navigation, or a ship's navigation given twice.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from registration.recorded.options import PairingOptions
from registration.recorded.reading.columns import NAV_FIELDS
from registration.recorded.reading.formats import read_columns
from registration.recorded.reading.rowcheck import Layout, nav_layout, plot_layout

__all__ = ["Source", "plan_sources"]


@dataclass
class Source:
    """One input file of the asynchronous form and what it provides."""

    path: Path
    layout: Layout
    clock_offset: float  # s that the file's clock reads ahead of the reference clock
    plots_of: str | None  # 'a'/'b' if the file holds that radar's plots
    nav_of: tuple[str, ...]  # ships whose navigation the file holds
    role: str  # human-readable

    def columns_for(self, sensor: str, kinds) -> list[int]:
        """Indices into the layout's non-time fields of ``sensor``'s ``kinds``."""
        out = []
        for kind in kinds:
            for j, f in enumerate(self.layout.fields[1:]):
                if f.kind == kind and (f.prefix == sensor or (f.prefix == "" and self.plots_of == sensor)):
                    out.append(j)
        return out


def _sensor_of_plot_file(cols: set[str]) -> str | None:
    has = [
        s
        for s in ("a", "b")
        if any(f"{s}_{k}_{u}" in cols for k, u in (("range", "m"), ("bearing", "deg"), ("elevation", "deg")))
    ]
    return has[0] if len(has) == 1 else None


def _plot_sensors(inputs: list[Path], cols: list[set[str]]) -> list[str]:
    """'a'/'b' for each of the two plot files: by column prefix, else by position."""
    first, second = (_sensor_of_plot_file(c) for c in cols)
    if first is None and second is None:
        first, second = "a", "b"
    elif first is None:
        first = "a" if second == "b" else "b"
    elif second is None:
        second = "a" if first == "b" else "b"
    assert first is not None and second is not None  # each branch above names both
    sensors = [first, second]
    if sensors[0] == sensors[1]:
        raise ValueError(
            f"both plot files {inputs[0]} and {inputs[1]} hold radar {sensors[0].upper()}'s plots (column "
            "prefix)"
        )
    return sensors


def _plot_source(path: Path, cols: set[str], sensor: str, options: PairingOptions) -> Source:
    prefixed = (
        f"{sensor}_range_m" in cols or f"{sensor}_bearing_deg" in cols or f"{sensor}_elevation_deg" in cols
    )
    lead = f"{sensor}_" if prefixed else ""
    with_nav = any(f"{lead}{f.file_name}" in cols for f in NAV_FIELDS)
    return Source(
        path,
        plot_layout(sensor, prefixed, with_nav),
        options.clock_offset(sensor),
        sensor,
        (sensor,) if with_nav else (),
        f"plots of radar {sensor.upper()}" + (" with navigation" if with_nav else ""),
    )


def _nav_source(path: Path) -> Source:
    cols = set(read_columns(path))
    ships = tuple(s for s in ("a", "b") if any(f"{s}_{f.file_name}" in cols for f in NAV_FIELDS))
    if not ships:
        raise ValueError(
            f"navigation file {path}: no navigation columns; expected time_s and a_lat_deg ... a_roll_deg "
            "and/or b_lat_deg ... b_roll_deg"
        )
    return Source(
        path,
        nav_layout(ships),
        0.0,
        None,
        ships,
        "navigation of ship(s) " + ", ".join(x.upper() for x in ships),
    )


def plan_sources(inputs: list[Path], navs: list[Path], options: PairingOptions) -> list[Source]:
    """The sources: radar A's plot file, radar B's, then the navigation files; refuse ambiguity."""
    if len(inputs) != 2:
        raise ValueError("the asynchronous form takes exactly two plot files (radar A, radar B)")
    cols = [set(read_columns(p)) for p in inputs]
    sensors = _plot_sensors(inputs, cols)
    sources = [_plot_source(path, c, s, options) for path, c, s in zip(inputs, cols, sensors)]
    sources += [_nav_source(path) for path in navs]
    for s in ("a", "b"):
        given = [src for src in sources if s in src.nav_of]
        if not given:
            raise ValueError(
                f"no navigation for ship {s.upper()}: give it in its plot file "
                f"({', '.join(f.file_name for f in NAV_FIELDS)}) or in a --nav file (prefixed {s}_)"
            )
        if len(given) > 1:
            raise ValueError(
                f"navigation of ship {s.upper()} is given twice ({given[0].path} and {given[1].path}); give "
                "it once"
            )
    # the first two sources are the plot files: plots_of is set
    return sorted(sources[:2], key=lambda src: str(src.plots_of)) + sources[2:]
