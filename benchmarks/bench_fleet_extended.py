#!/usr/bin/env python3
"""Cost of the extended sensor error model (range gain + time bias on every sensor) in the batch solver.

Run from a checkout::

    python3 benchmarks/bench_fleet_extended.py                  # 80 000 plots, 5 alternating repeats
    python3 benchmarks/bench_fleet_extended.py --repeats 7 --json out.json
    python3 benchmarks/bench_fleet_extended.py --profile        # and a cProfile of one solve per mode

Requirement checked (printed, never asserted: timings depend on the machine and its load): "the
batch on the 80 000-plot benchmark with gain and time bias on every sensor takes at most
LIMIT (1.5) times the time without them, measured in one run".

Problem: the fleet of ``bench_fleet.py`` (three ships and a shore site, eight sensors, ten
targets, 1 Hz per sensor and target over 1000 s: 80 000 plots, seed 3). Modes, all timed in the
same process, in alternating order (ABC, CBA, ABC, ...), so slow phases of the machine (other
processes, the 2 cores shared) hit every mode alike:

* ``base``: the benchmark as it is (6 states per sensor group, ``fleet_rows_4``);
* ``gain+time``: the same fleet simulated with a range gain of +-5e-4 and a time bias of +-0.3 s
  on every sensor (:func:`fleet_scenario` ``range_gain``, ``time_bias``), both estimated without
  prior (``prior_range_gain`` / ``prior_time_bias`` = inf): 11 states per group,
  ``fleet_rows_ext_4``, and every evaluation re-evaluates the windows' basis, the targets'
  velocities and the platforms' navigation at t - time bias. This is the mode of the requirement;
* ``gain+time-inner`` (unless ``--no-inner``): the ``gain+time`` problem without the plots within
  INNER_MARGIN_S of the ends of the navigation (90 of 80 000): no time bias then moves a plot
  outside the navigation, so the solver sets none aside (it weighs such plots 0 where they are
  outside, and solves anew only if that would empty a window); the difference from ``gain+time``
  is the cost of those plots, the rest is the cost of the model and of the data;
* ``model-only`` (unless ``--no-model-only``): the ``base`` data with the two columns added (the
  true gains and time biases are zero): the cost of the model itself. A time-bias estimate near
  zero can still move a plot at the very start or end outside the navigation (see the
  ``excluded_plots`` and ``fit_attempts`` rows).

Per mode: best and median wall time of :func:`solve_batch`, microseconds per plot, the fit alone
(``fit`` of the batch solver), the fit attempts (``determined_design`` calls: 2 when plots set aside
for their time bias would have emptied a window and the problem was solved again), the
Levenberg-Marquardt calls and iterations summed over every attempt (``BatchResult.iterations``
counts only the last attempt), and the number of calls and the time per call of ``evaluate``,
``normal_equations`` and ``reduce`` (the Schur complement), counted by wrapping those functions
wherever the package has bound them (a few microseconds per call). A ratio driven by more calls is a
different story from a ratio per call; both are printed. CPU time (all threads of the process) is
printed beside the wall time: on a loaded machine it varies less, but BLAS threads count twice (set
OPENBLAS_NUM_THREADS=1 to compare the two). Peak memory: one extra solve per mode under tracemalloc
(numpy's allocations included), after the timing.
"""

from __future__ import annotations

import argparse
import cProfile
import os
import pstats
import statistics
import sys
import time
import tracemalloc
from contextlib import contextmanager

import numpy as np
from bench_fleet import CONFIG  # a script beside this one
from common import add_arguments, write

import registration
from registration.fleet import BatchOptions, fleet_scenario, solve_batch

#: The requirement: gain+time over base, best of the repeats.
LIMIT = 1.5
RANGE_GAIN = 5e-4
TIME_BIAS_S = 0.3
SEED = 3
#: gain+time-inner leaves out the plots this close (s) to the ends of the navigation (2 x TIME_BIAS_S).
INNER_MARGIN_S = 0.6
#: The functions counted and timed per call, by name: found in whichever module of COUNTED_IN
#: defines them (see counted_functions), so that renaming a module does not break the benchmark.
COUNTED = ("fit", "levenberg_marquardt", "determined_design", "evaluate", "normal_equations", "reduce")
COUNTED_IN = "registration.fleet.batch"
PER_CALL = ("evaluate", "normal_equations", "reduce")


