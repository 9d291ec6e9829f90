"""The fleet's figures, checked on the matplotlib figures themselves: undetermined states drawn as
such, the identifiable sums drawn, titles inside the figure and clear of the panels, x tick labels
under every column, one colour and marker per target on the map."""

from types import SimpleNamespace

import numpy as np
import pytest
from matplotlib.text import Text

from registration.fleet import association_scenario, fleet_scenario, register_online, solve_batch
from registration.fleet.plots import estimates_figure, history_figure, map_figure, residuals_figure


@pytest.fixture(scope="module")
def level():
    sc = fleet_scenario(2, ship_motion=False, duration_s=150.0)
    return sc, solve_batch(sc.problem())


def _renderer(fig):
    fig.canvas.draw()
    return fig.canvas.get_renderer()


def _inside(fig, artist) -> bool:
    box = artist.get_window_extent(_renderer(fig))
    return box.x0 >= 0 and box.y0 >= 0 and box.x1 <= fig.bbox.width and box.y1 <= fig.bbox.height


def test_undetermined_states_are_drawn_as_undetermined(level):
    sc, result = level
    fig = estimates_figure(result, sc.truth_state)
    undetermined = {n for n, s in zip(result.layout.names, result.sigma) if np.isinf(s)}
    assert {"A:heading_error", "A-3D:bearing_bias", "B:heading_error"} <= undetermined
    seen = set()
    for ax in fig.axes:
        names = [t.get_text() for t in ax.get_yticklabels()]
        for bar in ax.patches:
            y = bar.get_y() + bar.get_height() / 2
            name = names[int(round(y))]
            assert bool(bar.get_hatch()) == (name in undetermined), name
            seen.add(name)
    assert undetermined <= seen
    legend = [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()]
    legend += [t.get_text() for lg in fig.legends for t in lg.get_texts()]
    assert any("undetermined" in t for t in legend), legend
    ticks = {t.get_text() for ax in fig.axes for t in ax.get_yticklabels()}
    assert "A:heading_error + A-3D:bearing_bias" in ticks  # the sums the data determine are drawn too


@pytest.mark.parametrize("online", [False, True])
def test_the_residuals_title_is_inside_the_figure(level, online):
    _, result = level
    title = ("at the final online estimate: " + result.chi_square.text()) if online else None
    fig = residuals_figure(result, title)
    texts = [t for t in fig.findobj(Text) if "mean squared normalised residual" in t.get_text()]
    assert texts and all(_inside(fig, t) for t in texts)


@pytest.fixture(scope="module")
def online_23():
    """An online run with 23 free states (C's roll error held fixed): the last row of panels is not full."""
    sc = fleet_scenario(0, duration_s=60.0)
    platforms = dict(sc.platforms)
    platforms["prior_roll"] = np.where(platforms["platform"] == "C", 0.0, platforms["prior_roll"])
    result = register_online(sc.plots, sc.sensors, sc.navigation, platforms, sc.references, residuals=False)
    assert result.layout.free.size == 23
    return sc, result


def test_history_title_clear_of_the_panels_and_x_labels_under_every_column(online_23):
    sc, result = online_23
    fig = history_figure(result, sc.truth_state)
    renderer = _renderer(fig)
    title = next(t for t in fig.findobj(Text) if t.get_text().startswith("Online estimates"))
    assert _inside(fig, title)
    box = title.get_window_extent(renderer)
    tops = [
        max(ax.title.get_window_extent(renderer).y1, ax.get_window_extent(renderer).y1)
        for ax in fig.axes
        if ax.get_visible()
    ]
    assert box.y0 - max(tops) >= 5  # pixels of white between the title and the panels' titles
    visible = [ax for ax in fig.axes if ax.get_visible()]
    columns = {}
    for ax in visible:
        spec = ax.get_subplotspec()
        col, row = spec.colspan.start, spec.rowspan.start
        if col not in columns or row > columns[col][0]:
            columns[col] = (row, ax)
    assert len(columns) == 4
    for _, ax in columns.values():
        labels = [
            t.label1 for t in ax.xaxis.get_major_ticks() if t.label1.get_visible() and t.label1.get_text()
        ]
        assert labels, ax.get_title()
        assert ax.get_xlabel() == "time (s)"


def test_every_target_on_the_map_has_its_own_colour_and_marker():
    sim = association_scenario(12, duration_s=40.0)
    problem = sim.scenario.problem()
    assert len(problem.target_ids) == 12
    fig = map_figure(problem, SimpleNamespace(estimate=np.zeros(problem.layout.n)))
    for ax in fig.axes:
        styles = [
            (line.get_color(), line.get_marker())
            for line in ax.get_lines()
            if not line.get_label().startswith("_")
        ]
        assert len(styles) == 12 and len(set(styles)) == 12, styles
