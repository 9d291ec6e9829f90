"""The plots of `registration register` come from a bounded series kept while streaming (no
output is read again), and a resumed run, which re-reads its outputs, plots the same points."""

from __future__ import annotations

import numpy as np
import pytest

import registration.recorded.output.plots as plots
import registration.recorded.run.filtering as filtering
import registration.recorded.run.runner as runner
from registration.recorded import RunOptions, run_register
from registration.recorded.output.plotseries import SERIES_FIELDS, PlotSeries, plot_step

from ._register_data import frame


def _feed(series: PlotSeries, n: int, sizes) -> None:
    rng = np.random.default_rng(1)
    data = {
        "time": np.arange(n, dtype=float),
        "x": rng.normal(size=(n, 12)),
        "raw_diff": rng.normal(size=(n, 3)),
        "rows": rng.normal(size=(n, 18)),
    }
    P = np.broadcast_to(np.eye(12), (n, 12, 12)) * (1.0 + np.arange(n))[:, None, None]
    start = 0
    for size in sizes:
        s = slice(start, min(start + size, n))
        series.add(
            data["time"][s],
            data["x"][s],
            P[s],
            data["raw_diff"][s],
            -data["raw_diff"][s],
            data["raw_diff"][s] * 2,
            data["raw_diff"][s] * 3,
            data["rows"][s],
        )
        start = s.stop
        if start >= n:
            break


@pytest.mark.parametrize("n", [1, 99, 100, 101, 1000, 4099])
def test_the_kept_rows_depend_on_the_row_count_only(n):
    a, b = PlotSeries(100), PlotSeries(100)
    _feed(a, n, [n])
    _feed(b, n, [7, 1, 250, 3] * n)
    got_a, got_b = a.arrays(), b.arrays()
    step = plot_step(n, 100)
    assert np.array_equal(got_a["time"], np.arange(0, n, step, dtype=float))
    assert len(got_a["time"]) <= 100 and (step == 1 or len(got_a["time"]) > 50)
    for name, width in SERIES_FIELDS.items():
        assert np.array_equal(got_a[name], got_b[name]), name
        assert got_a[name].shape == ((len(got_a["time"]),) if name == "time" else (len(got_a["time"]), width))
    assert np.array_equal(got_a["sigma"][:, 0], np.sqrt(1.0 + np.arange(0, n, step)))


def test_a_resumed_run_plots_the_points_of_an_uninterrupted_one(tmp_path, monkeypatch):
    monkeypatch.setattr(filtering, "PLOT_POINTS", 50)  # 300 rows: every 8th row is plotted
    monkeypatch.setattr(plots, "PLOT_POINTS", 50)
    seen = []
    draw = runner.write_plots

    def capture(series, status, folder):
        seen.append({k: np.array(v) for k, v in series.items()})
        return draw(series, status, folder)

    monkeypatch.setattr(runner, "write_plots", capture)
    inp = tmp_path / "in.csv"
    f = frame(300, motion=True)
    f.loc[17, "a_range_m"] = -1.0  # a rejected row: row numbers and registered ordinals differ
    f.to_csv(inp, index=False)

    def options(out, ckpt=None):
        return RunOptions(
            out=out,
            checkpoint=ckpt,
            checkpoint_every=64,
            chunk_rows=64,
            on_bad_row="skip",
            progress=False,
            log=lambda m: None,
        )

    run_register([inp], options(tmp_path / "ref"))
    with monkeypatch.context() as m:  # stopped in the second pass: the resumed run has no series in memory
        m.setattr(
            filtering, "information_at_estimate", lambda *a, **k: (_ for _ in ()).throw(KeyboardInterrupt)
        )
        with pytest.raises(KeyboardInterrupt):
            run_register([inp], options(tmp_path / "run", tmp_path / "run.ckpt"))
    run_register([inp], options(tmp_path / "run", tmp_path / "run.ckpt"))
    streamed, reread = seen
    assert len(streamed["time"]) == 38 == -(-299 // 8)
    assert np.array_equal(streamed["time"], reread["time"])
    for name in SERIES_FIELDS:  # the outputs hold degrees: a round trip costs an ulp or so
        assert np.allclose(streamed[name], reread[name], rtol=1e-13, atol=1e-9), name
    for png in ("estimates.png", "differences.png", "tracks.png"):
        assert (tmp_path / "run" / png).stat().st_size > 10_000