def counted_functions() -> dict:
    """name -> the function of that name defined in a loaded module under COUNTED_IN; a name no
    module defines any more is left out (its counts are reported as absent, not as zero)."""
    found: dict = {}
    for mod_name, module in sorted(sys.modules.items()):
        if module is None or not mod_name.startswith(COUNTED_IN):
            continue
        for name in COUNTED:
            fn = vars(module).get(name)
            if callable(fn) and getattr(fn, "__module__", None) == mod_name:
                found.setdefault(name, fn)
    return found


def problems(duration_s: float, model_only: bool, inner: bool = True) -> dict:
    """The problems of the modes (module docstring), by name."""
    out = {
        "base": fleet_scenario(SEED, duration_s=duration_s, config=CONFIG).problem(),
        "gain+time": fleet_scenario(
            SEED, duration_s=duration_s, config=CONFIG, range_gain=RANGE_GAIN, time_bias=TIME_BIAS_S
        ).problem(),
    }
    if inner:  # the gain+time problem without its plots within INNER_MARGIN_S of the navigation's ends
        prob = out["gain+time"]
        edge = (prob.time < INNER_MARGIN_S) | (prob.time > duration_s - INNER_MARGIN_S)
        out["gain+time-inner"] = prob.drop_plots(edge, ())
    if model_only:
        sc = fleet_scenario(SEED, duration_s=duration_s, config=CONFIG)
        n = sc.sensors["sensor"].size
        sc.sensors["prior_range_gain"] = np.full(n, np.inf)
        sc.sensors["prior_time_bias"] = np.full(n, np.inf)
        out["model-only"] = sc.problem()
    return out


class Counter:
    """Calls and seconds of the COUNTED functions while :meth:`installed`; the LM iterations."""

    def __init__(self):
        self.originals = counted_functions()
        self.calls = {name: 0 for name in self.originals}
        self.seconds = {name: 0.0 for name in self.originals}
        self.lm_iterations = 0

    def _wrap(self, name, fn):
        def wrapper(*args, **kwargs):
            t0 = time.perf_counter()
            value = fn(*args, **kwargs)
            self.seconds[name] += time.perf_counter() - t0
            self.calls[name] += 1
            if name == "levenberg_marquardt" and isinstance(value, tuple) and len(value) > 3:
                self.lm_iterations += int(value[3])  # (ev, normal, converged, iterations, history)
            return value

        wrapper.__wrapped__ = fn
        return wrapper

    @contextmanager
    def installed(self):
        """Every binding of the counted functions in the loaded registration modules replaced
        by a counting wrapper (by identity, so ``from x import f`` copies are caught), restored after."""
        originals = self.originals
        wrappers = {name: self._wrap(name, fn) for name, fn in originals.items()}
        by_id = {id(fn): name for name, fn in originals.items()}
        patched = []
        for mod_name, module in list(sys.modules.items()):
            if module is None or not mod_name.startswith("registration"):
                continue
            for attr, value in list(vars(module).items()):
                if id(value) in by_id and value is originals[by_id[id(value)]]:
                    setattr(module, attr, wrappers[by_id[id(value)]])
                    patched.append((module, attr, value))
        try:
            yield self
        finally:
            for module, attr, value in patched:
                setattr(module, attr, value)


def run_once(problem, options) -> dict:
    """One timed solve_batch with counters."""
    counter = Counter()
    with counter.installed():
        t0, c0 = time.perf_counter(), time.process_time()
        result = solve_batch(problem, options)
        seconds, cpu = time.perf_counter() - t0, time.process_time() - c0
    return {
        "seconds": seconds,
        "cpu_seconds": cpu,
        "calls": counter.calls,
        "call_seconds": counter.seconds,
        "lm_iterations": counter.lm_iterations,
        "reported_iterations": int(result.iterations),
        "converged": bool(result.converged),
        "states": int(result.layout.n),
        "excluded_plots": int(sum(e.n_plots for e in result.excluded)),
    }


