"""The compiled tracker loop (``registration._codegen.compiled_tracks``) gives the tracks of its
numpy reference loop (``sensor_tracks(..., compiled=False)``), plot for plot, in every tracker run
of the association: on fleets, seeds, clutter rates and scan periods the benchmark does not use."""

import numpy as np
import pytest

from registration import _codegen
from registration.fleet import associate_and_register, association_scenario
from registration.fleet.association.grouping import tracks, units

#: 2-D radars and one 3-D radar (the anchor), at other periods and offsets than the default fleet's.
SENSORS_2D = {
    "S-3D": ("S", (30.0, np.radians(0.1), np.radians(0.1)), 1.5, 0.9, (0.0, 5.0, 12.0)),
    "A-2D": ("A", (40.0, np.radians(0.2), np.nan), 2.0, 0.3, (0.0, -12.0, 18.0)),
    "B-2D": ("B", (35.0, np.radians(0.25), np.nan), 4.0, 1.1, (0.0, -10.0, 18.0)),
    "C-2D": ("C", (40.0, np.radians(0.2), np.nan), 2.5, 0.7, (0.0, -30.0, 22.0)),
    "S-2D": ("S", (30.0, np.radians(0.1), np.nan), 3.0, 0.2, (0.0, 0.0, 10.0)),
}

CASES = {
    "default fleet, crossing, clutter 3 a scan": dict(
        n_targets=8, crossing=True, clutter_per_scan=3.0, p_missed=0.2, seed=11
    ),
    "default fleet, no clutter": dict(n_targets=6, clutter_per_scan=0.0, p_missed=0.05, seed=23),
    "2-D radars at 2-4 s, a 3-D one at 1.5 s": dict(
        n_targets=7, crossing=True, clutter_per_scan=2.0, seed=37, sensors=SENSORS_2D
    ),
}

pytestmark = pytest.mark.skipif(_codegen.backend() != "c", reason="the compiled loop needs the C backend")


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_compiled_loop_gives_the_reference_tracks(case, monkeypatch):
    runs = []
    reference = tracks.sensor_tracks

    def both(*args, **kwargs):
        assigner_c, assigner_py = (type(args[3])() for _ in range(2))
        args_c, args_py = (args[:3] + (a,) + args[4:] for a in (assigner_c, assigner_py))
        compiled = reference(*args_c, **kwargs, compiled=True)
        numpy = reference(*args_py, **kwargs, compiled=False)
        runs.append((compiled, numpy, assigner_c.calls, assigner_py.calls))
        args[3].calls += assigner_c.calls
        return compiled

    monkeypatch.setattr(units, "sensor_tracks", both)
    sim = association_scenario(duration_s=150.0, **CASES[case])
    sc = sim.scenario
    associate_and_register(sim.plots, sc.sensors, sc.navigation, sc.platforms)
    assert runs  # the association ran the tracker (three times on most fleets)
    for compiled, numpy, calls_c, calls_py in runs:
        assert np.array_equal(compiled, numpy)
        assert calls_c == calls_py  # the same assignments were needed
    assert (runs[0][0] >= 0).mean() > 0.5  # most plots in tracks: a test of tracks, not of clutter
    if CASES[case]["clutter_per_scan"] > 0:
        assert sum(r[2] for r in runs) > 0  # the assignment was exercised, not only lone pairs
