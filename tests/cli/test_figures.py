"""The figures of `registration fuse` and `registration landing`: colours that viewers with
red-green colour blindness tell apart (they compared tab:red with tab:green), and the fuse legend
clear of the points."""

import itertools

from registration.fusion.evaluation import evaluate
from registration.fusion.plots import fused_figure, measurements_figure
from registration.fusion.scenarios import paper_scenario
from registration.landing.plots import METHOD_STYLES
from tests.colours import colours_told_apart, figure_colours_told_apart


def test_fuse_figures_use_colours_told_apart():
    ev = evaluate(paper_scenario(1), trials=20, seed=0)
    for fig in (fused_figure(ev, 20), measurements_figure(ev, 20)):
        assert figure_colours_told_apart(fig) == []


def test_fuse_measurement_legend_is_outside_the_points():
    ev = evaluate(paper_scenario(2), trials=200, seed=0)
    fig = measurements_figure(ev, 200)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    points = fig.axes[1]
    legend = points.get_legend().get_window_extent(renderer)
    assert not legend.overlaps(points.get_window_extent(renderer))


def test_landing_methods_have_colours_told_apart():
    for (a, (ca, _)), (b, (cb, _)) in itertools.combinations(METHOD_STYLES.items(), 2):
        assert colours_told_apart(ca, cb), (a, b)