def peak_memory(problem, options) -> float:
    """Peak traced memory (MB) of one solve_batch above what was allocated before."""
    tracemalloc.start()
    tracemalloc.reset_peak()
    base = tracemalloc.get_traced_memory()[0]
    solve_batch(problem, options)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return (peak - base) / 1e6


def profile(name: str, problem, options, top: int) -> None:
    """cProfile of one solve_batch: the ``top`` functions by own time and by cumulative time."""
    prof = cProfile.Profile()
    prof.enable()
    solve_batch(problem, options)
    prof.disable()
    print(f"\n=== cProfile, mode {name} ===")
    stats = pstats.Stats(prof)
    stats.sort_stats("tottime").print_stats(top)
    stats.sort_stats("cumulative").print_stats(top)


def summarise(name: str, runs: list, n_plots: int) -> dict:
    """Best-of and median figures of one mode's runs (the first run's counts: they do not vary);
    None for a counted function the package no longer defines."""
    t = [r["seconds"] for r in runs]
    best = min(runs, key=lambda r: r["seconds"])
    for r in runs:
        r["calls"] = {fn: r["calls"].get(fn) for fn in COUNTED}
        r["call_seconds"] = {fn: r["call_seconds"].get(fn, float("nan")) for fn in COUNTED}
    out = {
        "mode": name,
        "plots": n_plots,
        "states": best["states"],
        "best_s": min(t),
        "median_s": statistics.median(t),
        "all_s": t,
        "us_per_plot_best": 1e6 * min(t) / n_plots,
        "lm_calls": best["calls"]["levenberg_marquardt"],
        "fit_attempts": best["calls"]["determined_design"],
        "lm_iterations": best["lm_iterations"],
        "reported_iterations": best["reported_iterations"],
        "converged": best["converged"],
        "excluded_plots": best["excluded_plots"],
        "fit_best_s": min(r["call_seconds"]["fit"] for r in runs),
    }
    out["cpu_best_s"] = min(r["cpu_seconds"] for r in runs)
    out["outside_fit_best_s"] = min(r["seconds"] - r["call_seconds"]["fit"] for r in runs)
    out["best_s_per_lm_iteration"] = out["best_s"] / max(out["lm_iterations"], 1)
    for fn in PER_CALL:
        out[f"{fn}_calls"] = best["calls"][fn]
        per_call = [r["call_seconds"][fn] / max(r["calls"][fn] or 0, 1) for r in runs]
        out[f"{fn}_ms_per_call"] = 1e3 * min(per_call)
        out[f"{fn}_total_best_s"] = min(r["call_seconds"][fn] for r in runs)
    return out


def print_table(rows: list) -> None:
    keys = [k for k in rows[0] if k not in ("mode", "all_s")]
    print(f"\n{'':28s}" + "".join(f"{r['mode']:>17s}" for r in rows))
    for k in keys:
        cells = []
        for r in rows:
            v = r[k]
            cells.append(f"{v:17.4g}" if isinstance(v, float) else f"{str(v):>17s}")
        print(f"{k:28s}" + "".join(cells))


