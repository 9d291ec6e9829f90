"""Speed of the online fleet filter (registration.fleet.FleetFilter), with baselines in the same run.

    python3 benchmarks/bench_fleet_online.py                 # 8 sensors x 10 targets x 1000 s at 1 Hz
    python3 benchmarks/bench_fleet_online.py --duration 200 --repeats 5
    python3 benchmarks/bench_fleet_online.py --tiny          # seconds: does it still run?

Problem: the batch benchmark's fleet (benchmarks/bench_fleet.py: eight sensors of four kinds on
three ships and a shore site, ten targets, 80 000 plots over 1000 s, errors of 1 deg and 300 m),
20 s windows (one epoch, one update, per window). Timed, median of ``--repeats`` rounds
interleaved (common.interleave; ratios are medians of the rounds' ratios; figures in
benchmarks/results/fleet_online.json):

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

import numpy as np
from bench_fleet import CONFIG  # a script beside this one
from common import add_arguments, interleave, median, paired_ratio, summary, write

from registration.fleet import (
    BatchOptions,
    FleetFilter,
    OnlineOptions,
    fleet_scenario,
    register_online,
    solve_batch,
)
from registration.online import RegistrationConfig, register
from registration.online.scenario import ShipMotion, paper_scenario


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


def _two_ship(repeats: int, rows: int | None = None) -> dict:
    """The two-ship filter against the fleet filter on the paper scenario (its first ``rows``)."""
    from tests.fleet.two_ship import fleet_tables

    sc = paper_scenario(0, ship_motion=ShipMotion())
    if rows is not None:
        sc.data = {k: v[:rows] for k, v in sc.data.items()}
    config = RegistrationConfig()
    tables = fleet_tables(sc.data, config.sigma0, config.prior_sigma)
    options = OnlineOptions(window_s=0.0)
    n_plots = 2 * len(sc.data["time"])
    times, _ = interleave(
        {
            "register": lambda: register(sc.data, config),
            "fleet_online": lambda: register_online(**tables, options=options, residuals=False),
        },
        repeats,
    )
    return {
        "plots": n_plots,
        "register_us_per_plot": 1e6 * median(times["register"]) / n_plots,
        "fleet_online_us_per_plot": 1e6 * median(times["fleet_online"]) / n_plots,
        "ratio_fleet_over_register": paired_ratio(times, "fleet_online", "register"),
    }


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument(
        "--duration", type=float, default=1000.0, help="seconds of data (1 Hz per sensor and target)"
    )
    parser.add_argument("--repeats", type=int, default=3, help="interleaved rounds")
    add_arguments(parser)
    args = parser.parse_args(argv)
    if args.tiny:
        args.duration, args.repeats = 30.0, 1

    sc = fleet_scenario(3, duration_s=args.duration, config=CONFIG)
    order = np.argsort(sc.plots["time"], kind="stable")
    plots = {k: v[order] for k, v in sc.plots.items()}
    n = order.size
    load_before = os.getloadavg()
    times, values = interleave(
        {
            "streaming": lambda: _stream(sc, plots, 1.0),
            "whole": lambda: _whole(sc, plots),
            "batch": lambda: solve_batch(sc.problem(), BatchOptions()),
        },
        args.repeats,
    )
    streamed, whole, batch = values["streaming"], values["whole"], values["batch"]
    free = batch.layout.free
    sizes = {"duration_s": args.duration, "plots": n, "repeats": args.repeats}
    out = {
        "epochs": int(whole.result().history.time.size),
        "linearisations": whole.n_linearisations,
        "load_average_before": load_before,
        "us_per_plot": summary(times, per=n / 1e6),
        "streaming_1s_chunks_us_per_plot": 1e6 * median(times["streaming"]) / n,
        "whole_table_us_per_plot": 1e6 * median(times["whole"]) / n,
        "solve_batch_us_per_plot": 1e6 * median(times["batch"]) / n,
        "ratio_online_over_batch": paired_ratio(times, "whole", "batch"),
        "ratio_streaming_over_batch": paired_ratio(times, "streaming", "batch"),
        "streamed_equals_whole_bit_for_bit": bool(np.array_equal(streamed.estimate, whole.estimate)),
        "max_difference_from_batch_in_batch_sigma": float(
            np.abs((whole.estimate - batch.estimate)[free] / batch.sigma[free]).max()
        ),
        "two_ship_paper_scenario": _two_ship(args.repeats, 40 if args.tiny else None),
        "load_average_after": os.getloadavg(),
    }
    for key, value in {**sizes, **out}.items():
        print(f"{key:42s} {value}")
    write("fleet_online", args, sizes, out)
    return out


if __name__ == "__main__":
    main()
