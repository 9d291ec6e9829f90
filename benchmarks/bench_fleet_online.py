"""Speed of the online fleet filter (registration.fleet.FleetFilter), with baselines in the same run.

    python3 benchmarks/bench_fleet_online.py                 # 8 sensors x 10 targets x 1000 s at 1 Hz
    python3 benchmarks/bench_fleet_online.py --duration 200 --repeats 5

Problem: the batch benchmark's fleet (benchmarks/bench_fleet.py: eight sensors of four kinds on
three ships and a shore site, ten targets, 80 000 plots over 1000 s, errors of 1 deg and 300 m),
20 s windows (one epoch, one update, per window). Timed, best of ``--repeats``:

* streaming: plots fed as they would arrive, one ``update()`` per second of data, then ``flush()``;
* the whole table in one ``update()`` (what :func:`register_online` does, without its final
  residual pass);
* baselines: :func:`solve_batch` on the same plots (per plot), and the two-ship filter
  ``register()`` on the paper's scenario (per plot: two plots a row) beside the fleet filter on the
  same scenario as fleet tables (one epoch per instant, two plots per epoch).

Per plot, each epoch costs the fit of its target windows (a few calls of the generated
``fleet_rows_4`` over the epoch's plots) and one small dense update in NumPy; the Python per epoch
is amortised over its plots, so the cost per plot falls as epochs hold more plots. The estimate
is compared with the batch's (in batch sigmas) so the timed runs are known to be right.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from bench_fleet import CONFIG  # noqa: E402

from registration.fleet import BatchOptions, FleetFilter, fleet_scenario, solve_batch  # noqa: E402
from registration.fleet.online.filter import OnlineOptions, register_online  # noqa: E402
from registration.online import RegistrationConfig, register  # noqa: E402
from registration.online.scenario import ShipMotion, paper_scenario  # noqa: E402


def _best(fn, repeats: int):
    best, value = np.inf, None
    for _ in range(repeats):
        t0 = time.perf_counter()
        value = fn()
        best = min(best, time.perf_counter() - t0)
    return value, best


def _stream(sc, plots, step_s: float):
    filt = FleetFilter(sc.sensors, sc.navigation, sc.platforms, sc.references)
    edges = np.arange(0.0, plots["time"][-1] + step_s, step_s)
    cut = np.searchsorted(plots["time"], edges)
    for a, b in zip(cut[:-1], cut[1:]):
        if b > a:
            filt.update({k: v[a:b] for k, v in plots.items()})
    filt.flush()
    return filt


def _whole(sc, plots):
    filt = FleetFilter(sc.sensors, sc.navigation, sc.platforms, sc.references)
    filt.update(plots)
    filt.flush()
    return filt


def _two_ship(repeats: int) -> dict:
    from tests.fleet.two_ship import fleet_tables

    sc = paper_scenario(0, ship_motion=ShipMotion())
    config = RegistrationConfig()
    tables = fleet_tables(sc.data, config.sigma0, config.prior_sigma)
    options = OnlineOptions(window_s=0.0)
    n_plots = 2 * len(sc.data["time"])
    _, t_reg = _best(lambda: register(sc.data, config), repeats)
    _, t_fleet = _best(lambda: register_online(**tables, options=options, residuals=False), repeats)
    return {
        "plots": n_plots,
        "register_us_per_plot": 1e6 * t_reg / n_plots,
        "fleet_online_us_per_plot": 1e6 * t_fleet / n_plots,
        "ratio_fleet_over_register": t_fleet / t_reg,
    }


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument(
        "--duration", type=float, default=1000.0, help="seconds of data (1 Hz per sensor and target)"
    )
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args(argv)

    sc = fleet_scenario(3, duration_s=args.duration, config=CONFIG)
    order = np.argsort(sc.plots["time"], kind="stable")
    plots = {k: v[order] for k, v in sc.plots.items()}
    n = order.size
    _whole(sc, plots)  # warm-up: compiled library
    load_before = os.getloadavg()
    streamed, t_stream = _best(lambda: _stream(sc, plots, 1.0), args.repeats)
    whole, t_whole = _best(lambda: _whole(sc, plots), args.repeats)
    batch, t_batch = _best(lambda: solve_batch(sc.problem(), BatchOptions()), args.repeats)
    free = batch.layout.free
    out = {
        "plots": n,
        "epochs": int(whole.result().history.time.size),
        "linearisations": whole.n_linearisations,
        "load_average_before": load_before,
        "streaming_1s_chunks_us_per_plot": 1e6 * t_stream / n,
        "whole_table_us_per_plot": 1e6 * t_whole / n,
        "solve_batch_us_per_plot": 1e6 * t_batch / n,
        "ratio_online_over_batch": t_whole / t_batch,
        "streamed_equals_whole_bit_for_bit": bool(np.array_equal(streamed.estimate, whole.estimate)),
        "max_difference_from_batch_in_batch_sigma": float(
            np.abs((whole.estimate - batch.estimate)[free] / batch.sigma[free]).max()
        ),
        "two_ship_paper_scenario": _two_ship(args.repeats),
        "load_average_after": os.getloadavg(),
    }
    for key, value in out.items():
        print(f"{key:42s} {value}")
    return out


if __name__ == "__main__":
    main()