def ratios(rows: dict, mode: str, base: str = "base") -> dict:
    """mode over base: wall time (best, median), per LM iteration, per call and call counts."""
    a, b = rows[mode], rows[base]
    out = {
        "best": a["best_s"] / b["best_s"],
        "median": a["median_s"] / b["median_s"],
        "cpu_best": a["cpu_best_s"] / b["cpu_best_s"],
        "fit_best": a["fit_best_s"] / b["fit_best_s"],
        "lm_iterations": a["lm_iterations"] / max(b["lm_iterations"], 1),
        "per_lm_iteration": a["best_s_per_lm_iteration"] / b["best_s_per_lm_iteration"],
        "median_of_round_ratios": statistics.median(
            [x / y for x, y in zip(a["all_s"], b["all_s"], strict=True)]
        ),
    }
    for fn in PER_CALL:
        if a[f"{fn}_calls"] is None or b[f"{fn}_calls"] is None:
            continue
        out[f"{fn}_per_call"] = a[f"{fn}_ms_per_call"] / max(b[f"{fn}_ms_per_call"], 1e-300)
        out[f"{fn}_calls"] = a[f"{fn}_calls"] / max(b[f"{fn}_calls"], 1)
    if "peak_memory_mb" in a:
        out["peak_memory"] = a["peak_memory_mb"] / b["peak_memory_mb"]
    return out


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument(
        "--duration", type=float, default=1000.0, help="seconds of data (1 Hz per sensor and target)"
    )
    parser.add_argument("--repeats", type=int, default=5, help="timed solves per mode (alternating)")
    parser.add_argument("--no-model-only", action="store_true", help="leave out the model-only mode")
    parser.add_argument("--no-inner", action="store_true", help="leave out the gain+time-inner mode")
    parser.add_argument("--no-memory", action="store_true", help="skip the tracemalloc pass")
    parser.add_argument("--profile", action="store_true", help="print a cProfile of one solve per mode")
    parser.add_argument("--top", type=int, default=20, help="functions shown per cProfile table")
    add_arguments(parser)
    args = parser.parse_args(argv)
    if args.tiny:
        args.duration, args.repeats = 20.0, 1

    options = BatchOptions()
    probs = problems(args.duration, not args.no_model_only, not args.no_inner)
    names = list(probs)
    print(
        f"registration {getattr(registration, '__version__', '?')}, numpy {np.__version__}, "
        f"OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS')}, cpus {os.cpu_count()}, "
        f"load average before {os.getloadavg()}",
        flush=True,
    )
    for name in names:  # warm-up: compiled library, lazy imports, allocator
        solve_batch(probs[name], options)
    runs = {name: [] for name in names}
    for k in range(args.repeats):
        order = names if k % 2 == 0 else names[::-1]
        for name in order:
            r = run_once(probs[name], options)
            runs[name].append(r)
            calls = {fn: r["calls"].get(fn, "-") for fn in COUNTED}
            print(
                f"repeat {k + 1} {name:15s} {r['seconds']:7.3f} s (cpu {r['cpu_seconds']:6.3f} s)  "
                f"LM calls {calls['levenberg_marquardt']} iterations {r['lm_iterations']}  "
                f"evaluate {calls['evaluate']}  normal {calls['normal_equations']}  reduce {calls['reduce']}",
                flush=True,
            )
    rows = {name: summarise(name, runs[name], probs[name].n_plots) for name in names}
    if not args.no_memory:
        for name in names:
            rows[name]["peak_memory_mb"] = peak_memory(probs[name], options)
    print_table(list(rows.values()))
    out = {
        "load_average_after": os.getloadavg(),
        "limit": LIMIT,
        "modes": rows,
        "ratios": {name: ratios(rows, name) for name in names if name != "base"},
    }
    for name, rat in out["ratios"].items():
        print(f"\nratios {name} / base:")
        for k, v in rat.items():
            print(f"  {k:28s} {v:7.3f}")
    ratio = out["ratios"]["gain+time"]["best"]
    print(
        f"\nrequirement: gain+time / base = {ratio:.3f} (best of {args.repeats}; median "
        f"{out['ratios']['gain+time']['median']:.3f}; median of the rounds' ratios "
        f"{out['ratios']['gain+time']['median_of_round_ratios']:.3f}), limit {LIMIT}: "
        f"{'met' if ratio <= LIMIT else 'NOT met'}"
    )
    missing = sorted(set(COUNTED) - set(counted_functions()))
    if missing:
        print(f"not counted (no module under {COUNTED_IN} defines them any more): {', '.join(missing)}")
    print(f"load average after {out['load_average_after']}")
    if args.profile:
        for name in names:
            profile(name, probs[name], options, args.top)
    sizes = {"duration_s": args.duration, "plots": probs["base"].n_plots, "repeats": args.repeats}
    write("fleet_extended", args, sizes, out)
    return out


if __name__ == "__main__":
    main()
